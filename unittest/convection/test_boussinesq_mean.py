"""fix sph/boussinesq T0 'mean' (unittest/convection/in.boussinesq_mean): in
a cavity whose fluid warms as a whole, the buoyancy sums to zero to within
1 % of M g beta (mean T - its start) (one step's warming, T0 being found at
the step's end); with T0 fixed at the start's temperature it sums to that
value (to 1 %), which checks the measure.
usage: test_boussinesq_mean.py --lmp LMP --plugin PLUGIN"""

import argparse
import os
import re
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
from checks import below, finish, that
from lammps_checks import lammps_arguments, run_input


def buoyancy(args, workdir, t0):
    out = run_input(args.lmp, os.path.join(HERE, "in.boussinesq_mean"),
                    {"plugin": args.plugin, "t0": t0}, workdir, args.np, args.mpirun)
    force, expected, t_mean = (float(x) for x in re.search(r"^buoyancy: (\S+) (\S+) (\S+)", out, re.M).groups())
    return force, expected, t_mean


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    lammps_arguments(parser)
    args = parser.parse_args()
    workdir = tempfile.mkdtemp(prefix="boussinesq-mean-")
    force, expected, t_mean = buoyancy(args, workdir, "mean")
    that(t_mean > 0.5, "the fluid warms as a whole", f"mean T {t_mean:.4f} (walls 1, start 0)")
    below(abs(force) / expected, 0.01, "T0 mean: the buoyancy's sum, of M g beta (mean T - start)")
    force, expected, _ = buoyancy(args, workdir, "0.0")
    below(abs(force - expected) / expected, 0.01, "T0 fixed at the start: the sum is M g beta (mean T - T0), off by")
    finish()


if __name__ == "__main__":
    main()
