"""Frames of in.bodies' dump (temperature, the discs outlined) and its
checks: the discs never come closer to each other or to the tank's walls
than --min-gap spacings (the contact holds them) and the heat they gave
the gallium has risen above them (the plumes).

  python3 plot.py bodies.dump --dx 0.001 [--png bodies.png] [--times 0,0.3,1,2]
         [--min-gap 0.6] [--min-rise 2]
Prints the closest approaches, the discs' final speeds and the height of
the gallium's heat centroid above the discs; exit 1 when a check fails."""

import argparse
import sys

import numpy as np

from sphthermal_tools.dump import frame_times, read_frames

LIQUID, STEEL, TANK = 1, 2, 3


def bodies_of(frame, dx):
    """Ids of each disc: the steel particles joined by neighbours closer than 1.5 dx."""
    steel = frame["type"] == STEEL
    ids, xy = frame["id"][steel], np.column_stack([frame["x"][steel], frame["y"][steel]])
    label = -np.ones(len(ids), dtype=int)
    for seed in range(len(ids)):
        if label[seed] >= 0:
            continue
        label[seed] = label.max() + 1
        stack = [seed]
        while stack:
            k = stack.pop()
            near = np.flatnonzero((np.hypot(*(xy - xy[k]).T) < 1.5 * dx) & (label < 0))
            label[near] = label[seed]
            stack.extend(near)
    return [ids[label == b] for b in range(label.max() + 1)]


def closest(a, b):
    d = a[:, None, :] - b[None, :, :]
    return np.sqrt((d ** 2).sum(axis=2)).min()


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("dump")
    ap.add_argument("--dx", type=float, required=True)
    ap.add_argument("--png")
    ap.add_argument("--times", default="0,0.3,1,2")
    ap.add_argument("--min-gap", type=float, default=0.6, help="closest approach allowed, in dx")
    ap.add_argument("--min-rise", type=float, default=2.0,
                    help="least height of the heat centroid above the discs' centres, in dx")
    args = ap.parse_args()

    frames = read_frames(args.dump)
    times = frame_times(args.dump)
    dx = args.dx
    index = {int(i): k for k, i in enumerate(frames[0][1]["id"])}
    bodies = [np.array([index[int(i)] for i in b]) for b in bodies_of(frames[0][1], dx)]
    tank = frames[0][1]["type"] == TANK
    liquid = frames[0][1]["type"] == LIQUID
    t_cold = np.median(frames[0][1]["c_T"][liquid])

    gap_bodies, gap_tank = np.inf, np.inf
    for _, f in frames:
        xy = np.column_stack([f["x"], f["y"]])
        for a in range(len(bodies)):
            gap_tank = min(gap_tank, closest(xy[bodies[a]], xy[tank]))
            for b in range(a + 1, len(bodies)):
                gap_bodies = min(gap_bodies, closest(xy[bodies[a]], xy[bodies[b]]))
    last = frames[-1][1]
    speeds = [np.hypot(last["vx"][b].mean(), last["vy"][b].mean()) for b in bodies]
    vmax_liquid = np.hypot(last["vx"][liquid], last["vy"][liquid]).max()
    excess = np.clip(last["c_T"][liquid] - t_cold, 0.0, None)
    heat_y = (excess * last["y"][liquid]).sum() / excess.sum()
    disc_y = np.mean([last["y"][b].mean() for b in bodies])
    rise = (heat_y - disc_y) / dx
    print(f"{len(bodies)} discs; closest approach between discs {gap_bodies / dx:.3f} dx, "
          f"disc to tank {gap_tank / dx:.3f} dx (at most 0.98 dx: in contact)")
    print(f"t = {times[-1]:.3f} s: disc speeds " + " ".join(f"{s:.2e}" for s in speeds)
          + f" m/s (largest in the gallium {vmax_liquid:.3e} m/s); the gallium's heat centroid "
          f"{rise:.2f} dx above the discs' mean centre")
    failed = []
    if min(gap_bodies, gap_tank) < args.min_gap * dx:
        failed.append(f"a closest approach below {args.min_gap} dx")
    if rise < args.min_rise:
        failed.append(f"heat centroid less than {args.min_rise} dx above the discs")

    if args.png:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        wanted = [float(t) for t in args.times.split(",")]
        picks = [int(np.argmin([abs(t - w) for t in times])) for w in wanted]
        t_hot = frames[0][1]["c_T"][bodies[0]].max()
        fig, axes = plt.subplots(1, len(picks), figsize=(3.3 * len(picks), 3.3), squeeze=False)
        width = frames[0][1]["x"].max() - frames[0][1]["x"].min() + dx
        for ax, k in zip(axes[0], picks):
            f = frames[k][1]
            s = (3.0 * 72 * 0.8 * dx / width) ** 2  # a marker per spacing
            sc = ax.scatter(f["x"][~tank], f["y"][~tank], c=f["c_T"][~tank], s=s, marker="s",
                            cmap="inferno", vmin=t_cold, vmax=t_hot, linewidths=0)
            ax.scatter(f["x"][tank], f["y"][tank], c="0.6", s=s, marker="s", linewidths=0)
            for b in bodies:
                centre = (f["x"][b].mean(), f["y"][b].mean())
                radius = np.sqrt(len(b) / np.pi) * dx
                ax.add_patch(plt.Circle(centre, radius, fill=False, color="c", linewidth=0.6))
            ax.set_title(f"t = {times[k]:.2f} s")
            ax.set_aspect("equal")
            ax.set_xticks([])
            ax.set_yticks([])
        fig.colorbar(sc, ax=axes[0].tolist(), shrink=0.8, label="T (K)")
        fig.savefig(args.png, dpi=150)
        print(args.png)
    if failed:
        print("FAILED: " + "; ".join(failed))
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
