"""examples/forced-channel/in.exchanger goes on from its own restart file.

usage: test_exchanger_resume.py --lmp LMP --plugin PLUGIN

The parallel exchanger (10 across) runs 0.04 s (41 steps) once, and once to
0.02 s with a restart file, then from that file to 0.04 s. Resumed, it must
not set its start state again (temperatures 300/550/800 K, the Poiseuille
velocities): the last frames agree to 1e-8 m in position, 1e-6 m/s in
velocity and 0.01 K in temperature. Measured with the input's defaults
(the walls' surface, each stream's volume held): 2e-10 m, 4e-8 m/s and
1.5e-3 K, the difference LAMMPS's fix sph makes between one run and two
at an impulsive start; a reset state would be off by up to 250 K.
"""

import argparse
import os
import subprocess
import tempfile

import numpy as np

ROOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..")
from sphthermal_tools.dump import read_frames

from sphtest import finish, lammps_arguments

INPUT = os.path.join(ROOT, "examples", "forced-channel", "in.exchanger")


def run(a, tmp, out, tend, *extra):
    cmd = [a.lmp, "-in", INPUT, "-var", "plugin", a.plugin, "-var", "every", "0.04",
           "-var", "tend", str(tend), "-var", "out", out, "-log", "none", *extra]
    subprocess.run(cmd, cwd=tmp, check=True, stdout=subprocess.DEVNULL)
    step, columns = read_frames(os.path.join(tmp, out + ".dump"))[-1]
    return columns


def main():
    a = lammps_arguments(argparse.ArgumentParser(description=__doc__), mpi=False).parse_args()
    a.lmp, a.plugin = os.path.abspath(a.lmp), os.path.abspath(a.plugin)
    with tempfile.TemporaryDirectory() as tmp:
        whole = run(a, tmp, "whole", 0.04)
        run(a, tmp, "first", 0.02, "-var", "restart", "0.02")
        resumed = run(a, tmp, "resumed", 0.04, "-var", "resume", "first.restart.1")
    failures = []
    for key, limit, unit in (("x", 1e-8, "m"), ("y", 1e-8, "m"), ("vx", 1e-6, "m/s"),
                             ("vy", 1e-6, "m/s"), ("c_T", 1e-2, "K")):
        diff = np.abs(np.asarray(resumed[key]) - np.asarray(whole[key])).max()
        print(f"{key}: resumed against one run: largest difference {diff:.2e} {unit} (limit {limit:g})")
        if not diff < limit:
            failures.append(key)
    finish(failures)


if __name__ == "__main__":
    main()
