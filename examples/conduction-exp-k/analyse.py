"""Errors of the k = exp(4 T) example; writes <prefix>.png.

References: a fine 1-D finite-volume solution of the slab with its ends held
at 0 and 1 (tools/fv1d.py, its own error printed) up to t = 20 s, and the
exact steady profile T = ln(1 + (e^4 - 1) x / L) / 4 (by the Kirchhoff
transform: the steady flux k dT/dx = d(e^(4T)/4)/dx is uniform, so e^(4T) is
linear in x) at t = 60 s, when the slowest mode has decayed below 1e-6 (the
finite-volume solution changes by less than that after). Errors are in % of
the temperature difference between the ends, over the slab's particles.
"""

import argparse
import math
import os
import sys

import numpy as np

import fv1d
from sphthermal_tools.dump import read_frames

A = 4.0          # k = exp(A T)
TIMES = [1, 2, 5, 10, 20]   # against the finite-volume reference
T_STEADY = 60               # against the exact steady profile


def steady(x):
    return np.log1p(math.expm1(A) * x) / A


def main():
    p = argparse.ArgumentParser(description=__doc__)
    p.add_argument("prefix", help="dumps <prefix>.t<time>")
    p.add_argument("--cells", type=int, default=400, help="cells of the finite-volume reference")
    p.add_argument("--png", default="exp-k.png")
    p.add_argument("--max-mean-error", type=float, help="fail (exit 1) if a mean error (%%) is above")
    p.add_argument("--max-steady-error", type=float,
                   help="fail (exit 1) if the largest error (%%) against the exact steady profile is above")
    a = p.parse_args()

    law = f"exponential:1,{A}"
    layers = [fv1d.Layer(0.0, 0.5, law, 1000.0, 1.0, 0.0), fv1d.Layer(0.5, 1.0, law, 1000.0, 1.0, 1.0)]
    x_fv, T_fv = fv1d.solve(layers, 1.0, a.cells, TIMES, left=0.0, right=1.0)
    fv_error = fv1d.reference_error(layers, 1.0, a.cells, TIMES, left=0.0, right=1.0)
    print(f"finite-volume reference: {a.cells} cells, largest difference to {a.cells // 2} cells "
          f"{100 * fv_error:.3f} % (near the steep end x = 0)")

    print(f"{'t (s)':>8} {'mean err %':>11} {'max err %':>10}")
    frames, worst_mean = [], 0.0
    for t, T_ref in zip(TIMES, T_fv):
        c = read_frames(f"{a.prefix}.t{t}")[-1][1]
        err = 100.0 * np.abs(c["c_T"] - np.interp(c["x"], x_fv, T_ref))
        worst_mean = max(worst_mean, err.mean())
        frames.append(c)
        print(f"{t:8g} {err.mean():11.4f} {err.max():10.4f}   (against the finite-volume reference)")
    c = read_frames(f"{a.prefix}.t{T_STEADY}")[-1][1]
    frames.append(c)
    err = 100.0 * np.abs(c["c_T"] - steady(c["x"]))
    worst_mean = max(worst_mean, err.mean())
    print(f"{T_STEADY:8g} {err.mean():11.4f} {err.max():10.4f}   (against the exact steady profile; "
          f"max at x = {c['x'][np.argmax(err)]:.4f} m)")
    print(f"largest mean error over the output times: {worst_mean:.4f} % (Cleary 1998: 0.1 %)")

    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, ax = plt.subplots(figsize=(6.4, 4.2))
    for k, (t, colour) in enumerate(zip(TIMES + [T_STEADY], ["C0", "C1", "C2", "C3", "C4", "C5"])):
        order = np.argsort(frames[k]["x"])
        if k < len(TIMES):
            ax.plot(x_fv, T_fv[k], "-", color=colour, lw=1)
        ax.plot(frames[k]["x"][order][::3], frames[k]["c_T"][order][::3], ".", color=colour, ms=3,
                label=f"t = {t:g} s")
    ax.plot(x_fv, steady(x_fv), "k--", lw=0.8, label="exact steady")
    ax.set_xlabel("x (m)")
    ax.set_ylabel("T")
    ax.set_title(f"k = exp(4T): SPH (dots), finite volume (lines), exact steady (dashed)\n"
                 f"largest mean error {worst_mean:.3f} % of the range", fontsize=9)
    ax.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(a.png, dpi=120)
    print("plot:", os.path.abspath(a.png))

    failed = (a.max_mean_error is not None and worst_mean > a.max_mean_error) or \
             (a.max_steady_error is not None and err.max() > a.max_steady_error)
    if failed:
        print(f"FAIL: mean error above {a.max_mean_error} % or steady error above {a.max_steady_error} %")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
