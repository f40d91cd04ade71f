#!/usr/bin/env python3
"""The drag and lift of the cylinder in examples/open-cylinder against the
benchmark of Schafer & Turek (1996), test 2D-1 (Re = 20, steady):
C_D in [5.57, 5.59], C_L in [0.0104, 0.0110], the pressure difference
between the cylinder's front and back points in [0.1172, 0.1176] Pa.

Reads <out>.forces (fix ave/time of in.cylinder: step, t, C_D, C_L, the
pressure and viscous parts of C_D, dp), averages each over t >= --from
(the particles' noise is averaged out; the flow is steady), and prints the
means, their standard errors from blocks of --block s, and the error of
each against the benchmark's interval (0 inside it). Fails (exit 1) when
|C_D error| > --max-drag percent, |dp error| > --max-dp percent, or the
mean C_L lies outside [--min-lift, --max-lift]; --png writes the histories.
With in.cylinder's heat = yes the file's last column is the cylinder's mean
Nusselt number: its mean, and its error against --nu-ref (the finite-element
reference of tools/cylinder_heat_fe.py), failing above --max-nu percent.
usage: analyse.py FORCES [--from T] [--block S] [--max-drag P] [--max-dp P]
                  [--min-lift L] [--max-lift L] [--nu-ref NU] [--max-nu P]
                  [--png FILE]"""

import argparse
import sys

import numpy as np

BENCHMARK = {"C_D": (5.57, 5.59), "C_L": (0.0104, 0.0110), "dp": (0.1172, 0.1176)}


def interval_error(value, bounds):
    """relative error (percent) against the nearest bound, 0 inside"""
    lo, hi = bounds
    if lo <= value <= hi:
        return 0.0
    bound = lo if value < lo else hi
    return 100.0 * (value - bound) / bound


def block_error(values, t, block):
    """standard error of the mean from block means of 'block' seconds"""
    edges = np.arange(t[0], t[-1] + 1e-12, block)
    means = [values[(t >= a) & (t < a + block)].mean() for a in edges[:-1]
             if ((t >= a) & (t < a + block)).sum() > 0]
    if len(means) < 2:
        return float("nan")
    return float(np.std(means, ddof=1) / np.sqrt(len(means)))


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("forces")
    p.add_argument("--from", dest="t_from", type=float, default=3.0)
    p.add_argument("--block", type=float, default=0.5)
    p.add_argument("--max-drag", type=float)
    p.add_argument("--max-dp", type=float)
    p.add_argument("--min-lift", type=float)
    p.add_argument("--max-lift", type=float)
    p.add_argument("--nu-ref", type=float)
    p.add_argument("--max-nu", type=float)
    p.add_argument("--png")
    a = p.parse_args()
    d = np.loadtxt(a.forces)
    t = d[:, 1]
    sel = t >= a.t_from
    if sel.sum() < 10:
        sys.exit(f"FAIL: fewer than 10 samples after t = {a.t_from}")
    names = ["C_D", "C_L", "C_D pressure", "C_D viscous", "dp"]
    means = {}
    print(f"t = {t[sel][0]:.3f} .. {t[sel][-1]:.3f} s, {int(sel.sum())} samples")
    for k, name in enumerate(names):
        v = d[sel, 2 + k]
        means[name] = v.mean()
        se = block_error(v, t[sel], a.block)
        line = f"{name:13s} mean {v.mean():.5f} +- {se:.5f} (rms of the samples {v.std():.4f})"
        if name == "C_L":
            # the lift is smaller than its noise's standard error at these
            # resolutions: its distance from the interval in standard errors
            lo, hi = BENCHMARK[name]
            off = 0.0 if lo <= v.mean() <= hi else min(abs(v.mean() - lo), abs(v.mean() - hi))
            line += f"; benchmark [{lo}, {hi}], {off / se:.1f} standard errors off"
        elif name in BENCHMARK:
            lo, hi = BENCHMARK[name]
            line += f"; benchmark [{lo}, {hi}], error {interval_error(v.mean(), BENCHMARK[name]):+.2f} %"
        print(line)
    ok = True
    if d.shape[1] > 7 and np.any(d[sel, 7] != 0.0):
        v = d[sel, 7]
        se = block_error(v, t[sel], a.block)
        line = f"Nu            mean {v.mean():.5f} +- {se:.5f} (rms of the samples {v.std():.4f})"
        if a.nu_ref is not None:
            err = 100.0 * (v.mean() - a.nu_ref) / a.nu_ref
            line += f"; reference {a.nu_ref}, error {err:+.2f} %"
            if a.max_nu is not None and abs(err) > a.max_nu:
                print(f"FAIL: Nu off by more than {a.max_nu} %")
                ok = False
        print(line)
    elif a.max_nu is not None:
        print("FAIL: no Nusselt number in the file (in.cylinder's heat = yes writes it)")
        ok = False
    if a.max_drag is not None and abs(interval_error(means["C_D"], BENCHMARK["C_D"])) > a.max_drag:
        print(f"FAIL: C_D off by more than {a.max_drag} %")
        ok = False
    if a.max_dp is not None and abs(interval_error(means["dp"], BENCHMARK["dp"])) > a.max_dp:
        print(f"FAIL: dp off by more than {a.max_dp} %")
        ok = False
    if a.min_lift is not None and not (a.min_lift <= means["C_L"] <= a.max_lift):
        print(f"FAIL: mean C_L outside [{a.min_lift}, {a.max_lift}]")
        ok = False
    if a.png:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        fig, ax = plt.subplots(2, 1, figsize=(7, 6), sharex=True)
        ax[0].plot(t, d[:, 2], lw=0.5, label="C_D (SPH)")
        ax[0].axhspan(*BENCHMARK["C_D"], color="k", alpha=0.3, label="benchmark")
        ax[0].set_ylim(4.5, 7.0)
        ax[0].set_ylabel("C_D")
        ax[0].legend()
        ax[1].plot(t, d[:, 3], lw=0.5, label="C_L (SPH)")
        ax[1].axhline(np.mean(BENCHMARK["C_L"]), color="k", label="benchmark")
        ax[1].set_ylim(-1, 1)
        ax[1].set_ylabel("C_L")
        ax[1].set_xlabel("t (s)")
        ax[1].legend()
        fig.tight_layout()
        fig.savefig(a.png, dpi=120)
    print("PASS" if ok else "FAIL")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
