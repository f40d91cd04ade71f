"""Two fluids layered in a column under gravity (bench/stability's column
cases, 10 x 20, periodic in x, heavy below), with the default fix
sph/dt/reset to t = 0.5 s:
  * density ratio 2, 10 and 1000 with the light fluid's c0 giving it the
    heavy fluid's rho0 c0^2 (*matched*): stable, largest fluid speed below
    0.2 % of sqrt(g H) (measured 0.03-0.07 %), and pair sph/harmonic/visc
    does not warn;
  * density ratio 1000 with one c0 for both (unstable by t = 0.5 s in the
    stability map): the pair warns of the soft light fluid and names the c0
    that matches.
usage: test_two_fluid_column.py --lmp LMP --plugin PLUGIN"""

import argparse
import math
import os
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "..", "bench", "stability"))
import run_stability as stability  # noqa: E402
from checks import finish, that  # noqa: E402
from lammps_checks import lammps_arguments  # noqa: E402

WARNING = "the fluid of atom type 2 has rho0 c0^2"


def screen(args, case):
    """The screen output of a column case's last run."""
    with open(os.path.join(stability.case_dir(args, "column", case), "screen.last")) as f:
        return f.read()


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    lammps_arguments(parser, mpi=False)
    args = parser.parse_args()
    args.quick, args.timeout = True, 600.0    # quick: to t = 0.5 s
    args.work = tempfile.mkdtemp(prefix="two-fluid-column-")
    runner = stability.Runner(args)
    for case in ("layers, ratio 2, matched", "layers, ratio 10, matched", "layers, ratio 1000, matched"):
        p = stability.column_params(case)
        result = stability.column_run(args, runner, case, None)
        speed = 100 * result.get("vmax", math.inf) / math.sqrt(p["g"] * p["H"])
        that(result["stable"] and speed < 0.2, f"{case}: stable to t = 0.5 s with the default timestep, "
             "largest speed below 0.2 % of sqrt(g H)", f"{speed:.3g} %")
        that(WARNING not in screen(args, case), f"{case}: no warning of a soft fluid")
    stability.column_run(args, runner, "layers, ratio 1000", None)
    out = screen(args, "layers, ratio 1000")
    that(WARNING in out and "give type 2 c0 990.5 or more" in out,
         "layers, ratio 1000, one c0: the pair warns and names the matching c0 (990.5)")
    finish()


if __name__ == "__main__":
    main()
