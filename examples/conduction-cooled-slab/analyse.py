"""Errors of the slab cooled at one face (Ng et al. 2020, section 4.1) against the
exact series (Ng et al. 2020, eq 21, with its sign corrected); writes cooled-slab.png.

Slab 0 <= y <= L (L = 2 cm), alpha = k / (rho cv) = 1e-6 m^2/s, initially at
T_H = 200 C, the face y = L held at T_C = 0 C, the face y = 0 adiabatic. With
s = L - y the distance from the held face:
  T = T_C + (T_H - T_C) (4/pi) sum_{m>=0} sin(lambda_m s) / (2m+1) exp(-alpha lambda_m^2 t),
  lambda_m = (2m+1) pi / (2L).
Ng et al. 2020, eq 21, prints a prefactor -800/pi; with its cos(lambda_n y), y from the
adiabatic face, it is this series with +800/pi = 4 (T_H - T_C) / pi (the
printed sign gives T < 0 everywhere).
Errors over the slab's particles in % of T_H - T_C: max and L2
(sqrt(mean(err^2))) at each output time (tend/3, 2 tend/3, tend).
Arguments: <label>:<n>:<dump> ... (one per run).
"""

import argparse
import math
import os
import sys

import numpy as np

from sphthermal_tools.dump import read_frames

L, ALPHA, TH, TC = 0.02, 10.0 / (1.0 * 1.0e7), 200.0, 0.0


def exact(y, t, terms=400):
    """Exact temperature at height y (held face at y = L) and time t > 0."""
    m = np.arange(terms)[:, None]
    lam = (2 * m + 1) * math.pi / (2 * L)
    s = L - np.asarray(y, dtype=float)[None, :]
    series = np.sum(np.sin(lam * s) / (2 * m + 1) * np.exp(-ALPHA * lam ** 2 * t), axis=0)
    return TC + (TH - TC) * 4.0 / math.pi * series


def eq21_as_printed(y, t, terms=400):
    """Ng et al. 2020, eq 21, as printed (y from the lower, adiabatic face)."""
    n = np.arange(1, terms + 1)[:, None]
    lam = (2 * n - 1) * math.pi / (2 * L)
    y = np.asarray(y, dtype=float)[None, :]
    return -800.0 / math.pi * np.sum((-1.0) ** (n + 1) / (2 * n - 1) * np.exp(-ALPHA * lam ** 2 * t)
                                     * np.cos(lam * y), axis=0)


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("runs", nargs="+", help="label:n:dump")
    p.add_argument("--tend", type=float, default=120.0, help="time of the last frame (frames at tend/3 steps)")
    p.add_argument("--png", default="cooled-slab.png")
    p.add_argument("--max-error", action="append", default=[], metavar="LABEL=PERCENT",
                   help="fail (exit 1) if the max error of the finest run of LABEL is above (repeatable)")
    p.add_argument("--min-order", action="append", default=[], metavar="LABEL=ORDER",
                   help="fail (exit 1) if an observed order of the max error of LABEL is below (repeatable)")
    a = p.parse_args()
    max_error = {k: float(v) for k, v in (m.split("=", 1) for m in a.max_error)}
    min_order = {k: float(v) for k, v in (m.split("=", 1) for m in a.min_order)}

    ys = np.linspace(0.0, L, 201)
    check = exact(np.array([L, 0.0]), 40.0)
    printed = eq21_as_printed(np.array([0.0]), 40.0)[0]
    print(f"exact series at t = 40 s: T(held face) = {check[0]:.3e}, T(adiabatic face) = {check[1]:.4f} C; "
          f"eq 21 as printed gives {printed:.4f} C at the adiabatic face")

    results, profiles = {}, {}
    for run in a.runs:
        label, n, dump = run.split(":", 2)
        frames = [c for step, c in read_frames(dump) if step > 0]
        rows = []
        for k, c in enumerate(frames):
            t = (k + 1) * a.tend / len(frames)
            err = 100.0 * (c["c_T"] - exact(c["y"], t)) / (TH - TC)
            rows.append((t, np.abs(err).max(), math.sqrt(np.mean(err ** 2))))
            profiles.setdefault(label, {}).setdefault(int(n), []).append((t, c))
        results.setdefault(label, []).append((int(n), rows))

    print(f"{'wall':>14} {'n':>4} " + " ".join(f"{'max %':>7} {'L2 %':>7} (t={t:g})" for t, _, _ in
                                               results[next(iter(results))][0][1]) +
          f" {'max %':>7} {'order':>6}")
    failed = False
    for label, runs in results.items():
        runs.sort()
        prev = None
        for n, rows in runs:
            worst = max(r[1] for r in rows)
            l2 = max(r[2] for r in rows)
            order = math.log(prev[1] / worst) / math.log(n / prev[0]) if prev else float("nan")
            print(f"{label:>14} {n:4d} " + " ".join(f"{mx:7.3f} {l2r:7.3f}        " for _, mx, l2r in rows)
                  + f" {worst:7.3f} {order:6.2f}")
            if prev and label in min_order and order < min_order[label]:
                print(f"FAIL: {label}: order {order:.2f} below {min_order[label]}")
                failed = True
            prev = (n, worst)
        n, rows = runs[-1]
        worst, l2 = max(r[1] for r in rows), max(r[2] for r in rows)
        print(f"{label}: {n} x {n}: max error {worst:.3f} %, L2 error {l2:.3f} % of T_H - T_C "
              f"(largest over t = {', '.join(f'{r[0]:g}' for r in rows)} s)")
        if label in max_error and worst > max_error[label]:
            print(f"FAIL: {label}: max error {worst:.3f} % above {max_error[label]} %")
            failed = True

    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, (ax, bx) = plt.subplots(1, 2, figsize=(10, 4.2))
    nmin = min(n for runs in results.values() for n, _ in runs)
    markers = {"dirichlet": "o", "isothermal": "s", "dirichlet-h=dx": "^"}
    for k, (t, _) in enumerate(next(byn for byn in profiles.values() if nmin in byn)[nmin]):
        ax.plot(100 * ys, (exact(ys, t) - TC) / (TH - TC), "-", color=f"C{k}", lw=1, label=f"exact, t = {t:g} s")
    for label, byn in profiles.items():
        if label not in ("dirichlet", "isothermal") or nmin not in byn:
            continue
        for k, (t, c) in enumerate(byn[nmin]):
            # one column of the periodic slab (all columns are equal)
            sel = np.abs(c["x"] - c["x"].min()) < 1e-12
            ax.plot(100 * c["y"][sel], (c["c_T"][sel] - TC) / (TH - TC), markers.get(label, "^"), color=f"C{k}",
                    mfc="none" if label != "dirichlet" else f"C{k}", ms=5,
                    label=f"SPH {nmin} x {nmin}, {label}" if k == 0 else None)
    ax.axvline(100 * L, color="k", lw=0.5)
    ax.set_xlabel("y (cm); held face at y = 2 cm, adiabatic face at y = 0")
    ax.set_ylabel("T* = (T - T_C) / (T_H - T_C)")
    ax.set_title("slab cooled at one face (Ng et al. 2020, section 4.1)", fontsize=9)
    ax.legend(fontsize=7)
    for j, (label, runs) in enumerate(results.items()):
        ns = [n for n, _ in runs]
        bx.loglog(ns, [max(r[1] for r in rows) for _, rows in runs], markers.get(label, "^") + "-",
                  color=f"C{j + 3}", label=f"{label}, max")
        bx.loglog(ns, [max(r[2] for r in rows) for _, rows in runs], markers.get(label, "^") + "--",
                  color=f"C{j + 3}", mfc="none", label=f"{label}, L2")
    ns = np.array(sorted({n for runs in results.values() for n, _ in runs}), dtype=float)
    ref = max(max(r[1] for r in rows) for runs in results.values() for _, rows in runs)
    bx.loglog(ns, ref * (ns[0] / ns), "k:", lw=1, label="first order")
    bx.loglog(ns, ref * (ns[0] / ns) ** 2, "k-.", lw=1, label="second order")
    bx.set_xticks(ns)
    bx.set_xticklabels([f"{n:g}" for n in ns])
    bx.minorticks_off()
    bx.set_xlabel("particles across")
    bx.set_ylabel("error, % of T_H - T_C (largest of t = 40, 80, 120 s)")
    bx.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(a.png, dpi=120)
    print("plot:", os.path.abspath(a.png))
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
