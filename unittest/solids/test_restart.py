"""Restart of a MACHDYN scene (unittest/solids/in.restart): Xu's bar heated
by a flux, 40 steps written to a restart file and read back for 40 more
(on --np ranks) gives the temperatures and the books of 80 steps run as
two runs in one go (to 1e-12 of the largest).
usage: test_restart.py --lmp LMP --plugin PLUGIN --np N --mpirun MPIRUN"""

import argparse
import os
import re
import tempfile

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
INPUT = os.path.join(HERE, "in.restart")
from checks import below, finish, that
from lammps_checks import read_dump, run_input
from sphtest import lammps_arguments


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    lammps_arguments(parser)
    args = parser.parse_args()
    workdir = tempfile.mkdtemp(prefix="sph-restart-")
    plugin = os.path.abspath(args.plugin)

    def run(mode, np_=1):
        text = run_input(args.lmp, INPUT, {"plugin": plugin, "mode": mode, "out": f"{mode}.dump"},
                         workdir, np_, args.mpirun)
        # the books at the end of the last run of 40 steps
        return [float(v) for v in re.findall(r"^\s*80\s+(\S+)\s*$", text, re.M)[:1]]

    whole = run("whole")
    run("write")
    read = run("read", args.np)
    a = read_dump(os.path.join(workdir, "whole.dump"))
    b = read_dump(os.path.join(workdir, "read.dump"))
    scale = max(abs(a["c_th"]).max(), 1e-300)
    same_atoms = np.array_equal(a["id"], b["id"])
    that(same_atoms, "the same atom IDs after the restart", f"{len(a['id'])} and {len(b['id'])} atoms")
    if same_atoms:
        below(abs(a["c_th"] - b["c_th"]).max() / scale, 1e-12,
              f"T after a restart read on {args.np} rank(s) against one run")
    below(abs(whole[0] - read[0]) / abs(whole[0]) if whole and read else 1.0, 1e-12,
          "the thermal energy at step 80")
    finish()


if __name__ == "__main__":
    main()
