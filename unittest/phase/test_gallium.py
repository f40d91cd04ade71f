"""Melting of gallium in a cavity heated from one side, with natural
convection in the melt (examples/phase-gallium/in.gallium; the experiment
of Gau and Viskanta 1986 and pure conduction: tools/gallium_reference.py),
coarse: 20 particles across the height, to 4.5 min (snapshots at 1, 2, 3, 4
and 4.5 min), one run for both checks.

  melt        at 1 min, while the melt is thin: the melted volume within 5 %
              of pure conduction's (the two-phase Neumann solution;
              measured -2.3 %). At 4.5 min: the melted volume within 0.02 of
              the experiment's 0.205 (measured +0.005) and at least 0.01
              above conduction's 0.1875 (measured +0.023); the front at the
              top, middle and bottom within 0.04 W of the experiment's
              (measured -0.013, -0.004, +0.027) and tilted by convection:
              top minus bottom at least 0.06 W (measured 0.105; the
              experiment 0.145; conduction alone leaves it upright)
  solid       at every snapshot: every fully solid particle at rest (the
              mushy damping holds it), every particle within a quarter
              spacing of the cavity
  mean T      compute sph/thermal's mean temperature at 4.5 min equal to
              the particles' mean (equal masses and cv) to 1e-6, between
              the walls' temperatures (the latent heat is not a temperature)
"""

import argparse
import os
import sys
import tempfile

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "tools"))
sys.path.insert(0, os.path.join(HERE, "..", "..", "tools"))
from checks import below, finish, inside, that  # noqa: E402
from lammps_checks import lammps_arguments, read_dump, run_input, thermo_tables  # noqa: E402
import gallium_reference as ref  # noqa: E402

INPUT = os.path.join(HERE, "..", "..", "examples", "phase-gallium", "in.gallium")
N = 20
TIMES = (60, 120, 180, 240, 270)


def run(args):
    with tempfile.TemporaryDirectory() as tmp:
        out = run_input(args.lmp, INPUT, {"plugin": args.plugin, "n": N, "tend": TIMES[-1], "every": 10000}, tmp)
        frames = {t: read_dump(os.path.join(tmp, f"gallium.{t}.dump")) for t in TIMES}
    return frames, thermo_tables(out)[-1]


def check_mean_temperature(frames, table):
    # the particles' masses and cv are equal: compute sph/thermal's mean T is
    # the mean of their temperatures (the melt's latent heat not counted)
    mean = float(frames[270]["c_T"].mean())
    below(abs(table["c_T"][-1] - mean), 1e-6 * mean,
          f"4.5 min: compute sph/thermal's mean T {table['c_T'][-1]:.8g} = the particles' mean {mean:.8g}")
    inside(table["c_T"][-1], ref.T_INITIAL, ref.T_HOT, "4.5 min: the mean T between the walls' (K)")


def check_melt(frames):
    early = ref.melted_fraction(frames[60])
    conduction = ref.conduction_melt_fraction(60.0)
    below(abs(early / conduction - 1.0), 0.05, "1 min: melted volume against pure conduction's (relative)")
    late = frames[270]
    melted = ref.melted_fraction(late)
    measured = ref.experiment_at(ref.MELT_TIMES, ref.MELT_FRACTION, 270.0)
    below(abs(melted - measured), 0.02, f"4.5 min: melted volume {melted:.4f} against the experiment's {measured}")
    that(melted >= ref.conduction_melt_fraction(270.0) + 0.01, "4.5 min: convection melts more than conduction",
         f"{melted:.4f} against {ref.conduction_melt_fraction(270.0):.4f}")
    fronts = ref.front_positions(late, ref.HEIGHT / N)
    for row, values in (("top", ref.FRONT_TOP), ("middle", ref.FRONT_MIDDLE), ("bottom", ref.FRONT_BOTTOM)):
        measured = ref.experiment_at(ref.FRONT_TIMES, values, 270.0)
        below(abs(fronts[row] - measured), 0.04, f"4.5 min: front at the {row} {fronts[row]:.4f} against {measured}")
    inside(fronts["top"] - fronts["bottom"], 0.06, 1.0, "4.5 min: the front tilted (top - bottom, fraction of W)")


def check_solid(frames):
    spacing = ref.HEIGHT / N
    width = round(ref.WIDTH / spacing) * spacing
    for t, frame in frames.items():
        solid = frame["f_phase"] <= 0.0
        that(solid.any(), f"{t} s: solid left")
        below(float(np.hypot(frame["vx"][solid], frame["vy"][solid]).max()), 0.0, f"{t} s: speed of solid particles")
        margin = 0.25 * spacing
        inside_x = (frame["x"] > -margin) & (frame["x"] < width + margin)
        inside_y = (frame["y"] > -margin) & (frame["y"] < ref.HEIGHT + margin)
        that(bool((inside_x & inside_y).all()), f"{t} s: every particle in the cavity (to a quarter spacing)")


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    lammps_arguments(parser, mpi=False)
    args = parser.parse_args()
    frames, table = run(args)
    check_melt(frames)
    check_solid(frames)
    check_mean_temperature(frames, table)
    finish()


if __name__ == "__main__":
    main()
