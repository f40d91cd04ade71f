"""The Stefan problems of run.sh against Neumann's exact solution
(tools/stefan.py): writes the results table (Markdown, to stdout) and
stefan.png (the melt's depth against time, the temperature at t = 1).

  python3 results.py OUT     # OUT: run.sh's output directory
"""

import math
import os
import sys

import numpy as np

import stefan
from sphthermal_tools.dump import read_frames
from sphthermal_tools.log import thermo_tables

HERE = os.path.dirname(os.path.abspath(__file__))
TW, TM = 1.0, 0.0
# (name, Ti, the solid's conductivity ks, the liquid's specific heat cl,
# label, resolutions)
CASES = (("one", 0.0, 1.0, 1.0, "one-phase (solid at Tm)", (40, 80, 160, 320)),
         ("two", -0.5, 1.0, 1.0, "two-phase (solid at Tm - 0.5)", (40, 80, 160, 320)),
         ("two_k2", -0.5, 2.0, 1.0, "two-phase, the solid's k = 2 (on [0, 6])", (120, 240, 480)),
         ("two_k05", -0.5, 0.5, 1.0, "two-phase, the solid's k = 0.5", (80, 160, 320)),
         ("two_c2", -0.5, 1.0, 2.0, "two-phase, the liquid's cv = 2", (80, 160, 320)),
         ("two_c05", -0.5, 1.0, 0.5, "two-phase, the liquid's cv = 0.5", (80, 160, 320)))


def run_of(out, name):
    with open(os.path.join(out, f"log.{name}")) as f:
        table = thermo_tables(f.read())[-2]
    frame = read_frames(os.path.join(out, f"{name}.dump"))[-1][1]
    return table, frame


def errors(table, ti, ks, cl):
    # rho = 1, L = 1, the melt's k = 1: alpha_l = 1 / cl, alpha_s = ks,
    # St_l = cl (Tw - Tm), St_s = Tm - Ti
    lam = stefan.neumann_lambda(cl, TM - ti, math.sqrt(1.0 / (cl * ks)))
    t, depth = table["Time"], table["v_depth"]
    exact = np.array([stefan.front(tt, lam, 1.0 / cl) for tt in t])
    late = t >= 0.5
    return depth[-1] / exact[-1] - 1.0, np.abs(depth[late] / exact[late] - 1.0).max(), lam


def main():
    out = sys.argv[1]
    print("# Neumann's Stefan problem with fix sph/phase\n")
    print("Written by `results.py` from `./run.sh`: every property 1, the face held at Tw = 1, melting at "
          "Tm = 0, latent heat 1 (the solid's conductivity ks where given: k steps from ks to 1 "
          "at Tm; the liquid's specific heat cl where given, fix sph/phase's cv_liquid: the liquid's Stefan "
          "number cl, its diffusivity 1 / cl); n particles on [0, 4] (on [0, 6] for ks = 2, whose solid takes the heat farther), h = 1.3 dx (cubic spline), "
          "fix sph/dt/reset's default timestep, to t = 1. The depth is the liquid volume per height. "
          "Exact: `tools/stefan.py` (its root to 1e-15).\n")
    print("| case | n | depth at t = 1 | exact | error | largest error from t = 0.5 | "
          "largest T error / (Tw - Ti) | energy balance / heat |")
    print("|---|---|---|---|---|---|---|---|")
    curves = {}
    for key, ti, ks, cl, label, resolutions in CASES:
        for n in resolutions:
            table, frame = run_of(out, f"{key}_{n}")
            end, late, lam = errors(table, ti, ks, cl)
            exact_t = np.array([stefan.temperature(x, table["Time"][-1], lam, TW, TM, ti, 1.0 / cl, ks)
                                for x in frame["x"]])
            t_error = np.abs(frame["c_T"] - exact_t).max() / (TW - ti)
            balance = np.abs(table["v_balance"]).max() / table["f_heat"][-1]
            print(f"| {label} | {n} | {table['v_depth'][-1]:.5f} | {stefan.front(1.0, lam, 1.0 / cl):.5f} | "
                  f"{100 * end:+.3f} % | {100 * late:.2f} % | {100 * t_error:.2f} % | {balance:.1e} |")
            curves[(key, n)] = (table, frame, lam, ti, ks, cl)
    table, frame = run_of(out, "mushy_80")
    lam = stefan.neumann_lambda(1.0)
    balance = np.abs(table["v_balance"]).max() / table["f_heat"][-1]
    print(f"\nMushy zone 0.1 wide about Tm (solidus -0.05, liquidus 0.05), the solid at the solidus, n = 80: "
          f"liquid volume per height {table['v_depth'][-1]:.5f} at t = 1, "
          f"{100 * (table['v_depth'][-1] / stefan.front(1.0, lam, 1.0) - 1):+.2f} % from the pure "
          f"substance's front; energy balance {balance:.1e} of the heat.")

    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, (left, right) = plt.subplots(1, 2, figsize=(10, 4))
    for key, ti, ks, cl, label, resolutions in CASES:
        n = resolutions[0] if key == "two_k2" else 80    # the same spacing, 0.05
        table, frame, lam, _, _, _ = curves[(key, n)]
        t = np.linspace(0.0, 1.0, 200)
        left.plot(t, [stefan.front(tt, lam, 1.0 / cl) for tt in t], "k-", lw=0.8)
        left.plot(table["Time"][::5], table["v_depth"][::5], "o", ms=3, label=f"{label}, dx = 0.05")
        x = np.linspace(0.0, 2.5, 300)
        right.plot(x, [stefan.temperature(xx, 1.0, lam, TW, TM, ti, 1.0 / cl, ks) for xx in x], "k-", lw=0.8)
        rows = frame["y"] < frame["y"].min() + 1e-9
        right.plot(frame["x"][rows], frame["c_T"][rows], "o", ms=3, label=label)
    left.set_xlabel("t")
    left.set_ylabel("melt depth s")
    left.legend(fontsize=8)
    left.set_title("front (lines: Neumann)")
    right.set_xlabel("x")
    right.set_ylabel("T at t = 1")
    right.set_xlim(0.0, 2.5)
    right.legend(fontsize=8)
    right.set_title("temperature (lines: Neumann)")
    fig.tight_layout()
    fig.savefig(os.path.join(HERE, "stefan.png"), dpi=110)


if __name__ == "__main__":
    main()
