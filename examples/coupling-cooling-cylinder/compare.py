"""The cooling cylinder against its reference: the disc's mean temperature
from in.cooling's series file against tools/conjugate_cylinder.py for the
disc of the same area (R_eq = sqrt(N_disc / pi) dx) in an adiabatic circle
of the periodic box's area, steel in water. Errors are per cent of the
initial difference (60 K).

  python3 compare.py cooling.series --R 0.0100293 --box 0.04 [--png cooling.png]
         [--max-error 1.0]
Exit 1 when the largest error at the comparison times exceeds --max-error."""

import argparse
import sys

import numpy as np

import conjugate_cylinder as cc

STEEL = (7850.0, 490.0, 45.0, 353.15)
WATER = (1000.0, 4180.0, 0.6, 293.15)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("series", help="fix ave/time file: time, disc mean T, disc speed")
    ap.add_argument("--R", type=float, required=True, help="equal-area radius of the disc (m)")
    ap.add_argument("--box", type=float, required=True, help="side of the periodic box (m)")
    ap.add_argument("--times", default="1,2,5,10,20,40,60")
    ap.add_argument("--png")
    ap.add_argument("--max-error", type=float, default=None, help="per cent of 60 K")
    a = ap.parse_args()

    data = np.loadtxt(a.series, comments="#")
    t, T, speed = data[:, 1], data[:, 2], data[:, 3]
    times = [x for x in (float(v) for v in a.times.split(",")) if x <= t[-1] + 1e-9]
    R_out = a.box / np.sqrt(np.pi)
    ref = cc.solve(a.R, R_out, cc.Material(*STEEL), cc.Material(*WATER), times)
    _, own = cc.reference_error(ref)
    dT = STEEL[3] - WATER[3]
    sph = np.interp(times, t, T)
    err = 100.0 * (sph - np.array(ref["mean_solid"])) / dT
    print(f"disc R = {a.R:.6g} m (equal area), adiabatic circle R_out = {R_out:.6g} m")
    print("   t (s)   SPH mean T (K)   reference (K)   error (% of 60 K)   reference's own (%)")
    for i, ti in enumerate(times):
        print(f"{ti:8.3g}   {sph[i]:14.6f}   {ref['mean_solid'][i]:13.6f}   {err[i]:+17.4f}"
              f"   {100.0 * own[i] / dT:19.2e}")
    worst = float(np.max(np.abs(err)))
    print(f"largest error of the disc's mean temperature: {worst:.4f} % of 60 K; "
          f"largest disc speed {np.max(speed):.3e} m/s")
    if a.png:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        tt = np.linspace(t[1] if len(t) > 1 else times[0], t[-1], 60)
        fine = cc.solve(a.R, R_out, cc.Material(*STEEL), cc.Material(*WATER), list(tt))
        fig, ax = plt.subplots(figsize=(6, 4))
        ax.plot(t, T, "-", lw=2, label="SPH (rigid steel disc in water)")
        ax.plot(tt, fine["mean_solid"], "k--", label="tools/conjugate_cylinder.py")
        ax.set_xlabel("t (s)")
        ax.set_ylabel("mean temperature of the disc (K)")
        ax.set_title(f"cooling cylinder, largest error {worst:.2f} % of 60 K")
        ax.legend()
        fig.tight_layout()
        fig.savefig(a.png, dpi=120)
        print(f"wrote {a.png}")
    if a.max_error is not None and worst > a.max_error:
        print(f"FAIL: {worst:.4f} % > {a.max_error} %")
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
