"""Conduction in a disc (Cleary 1998, section 3.5) against the Bessel series
(Carslaw & Jaeger 1959, Conduction of Heat in Solids: the infinite cylinder
with its surface held at a constant temperature); writes disc.png.

Arguments: label:prefix ... (one per run; <prefix>.dump with id type x y c_T,
<prefix>.flux with t, Q energy method, Q direct, total energy). Errors of the
interior particles (type 1) in % of T0 - Tw at every output time t > 0:
mean |T - T_exact| (Cleary: < 0.5 % at each time) and max; heat flow out
through the rim per unit depth by the energy method (eq 10) and the direct
estimate (eq 9) against Q' = 4 pi k (T0 - Tw) sum_n exp(-j_n^2 Fo), in % of
the exact value. The thresholds apply to the first run.
"""

import argparse
import os
import sys

import numpy as np

from sphthermal_tools.dump import read_frames
import disc_exact


def analyse(prefix, a):
    frames = read_frames(prefix + ".dump")
    rows = []
    for step, c in frames:
        t = step * a.dt
        if t <= 0:
            continue
        fo = a.alpha * t / a.R ** 2
        inner = c["type"] == 1
        r = np.hypot(c["x"][inner], c["y"][inner]) / a.R
        T = (c["c_T"][inner] - a.Tw) / (a.T0 - a.Tw)
        err = T - disc_exact.theta(r, fo)
        rows.append((t, fo, 100 * np.abs(err).mean(), 100 * np.abs(err).max(), 100 * err.mean()))
    flux = np.loadtxt(prefix + ".flux", ndmin=2)
    flux = flux[flux[:, 0] > 0]
    fo = a.alpha * flux[:, 0] / a.R ** 2
    exact = a.k * (a.T0 - a.Tw) * disc_exact.heat_flow(fo)
    drift = abs(flux[:, 3] / flux[0, 3] - 1.0).max()
    last = frames[-1][1]
    return dict(rows=np.array(rows), t=flux[:, 0], fo=fo, exact=exact, q_energy=flux[:, 1],
                q_direct=flux[:, 2], err_energy=100 * (flux[:, 1] / exact - 1),
                err_direct=100 * (flux[:, 2] / exact - 1), drift=drift, last=last,
                t_last=frames[-1][0] * a.dt)


def main():
    p = argparse.ArgumentParser(description=__doc__)
    p.add_argument("runs", nargs="+", help="label:prefix")
    p.add_argument("--R", type=float, default=0.5, help="radius of the rim (wall ring), m")
    p.add_argument("--alpha", type=float, default=1e-3, help="k / (rho cv)")
    p.add_argument("--k", type=float, default=1.0)
    p.add_argument("--T0", type=float, default=1.0)
    p.add_argument("--Tw", type=float, default=0.0)
    p.add_argument("--dt", type=float, default=0.1)
    p.add_argument("--from-fo", type=float, default=0.0,
                   help="flux errors from this Fourier number on (the largest is reported)")
    p.add_argument("--png", default="disc.png")
    p.add_argument("--plot", help="labels (comma separated) to plot; default all")
    p.add_argument("--max-mean-error", type=float, help="fail above this mean T error (%%), any time")
    p.add_argument("--max-error", type=float, help="fail above this max T error (%%), any time")
    p.add_argument("--max-flux-error", type=float, help="fail above this energy-method flux error (%%)")
    p.add_argument("--max-direct-error", type=float, help="fail above this direct flux error (%%)")
    a = p.parse_args()

    dev, _ = disc_exact.check()
    print(f"Bessel series against its check values at Fo = 0.1: "
          f"max relative deviation {dev:.1e}; centre at half at Fo = {disc_exact.fo_centre_half():.4f}")
    results = []
    for run in a.runs:
        label, prefix = run.split(":", 1)
        res = analyse(prefix, a)
        results.append((label, res))
        print(f"\n== {label} ({prefix})")
        print(f"{'t (s)':>6} {'Fo':>6} {'mean err %':>10} {'max err %':>9} {'bias %':>7} "
              f"{'Q exact':>8} {'Q energy':>9} {'err %':>6} {'Q direct':>9} {'err %':>6}")
        qi = {round(t, 9): i for i, t in enumerate(res["t"])}
        for t, fo, mean, mx, bias in res["rows"]:
            i = qi.get(round(t, 9))
            q = (f"{res['exact'][i]:8.4f} {res['q_energy'][i]:9.4f} {res['err_energy'][i]:6.2f} "
                 f"{res['q_direct'][i]:9.4f} {res['err_direct'][i]:6.2f}") if i is not None else ""
            print(f"{t:6.2f} {fo:6.3f} {mean:10.3f} {mx:9.3f} {bias:7.3f} {q}")
        sel = res["fo"] >= a.from_fo - 1e-12
        res["worst_energy"] = np.abs(res["err_energy"][sel]).max()
        res["worst_direct"] = np.abs(res["err_direct"][sel]).max()
        res["worst_mean"] = res["rows"][:, 2].max()
        res["worst_max"] = res["rows"][:, 3].max()
        print(f"{label}: mean error (largest over the output times) {res['worst_mean']:.3f} %, "
              f"max error {res['worst_max']:.3f} % of T0 - Tw (Cleary: mean < 0.5 %); "
              f"at Fo = {res['rows'][-1, 1]:.3f}: mean {res['rows'][-1, 2]:.3f} %")
        print(f"{label}: heat flow error from Fo = {a.from_fo:g}: energy method {res['worst_energy']:.2f} %, "
              f"direct {res['worst_direct']:.2f} %; energy drift {res['drift']:.1e}")

    print(f"\n{'run':>22} {'mean T err %':>12} {'max T err %':>11} {'Q energy err %':>14} {'Q direct err %':>14}")
    for label, res in results:
        print(f"{label:>22} {res['worst_mean']:12.3f} {res['worst_max']:11.3f} "
              f"{res['worst_energy']:14.2f} {res['worst_direct']:14.2f}")

    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    shown = results if not a.plot else [r for r in results if r[0] in a.plot.split(",")]
    fig, (a1, a2, a3) = plt.subplots(1, 3, figsize=(15, 4.4))
    rr = np.linspace(0, 1, 200)
    fo_last = a.alpha * shown[0][1]["t_last"] / a.R ** 2
    a1.plot(rr * a.R, a.Tw + (a.T0 - a.Tw) * disc_exact.theta(rr, fo_last), "k-", lw=1.2, label="exact (Bessel series)")
    marks = ["o", "x", "+", "s", "^", "v", "d"]
    colours = ["C0", "C3", "C2", "C1", "C4", "C5", "C6"]
    for m, col, (label, res) in zip(marks, colours, shown):
        c = res["last"]
        inner = c["type"] == 1
        a1.plot(np.hypot(c["x"][inner], c["y"][inner]), c["c_T"][inner], m, color=col, ms=2.5, mfc="none",
                label=f"{label} (mean err {res['rows'][-1, 2]:.2f} %)")
    a1.set_xlabel("r (m)")
    a1.set_ylabel("T")
    a1.set_title(f"T(r) at t = {shown[0][1]['t_last']:g} s (Fo = {fo_last:.3f}, centre at half)", fontsize=9)
    a1.legend(fontsize=7)
    tt = np.linspace(shown[0][1]["t"][0] * 0.5, shown[0][1]["t"][-1], 300)
    a2.plot(tt, a.k * (a.T0 - a.Tw) * disc_exact.heat_flow(a.alpha * tt / a.R ** 2), "k-", lw=1.2, label="exact")
    for (label, res), col in zip(shown, colours):
        a2.plot(res["t"], res["q_energy"], "o", color=col, ms=3, mfc="none", label=f"{label}, energy (eq 10)")
        a2.plot(res["t"], res["q_direct"], "+", color=col, ms=6, label=f"{label}, direct (eq 9)")
    a2.set_xlabel("t (s)")
    a2.set_ylabel("heat flow out through the rim (W/m)")
    a2.set_yscale("log")
    a2.set_title("heat flow through the rim per unit depth", fontsize=9)
    a2.legend(fontsize=7)
    for (label, res), col in zip(shown, colours):
        a3.plot(res["rows"][:, 1], res["rows"][:, 2], "-o", color=col, ms=3, label=f"{label}, T mean error")
        a3.plot(res["fo"], np.abs(res["err_energy"]), ":", color=col, label=f"{label}, |Q energy error|")
        a3.plot(res["fo"], np.abs(res["err_direct"]), "--", color=col, lw=0.8, label=f"{label}, |Q direct error|")
    a3.axhline(0.5, color="k", lw=0.8, ls="--", label="Cleary: mean error < 0.5 %")
    a3.set_yscale("log")
    a3.set_xlabel("Fo = alpha t / R^2")
    a3.set_ylabel("error, %")
    a3.set_title("errors against time", fontsize=9)
    a3.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(a.png, dpi=110)
    print("plot:", os.path.abspath(a.png))

    first = results[0][1]
    failed = first["drift"] > 1e-12
    for value, limit in ((first["worst_mean"], a.max_mean_error), (first["worst_max"], a.max_error),
                         (first["worst_energy"], a.max_flux_error), (first["worst_direct"], a.max_direct_error)):
        failed = failed or (limit is not None and value > limit)
    if failed:
        print(f"FAIL ({results[0][0]}): mean T error above {a.max_mean_error} %, max above {a.max_error} %, "
              f"flux error above {a.max_flux_error} % (energy) or {a.max_direct_error} % (direct), "
              "or energy drift above 1e-12")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
