#!/usr/bin/env python3
"""The shedding cylinder of examples/open-cylinder against the benchmark of
Schafer & Turek (1996), test 2D-2 (Re = 100, periodic): the Strouhal
number St = f D / U in [0.295, 0.305], the largest drag coefficient
C_D,max in [3.22, 3.24], the largest lift coefficient C_L,max in
[0.99, 1.01], and the pressure difference across the cylinder half a
period after the lift's maximum, dp in [2.46, 2.50] Pa (D = 0.1 m, U = 1 m/s).

Reads <out>.forces (in.cylinder with re = 100: step, t, C_D, C_L, the
pressure and viscous parts of C_D, dp) and, over --from <= t <= --to, fits each
series with a mean and the first three harmonics of one frequency f: f
is the one whose fit leaves the least of C_L unexplained (scanned around
the spectrum's peak), so the particles' acoustic noise, which the fit
leaves out, does not shift the maxima. The fit over each half of the
window gives St again: their difference says whether the shedding had
settled. Fails (exit 1) when St is off the benchmark's interval by more
than --max-st percent or C_L,max is below --min-lift; --png writes the
histories with the fits.
usage: analyse_shedding.py FORCES [--from T] [--to T] [--max-st P] [--min-lift L]
                           [--png FILE]"""

import argparse
import sys

import numpy as np

# (beside this script: the error against an interval, as for test 2D-1)
from analyse import interval_error

BENCHMARK = {"St": (0.295, 0.305), "C_D,max": (3.22, 3.24), "C_L,max": (0.99, 1.01),
             "dp": (2.46, 2.50)}
DIAMETER, SPEED = 0.1, 1.0
HARMONICS = 3


def basis(t, f):
    """the mean and HARMONICS harmonics of f at times t"""
    columns = [np.ones_like(t)]
    for k in range(1, HARMONICS + 1):
        columns += [np.cos(2 * np.pi * k * f * t), np.sin(2 * np.pi * k * f * t)]
    return np.column_stack(columns)


def fit(t, y, f):
    """least-squares coefficients of basis(t, f) and the residual's rms"""
    b = basis(t, f)
    coef, *_ = np.linalg.lstsq(b, y, rcond=None)
    return coef, float(np.sqrt(np.mean((y - b @ coef) ** 2)))


def frequency(t, lift):
    """the frequency whose harmonic fit of the lift leaves the least residual,
    scanned within 10 % of the spectrum's peak between St = 0.1 and 0.6 (the
    acoustic noise peaks at several times the shedding's frequency)"""
    dt = np.mean(np.diff(t))
    spectrum = np.abs(np.fft.rfft((lift - lift.mean()) * np.hanning(len(lift))))
    freqs = np.fft.rfftfreq(len(lift), dt)
    band = (freqs >= 0.1 * SPEED / DIAMETER) & (freqs <= 0.6 * SPEED / DIAMETER)
    peak = freqs[band][np.argmax(spectrum[band])]
    trial = np.linspace(0.9 * peak, 1.1 * peak, 2001)
    residual = [fit(t, lift, f)[1] for f in trial]
    return float(trial[int(np.argmin(residual))])


def main():
    p = argparse.ArgumentParser(description=__doc__,
                                formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("forces")
    p.add_argument("--from", dest="t_from", type=float, default=3.0)
    p.add_argument("--to", dest="t_to", type=float, default=np.inf)
    p.add_argument("--max-st", type=float)
    p.add_argument("--min-lift", type=float)
    p.add_argument("--png")
    a = p.parse_args()
    d = np.loadtxt(a.forces)
    t_all = d[:, 1]
    sel = (t_all >= a.t_from) & (t_all <= a.t_to)
    t = t_all[sel]
    if len(t) < 50:
        sys.exit(f"FAIL: fewer than 50 samples after t = {a.t_from}")
    drag, lift, dp = d[sel, 2], d[sel, 3], d[sel, 6]
    f = frequency(t, lift)
    periods = (t[-1] - t[0]) * f
    print(f"t = {t[0]:.3f} .. {t[-1]:.3f} s, {len(t)} samples, {periods:.1f} periods")
    st = f * DIAMETER / SPEED
    half = len(t) // 2
    st_halves = [frequency(t[s], lift[s]) * DIAMETER / SPEED
                 for s in (slice(0, half), slice(half, None))]
    # the fitted curves, sampled finely over one period
    fine = t[0] + np.linspace(0.0, 1.0 / f, 2001)
    curves = {}
    noise = {}
    for name, y in (("C_D", drag), ("C_L", lift), ("dp", dp)):
        coef, rms = fit(t, y, f)
        curves[name] = (coef, basis(fine, f) @ coef)
        noise[name] = rms
    t_lift_max = fine[int(np.argmax(curves["C_L"][1]))]
    dp_half = float(basis(np.array([t_lift_max + 0.5 / f]), f) @ curves["dp"][0])
    values = {"St": st, "C_D,max": float(curves["C_D"][1].max()),
              "C_L,max": float(curves["C_L"][1].max()), "dp": dp_half}
    print(f"St        {st:.4f} (halves of the window: {st_halves[0]:.4f}, {st_halves[1]:.4f}); "
          f"benchmark {list(BENCHMARK['St'])}, error {interval_error(st, BENCHMARK['St']):+.2f} %")
    for name in ("C_D,max", "C_L,max", "dp"):
        source = "dp" if name == "dp" else name.split(",")[0]
        extra = " (half a period after C_L,max)" if name == "dp" else ""
        print(f"{name:9s} {values[name]:.4f}{extra}; benchmark {list(BENCHMARK[name])}, "
              f"error {interval_error(values[name], BENCHMARK[name]):+.2f} %; "
              f"noise about the fit {noise[source]:.3f} rms")
    print(f"C_D       from {curves['C_D'][1].min():.4f} to {curves['C_D'][1].max():.4f}; "
          f"C_L from {curves['C_L'][1].min():.4f} to {curves['C_L'][1].max():.4f}")
    ok = True
    if a.max_st is not None and abs(interval_error(st, BENCHMARK["St"])) > a.max_st:
        print(f"FAIL: St off by more than {a.max_st} %")
        ok = False
    if a.min_lift is not None and values["C_L,max"] < a.min_lift:
        print(f"FAIL: C_L,max below {a.min_lift}: the cylinder does not shed")
        ok = False
    if a.png:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        fig, ax = plt.subplots(2, 1, figsize=(7, 6), sharex=True)
        for axis, (name, column) in zip(ax, (("C_D", 2), ("C_L", 3))):
            axis.plot(t_all, d[:, column], lw=0.4, color="0.6", label=f"{name} (SPH)")
            axis.plot(t, basis(t, f) @ fit(t, d[sel, column], f)[0], lw=1.0, color="C0",
                      label="harmonic fit")
            axis.axhspan(*BENCHMARK[f"{name},max"], color="C3", alpha=0.4,
                         label=f"benchmark {name},max")
            axis.set_ylabel(name)
            axis.legend(loc="lower left", fontsize=8)
        ax[0].set_ylim(2.8, 3.6)
        ax[1].set_ylim(-1.5, 1.5)
        ax[1].set_xlabel("t (s)")
        fig.tight_layout()
        fig.savefig(a.png, dpi=120)
    print("PASS" if ok else "FAIL")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
