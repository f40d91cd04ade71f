"""Errors of the three-solids example (Ng et al. 2020, section 4.2); writes <prefix>.png.

Solids 0 < x < 1 m (k = 10), 1 m < x < 3 m (k = 2), 3 m < x < 4 m (k = 10),
rho = 1, cv = 1e3, initially at T_C = 300 K; T_C held at x = 0, T_H = 420 K at
x = 4 m. References:
  * steady state, the exact solution of the composite wall (the thermal
    resistances L_i / k_i of the three solids in series):
    q = (T_H - T_C) / sum(L_i / k_i) = 100 W/m^2, T = 300 + 10 x (left),
    310 + 50 (x - 1) (middle), 410 + 10 (x - 3) (right);
  * transient, a fine 1-D finite-volume solution (tools/fv1d.py; its own
    error, against half its cells, is printed).
Errors are in % of T_H - T_C over all particles. The dump has frames at
tend/nout, 2 tend/nout, ..., tend.
"""

import argparse
import os
import sys

import numpy as np

import fv1d
from sphthermal_tools.dump import read_frames

TC, TH, LENGTH = 300.0, 420.0, 4.0
LAYERS = [fv1d.Layer(0.0, 1.0, "constant:10", 1.0, 1.0e3, TC),
          fv1d.Layer(1.0, 3.0, "constant:2", 1.0, 1.0e3, TC),
          fv1d.Layer(3.0, 4.0, "constant:10", 1.0, 1.0e3, TC)]


def steady(x):
    """Composite wall: layers (L_i, k_i) = (1, 10), (2, 2), (1, 10), faces at T_C and T_H."""
    bounds = [(L.x0, L.x1, float(L.k(np.array([TC]))[0])) for L in LAYERS]
    q = (TH - TC) / sum((x1 - x0) / k for x0, x1, k in bounds)
    T = np.empty_like(x)
    Tface = TC
    for x0, x1, k in bounds:
        sel = (x >= x0) & (x <= x1)
        T[sel] = Tface + q / k * (x[sel] - x0)
        Tface += q / k * (x1 - x0)
    return T


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("prefix", nargs="?", default="three-solids")
    p.add_argument("--tend", type=float, default=3000.0)
    p.add_argument("--cells", type=int, default=160, help="finite-volume cells (a multiple of 4)")
    p.add_argument("--label", default="dirichlet walls")
    p.add_argument("--max-steady", type=float, help="fail (exit 1) above this max error at tend, %%")
    p.add_argument("--max-transient", type=float,
                   help="fail (exit 1) above this max error against the finite-volume solution at any time, %%")
    a = p.parse_args()

    jump = TH - TC
    frames = [c for step, c in read_frames(a.prefix + ".dump") if step > 0]
    times = [(k + 1) * a.tend / len(frames) for k in range(len(frames))]
    x_fv, T_fv = fv1d.solve(LAYERS, LENGTH, a.cells, times, left=TC, right=TH)
    fv_error = fv1d.reference_error(LAYERS, LENGTH, a.cells, times, left=TC, right=TH)
    print(f"finite-volume reference: {a.cells} cells, largest difference to {a.cells // 2} cells "
          f"{100 * fv_error / jump:.4f} % of T_H - T_C")
    print(f"composite wall: q = {(TH - TC) / 1.2:g} W/m^2, interfaces at "
          f"{steady(np.array([1.0]))[0]:g} K and {steady(np.array([3.0]))[0]:g} K")

    print(f"{'t (s)':>8} {'max err % (FV)':>15} {'mean err % (FV)':>16} {'max err % (steady)':>19} "
          f"{'FV from steady %':>17}")
    rows = []
    for t, c, T_ref in zip(times, frames, T_fv):
        e_fv = 100.0 * np.abs(c["c_T"] - np.interp(c["x"], x_fv, T_ref)) / jump
        e_st = 100.0 * np.abs(c["c_T"] - steady(c["x"])) / jump
        unsteady = 100.0 * np.abs(T_ref - steady(x_fv)).max() / jump
        rows.append((t, e_fv.max(), e_fv.mean(), e_st.max(), e_st.mean(), unsteady))
        print(f"{t:8.4g} {e_fv.max():15.4f} {e_fv.mean():16.4f} {e_st.max():19.4f} {unsteady:17.5f}")

    t_end, _, _, st_max, st_mean, unsteady = rows[-1]
    worst = max(rows, key=lambda r: r[1])
    c = frames[-1]
    print(f"{a.label}: steady state (t = {t_end:g} s, the exact transient is {unsteady:.4f} % from it): "
          f"max error {st_max:.4f} %, mean {st_mean:.4f} % of T_H - T_C")
    print(f"{a.label}: transient: max error against finite volume {worst[1]:.4f} % (at t = {worst[0]:g} s)")

    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, (ax, bx) = plt.subplots(1, 2, figsize=(10, 4.2))
    shown = [k for k, t in enumerate(times) if t in (100.0, 200.0, 500.0, 1000.0)] + [len(times) - 1]
    xs = np.linspace(0.0, LENGTH, 801)
    for j, k in enumerate(shown):
        c, t = frames[k], times[k]
        sel = np.abs(c["y"] - c["y"].min()) < 1e-9    # one row (all rows are equal)
        ax.plot(x_fv, (T_fv[k] - TC) / jump, "-", color=f"C{j}", lw=1, label=f"finite volume, t = {t:g} s")
        ax.plot(c["x"][sel], (c["c_T"][sel] - TC) / jump, "o", color=f"C{j}", ms=3, mfc="none",
                label=f"SPH, t = {t:g} s")
    ax.plot(xs, (steady(xs) - TC) / jump, "k--", lw=1, label="exact steady state")
    for xi in (1.0, 3.0):
        ax.axvline(xi, color="grey", lw=0.5)
    ax.set_xlabel("x (m)")
    ax.set_ylabel("T* = (T - T_C) / (T_H - T_C)")
    ax.set_title(f"three solids (Ng et al. 2020, section 4.2), {a.label}", fontsize=9)
    ax.legend(fontsize=6)
    r = np.array(rows)
    bx.semilogy(r[:, 0], r[:, 1], "o-", ms=3, label="max error against finite volume")
    bx.semilogy(r[:, 0], r[:, 2], "s--", ms=3, label="mean error against finite volume")
    bx.semilogy(r[:, 0], np.maximum(r[:, 5], 1e-6), "k:", label="finite volume from steady state (max)")
    bx.set_xlabel("t (s)")
    bx.set_ylabel("% of T_H - T_C")
    bx.set_title(f"steady-state max error {st_max:.3f} % at t = {t_end:g} s", fontsize=9)
    bx.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(a.prefix + ".png", dpi=120)
    print("plot:", os.path.abspath(a.prefix + ".png"))

    failed = False
    if a.max_steady is not None and st_max > a.max_steady:
        print(f"FAIL: steady-state max error {st_max:.4f} % above {a.max_steady} %")
        failed = True
    if a.max_transient is not None and worst[1] > a.max_transient:
        print(f"FAIL: transient max error {worst[1]:.4f} % above {a.max_transient} %")
        failed = True
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
