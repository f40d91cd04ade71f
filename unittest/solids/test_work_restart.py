"""Restart of the work-to-heat tallies (unittest/solids/in.work, the plastic
pull in two halves): read back from a restart file (on --np ranks), fix
sph/materials continues its tallies, so that the heat made of plastic work
since the start equals the solid's energy sum(esph) to round-off, and the
heat is that of the same pull run in one go (within 1 %: LAMMPS's MACHDYN
does not continue a moving solid exactly across a restart: its work differs
by 0.3 %).
usage: test_work_restart.py --lmp LMP --plugin PLUGIN --np N --mpirun MPIRUN"""

import argparse
import os
import re
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
INPUT = os.path.join(HERE, "in.work")
from checks import below, finish, that
from lammps_checks import run_input
from sphtest import lammps_arguments


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    lammps_arguments(parser)
    args = parser.parse_args()
    workdir = tempfile.mkdtemp(prefix="sph-work-restart-")
    plugin = os.path.abspath(args.plugin)

    def run(mode, np_=1):
        text = run_input(args.lmp, INPUT, {"plugin": plugin, "mode": mode}, workdir, np_, args.mpirun)
        found = re.findall(r"^tallies: (\S+) (\S+) (\S+)\s*$", text, re.M)
        return [float(v) for v in found[-1]] if found else None

    whole = run("whole")
    run("write")
    read = run("read", args.np)
    that(whole is not None and read is not None, "both runs printed their tallies", f"{whole} {read}")
    if whole and read:
        work, heat, energy = read
        that(heat > 0.0 and work > heat, "plastic work made heat", f"work {work}, heat {heat}")
        below(abs(heat - energy) / heat, 1e-12,
              f"heat tally {heat} against the solid's energy {energy} after a restart on {args.np} rank(s)")
        below(abs(heat - whole[1]) / whole[1], 1e-2,
              f"heat tally {heat} after a restart against {whole[1]} in one go")
    finish()


if __name__ == "__main__":
    main()
