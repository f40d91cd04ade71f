#!/usr/bin/env python3
"""Read the dump of in.tank (id type x y vx vy c_T, all atoms, every dumpdt
seconds) and print, per frame, the fluid's mean temperature, the largest
speed, the circulation of each half (the two cells: negative on the left,
clockwise; positive on the right), the mean height of the top component
(component A, type 2; 0.75 H at the start, 0.5 H when fully mixed) and the
fluid atoms outside the cavity. With --png, a picture of the components and
of the temperature with the velocity at some times.

    analyse.py tank.dump [--times 0 5 10 20 60 300] [--png tank.png]
"""
import argparse

import numpy as np

from sphthermal_tools.dump import frame_times, read_frames

L = 0.0386


def frames(path):
    """Yield (step, time or None, array of id type x y vx vy T sorted by id)
    for each frame of the dump; a frame written twice at the same step (at
    the start of a run) is given once."""
    last = None
    for (step, c), time in zip(read_frames(path), frame_times(path)):
        if step != last:
            yield step, time, np.column_stack([c[k] for k in ("id", "type", "x", "y", "vx", "vy", "c_T")])
        last = step


def summary(d):
    f = d[d[:, 1] <= 2]
    x, y, vx, vy, T = f[:, 2] / L, f[:, 3] / L, f[:, 4], f[:, 5], f[:, 6]
    top = f[:, 1] == 2

    def circulation(mask, xc):
        # mean angular velocity-like quantity (r x v)_z about the half's centre, m^2/s
        return L * np.mean((x[mask] - xc) * vy[mask] - (y[mask] - 0.5) * vx[mask])

    outside = np.sum((x < 0) | (x > 1) | (y < 0) | (y > 1))
    return dict(n=len(f), T=T.mean(), vmax=np.hypot(vx, vy).max(),
                circ_left=circulation(x < 0.5, 0.25), circ_right=circulation(x > 0.5, 0.75),
                ytop=y[top].mean(), outside=outside)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("dump")
    ap.add_argument("--dt", type=float, default=5.0, help="dump interval in s (the time of a frame when the dump has no ITEM: TIME)")
    ap.add_argument("--times", type=float, nargs="*", default=[0, 5, 10, 20, 60, 300],
                    help="times of the pictures (the nearest frames)")
    ap.add_argument("--png", help="write the pictures here")
    args = ap.parse_args()

    kept = {}
    print("frame  t(s)  fluid  outside  mean T (K)  max speed (m/s)  circulation left, right (m^2/s)  mean y of top component / H")
    for i, (step, time, d) in enumerate(frames(args.dump)):
        t = time if time is not None else i * args.dt
        s = summary(d)
        print(f"{i:5d} {t:7.2f} {s['n']:6d} {s['outside']:5d} {s['T']:11.4f} {s['vmax']:14.3e} "
              f"{s['circ_left']:+12.3e} {s['circ_right']:+11.3e} {s['ytop']:10.4f}")
        for tp in args.times:
            if abs(t - tp) < 0.5 * args.dt and (tp not in kept or abs(t - tp) < abs(kept[tp][0] - tp)):
                kept[tp] = (t, d)
    if not args.png:
        return
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    times = sorted(kept)
    fig, ax = plt.subplots(2, len(times), figsize=(2.4 * len(times) + 1.0, 5.2), squeeze=False,
                           layout="constrained")
    for j, tp in enumerate(times):
        t, d = kept[tp]
        f = d[d[:, 1] <= 2]
        x, y = f[:, 2] / L, f[:, 3] / L
        a = ax[0, j]
        a.scatter(x, y, c=np.where(f[:, 1] == 2, "tab:red", "tab:blue"), s=3, lw=0)
        a.set_title(f"t = {t:g} s")
        b = ax[1, j]
        sc = b.scatter(x, y, c=f[:, 6], s=3, lw=0, cmap="coolwarm", vmin=283, vmax=303)
        sp = np.hypot(f[:, 4], f[:, 5]).max()
        if sp > 0:
            k = slice(None, None, 4)
            b.quiver(x[k], y[k], f[k, 4], f[k, 5], scale=12 * sp, width=0.004)
            b.text(0.02, 1.02, f"max {sp * 1000:.2g} mm/s", fontsize=7, transform=b.transAxes)
        for a2 in (a, b):
            a2.set_aspect("equal")
            a2.set_xlim(0, 1)
            a2.set_ylim(0, 1)
            a2.set_xticks([])
            a2.set_yticks([])
    ax[0, 0].set_ylabel("components (red: top, A)")
    ax[1, 0].set_ylabel("T (283-303 K), velocity")
    fig.colorbar(sc, ax=ax[:, -1].tolist(), shrink=0.6, label="T (K)")
    fig.savefig(args.png, dpi=80)
    try:  # a palette of 64 colours: a quarter of the file
        from PIL import Image
        Image.open(args.png).convert("RGB").quantize(64).save(args.png)
    except ImportError:
        pass
    print("wrote", args.png)


if __name__ == "__main__":
    main()
