"""The pour of in.pour: the run-out of the front against Martin and Moyce's
dam break, the freezing against time (solid fraction, the shell on the
mould's floor, the speeds of liquid and solid particles, the energy
books), as Markdown to stdout, and pour.png (the melt at six times,
coloured by its liquid fraction, and the solid fraction against time).

  python3 pour.py OUT N [N ...]   # OUT: run.sh's output directory; N: particles across the column
"""

import os
import sys

import numpy as np

import dam_break_reference as reference
from sphthermal_tools.dump import frame_times, read_frames
from sphthermal_tools.log import thermo_tables

HERE = os.path.dirname(os.path.abspath(__file__))
LENGTH = 4.0            # the mould's floor, in column widths a
G = 1.0                 # in.pour's gravity, a = 1
SHOWN = (0.0, 1.0, 2.0, 3.0, 6.0, 12.0)
TABLED = (0.0, 1.0, 2.0, 3.0, 6.0, 9.0, 12.0, 15.0, 18.0, 20.0)


def main_table(out, n):
    """in.pour's thermo rows of the main run (the longest table)"""
    with open(os.path.join(out, f"log.pour{n}")) as f:
        return max((t for t in thermo_tables(f.read()) if "v_balance" in t), key=lambda t: len(t["Time"]))


def floor_shell(frame, n):
    """The solid's mean thickness on the mould's floor between x = 1 and 3
    (away from the end walls), in a: in each column of particles the
    height of the lowest particle not solid less half a spacing (the
    freezing front), or of the highest plus half a spacing where the whole
    column is solid."""
    spacing = 1.0 / n
    x, y, solid = frame["x"], frame["y"], frame["f_phase"] <= 0.0
    heights = []
    for left in np.arange(1.0, 3.0 - 0.5 * spacing, spacing):
        here = (x >= left) & (x < left + spacing)
        if not here.any():
            continue
        melt = here & ~solid
        heights.append(y[melt].min() - 0.5 * spacing if melt.any() else y[here].max() + 0.5 * spacing)
    return float(np.mean(heights)) if heights else 0.0


def main():
    out, sizes = sys.argv[1], [int(a) for a in sys.argv[2:]]
    print("# A melt poured into a cold mould (fix sph/phase under gravity)\n")
    print("Written by pour.py (run.sh). The column a = 1 wide, 2 high, released at t = 0;")
    print("the mould 4 long, its walls at 0; the melt at 1.5, freezing at 1 (latent heat 1).")
    print("Z = x / a of the front, T = t sqrt(2 g / a).\n")
    print("## The run-out against Martin and Moyce's dam break (1952)\n")
    points = [(t, z) for t, z in reference.MARTIN_MOYCE if z < LENGTH - 0.5]
    print("| T | experiment | " + " | ".join(f"n = {n}" for n in sizes) + " |")
    print("|---|---|" + "---|" * len(sizes))
    tables = {n: main_table(out, n) for n in sizes}
    rows = {n: [(t * (2.0 * G) ** 0.5, z, m) for t, z, m in
                zip(tables[n]["Time"], tables[n]["v_front"], tables[n]["v_nmelt"])] for n in sizes}
    worst = dict.fromkeys(sizes, 0.0)
    for t, z in points:
        cells = []
        for n in sizes:
            got = reference.front_at(rows[n], t)
            worst[n] = max(worst[n], abs(got / z - 1.0))
            cells.append(f"{got:.3f} ({100 * (got / z - 1):+.1f} %)")
        print(f"| {t:.3f} | {z:.3f} | " + " | ".join(cells) + " |")
    print("\nLargest difference before the far wall: " +
          ", ".join(f"{100 * worst[n]:.1f} % at n = {n}" for n in sizes) + ".\n")
    print("## Freezing\n")
    print("Solid: the fraction of the melt's mass solid; floor shell: the solid's mean")
    print("thickness on the mould's floor from x = 1 to 3 (a); speeds: the largest of the particles that are")
    print("liquid or mushy, and of those that are solid; balance: (change of sum m e - heat")
    print("into the mould) / sum m e at the start.\n")
    worst_balance = {}
    frames_kept = {}
    for n in sizes:
        path = os.path.join(out, f"pour{n}.dump")
        frames = read_frames(path)
        stamps = frame_times(path)
        frames_kept[n] = list(zip(stamps, (f for _, f in frames)))
        table = tables[n]
        worst_balance[n] = np.max(np.abs(table["v_balance"]))
        print(f"n = {n} ({int(table['v_nmelt'][0])} particles of melt):\n")
        print("| t | solid | floor shell | liquid's largest speed | solid's largest speed | balance |")
        print("|---|---|---|---|---|---|")
        for wanted in TABLED:
            t, frame = min(frames_kept[n], key=lambda tf: abs(tf[0] - wanted))
            speed = np.hypot(frame["vx"], frame["vy"])
            solid = frame["f_phase"] <= 0.0
            k = int(np.argmin(np.abs(table["Time"] - t)))
            print(f"| {t:.3g} | {1.0 - frame['f_phase'].mean():.4f} | {floor_shell(frame, n):.3f} | "
                  f"{speed[~solid].max() if (~solid).any() else 0.0:.3g} | "
                  f"{speed[solid].max() if solid.any() else 0.0:.3g} | {table['v_balance'][k]:.1e} |")
        kept = int(table["v_nmelt"][-1]) == int(table["v_nmelt"][0])
        print(f"\nTo t = {table['Time'][-1]:.3g}: {'every particle kept' if kept else 'particles lost'}, "
              f"the energy books balanced to {worst_balance[n]:.1e} of the melt's energy.\n")
    plot(frames_kept, tables, sizes)


def plot(frames_kept, tables, sizes):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    n = max(sizes)
    fig = plt.figure(figsize=(12, 7.5))
    grid = fig.add_gridspec(3, 3, height_ratios=[1, 1, 1.1])
    for k, t_wanted in enumerate(SHOWN):
        ax = fig.add_subplot(grid[k // 3, k % 3])
        t, frame = min(frames_kept[n], key=lambda tf: abs(tf[0] - t_wanted))
        state = ax.scatter(frame["x"], frame["y"], c=frame["f_phase"], s=4.0 * (40 / n) ** 2,
                           cmap="coolwarm", vmin=0.0, vmax=1.0, linewidths=0)
        ax.plot([0, 0, LENGTH, LENGTH], [3, 0, 0, 3], color="0.3", lw=2)
        ax.set_xlim(-0.2, LENGTH + 0.2)
        ax.set_ylim(-0.2, 2.2)
        ax.set_aspect("equal")
        ax.set_title(f"t = {t:.3g} sqrt(a / g)", fontsize=9)
        ax.tick_params(labelsize=7)
    fig.colorbar(state, ax=fig.axes, shrink=0.5, label="liquid fraction")
    ax = fig.add_subplot(grid[2, :])
    for m in sizes:
        ax.plot(tables[m]["Time"], tables[m]["v_solid"], label=f"solid fraction, n = {m}")
    ax.set_xlabel("t sqrt(g / a)")
    ax.set_ylabel("solid fraction of the melt")
    ax.legend(fontsize=8)
    fig.savefig(os.path.join(HERE, "pour.png"), dpi=110)


if __name__ == "__main__":
    main()
