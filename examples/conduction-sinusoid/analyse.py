"""Wall heat flux of the sinusoid example against the exact solution; writes sinusoid.png.

Exact solution of the heat equation (one decaying Fourier mode): with
isothermal sides at T = 0 a distance l apart, T = sin(pi x'/l) exp(-(pi/l)^2 alpha t)
solves dT/dt = alpha d2T/dx'2 with T = 0 on both sides, and the heat flux
through each side per unit length of side is q = k dT/dx' = k (pi/l) exp(-(pi/l)^2 alpha t).
SPH: the heat taken up by each isothermal wall per unit time (energy method,
Cleary 1998, eq 10, fix sph/wall/isothermal) and the direct estimate from the
temperature gradient at the wall particles (eq 9, compute sph/heatflux/atom),
divided by the side's length.
Errors are relative to the exact flux at the same time.
"""

import argparse
import math
import os
import sys

import numpy as np

from sphthermal_tools.dump import read_frames


def main():
    p = argparse.ArgumentParser(description=__doc__)
    p.add_argument("prefix", nargs="?", default="sinusoid", help="<prefix>.flux and <prefix>.dump")
    p.add_argument("--n", type=int, default=40, help="particles per side")
    p.add_argument("--alpha", type=float, default=0.1, help="k / (rho cv)")
    p.add_argument("--k", type=float, default=1.0)
    p.add_argument("--dt", type=float, default=0.0005)
    p.add_argument("--png", default="sinusoid.png")
    p.add_argument("--max-error", type=float, help="fail (exit 1) above this flux error, %%")
    p.add_argument("--max-direct-error", type=float,
                   help="fail (exit 1) above this flux error of the direct estimate, %%")
    args = p.parse_args()

    dx = 1.0 / args.n
    l = (args.n - 1) * dx
    rate = (math.pi / l) ** 2 * args.alpha
    data = np.loadtxt(args.prefix + ".flux", ndmin=2)
    t, q_left, q_right = data[:, 0], data[:, 1], data[:, 2]
    exact = args.k * (math.pi / l) * np.exp(-rate * t)
    err_left = 100.0 * (q_left - exact) / exact
    err_right = 100.0 * (q_right - exact) / exact
    energy_drift = abs(data[:, 3] / data[0, 3] - 1.0).max()
    qd_left, qd_right = data[:, 4], data[:, 5]
    direct = 100.0 * np.maximum(abs(qd_left - exact), abs(qd_right - exact)) / exact

    print(f"{'t (s)':>7} {'exact q':>10} {'SPH q left':>11} {'error %':>8} {'SPH q right':>12} {'error %':>8}"
          f" {'direct: error %':>16}")
    for row in zip(t, exact, q_left, err_left, q_right, err_right, direct):
        print("{:7.3f} {:10.5f} {:11.5f} {:8.3f} {:12.5f} {:8.3f} {:16.3f}".format(*row))
    worst = max(abs(err_left).max(), abs(err_right).max())
    print(f"flux error, energy method (largest over t = 0 ... {t[-1]:g} s, both walls): {worst:.3f} %")
    print(f"flux error, direct estimate (largest over t = 0 ... {t[-1]:g} s, both walls): "
          f"{direct.max():.3f} %")
    print(f"relative drift of the energy of particles and walls: {energy_drift:.2e}")

    # temperature along the slab's middle row against the exact profile
    frames = read_frames(args.prefix + ".dump")
    step, c = frames[len(frames) // 2]
    tt = step * args.dt
    ymid = 0.5 * args.n * dx
    row = np.abs(c["y"] - ymid) < 0.51 * dx
    xs = np.sort(c["x"][row])
    T_row = c["c_T"][row][np.argsort(c["x"][row])]

    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, (a1, a2) = plt.subplots(1, 2, figsize=(10, 4))
    a1.plot(t, exact, "k-", lw=1, label="exact")
    a1.plot(t, q_left, "o", ms=3, label="SPH, left wall")
    a1.plot(t, q_right, "x", ms=4, label="SPH, right wall")
    a1.plot(t, qd_left, "+", ms=6, label="SPH, direct estimate (eq 9), left")
    a1.set_xlabel("t (s)")
    a1.set_ylabel("heat flux per unit length of side (W/m^2)")
    a1.set_title(f"wall flux: max error {worst:.2f} % (energy), {direct.max():.2f} % (direct)",
                 fontsize=9)
    a1.legend(fontsize=8)
    xe = np.linspace(0.5 * dx, 0.5 * dx + l, 200)
    a2.plot(xe, np.sin(math.pi * (xe - 0.5 * dx) / l) * math.exp(-rate * tt), "k-", lw=1, label="exact")
    a2.plot(xs, T_row, ".", label="SPH, middle row")
    a2.set_xlabel("x (m)")
    a2.set_ylabel("T")
    a2.set_title(f"temperature at t = {tt:g} s")
    a2.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(args.png, dpi=120)
    print("plot:", os.path.abspath(args.png))

    failed = args.max_error is not None and worst > args.max_error
    failed = failed or energy_drift > 1e-12
    failed = failed or (args.max_direct_error is not None and direct.max() > args.max_direct_error)
    if failed:
        print(f"FAIL: flux error above {args.max_error} % (energy) or {args.max_direct_error} % (direct),"
              " or energy drift above 1e-12")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
