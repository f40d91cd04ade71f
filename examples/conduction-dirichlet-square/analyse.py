"""Convergence of the Dirichlet square (Reece et al. 2024, section 3.1) against the exact
series (Reece et al. 2024, eq 30); writes square.png.

T = T1 sum_{n odd} 4/(n pi) sin(n pi y) sinh(n pi x) / sinh(n pi) on [0,1]^2,
hot side x = 1 at T1 = 100, the other sides at 0. Errors over the interior
particles, relative to T1: L2 = sqrt(mean (T - T_exact)^2) / T1 and max.
Arguments: <kernel>:<n>:<dump> ... (one per run).
"""

import argparse
import math
import os
import sys

import numpy as np

from sphthermal_tools.dump import read_frames

T1 = 100.0


def exact(x, y, terms=20001):
    n = np.arange(1, terms + 1, 2)[:, None]
    # sinh(n pi x) / sinh(n pi) without overflow
    ratio = np.exp(n * math.pi * (x - 1.0)) * (1.0 - np.exp(-2.0 * n * math.pi * x)) / (1.0 - np.exp(-2.0 * n * math.pi))
    return T1 * np.sum(4.0 / (n * math.pi) * np.sin(n * math.pi * y) * ratio, axis=0)


def main():
    p = argparse.ArgumentParser(description=__doc__)
    p.add_argument("runs", nargs="+", help="kernel:n:dump")
    p.add_argument("--png", default="square.png")
    p.add_argument("--max-l2", type=float, help="fail (exit 1) if the finest run's L2 error (%%) is above")
    p.add_argument("--min-order", type=float, help="fail (exit 1) if an observed L2 order is below")
    a = p.parse_args()

    results = {}
    for run in a.runs:
        kernel, n, dump = run.split(":", 2)
        c = read_frames(dump)[-1][1]
        err = c["c_T"] - exact(c["x"], c["y"])
        results.setdefault(kernel, []).append((int(n), 100 * math.sqrt(np.mean(err ** 2)) / T1,
                                               100 * np.abs(err).max() / T1))
    check_center = exact(np.array([0.5]), np.array([0.5]))[0]
    print(f"exact series at the centre: {check_center:.6f} (T1/4 = {T1 / 4})")
    print(f"{'kernel':>10} {'n':>5} {'L2 error %':>11} {'order':>6} {'max error %':>12}")
    failed = False
    for kernel, rows in results.items():
        rows.sort()
        for k, (n, l2, mx) in enumerate(rows):
            order = math.log(rows[k - 1][1] / l2) / math.log(n / rows[k - 1][0]) if k else float("nan")
            print(f"{kernel:>10} {n:5d} {l2:11.4f} {order:6.2f} {mx:12.4f}")
            if k and a.min_order is not None and order < a.min_order:
                failed = True
        if a.max_l2 is not None and rows[-1][1] > a.max_l2:
            failed = True

    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(figsize=(5.5, 4.2))
    for kernel, rows in results.items():
        ns, l2s = [r[0] for r in rows], [r[1] for r in rows]
        ax.loglog(ns, l2s, "o-", label=f"{kernel}")
    ns = np.array(sorted({r[0] for rows in results.values() for r in rows}), dtype=float)
    ref = max(r[1] for rows in results.values() for r in rows)
    ax.loglog(ns, ref * (ns[0] / ns), "k:", lw=1, label="first order")
    ax.loglog(ns, ref * (ns[0] / ns) ** 2, "k--", lw=1, label="second order")
    ax.set_xlabel("particles across")
    ax.set_ylabel("L2 error, % of T1")
    ax.set_title("Dirichlet square, steady")
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(a.png, dpi=120)
    print("plot:", os.path.abspath(a.png))
    if failed:
        print(f"FAIL: L2 error above {a.max_l2} % or order below {a.min_order}")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
