"""A melt poured into a cold mould (examples/phase-casting/in.pour): a hot
column released at one end of an open mould under gravity, freezing from
the mould's walls as it flows, coarse: 10 particles across the column, to
t = 20 sqrt(a / g). Checks:

  run-out     the front against Martin and Moyce's dam break at T = 2.547
              (Z = 2.995) within 15 % (measured 2.696, -10 %), and at the
              far wall (x > 3.5; measured 3.91) before freezing stops it
  freezing    at t = 1 every solid particle in the first row along the
              mould's floor or walls (the shell grows from them); the solid
              fraction never falls by more than 1e-3 of the melt between
              snapshots, and ends between 0.9 and 1 (measured 0.983); every
              solid particle at rest in every snapshot (below 1e-6
              sqrt(g a): one that turns solid within a step is held from
              the next; measured 0); the melt at rest at
              the end (largest speed below 1e-3 sqrt(g a); measured 2e-5)
  books       every particle kept, inside the mould (to a quarter spacing)
              in every snapshot; the heat into the mould equals the change
              of the melt's sum m e, latent heat included, to 1e-12 of it
              (measured 5e-15)

With --np N (test phase.mpi.pour_np2) instead: the pour to t = 3 (the
front at the far wall, the shell growing) on N ranks against 1 rank,
every particle's position, velocity, temperature and liquid fraction equal
to 1e-10 (measured 0 in the dump's 8 digits).
"""

import argparse
import os
import sys
import tempfile

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "tools"))
sys.path.insert(0, os.path.join(HERE, "..", "..", "tools"))
import dam_break_reference as reference  # noqa: E402
from checks import below, finish, inside, that  # noqa: E402
from lammps_checks import lammps_arguments, run_input, thermo_tables  # noqa: E402
from sphthermal_tools.dump import frame_times, read_frames  # noqa: E402

INPUT = os.path.join(HERE, "..", "..", "examples", "phase-casting", "in.pour")
N = 10
LENGTH = 4.0


def check_ranks(args):
    frames = {}
    for np_ in (1, args.np):
        with tempfile.TemporaryDirectory() as tmp:
            run_input(args.lmp, INPUT, {"plugin": args.plugin, "n": N, "tend": 3}, tmp, np_, args.mpirun)
            frames[np_] = read_frames(os.path.join(tmp, "pour.dump"))[-1][1]
    one, many = frames[1], frames[args.np]
    that(len(one["id"]) == len(many["id"]), f"{args.np} ranks: every particle in the last snapshot")
    for column in ("x", "y", "vx", "vy", "c_T", "f_phase"):
        below(float(np.abs(one[column] - many[column]).max()), 1e-10,
              f"{args.np} ranks against 1 at t = 3: {column} (largest difference)")
    that(bool((one["f_phase"] <= 0.0).any()), "solid at t = 3 (the comparison covers freezing)")
    finish()


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    lammps_arguments(parser)
    args = parser.parse_args()
    if args.np > 1:
        check_ranks(args)
        return
    with tempfile.TemporaryDirectory() as tmp:
        out = run_input(args.lmp, INPUT, {"plugin": args.plugin, "n": N, "tend": 20}, tmp)
        path = os.path.join(tmp, "pour.dump")
        frames = [f for _, f in read_frames(path)]
        stamps = frame_times(path)
    table = max((t for t in thermo_tables(out) if "v_balance" in t), key=lambda t: len(t["Time"]))
    spacing = 1.0 / N

    rows = list(zip(table["Time"] * 2.0 ** 0.5, table["v_front"], table["v_nmelt"]))
    t_ref, z_ref = 2.547, 2.995
    front = reference.front_at(rows, t_ref)
    below(abs(front / z_ref - 1.0), 0.15, f"front at T = {t_ref} against Martin and Moyce ({front:.3f} a)", ".3f")
    that(table["v_front"].max() > 3.5, "the front at the far wall", f"{table['v_front'].max():.3f} a")

    first = frames[int(np.argmin(np.abs(np.array(stamps) - 1.0)))]
    solid = first["f_phase"] <= 0.0
    x, y = first["x"][solid], first["y"][solid]
    to_mould = np.minimum(np.minimum(x, LENGTH - x), y)
    that(bool(solid.any()), "solid at t = 1")
    below(float(to_mould.max()), spacing, "distance of the solid from the mould at t = 1 (a)")

    solid_fraction = np.array([1.0 - f["f_phase"].mean() for f in frames])
    below(float(-np.diff(solid_fraction).min()), 1e-3, "the solid fraction's largest fall between snapshots")
    inside(solid_fraction[-1], 0.9, 1.0, "the solid fraction at the end")
    margin = 0.25 * spacing
    for t, frame in zip(stamps, frames):
        solid = frame["f_phase"] <= 0.0
        # (a particle that turns solid within a step is held from the next)
        below(float(np.hypot(frame["vx"][solid], frame["vy"][solid]).max(initial=0.0)), 1e-6,
              f"speed of solid particles at t = {t:g}")
        inside_mould = (frame["x"] > -margin) & (frame["x"] < LENGTH + margin) & (frame["y"] > -margin)
        that(bool(inside_mould.all()), f"every particle inside the mould at t = {t:g}")
        that(len(frame["id"]) == table["v_nmelt"][0], f"every particle in the snapshot at t = {t:g}")
    below(table["c_vmax"][-1], 1e-3, "the melt's largest speed at the end (sqrt(g a))")
    that(bool((table["v_nmelt"] == table["v_nmelt"][0]).all()), "every particle kept")
    below(float(np.abs(table["v_balance"]).max()), 1e-12, "energy books (heat into the mould against sum m e)")
    finish()


if __name__ == "__main__":
    main()
