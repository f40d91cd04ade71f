"""Error of the erf example against the exact solution; writes erf.png.

T = (TL + TR)/2 + (TR - TL)/2 erf((x - x0) / sqrt(4 alpha t))
(Cleary 1998, eq 11, with its erratum: the similarity variable is x'/(2 sqrt(alpha t))).
Errors are in % of the temperature jump TR - TL = 1.
"""

import argparse
import math
import os
import sys

import numpy as np

from sphthermal_tools.dump import read_frames


def exact(x, t, alpha, x0):
    erf = np.vectorize(math.erf)
    return 0.5 + 0.5 * erf((x - x0) / math.sqrt(4.0 * alpha * t))


def main():
    p = argparse.ArgumentParser(description=__doc__)
    p.add_argument("dump", nargs="?", default="erf.dump")
    p.add_argument("--dt", type=float, default=0.005)
    p.add_argument("--alpha", type=float, default=1.0e-3, help="k / (rho cv)")
    p.add_argument("--x0", type=float, default=0.5)
    p.add_argument("--png", default="erf.png")
    p.add_argument("--label", default="pair sph/cleary/heat")
    p.add_argument("--max-mean-error", type=float, help="fail (exit 1) above this mean error, %%")
    p.add_argument("--max-error", type=float, help="fail (exit 1) above this max error, %%")
    args = p.parse_args()

    frames = [(step * args.dt, c) for step, c in read_frames(args.dump) if step > 0]
    if not frames:
        sys.exit("analyse: no frames after t = 0 in " + args.dump)

    print(f"{'t (s)':>8} {'mean error %':>13} {'max error %':>12}")
    worst_mean = worst_max = 0.0
    for t, c in frames:
        err = 100.0 * np.abs(c["c_T"] - exact(c["x"], t, args.alpha, args.x0))
        worst_mean, worst_max = max(worst_mean, err.mean()), max(worst_max, err.max())
        print(f"{t:8.3f} {err.mean():13.4f} {err.max():12.4f}")
    print(f"{args.label}: mean error (largest over the output times): {worst_mean:.4f} % of the jump")
    print(f"{args.label}: max error  (largest over the output times): {worst_max:.4f} % of the jump")

    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, ax = plt.subplots(figsize=(6.4, 4.2))
    shown = [frames[0], frames[len(frames) // 4], frames[-1]]
    for (t, c), colour in zip(shown, ["C0", "C1", "C2"]):
        xs = np.linspace(c["x"].min(), c["x"].max(), 400)
        ax.plot(xs, exact(xs, t, args.alpha, args.x0), "-", color=colour, lw=1, label=f"exact, t = {t:g} s")
        ax.plot(c["x"], c["c_T"], ".", color=colour, ms=3, label=f"SPH, t = {t:g} s")
    ax.set_xlabel("x (m)")
    ax.set_ylabel("T")
    ax.set_title(f"erf slab, {args.label}: mean error {worst_mean:.3f} %, max {worst_max:.3f} %",
                 fontsize=9)
    ax.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(args.png, dpi=120)
    print("plot:", os.path.abspath(args.png))

    failed = (args.max_mean_error is not None and worst_mean > args.max_mean_error) or (
        args.max_error is not None and worst_max > args.max_error)
    if failed:
        print(f"FAIL: errors above the thresholds (mean {args.max_mean_error} %, max {args.max_error} %)")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
