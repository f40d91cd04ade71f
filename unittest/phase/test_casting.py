"""The casting-like scene (examples/phase-casting/in.casting): a melt
flowing through a channel chilled from x = 1 to 3 (open inlet and outlet),
coarse: 10 particles across, to t = 30 (H / U). Checks at the end:

  shell       a solid shell: the solid fraction of the channel between 0.05
              and 0.2 (measured 0.095); every solid particle on the chilled
              stretch (x from 1 to 3 + 2 spacings; measured 1.14 to 3.01);
              thicker on its downstream half than on its upstream half
              (measured 0.18 against 0.09 H); the same on both walls to a
              spacing in every bin (the scene is symmetric); every solid
              particle at rest
  flow        as many particles out as in to 5 % (measured 304 and 300),
              every particle between the walls (to a quarter spacing), the
              mould taking heat from the melt (its Nusselt number above 1;
              measured 3.7)
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
from lammps_checks import lammps_arguments, run_input, thermo_tables  # noqa: E402
from sphthermal_tools.dump import read_frames  # noqa: E402

INPUT = os.path.join(HERE, "..", "..", "examples", "phase-casting", "in.casting")
N = 10


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    lammps_arguments(parser, mpi=False)
    args = parser.parse_args()
    with tempfile.TemporaryDirectory() as tmp:
        out = run_input(args.lmp, INPUT, {"plugin": args.plugin, "n": N, "tend": 30}, tmp)
        frame = read_frames(os.path.join(tmp, "casting.dump"))[-1][1]
    table = [t for t in thermo_tables(out) if "v_solid" in t][-1]
    spacing = 1.0 / N
    solid = frame["f_phase"] <= 0.0
    inside(table["v_solid"][-1], 0.05, 0.2, "solid fraction of the channel")
    x, y = frame["x"][solid], frame["y"][solid]
    inside(x.min(), 1.0, 3.0, "the shell's upstream end (x)")
    inside(x.max(), 1.0, 3.0 + 2 * spacing, "the shell's downstream end (x)")
    edges = np.arange(1.0, 3.0 + 0.5 * spacing, spacing)
    bottom = np.histogram(x[y < 0.5], edges)[0] * spacing
    top = np.histogram(x[y >= 0.5], edges)[0] * spacing
    half = len(edges) // 2
    upstream, downstream = (bottom + top)[:half].mean() / 2, (bottom + top)[half:].mean() / 2
    that(downstream > upstream, "the shell thicker downstream", f"{downstream:.3f} against {upstream:.3f} H")
    below(float(np.abs(bottom - top).max()), spacing * 1.0001, "the shell the same on both walls (thickness, H)")
    below(float(np.hypot(frame["vx"][solid], frame["vy"][solid]).max()), 0.0, "speed of solid particles")
    n_in, n_out = table["f_in[1]"][-1], table["f_out[1]"][-1]
    below(abs(n_out - n_in), 0.05 * n_in, f"particles out ({n_out:g}) against in ({n_in:g})")
    margin = 0.25 * spacing
    that(bool(((frame["y"] > -margin) & (frame["y"] < 1.0 + margin)).all()), "every particle between the walls")
    inside(table["c_nu_mould[1]"][-1], 1.0, 100.0, "the mould's Nusselt number")
    finish()


if __name__ == "__main__":
    main()
