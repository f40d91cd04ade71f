"""The casting-like scene of run.sh: the solid shell's thickness along the
mould against time (Markdown, to stdout) and casting.png (the liquid
fraction and the temperature at the end, with the melt's velocity; the
shell's thickness along the channel at each snapshot; the solid fraction
and the mould's Nusselt number against time).

  python3 results.py OUT N    # OUT: run.sh's output directory; N: particles across H
"""

import os
import sys

import numpy as np

from sphthermal_tools.dump import frame_times, read_frames
from sphthermal_tools.log import thermo_tables

HERE = os.path.dirname(os.path.abspath(__file__))
MOULD = (1.0, 3.0)
LENGTH = 6.0


def shell_thickness(frame, n, edges):
    """The solid's thickness on the bottom and the top wall in bins along x:
    the solid particles' count per bin times their area over the bin's
    width (each wall's half of the channel)."""
    solid = frame["f_phase"] <= 0.0
    x, y = frame["x"][solid], frame["y"][solid]
    area = (1.0 / n) ** 2
    width = np.diff(edges)
    bottom = np.histogram(x[y < 0.5], edges)[0] * area / width
    top = np.histogram(x[y >= 0.5], edges)[0] * area / width
    return bottom, top


def main():
    out, n = sys.argv[1], int(sys.argv[2])
    frames = read_frames(os.path.join(out, "casting.dump"))
    stamps = frame_times(os.path.join(out, "casting.dump"))
    with open(os.path.join(out, "log.casting")) as f:
        # the main run's table (the longest), not the final snapshot's
        series = max((t for t in thermo_tables(f.read()) if "v_solid" in t), key=lambda t: len(t["Time"]))
    # bins of whole columns of particles, about 0.25 long
    width = max(1, round(0.25 * n)) / n
    edges = np.arange(0.0, LENGTH + 0.5 * width, width)
    centres = 0.5 * (edges[1:] + edges[:-1])
    print("# Casting-like scene: a melt flowing through a chilled mould (fix sph/phase)\n")
    print(f"n = {n} particles across H. The shell's thickness (fraction of H, bottom / top wall) in "
          f"bins {width:.3g} long along the channel; the mould is x = 1 to 3.\n")
    shown = [c for c in centres if MOULD[0] - width < c < MOULD[1] + 2 * width]
    print("| t | " + " | ".join(f"x = {c:.3g}" for c in shown) + " | solid fraction |")
    print("|---" * (2 + len(shown)) + "|")
    times = []
    for (step, frame), t in zip(frames, stamps):
        bottom, top = shell_thickness(frame, n, edges)
        t_label = f"{t:.3g}"
        times.append((t, bottom, top))
        cells = [f"{bottom[i]:.3f} / {top[i]:.3f}" for i, c in enumerate(centres) if c in shown]
        solid = 1.0 - frame["f_phase"].mean()
        print(f"| {t_label} | {' | '.join(cells)} | {solid:.4f} |")
    last = frames[-1][1]
    solid = last["f_phase"] <= 0.0
    print(f"\nAt the end: solid particles from x = {last['x'][solid].min():.3f} to {last['x'][solid].max():.3f}, "
          f"their largest speed {np.hypot(last['vx'][solid], last['vy'][solid]).max():.1e}; the melt's largest "
          f"speed {np.hypot(last['vx'], last['vy']).max():.4f} (inflow mean 0.1); particles in "
          f"{int(series['f_in[1]'][-1])}, out {int(series['f_out[1]'][-1])}; the mould's Nusselt number "
          f"{series['c_nu_mould[1]'][-1]:.3f}.")

    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig = plt.figure(figsize=(11, 8))
    grid = fig.add_gridspec(3, 2, height_ratios=(1, 1, 1.3))
    for row, (column, label, cmap) in enumerate((("f_phase", "liquid fraction", "coolwarm"),
                                                 ("c_T", "temperature", "inferno"))):
        axis = fig.add_subplot(grid[row, :])
        scatter = axis.scatter(last["x"], last["y"], c=last[column], s=5, cmap=cmap)
        if column == "c_T":
            pick = slice(None, None, 7)
            axis.quiver(last["x"][pick], last["y"][pick], last["vx"][pick], last["vy"][pick], scale=3.0, width=0.002)
        axis.axvspan(*MOULD, ymin=0.0, ymax=0.02, color="C0")
        axis.axvspan(*MOULD, ymin=0.98, ymax=1.0, color="C0")
        axis.set_aspect("equal")
        axis.set_xlim(0.0, LENGTH)
        axis.set_ylim(0.0, 1.0)
        axis.set_title(f"{label} at t = {series['Time'][-1]:.3g} (the mould: blue bars)", fontsize=10)
        fig.colorbar(scatter, ax=axis, shrink=0.9, pad=0.01)
    thickness = fig.add_subplot(grid[2, 0])
    for t, bottom, top in times[1::3] + ([times[-1]] if (len(times) - 2) % 3 else []):
        thickness.step(edges[:-1], 0.5 * (bottom + top), where="post", label=f"t = {t:.3g}")
    thickness.axvspan(*MOULD, color="C0", alpha=0.1)
    thickness.set_xlabel("x / H")
    thickness.set_ylabel("shell thickness / H (mean of the walls)")
    thickness.legend(fontsize=7)
    history = fig.add_subplot(grid[2, 1])
    history.plot(series["Time"], series["v_solid"], "k-", label="solid fraction of the channel")
    history.set_xlabel("t (H / U)")
    history.set_ylabel("solid fraction")
    nusselt = history.twinx()
    nusselt.plot(series["Time"], series["c_nu_mould[1]"], "C3-", lw=0.8)
    nusselt.set_ylabel("the mould's Nusselt number", color="C3")
    fig.tight_layout()
    fig.savefig(os.path.join(HERE, "casting.png"), dpi=100)


if __name__ == "__main__":
    main()
