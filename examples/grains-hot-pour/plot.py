"""The frames of examples/grains-hot-pour (run.sh) as one PNG: the oil in
one layer across the slab coloured by its temperature (the tank grey), and
every grain (seen through the slab) as a circle coloured by its own, on a
scale of its own.
usage: plot.py hot-pour.dump times out.png   (times: comma-separated, s)"""

import sys

import numpy as np

from sphthermal_tools.dump import read_frames

OIL_TYPE, TANK_TYPE, GRAIN_TYPE = 1, 2, 3


def frame_at(frames, times, t):
    """The frame whose time is nearest t."""
    return frames[int(np.argmin([abs(s - t) for s in times]))]


def main():
    path, wanted, out = sys.argv[1], [float(t) for t in sys.argv[2].split(",")], sys.argv[3]
    frames = read_frames(path)
    times = [float(t) for t in open(path).read().split("ITEM: TIME\n")[1:] for t in [t.split("\n", 1)[0]]]
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    chosen = [frame_at(frames, times, t) for t in wanted]
    first = frames[0][1]
    grain0 = first["type"] == GRAIN_TYPE
    oil0 = first["type"] == OIL_TYPE
    t_oil, t_grains = first["v_T"][oil0].min(), first["v_T"][grain0].max()
    # the oil warms by a few K, the grains cool by tens: a scale each
    oil_top = max(t_oil + 1.0, max(c["v_T"][c["type"] == OIL_TYPE].max() for _, c in chosen))
    fig, axes = plt.subplots(1, len(wanted), figsize=(2.6 * len(wanted) + 1.6, 3.4), sharey=True,
                             constrained_layout=True)
    for ax, (step, c) in zip(np.atleast_1d(axes), chosen):
        time = times[[s for s, _ in frames].index(step)]
        grain = c["type"] == GRAIN_TYPE
        layer = c["y"] < 1e-3
        oil = layer & (c["type"] == OIL_TYPE)
        tank = layer & (c["type"] == TANK_TYPE)
        ax.scatter(1e3 * c["x"][tank], 1e3 * c["z"][tank], color="0.6", s=9, marker="s", linewidths=0)
        so = ax.scatter(1e3 * c["x"][oil], 1e3 * c["z"][oil], c=c["v_T"][oil], s=9, marker="s", cmap="inferno",
                        vmin=t_oil, vmax=oil_top, linewidths=0)
        sg = ax.scatter(1e3 * c["x"][grain], 1e3 * c["z"][grain], c=c["v_T"][grain], s=12, cmap="winter",
                        vmin=t_oil, vmax=t_grains, edgecolors="w", linewidths=0.3)
        ax.set_title(f"t = {time:.2f} s")
        ax.set_aspect("equal")
        ax.set_xlabel("x (mm)")
    np.atleast_1d(axes)[0].set_ylabel("z (mm)")
    fig.colorbar(so, ax=axes, label="oil T (K)", shrink=0.85, pad=0.01)
    fig.colorbar(sg, ax=axes, label="grains T (K)", shrink=0.85, pad=0.01)
    fig.savefig(out, dpi=120)
    print(out)


if __name__ == "__main__":
    main()
