"""Xu's 3-D bar, a MACHDYN solid heated at one face, against the exact 1-D
solutions (Carslaw and Jaeger 1959, sections 3.3 and 3.4); writes bar.png.

Bar 0 <= x <= L = 1, alpha = k / (rho cv) = 1, initially at T = 0,
adiabatic at x = L:
  held (T = 1 at x = 0):
    T = 1 - sum_{m>=0} 4 / ((2m+1) pi) sin(l_m x) exp(-l_m^2 t),  l_m = (2m+1) pi / (2L);
  flux (q = 1 into x = 0, k = 1):
    T = q t / L + q/k ((L - x)^2 / (2L) - L/6)
        - (2 q L / k) sum_{n>=1} cos(n pi x / L) / (n pi)^2 exp(-(n pi / L)^2 t).
The error is the largest over the bar's particles, in % of the exact
temperature at the heated face (1 held; the face's rise with the flux).
Arguments: <case>:<label>:<dump> ... [--max-error P] [--same-as LABEL --rtol R]
(--same-as: every run's temperatures equal those of run LABEL to R).
"""

import argparse
import math
import sys

import numpy as np

from sphthermal_tools.dump import read_frames

L = 1.0


def held(x, t, terms=400):
    m = np.arange(terms)[:, None]
    lam = (2 * m + 1) * math.pi / (2 * L)
    s = np.sum(4.0 / ((2 * m + 1) * math.pi) * np.sin(lam * x[None, :]) * np.exp(-lam ** 2 * t), axis=0)
    return 1.0 - s


def flux(x, t, q=1.0, k=1.0, terms=400):
    n = np.arange(1, terms + 1)[:, None]
    series = np.sum(np.cos(n * math.pi * x[None, :] / L) / (n * math.pi) ** 2
                    * np.exp(-(n * math.pi / L) ** 2 * t), axis=0)
    return q * t / L + q / k * ((L - x) ** 2 / (2 * L) - L / 6) - 2 * q * L / k * series


EXACT = {"held": held, "flux": flux}


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("runs", nargs="+", help="case:label:dump")
    parser.add_argument("--tend", type=float, default=0.2)
    parser.add_argument("--max-error", type=float, help="fail above this error (%%)")
    parser.add_argument("--same-as", help="label of the run the others must equal")
    parser.add_argument("--rtol", type=float, default=1e-12)
    parser.add_argument("--png", default="bar.png")
    parser.add_argument("--results", help="write the errors as a markdown table to this file")
    args = parser.parse_args()

    results, temps = [], {}
    for run in args.runs:
        case, label, path = run.split(":")
        _, frame = read_frames(path)[-1]
        bar = frame["type"] == 1
        x, temp = frame["x"][bar], frame["c_th"][bar]
        exact = EXACT[case](x, args.tend)
        scale = EXACT[case](np.array([0.0]), args.tend)[0]
        error = 100.0 * np.max(np.abs(temp - exact)) / scale
        results.append((case, label, error, x, temp, exact))
        temps[label] = frame["c_th"]
        print(f"bar: {case} {label}: max |T - T_exact| = {error:.3f} % of the face's T at t = {args.tend}")

    ok = True
    if args.max_error is not None:
        for case, label, error, *_ in results:
            if not error <= args.max_error:
                print(f"bar: FAIL {case} {label}: error {error:.3f} % above {args.max_error} %")
                ok = False
    if args.same_as:
        ref = temps[args.same_as]
        for label, t in temps.items():
            diff = np.max(np.abs(t - ref)) / np.max(np.abs(ref))
            print(f"bar: {label} against {args.same_as}: largest relative difference {diff:.2e}")
            if not diff <= args.rtol:
                print(f"bar: FAIL {label} differs from {args.same_as} by {diff:.2e} > {args.rtol:g}")
                ok = False

    if args.results:
        with open(args.results, "w") as f:
            f.write("# Xu's bar, a MACHDYN solid: errors against the exact series\n\n"
                    "Written by examples/solid-machdyn-bar/analyse.py (run.sh): the largest |T - T_exact| "
                    f"over the bar's particles at t = {args.tend}, in % of the exact temperature at the "
                    "heated face.\n\n| case | the bar | particles across | error |\n|---|---|---|---|\n")
            for case, label, error, *_ in results:
                across = label.replace("free-", "").replace("n=", "")
                how = "the bar alone (free side faces)" if label.startswith("free") else "set in SPH particles"
                f.write(f"| {case} | {how} | {across} | {error:.2f} % |\n")
        print(f"bar: wrote {args.results}")

    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(figsize=(6.4, 4.2))
    xs = np.linspace(0.0, L, 201)
    for case in sorted({r[0] for r in results}):
        ax.plot(xs, EXACT[case](xs, args.tend), "k-", lw=1)
    for case, label, error, x, temp, _ in results:
        order = np.argsort(x)
        ax.plot(x[order], temp[order], ".", ms=3, label=f"{case}, {label} ({error:.2f} %)")
    ax.set_xlabel("x")
    ax.set_ylabel(f"T at t = {args.tend}")
    ax.set_title("MACHDYN bar heated at x = 0: SPH (points), exact (lines)")
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(args.png, dpi=120)
    print(f"bar: wrote {args.png}")
    print("bar: passed" if ok else "bar: FAILED")
    sys.exit(0 if ok else 1)


if __name__ == "__main__":
    main()
