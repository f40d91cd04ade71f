"""Xu's Taylor bar (examples/solid-machdyn-taylor/in.taylor) on N ranks
against 1 rank, 4 particles across (240), to 50 us (tests
solids.mpi.taylor_np2, _np4):

  fixed reference  without renewing pair smd/tlsph's reference
                   configuration (update none), on Simo's wall and on the
                   penalty wall, every particle's position, velocity,
                   temperature and plastic strain in every snapshot equal
                   to 1 rank's to the last of the dump's 10 digits, which
                   round-off can flip (measured: one velocity's last digit
                   on 4 ranks); create_atoms numbers the particles by
                   rank, so they are matched by their initial positions
  renewed          with the example's renewal (update constant 0.5) the
                   final length and radius within 1 % of 1 rank's
                   (measured 0.09 % and 0.21 % in length on 2 and 4 ranks):
                   MACHDYN renews when a pair has stretched past the
                   threshold, and a step's round-off can move a renewal by
                   a step, after which the runs differ by the
                   discretisation, not by round-off; every particle kept
"""

import argparse
import os
import re
import sys
import tempfile

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "tools"))
sys.path.insert(0, os.path.join(HERE, "..", "..", "tools"))
from checks import below, finish, that  # noqa: E402
from lammps_checks import lammps_arguments, run_input  # noqa: E402
from sphthermal_tools.dump import read_frames  # noqa: E402

INPUT = os.path.join(HERE, "..", "..", "examples", "solid-machdyn-taylor", "in.taylor")
DIGIT = 1e-9  # the last of the dump's 10 significant digits, relative
COLUMNS = {"x": 1e-12, "y": 1e-12, "z": 1e-12, "vx": 1e-9, "vy": 1e-9, "vz": 1e-9, "c_th": 1e-9, "c_ep": 1e-12}


def by_initial_position(frames):
    """The frames with their particles in the order of their initial positions."""
    first = frames[0]
    key = np.lexsort([np.round(first[c], 9) for c in ("z", "y", "x")])
    order_of_id = {int(i): k for k, i in enumerate(first["id"][key])}
    aligned = []
    for frame in frames:
        order = np.argsort([order_of_id[int(i)] for i in frame["id"]])
        aligned.append({c: v[order] for c, v in frame.items()})
    return aligned


def run(args, np_, update, wall="penalty"):
    with tempfile.TemporaryDirectory() as tmp:
        out = run_input(args.lmp, INPUT, {"plugin": args.plugin, "n": 4, "tend": 50e-6, "update": update, "wall": wall,
                                          "out": "bar.dump"}, tmp, np_, args.mpirun)
        frames = [f for _, f in read_frames(os.path.join(tmp, "bar.dump"))]
    shape = re.search(r"taylor: n 4 t \S+ us length (\S+) mm radius (\S+) mm", out)
    that(shape is not None, f"{np_} ranks, update {update}: the final length and radius printed")
    return by_initial_position(frames), (float(shape.group(1)), float(shape.group(2)))


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    lammps_arguments(parser)
    args = parser.parse_args()

    for wall in ("penalty", "simo"):
        one, _ = run(args, 1, "none", wall)
        many, _ = run(args, args.np, "none", wall)
        that(len(one) == len(many), f"{wall} wall, {args.np} ranks: as many snapshots as 1 rank")
        for k, (a, b) in enumerate(zip(one, many)):
            that(len(a["id"]) == len(b["id"]), f"snapshot {k}: every particle on {args.np} ranks")
            for column, tolerance in COLUMNS.items():
                # beyond the last of the dump's 10 digits, which round-off can flip
                beyond = np.abs(a[column] - b[column]) - DIGIT * np.abs(a[column])
                below(float(beyond.max()), tolerance,
                      f"{wall} wall, update none, {args.np} ranks against 1, snapshot {k}: {column} "
                      f"(largest difference beyond the dump's last digit)")
        that(float(one[-1]["c_ep"].max()) > 1.0, f"{wall} wall: the comparison covers plastic flow (plastic strain above 1)")

    one_frames, one_shape = run(args, 1, "constant")
    many_frames, many_shape = run(args, args.np, "constant")
    that(len(one_frames[-1]["id"]) == len(many_frames[-1]["id"]) == 240, f"update constant: every particle kept")
    for name, a, b in zip(("length", "radius"), one_shape, many_shape):
        below(abs(b / a - 1.0), 0.01, f"update constant, {args.np} ranks against 1: final {name} ({b} against {a} mm)")
    finish()


if __name__ == "__main__":
    main()
