"""compute sph/force gives the same force and torque on 1 rank and on
--np ranks (to 1e-10 of |F| and |T|), with newton on and off: the pair
sums each pair once over all ranks (with newton off, a pair across two
ranks is in both ranks' lists, and only the owner of the group's atom
counts it). unittest/body/in.force, check sum, 200 steps (which also
asserts the compute against the forces the pair gave the disc).
usage: test_force_ranks.py --lmp LMP --plugin PLUGIN --np N --mpirun MPIRUN"""

import argparse
import os
import re
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
from checks import below, finish, that
from lammps_checks import lammps_arguments, run_input


def force(args, workdir, np, newton):
    out = run_input(args.lmp, os.path.join(HERE, "in.force"),
                    {"plugin": os.path.abspath(args.plugin), "check": "sum", "newton": newton}, workdir, np,
                    args.mpirun)
    that("force: sum passed" in out, f"{np} rank(s), newton {newton}: the compute equals the disc's f",
         "its pass line")
    m = re.search(r"^force: .* F = \((\S+), (\S+)\), T = (\S+)$", out, re.M)
    return [float(v) for v in m.groups()]


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    lammps_arguments(parser)
    args = parser.parse_args()
    workdir = tempfile.mkdtemp(prefix="sph-force-")
    one = force(args, workdir, 1, "on")
    for newton in ("on", "off"):
        many = force(args, workdir, args.np, newton)
        scale_f = abs(one[0]) + abs(one[1])
        below((abs(many[0] - one[0]) + abs(many[1] - one[1])) / scale_f, 1e-10,
              f"{args.np} ranks, newton {newton}: F against 1 rank")
        below(abs(many[2] - one[2]) / abs(one[2]), 1e-10,
              f"{args.np} ranks, newton {newton}: T against 1 rank")
    finish()


if __name__ == "__main__":
    main()
