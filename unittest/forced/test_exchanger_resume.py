"""examples/forced-channel/in.exchanger (and in.channel) go on from their own
restart files.

usage: test_exchanger_resume.py --lmp LMP --plugin PLUGIN [--input exchanger|channel]

The parallel exchanger (10 across) runs 0.04 s (68 steps of fix
sph/dt/reset's timestep) once, and 0.03 s with a restart file every 0.02 s
(of the first timestep's steps: written within the run, at a step of the
whole run) and on from that file to 0.04 s. Resumed, it must not set its
start state again (temperatures 300/550/800 K, the Poiseuille
velocities): the last frames agree to 1e-8 m in position, 1e-6 m/s in
velocity and 0.01 K in temperature. Measured with the input's defaults
(the walls' surface, each stream's volume held): 1e-10 m, 1.3e-8 m/s and
5.5e-4 K, the difference LAMMPS's fix sph makes between one run and two
at an impulsive start; a reset state would be off by up to 250 K.

With --input channel: in.channel (Re 65.2, 10 across, 20 long, the walls'
surface, which needs its region again on a resume; the timestep of fix
sph/dt/reset, which the restart file keeps) runs 2 s once, and 1.5 s with
a restart file every 1 s and on from that file; positions to
1e-6 m (the dump's last digit at 20 m), the other limits the same.
"""

import argparse
import os
import subprocess
import tempfile

import numpy as np

ROOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..")
from sphthermal_tools.dump import read_frames

from sphtest import finish, lammps_arguments

# per input: its variables, the whole run's end (s), the first run's end and
# its restart interval (s), the limit on positions (m: the dump's 10 digits
# at the channel's 20 m; a reset state is off by u t = 0.8 m)
CASES = {"exchanger": ([], 0.04, 0.03, 0.02, 1e-8),
         "channel": (["-var", "n", "10", "-var", "length", "20", "-var", "re", "65.2"], 2.0, 1.5,
                     1.0, 1e-6)}


def run(a, tmp, out, tend, *extra):
    variables, whole = CASES[a.input][:2]
    cmd = [a.lmp, "-in", os.path.join(ROOT, "examples", "forced-channel", "in." + a.input),
           "-var", "plugin", a.plugin, "-var", "every", str(whole), *variables,
           "-var", "tend", str(tend), "-var", "out", out, "-log", "none", *extra]
    subprocess.run(cmd, cwd=tmp, check=True, stdout=subprocess.DEVNULL)
    step, columns = read_frames(os.path.join(tmp, out + ".dump"))[-1]
    return columns


def main():
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--input", choices=sorted(CASES), default="exchanger")
    a = lammps_arguments(parser, mpi=False).parse_args()
    a.lmp, a.plugin = os.path.abspath(a.lmp), os.path.abspath(a.plugin)
    with tempfile.TemporaryDirectory() as tmp:
        end, first_end, interval, position = CASES[a.input][1:]
        whole = run(a, tmp, "whole", end)
        run(a, tmp, "first", first_end, "-var", "restart", str(interval))
        resumed = run(a, tmp, "resumed", end, "-var", "resume", "first.restart.1")
    failures = []
    for key, limit, unit in (("x", position, "m"), ("y", position, "m"), ("vx", 1e-6, "m/s"),
                             ("vy", 1e-6, "m/s"), ("c_T", 1e-2, "K")):
        diff = np.abs(np.asarray(resumed[key]) - np.asarray(whole[key])).max()
        print(f"{key}: resumed against one run: largest difference {diff:.2e} {unit} (limit {limit:g})")
        if not diff < limit:
            failures.append(key)
    finish(failures)


if __name__ == "__main__":
    main()
