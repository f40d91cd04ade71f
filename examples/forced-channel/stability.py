#!/usr/bin/env python3
"""The spanwise velocity of heated-channel runs against time (Ng et al.
2020, Figs 7-9: with and without particle shifting): the largest |v| of the
fluid over u_max, from the thermo output (v_vymax) of each log, printed at
the end of each run and plotted (log scale) to a PNG.

  stability.py log.rest-yes:shifted log.rest-no:'no shifting' [--png stability.png]
               [--max-vy PCT]   (exit 1 if the first log ends above PCT % of u_max)
"""
import argparse
import os
import sys

from sphthermal_tools.log import longest_thermo_table


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawTextHelpFormatter)
    p.add_argument("logs", nargs="+", help="log[:label]")
    p.add_argument("--png", default="stability.png")
    p.add_argument("--max-vy", type=float)
    a = p.parse_args()

    runs = []
    for item in a.logs:
        path, _, label = item.partition(":")
        with open(path) as f:
            table = longest_thermo_table(f.read())
        runs.append((label or os.path.basename(path), table["Time"], 100.0 * table["v_vymax"]))
    for label, t, vy in runs:
        print(f"{label}: t = {t[-1]:.0f} s, largest |v| {vy[-1]:.4f} % of u_max "
              f"(largest over the run {vy.max():.4f} % at t = {t[vy.argmax()]:.0f} s)")
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        fig, ax = plt.subplots(figsize=(6.5, 4))
        for label, t, vy in runs:
            ax.semilogy(t, vy, label=label)
        ax.axhline(1.0, ls=":", color="k", lw=1)
        ax.set_xlabel("t (s)")
        ax.set_ylabel("largest |v| of the fluid (% of u_max)")
        ax.set_title("Heated channel, Re = 652: spanwise velocity")
        ax.legend()
        fig.tight_layout()
        fig.savefig(a.png, dpi=110)
        print(f"wrote {a.png}")
    except ImportError:
        print("no matplotlib: no PNG")
    if a.max_vy is not None and not runs[0][2][-1] <= a.max_vy:
        print(f"FAIL: {runs[0][0]} ends at {runs[0][2][-1]:.4f} % of u_max, above {a.max_vy} %")
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
