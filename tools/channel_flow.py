"""The analysis shared by the channel-flow examples (flow-poiseuille,
flow-couette): velocity profiles dumped at several times (<prefix>.t<time>,
columns id x y vx vy) against an exact u(y, t); errors in % of a reference
speed over all fluid particles, |vy| (0 exactly) in the same unit; a PNG of
the profiles and their errors; thresholds that make the exit status 1."""

import argparse
import os

import numpy as np

from sphthermal_tools.dump import read_frames


def poiseuille_from_rest(y, t, u_max, nu, width, terms=200):
    """Poiseuille flow started from rest by a body force (the series solution
    of Morris, Fox & Zhu 1997), steady centre-line velocity u_max:
    u = F/(2 nu) y (W - y)
        - sum_{n>=0} 4 F W^2 / (nu pi^3 (2n+1)^3) sin((2n+1) pi y / W) exp(-(2n+1)^2 pi^2 nu t / W^2)
    with F = 8 u_max nu / W^2."""
    y = np.asarray(y, dtype=float)
    force = 8.0 * u_max * nu / width ** 2
    k = 2 * np.arange(terms)[:, None] + 1
    series = 4 * force * width ** 2 / (nu * np.pi ** 3 * k ** 3) * np.sin(k * np.pi * y / width) \
        * np.exp(-k ** 2 * np.pi ** 2 * nu * t / width ** 2)
    return force / (2 * nu) * y * (width - y) - series.sum(axis=0)


def run(description, exact, times, speed, speed_name, title, name, width):
    """exact(y, t): the reference; speed: the reference speed (speed_name, e.g.
    'u_max'); name: default dump prefix and PNG (name.dump, name.png); width:
    of the channel, for the plot."""
    p = argparse.ArgumentParser(description=description)
    p.add_argument("prefix", nargs="?", default=f"{name}.dump", help="dumps <prefix>.t<time>")
    p.add_argument("--png", default=f"{name}.png")
    p.add_argument("--label", default="40 across")
    p.add_argument("--max-error", type=float, help="fail (exit 1) if the max error (%%) at any time is above")
    p.add_argument("--max-steady-error", type=float,
                   help="fail (exit 1) if the max error (%%) at the last time (steady) is above")
    p.add_argument("--max-vy", type=float, help=f"fail (exit 1) if max |vy| (%% of {speed_name}) is above")
    a = p.parse_args()

    print(f"{'t (s)':>8} {'mean err %':>11} {'max err %':>10} {'max |vy| %':>11}")
    frames, worst, worst_vy = [], 0.0, 0.0
    for t in times:
        c = read_frames(f"{a.prefix}.t{t}")[-1][1]
        err = 100.0 * np.abs(c["vx"] - exact(c["y"], t)) / speed
        vy = 100.0 * np.abs(c["vy"]).max() / speed
        worst, worst_vy = max(worst, err.max()), max(worst_vy, vy)
        frames.append(c)
        print(f"{t:8g} {err.mean():11.4f} {err.max():10.4f} {vy:11.4f}")
    steady = err.max()
    ys = np.linspace(0.0, width, 401)
    unsteady = 100 * np.abs(exact(ys, times[-1]) - exact(ys, 1e9)).max() / speed
    print(f"{a.label}: max error {worst:.4f} % of {speed_name} (all times), {steady:.4f} % at "
          f"t = {times[-1]} s (steady to {unsteady:.3f} %); max |vy| {worst_vy:.4f} %")

    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, (ax, ax2) = plt.subplots(1, 2, figsize=(8.4, 4.2), gridspec_kw={"width_ratios": [3, 2]})
    for k, t in enumerate(times):
        c, colour = frames[k], f"C{k}"
        ax.plot(exact(ys, t), ys, "-", color=colour, lw=1)
        ax.plot(c["vx"], c["y"], ".", color=colour, ms=3, label=f"t = {t:g} s")
        order = np.argsort(c["y"])
        err = 100.0 * (c["vx"] - exact(c["y"], t)) / speed
        ax2.plot(err[order], c["y"][order], ".", color=colour, ms=2)
    ax.set_xlabel("u (m/s)")
    ax.set_ylabel("y (m)")
    ax.legend(fontsize=7)
    ax.set_title(f"{title}, {a.label}: SPH (dots), exact (lines)", fontsize=9)
    ax2.axvline(0.0, color="k", lw=0.5)
    ax2.set_xlabel(f"error (% of {speed_name})")
    ax2.set_title(f"max error {worst:.2f} %, steady {steady:.2f} %", fontsize=9)
    fig.tight_layout()
    fig.savefig(a.png, dpi=120)
    print("plot:", os.path.abspath(a.png))

    failed = (a.max_error is not None and worst > a.max_error) or \
             (a.max_steady_error is not None and steady > a.max_steady_error) or \
             (a.max_vy is not None and worst_vy > a.max_vy)
    if failed:
        print(f"FAIL: errors above the thresholds (max {a.max_error} %, steady {a.max_steady_error} %, "
              f"|vy| {a.max_vy} %)")
    return 1 if failed else 0
