"""Freezing of a liquid in a square cavity cooled from one side
(examples/phase-freezing/in.freezing: Ra = 1e5, Pr = 1, Stefan number 1),
coarse: 20 particles across. The reference is the package's finite-volume
enthalpy-porosity solver on its finest grid (tools/phase_fv_results.json,
written by tools/phase_fv.py).

  --check convection   to t = 80 (snapshots at 10, 20, 40, 80): the solid
                       fraction within 0.035 of the finite volume's at each
                       time (measured -0.012 to -0.025), at least 0.1
                       below pure conduction's at t = 80 (convection brings
                       the liquid's heat to the front: 0.25 against 0.42),
                       the front tilted (bottom minus top at least 0.2 H at
                       t = 80; the finite volume 0.27), every fully solid
                       particle at rest, every particle in the cavity
  --check conduction   without gravity, to t = 320: the solid fraction at
                       t = 20 within 0.02 of Neumann's exact one (the solid
                       still thin against H; measured -0.010); the steady
                       state: the front in the middle row at H/2 to 0.01 H
                       and T linear between the walls, Tm - 1 + 2 x / H, to
                       1e-3 at every particle (measured 3.4e-4)
"""

import argparse
import math
import os
import sys
import tempfile

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "tools"))
sys.path.insert(0, os.path.join(HERE, "..", "..", "tools"))
from checks import below, finish, inside, that  # noqa: E402
from lammps_checks import lammps_arguments, read_dump, run_input  # noqa: E402
import phase_fv  # noqa: E402
import stefan  # noqa: E402
from sphthermal_tools import phase  # noqa: E402

INPUT = os.path.join(HERE, "..", "..", "examples", "phase-freezing", "in.freezing")
N = 20
TM = 300.0


def run(args, g, times):
    with tempfile.TemporaryDirectory() as tmp:
        run_input(args.lmp, INPUT, {"plugin": args.plugin, "n": N, "tend": times[-1], "g": g, "every": 100000},
                  tmp)
        return {t: read_dump(os.path.join(tmp, f"freezing.{t}.dump")) for t in times}


def finite_volume(kind):
    """{t: sample} of phase_fv's finest grid."""
    return phase_fv.reference_series("freezing", kind)[0]


def check_in_cavity(frames):
    spacing = 1.0 / N
    margin = 0.25 * spacing
    for t, frame in frames.items():
        ok = (frame["x"] > -margin) & (frame["x"] < 1.0 + margin) & (frame["y"] > -margin) & (frame["y"] < 1.0 + margin)
        that(bool(ok.all()), f"t = {t}: every particle in the cavity (to a quarter spacing)")


def check_convection(args):
    frames = run(args, 1.0, (10, 20, 40, 80))
    fv, conduction = finite_volume("convection"), finite_volume("conduction")
    for t, frame in frames.items():
        solid = 1.0 - phase.liquid_fraction(frame)
        ref = 1.0 - fv[float(t)]["liquid_fraction"]
        below(abs(solid - ref), 0.035, f"t = {t}: solid fraction {solid:.4f} against the finite volume's {ref:.4f}")
        held = frame["f_phase"] <= 0.0
        that(held.any(), f"t = {t}: solid particles")
        below(float(np.hypot(frame["vx"][held], frame["vy"][held]).max()), 0.0, f"t = {t}: speed of solid particles")
    solid = 1.0 - phase.liquid_fraction(frames[80])
    still = 1.0 - conduction[80.0]["liquid_fraction"]
    that(solid <= still - 0.1, "t = 80: convection slows the freezing", f"{solid:.4f} against conduction's {still:.4f}")
    fronts = phase.front_positions(frames[80], 1.0 / N, 1.0, 1.0, "solid")
    inside(fronts["bottom"] - fronts["top"], 0.2, 1.0, "t = 80: the front tilted (bottom - top, fraction of H)")
    check_in_cavity(frames)


def check_conduction(args):
    frames = run(args, 0.0, (20, 320))
    lam = stefan.neumann_lambda(1.0, 1.0, 1.0)
    exact = stefan.front(20.0, lam, math.sqrt(2.0e-5))
    solid = 1.0 - phase.liquid_fraction(frames[20])
    below(abs(solid - exact), 0.02, f"t = 20: solid fraction {solid:.4f} against Neumann's {exact:.4f}")
    steady = frames[320]
    front = phase.front_positions(steady, 1.0 / N, 1.0, 1.0, "solid")["middle"]
    below(abs(front - 0.5), 0.01, f"t = 320: the front {front:.4f} at H/2")
    error = float(np.abs(steady["c_T"] - (TM - 1.0 + 2.0 * steady["x"])).max())
    below(error, 1e-3, "t = 320: T against the linear steady profile")
    check_in_cavity(frames)


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    lammps_arguments(parser, mpi=False)
    parser.add_argument("--check", choices=("convection", "conduction"), required=True)
    args = parser.parse_args()
    {"convection": check_convection, "conduction": check_conduction}[args.check](args)
    finish()


if __name__ == "__main__":
    main()
