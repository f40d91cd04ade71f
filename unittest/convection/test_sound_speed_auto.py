"""The speed of sound found from the scene (unittest/convection/in.sound_speed_auto):
with 'eos linear auto' fix sph/materials takes from fix sph/boussinesq the c0
at which the buoyancy compresses the fluid by 0.05, c0^2 = |g| beta
max|T - T0| L / 0.05 (here |g| = 100, beta = 1, max|T - T0| = 0.3 x 0.9375 of
the warmest fluid column, L = 7 spacings, the fluid's extent along g); the
log says so and fix sph/boussinesq gives no compression warning. The run
equals one with that c0 and the background pressure 0.1 rho0 c0^2 given as
numbers (the 'relative' background), to round-off; 'eos tait auto 7' finds
the same c0; a restarted run keeps the c0 of its restart file although its
own scene would give another.
usage: test_sound_speed_auto.py --lmp LMP --plugin PLUGIN [--np N --mpirun M]"""

import argparse
import math
import os
import re
import tempfile

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
from checks import finish, that
from lammps_checks import lammps_arguments, read_dump, run_input

SPACING = 0.125
EXPECTED = math.sqrt(100.0 * 1.0 * (0.3 * (8 - 0.5) * SPACING) * (7 * SPACING) / 0.05)
WARMER = math.sqrt(100.0 * 1.0 * (0.6 * (8 - 0.5) * SPACING) * (7 * SPACING) / 0.05)


def run(args, workdir, **variables):
    return run_input(args.lmp, os.path.join(HERE, "in.sound_speed_auto"),
                     dict(plugin=args.plugin, **variables), workdir, args.np, args.mpirun)


def speeds(out):
    return [float(v) for v in re.findall(r"^c0 = (\S+)", out, re.M)]


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    lammps_arguments(parser)
    args = parser.parse_args()
    workdir = tempfile.mkdtemp(prefix="sound-speed-auto-")

    out = run(args, workdir, out="auto.dump")
    c0 = speeds(out)
    that(len(c0) == 1 and abs(c0[0] / EXPECTED - 1.0) < 1e-13,
         f"auto: c0 {c0} is sqrt(|g| beta max|T - T0| L / 0.05) = {EXPECTED:.15g} to 1e-13")
    said = re.search(r"Fix sph/materials: speed of sound of atom type 1 is (\S+) \(auto: the buoyancy "
                     r"of fix sph/boussinesq buoyancy compresses it by 0.05.*background pressure (\S+) "
                     r"\(0.1 rho0 c0\^2\)", out)
    that(said is not None and abs(float(said.group(1)) / EXPECTED - 1.0) < 1e-5
         and abs(float(said.group(2)) / (0.1 * EXPECTED ** 2) - 1.0) < 1e-5,
         "the log names the speed of sound, why, and the background pressure it gives")
    that("may compress" not in out, "no compression warning at the speed found")

    given = run(args, workdir, c0=f"{c0[0]:.17g}", bg=f"{0.1 * 1.0 * c0[0] * c0[0]:.17g}",
                out="given.dump")
    that("speed of sound of atom type" not in given, "a c0 given is not announced")
    a, b = read_dump(os.path.join(workdir, "auto.dump")), read_dump(os.path.join(workdir, "given.dump"))
    worst = max(np.abs(a[k] - b[k]).max() / np.abs(b[k]).max() for k in ("x", "y", "vx", "vy", "c_T"))
    moving = np.abs(b["vy"]).max() > 1e-3
    that(np.array_equal(a["id"], b["id"]) and worst <= 1e-12 and moving,
         f"auto with background 0.1 relative equals c0 and background given as numbers: largest "
         f"difference {worst:.2e} of the largest value (limit 1e-12); the fluid moves: {moving}")

    tait = speeds(run(args, workdir, eos="tait", gamma=7, out="tait.dump"))
    that(tait == c0, f"eos tait auto 7 finds the same c0 ({tait} and {c0})")

    out = run(args, workdir, restart="yes", out="restart.dump")
    before, after = speeds(out)[0], speeds(out)[-1]
    that(len(speeds(out)) == 2 and before == c0[0] and after == before
         and "auto, from the restart file" in out.split("resumed", 1)[0],
         f"a restarted run keeps the restart file's c0 ({after}), not its own scene's "
         f"({WARMER:.6g})")
    finish()


if __name__ == "__main__":
    main()
