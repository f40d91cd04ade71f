"""Errors of the two-fluid layered Couette example; writes two-fluid-couette.png.

Steady state (the exact solution of the momentum equation): fluid 1 (mu1) on the fixed wall
for 0 < y < L1, fluid 2 (mu2) under the wall moving at V0 for L1 < y < W; the
shear stress tau = V0 / (L1/mu1 + L2/mu2) is the same in both layers and the
profile is linear in each, u = tau y / mu1 below the interface and
u = V0 - tau (W - y) / mu2 above.
Transient (the earlier output times): a fine 1-D finite-volume solution of
rho du/dt = d/dy (mu du/dy) with the two layers (series, i.e. harmonic,
viscosity between cells; exact in time through the eigenvectors of the
semi-discrete operator); its own error is stated (against half the cells).
Errors are in % of V0, over all fluid particles.
"""

import argparse
import os
import sys

import numpy as np

from sphthermal_tools.dump import read_frames

W, RHO, MU1 = 20.0, 1.0, 0.248
L1 = W / 2
V0 = 65.2 * MU1 / (RHO * W)
TIMES = [20, 100, 300, 600, 1200]


def steady(y, mu2):
    tau = V0 / (L1 / MU1 + (W - L1) / mu2)
    return np.where(y < L1, tau * y / MU1, V0 - tau * (W - y) / mu2)


def finite_volume(mu2, cells, times):
    """Cell centres and u at the given times; u = 0 at t = 0, u(0) = 0, u(W) = V0."""
    dy = W / cells
    y = (np.arange(cells) + 0.5) * dy
    mu = np.where(y < L1, MU1, mu2)
    g = 2 * mu[:-1] * mu[1:] / (mu[:-1] + mu[1:]) / dy        # between cells
    g0, gw = mu[0] / (dy / 2), mu[-1] / (dy / 2)              # to the walls
    A = np.zeros((cells, cells))
    i = np.arange(cells - 1)
    A[i, i + 1] = A[i + 1, i] = g
    A[i, i] -= g
    A[i + 1, i + 1] -= g
    A[0, 0] -= g0
    A[-1, -1] -= gw
    A /= RHO * dy
    b = np.zeros(cells)
    b[-1] = gw * V0 / (RHO * dy)
    u_s = np.linalg.solve(A, -b)
    lam, vec = np.linalg.eigh(A)                              # A is symmetric (uniform rho, dy)
    coef = vec.T @ (-u_s)
    return y, [u_s + vec @ (np.exp(lam * t) * coef) for t in times]


def main():
    p = argparse.ArgumentParser(description=__doc__)
    p.add_argument("prefix", nargs="?", default="two-fluid-couette.dump", help="dumps <prefix>.t<time>")
    p.add_argument("--ratio", type=float, default=10.0, help="mu2 / mu1")
    p.add_argument("--cells", type=int, default=800, help="cells of the finite-volume reference")
    p.add_argument("--png", default="two-fluid-couette.png")
    p.add_argument("--label", default="40 across")
    p.add_argument("--max-error", type=float, help="fail (exit 1) if the max error (%%) at any time is above")
    p.add_argument("--max-steady-error", type=float,
                   help="fail (exit 1) if the max error (%%) against the exact steady profile is above")
    a = p.parse_args()
    mu2 = a.ratio * MU1

    y_fv, u_fv = finite_volume(mu2, a.cells, TIMES)
    y_half, u_half = finite_volume(mu2, a.cells // 2, TIMES)
    fv_error = max(100 * np.abs(np.interp(y_fv, y_half, uh) - u).max() / V0 for u, uh in zip(u_fv, u_half))
    tau = V0 / (L1 / MU1 + (W - L1) / mu2)
    print(f"V0 = {V0:.6g} m/s, mu1 = {MU1}, mu2 = {mu2:.6g}, interface velocity {tau * L1 / MU1:.6g} m/s")
    print(f"finite-volume reference: {a.cells} cells, largest difference to {a.cells // 2} cells "
          f"{fv_error:.4f} % of V0")
    print(f"{'t (s)':>8} {'mean err %':>11} {'max err %':>10} {'max |vy| %':>11}")
    frames, worst = [], 0.0
    for t, u_ref in zip(TIMES, u_fv):
        c = read_frames(f"{a.prefix}.t{t}")[-1][1]
        err = 100.0 * np.abs(c["vx"] - np.interp(c["y"], y_fv, u_ref)) / V0
        worst = max(worst, err.max())
        frames.append(c)
        print(f"{t:8g} {err.mean():11.4f} {err.max():10.4f} {100 * np.abs(c['vy']).max() / V0:11.4f}"
              "   (against the finite-volume reference)")
    c = frames[-1]
    err = 100.0 * np.abs(c["vx"] - steady(c["y"], mu2)) / V0
    steady_err = err.max()
    print(f"{TIMES[-1]:8g} {err.mean():11.4f} {err.max():10.4f} {'':11}   (against the exact steady profile; "
          f"max at y = {c['y'][np.argmax(err)]:.3f} m; the flow is steady to "
          f"{100 * np.abs(u_fv[-1] - steady(y_fv, mu2)).max() / V0:.4f} %)")
    print(f"{a.label}: steady max error {steady_err:.4f} % of V0, transient max {worst:.4f} %")

    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, (ax, ax2) = plt.subplots(1, 2, figsize=(8.4, 4.2), gridspec_kw={"width_ratios": [3, 2]})
    for k, (t, colour) in enumerate(zip(TIMES, ["C0", "C1", "C2", "C3", "C4"])):
        c = frames[k]
        ax.plot(u_fv[k], y_fv, "-", color=colour, lw=1)
        ax.plot(c["vx"], c["y"], ".", color=colour, ms=3, label=f"t = {t:g} s")
        order = np.argsort(c["y"])
        err = 100.0 * (c["vx"] - np.interp(c["y"], y_fv, u_fv[k])) / V0
        ax2.plot(err[order], c["y"][order], ".", color=colour, ms=2)
    ys = np.linspace(0, W, 401)
    ax.plot(steady(ys, mu2), ys, "k--", lw=0.8, label="exact steady")
    for axis in (ax, ax2):
        axis.axhline(L1, color="grey", lw=0.5, ls=":")
    ax.set_xlabel("u (m/s)")
    ax.set_ylabel("y (m)")
    ax.legend(fontsize=7)
    ax.set_title(f"two-fluid Couette, mu2/mu1 = {a.ratio:g}, {a.label}:\nSPH (dots), finite volume (lines)",
                 fontsize=9)
    ax2.axvline(0.0, color="k", lw=0.5)
    ax2.set_xlabel("error (% of V0)")
    ax2.set_title(f"steady max error {steady_err:.2f} %", fontsize=9)
    fig.tight_layout()
    fig.savefig(a.png, dpi=120)
    print("plot:", os.path.abspath(a.png))

    failed = (a.max_error is not None and worst > a.max_error) or \
             (a.max_steady_error is not None and steady_err > a.max_steady_error)
    if failed:
        print(f"FAIL: errors above the thresholds (max {a.max_error} %, steady {a.max_steady_error} %)")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
