"""Spurious motion and pressure of the hydrostatic column; writes hydrostatic.png.

The column starts at rest in hydrostatic equilibrium and must stay there:
the largest fluid speed over the run is given in % of sqrt(g H). The pressure
of the particles at the end, P = c0^2 (rho - rho0) (linear EOS), is compared
with the exact hydrostatic pressure of the compressible column,
P = rho0 c0^2 (exp(g (ys - y) / c0^2) - 1), ys the height of its free surface,
and with the incompressible rho0 g (H - (y - yb)), yb = ys - Hc the bottom of
the column, Hc = c0^2 / g ln(1 + g H / c0^2) its height (bottom pressure
rho0 g H); errors in % of rho0 g H. With init compressed, sph/set
hydrostatic moved every row down to the compressed column, the lowest atom
(ybottom, a wall particle) staying in place: the surface, H - ybottom above
it on the lattice, is at ys = ybottom + c0^2 / g ln(1 + g (H - ybottom) / c0^2).
With init lattice the bottom y = 0 stays and the column settles to ys = Hc.
"""

import argparse
import os
import sys

import numpy as np

from sphthermal_tools.dump import read_frames


def main():
    p = argparse.ArgumentParser(description=__doc__)
    p.add_argument("prefix", nargs="?", default="hydrostatic", help="files <prefix>.par, <prefix>.speed and <prefix>.end")
    p.add_argument("--png", default="hydrostatic.png")
    p.add_argument("--label", default="20 x 40")
    p.add_argument("--max-speed", type=float, help="fail (exit 1) if the largest speed (%% of sqrt(g H)) is above")
    p.add_argument("--max-pressure-error", type=float,
                   help="fail (exit 1) if the largest pressure error (%% of rho0 g H) is above")
    a = p.parse_args()

    with open(f"{a.prefix}.par") as f:
        words = f.read().split()
    par = dict(zip(words[0::2], words[1::2]))
    H, g, c0, rho0 = (float(par[k]) for k in ("H", "g", "c0", "rho0"))
    Hc = c0 ** 2 / g * np.log1p(g * H / c0 ** 2)
    if par.get("init", "compressed") == "compressed":
        ybottom = float(par["ybottom"])
        ys = ybottom + c0 ** 2 / g * np.log1p(g * (H - ybottom) / c0 ** 2)
    else:
        ys = Hc
    vref = np.sqrt(g * H)
    t, speed = np.loadtxt(f"{a.prefix}.speed", unpack=True)
    speed = 100.0 * speed / vref
    k = np.argmax(speed)
    n10 = max(1, len(t) // 10)
    print(f"H = {H} m, g = {g} m/s^2, c0 = {c0:.6g} m/s = {c0 / vref:.3g} sqrt(g H), {t[-1]:.4g} s")
    print(f"largest speed {speed.max():.4f} % of sqrt(g H) (at t = {t[k]:.4g} s); "
          f"over the last tenth {speed[-n10:].max():.4f} %; at the end {speed[-1]:.4f} %")

    c = read_frames(f"{a.prefix}.end")[-1][1]
    y, P = c["y"], c0 ** 2 * (c["c_rho"] - rho0)
    exact = rho0 * c0 ** 2 * np.expm1(g * (ys - y) / c0 ** 2)
    err = 100.0 * (P - exact) / (rho0 * g * H)
    # the incompressible column of depth H, with the same bottom as the compressed one
    err_inc = 100.0 * (P - rho0 * g * (H - (y - (ys - Hc)))) / (rho0 * g * H)
    x = c["x"]
    inner = (x > x.min() + 0.1 * H) & (x < x.max() - 0.1 * H)
    print(f"pressure at the end: max error {np.abs(err).max():.4f} %, mean {np.abs(err).mean():.4f} % of rho0 g H "
          f"(against the compressible column); against rho0 g (H - y): max {np.abs(err_inc).max():.4f} %")
    print(f"{a.label}: largest speed {speed.max():.4f} % of sqrt(g H), pressure error {np.abs(err).max():.4f} %")

    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, (ax, ax2) = plt.subplots(1, 2, figsize=(8.4, 4.2))
    ax.semilogy(t, np.maximum(speed, 1e-6), "-", lw=0.8)
    ax.set_xlabel("t (s)")
    ax.set_ylabel("largest fluid speed (% of sqrt(g H))")
    ax.set_title(f"hydrostatic column {a.label}: largest speed {speed.max():.3f} %", fontsize=9)
    yy = np.linspace(ys - Hc, ys, 200)
    ax2.plot(rho0 * c0 ** 2 * np.expm1(g * (ys - yy) / c0 ** 2), yy, "k-", lw=1, label="exact")
    ax2.plot(P[inner], y[inner], ".", ms=2, color="C0", label="SPH, interior")
    ax2.plot(P[~inner], y[~inner], ".", ms=2, color="C1", label="SPH, next to the side walls")
    ax2.set_xlabel("P (Pa)")
    ax2.set_ylabel("y (m)")
    ax2.legend(fontsize=7)
    ax2.set_title(f"pressure at t = {t[-1]:.3g} s: max error {np.abs(err).max():.2f} % of rho0 g H", fontsize=9)
    fig.tight_layout()
    fig.savefig(a.png, dpi=120)
    print("plot:", os.path.abspath(a.png))

    failed = (a.max_speed is not None and speed.max() > a.max_speed) or \
             (a.max_pressure_error is not None and np.abs(err).max() > a.max_pressure_error)
    if failed:
        print(f"FAIL: above the thresholds (speed {a.max_speed} %, pressure {a.max_pressure_error} %)")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
