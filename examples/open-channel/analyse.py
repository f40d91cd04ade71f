#!/usr/bin/env python3
"""The open channel of in.channel against Poiseuille's flow: from the frames
of <out>.dump at t >= --from (averaged), per column of particles (width dx)
along the channel:
  - the profile's departure from u = 6 U y (H - y) / H^2, in % of its
    centre speed 1.5 U: per column the rms over its particles; over the
    developed part (x >= --developed, up to 0.5 H before the outlet) the
    largest of the mean departures of the particles of each row of height
    dx;
  - the centre speed u_c (a quadratic through the particles within 0.2 H
    of the centre line) and where it first reaches 99 % of 1.5 U: the
    entrance length, printed next to the correlation of Durst, Ray, Unsal
    and Bayoumi (J. Fluids Eng. 127 (2005) 1154-1160) for a plane channel,
    L/H = (0.631^1.6 + (0.0442 Re)^1.6)^(1/1.6); with --reference, u_c
    against our own solution of the entrance flow (tools/channel_entrance.py);
  - the mean density, whose slope along the developed part gives the
    pressure gradient c0^2 d rho / dx, against Poiseuille's 12 mu U / H^2.
Fails (exit 1) when the developed profile departs by more than --max-profile
%, the pressure gradient by more than --max-gradient %, the entrance
length exceeds --max-entrance (a parabolic inflow enters developed) or the
centre speed departs from --reference by more than --max-reference.

  analyse.py channel.dump --re 20 --c0 2.0 [--from 80] [--developed 3]
"""

import argparse
import sys

import numpy as np

from sphthermal_tools.dump import frame_times, read_frames

U = 0.1
H = 1.0


def plot(path, centres, uc, x, y, vx, inside, dx, re, reference):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, (left, right) = plt.subplots(1, 2, figsize=(10, 4))
    left.plot(centres, uc, "o-", ms=3, label="SPH")
    if reference is not None:
        left.plot(reference[:, 0], reference[:, 1], "k-", label="tools/channel_entrance.py")
    left.axhline(0.99, color="grey", lw=0.8, ls="--", label="99 %")
    left.set_xlabel("x / H")
    left.set_ylabel("centre speed / 1.5 U")
    left.set_title(f"along the channel, Re = {re:g}")
    left.legend()
    rows = np.floor(y[inside] / dx).astype(int)
    mean_y = [np.mean(y[inside][rows == r]) for r in np.unique(rows)]
    mean_u = [np.mean(vx[inside][rows == r]) for r in np.unique(rows)]
    s = np.linspace(0.0, H, 101)
    right.plot(6.0 * U * s * (H - s) / H**2 / (1.5 * U), s, "k-", label="Poiseuille")
    right.plot(np.array(mean_u) / (1.5 * U), mean_y, "o", ms=4, label="SPH, mean of each row")
    right.set_xlabel("u / 1.5 U")
    right.set_ylabel("y / H")
    right.set_title("developed part")
    right.legend()
    fig.tight_layout()
    fig.savefig(path, dpi=100)
    print(f"wrote {path}")


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("dump")
    p.add_argument("--re", type=float, required=True)
    p.add_argument("--c0", type=float, required=True)
    p.add_argument("--n", type=int, default=None,
                   help="particles across H (default: from the rows of the first frame, a lattice; "
                        "give it for a jittered start)")
    p.add_argument("--from", dest="t_from", type=float, default=0.0,
                   help="average the frames from this time on (default: the last frame only)")
    p.add_argument("--developed", type=float, default=3.0,
                   help="the developed part starts this far from the inlet (in H)")
    p.add_argument("--max-profile", type=float, default=None)
    p.add_argument("--max-gradient", type=float, default=None)
    p.add_argument("--png", help="write the centre speed along the channel and the developed profile here")
    p.add_argument("--reference", help="x and u_c / 1.5 U of tools/channel_entrance.py --write, for the "
                   "entrance region (uniform inflow)")
    p.add_argument("--max-reference", type=float, default=None,
                   help="fail when u_c departs from --reference by more than this (of 1.5 U) up to 3 H")
    p.add_argument("--max-entrance", type=float, default=None,
                   help="fail when the centre speed reaches 99 %% of 1.5 U later than this (in H)")
    a = p.parse_args()

    frames = [columns for _, columns in read_frames(a.dump)]
    times = frame_times(a.dump)
    chosen = [k for k, t in enumerate(times) if t >= a.t_from - 1e-9] if a.t_from > 0.0 else [-1]
    x, y, vx, rho = (np.concatenate([frames[k][name] for k in chosen]) for name in ("x", "y", "vx", "c_rho"))
    # the spacing: H / n, or the lattice's, from the rows of the first frame
    if a.n:
        dx = H / a.n
    else:
        rows = np.unique(np.round(frames[0]["y"], 9))
        dx = float(np.min(np.diff(rows)))
    length = round((x.max() + 0.5 * dx) / dx) * dx
    nu = U * H / a.re
    umax = 1.5 * U
    print(f"{len(chosen)} frame(s) from t = {times[chosen[0]]:.4g} s; dx = {dx:.4g} H, channel {length:.4g} H, "
          f"Re = {a.re:g}")
    print("     x/H   u_c/(1.5 U)   rms profile error (% of 1.5 U)   rho")
    centres = np.arange(0.5 * dx, length, dx)
    uc, worst, mean_rho = [], [], []
    for xc in centres:
        m = np.abs(x - xc) < 0.5 * dx
        near = m & (np.abs(y - 0.5 * H) < 0.2 * H)
        coef = np.polyfit(y[near] - 0.5 * H, vx[near], 2)
        uc.append(coef[-1] / umax)
        exact = 6.0 * U * y[m] * (H - y[m]) / H**2
        worst.append(100.0 * np.sqrt(np.mean((vx[m] - exact) ** 2)) / umax)
        mean_rho.append(np.mean(rho[m]))
    uc, worst, mean_rho = np.array(uc), np.array(worst), np.array(mean_rho)
    for k in range(0, len(centres), max(1, len(centres) // 24)):
        print(f"  {centres[k]:6.3f}   {uc[k]:9.4f}   {worst[k]:10.2f}   {mean_rho[k]:.6f}")

    reached = np.nonzero(uc >= 0.99)[0]
    entrance = None
    if len(reached):
        k = reached[0]
        entrance = centres[k] if k == 0 else np.interp(0.99, [uc[k - 1], uc[k]], [centres[k - 1], centres[k]])
    reference = None
    reference_error = None
    if a.reference:
        reference = np.loadtxt(a.reference, ndmin=2)
        near = centres <= 3.0
        ref = np.interp(centres[near], reference[:, 0], reference[:, 1])
        worst = np.argmax(np.abs(uc[near] - ref))
        reference_error = abs(uc[near][worst] - ref[worst])
        shown = ", ".join(f"{xs:g} H {np.interp(xs, centres, uc):.3f} ({np.interp(xs, reference[:, 0], reference[:, 1]):.3f})"
                          for xs in (0.1, 0.25, 0.5, 0.75, 1.0, 1.5))
        print(f"centre speed against the reference {a.reference} (x <= 3 H): largest difference "
              f"{uc[near][worst] - ref[worst]:+.3f} of 1.5 U at x = {centres[near][worst]:.3f} H; {shown}")
    durst = (0.631**1.6 + (0.0442 * a.re) ** 1.6) ** (1.0 / 1.6)
    print(f"entrance length (u_c = 0.99 of 1.5 U): "
          f"{'not reached' if entrance is None else f'{entrance:.3f} H'}; Durst et al. 2005: {durst:.3f} H")

    developed = (centres >= a.developed) & (centres <= length - 0.5)
    inside = (x >= a.developed - 0.5 * dx) & (x <= length - 0.5 + 0.5 * dx)
    row = np.floor(y / dx).astype(int)
    profile = 0.0
    for r in np.unique(row[inside]):
        k = inside & (row == r)
        profile = max(profile, abs(np.mean(vx[k] - 6.0 * U * y[k] * (H - y[k]) / H**2)))
    profile *= 100.0 / umax
    slope = np.polyfit(centres[developed], mean_rho[developed], 1)[0]
    gradient = -a.c0**2 * slope
    exact_gradient = 12.0 * nu * U / H**2    # rho0 = 1
    gradient_error = 100.0 * (gradient / exact_gradient - 1.0)
    print(f"developed part (x >= {a.developed:g} H): profile within {profile:.2f} % of 1.5 U; "
          f"centre speed {np.mean(uc[developed]):.4f} of 1.5 U; "
          f"-dp/dx {gradient:.6g} against 12 mu U / H^2 = {exact_gradient:.6g} ({gradient_error:+.2f} %)")
    if a.png:
        plot(a.png, centres, uc, x, y, vx, inside, dx, a.re, reference)
    failed = []
    if a.max_profile is not None and not profile <= a.max_profile:
        failed.append(f"developed profile off by {profile:.2f} % (limit {a.max_profile} %)")
    if a.max_gradient is not None and not abs(gradient_error) <= a.max_gradient:
        failed.append(f"pressure gradient off by {gradient_error:+.2f} % (limit {a.max_gradient} %)")
    if a.max_entrance is not None and not (entrance is not None and entrance <= a.max_entrance):
        failed.append(f"entrance length {entrance} H (limit {a.max_entrance} H)")
    if a.max_reference is not None and not (reference_error is not None and reference_error <= a.max_reference):
        failed.append(f"centre speed {reference_error} of 1.5 U from the reference (limit {a.max_reference})")
    for f in failed:
        print("FAIL:", f)
    sys.exit(1 if failed else 0)


if __name__ == "__main__":
    main()
