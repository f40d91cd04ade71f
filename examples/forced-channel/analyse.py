#!/usr/bin/env python3
"""Analyse the heated channel (in.channel): the last frame of <out>.dump
against the finite-volume reference of tools/channel_fv.py.

Printed and checked:
- temperature across the channel (fluid, and the slabs with --walls thick)
  at x = 5, 50, 100, 150, 195 m: the particles of the column nearest each
  station against the reference at each particle's place; the largest
  error in % of T_w - T_in;
- the bulk (mixing-cup) temperature along x and the local Nusselt number
  Nu = q D_h / (k (T_w - T_b)), D_h = 2 W, from the heat the wall's dummy
  particles give to the fluid (walls = dirichlet), against the reference,
  in the column at each station and as the mean of the columns within 2.5 m
  of it (one column's heat at one frame carries the particles' noise);
- the flow: u against the Poiseuille profile (in % of u_max) and the
  largest |v| (in % of u_max; 0 exactly for a laminar flow), and the flow
  rate (mean u of the fluid against the profile's mean).
A PNG shows the profiles, the bulk temperature and Nu.

With --series (a run started from rest): every frame's u against the
series solution of Poiseuille flow started from rest (Morris, Fox & Zhu
1997), at the frame's time (the dump's ITEM: TIME, dump_modify time yes):
per particle (mean and largest error) and as a profile (u - series
averaged in rows of one spacing: the largest row and the centre rows),
and with --series-png a plot of u(y) (the fluid averaged in rows of one
spacing) against the series at t = 50, 100, 200, 300 s and the last frame.

With --open (in.channel's inlet = open) the particles of the buffers
behind the inlet and the outlet, and the walls alongside them, are left
out: only 0 <= x < 200 m is the channel.

  analyse.py channel.dump [--walls dirichlet|thick] [--ksk 1] [--re 652]
             [--n 20] [--open] [--png channel.png] [--max-t-error PCT] [--max-vy PCT]
             [--series [--series-png FILE]]
"""
import argparse
import sys

import numpy as np

import channel_fv
from sphthermal_tools.dump import frame_times, read_frames

from channel_flow import poiseuille_from_rest

W, LENGTH, MU, RHO, K, T_W, T_IN = 20.0, 200.0, 0.248, 1.0, 131914.89, 420.0, 300.0
STATIONS = (5.0, 50.0, 100.0, 150.0, 195.0)


def reference(a):
    case = "thick-wall" if a.walls == "thick" else "heated"
    problem = channel_fv.preset(case, re=a.re, ks_ratio=a.ksk)
    return channel_fv.solve(problem, nx=a.ref_nx, ny=a.ref_ny)


def row_means(y, values, dx, n):
    """values averaged in the n rows of one spacing across the channel"""
    row = np.clip((y / dx).astype(int), 0, n - 1)
    return np.bincount(row, values, n) / np.maximum(np.bincount(row, None, n), 1)


def plot_series(a, frames, frame_time, dx, u_max, times=(50.0, 100.0, 200.0, 300.0)):
    """u(y) of the frames nearest to times and of the last one, rows of one spacing."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    chosen = []
    for t in times:
        k = min(range(1, len(frames)), key=lambda i: abs(frame_time[i] - t))
        if abs(frame_time[k] - t) < 0.5 * t and k not in chosen:
            chosen.append(k)
    if len(frames) - 1 not in chosen:
        chosen.append(len(frames) - 1)
    y_fine = np.linspace(0.0, W, 201)
    rows = np.arange(a.n)
    fig, ax = plt.subplots(figsize=(6.5, 4.5))
    for k in chosen:
        f, t = frames[k][1], frame_time[k]
        fl = f["type"] == 1
        u_row = row_means(f["y"][fl], f["vx"][fl], dx, a.n)
        line, = ax.plot(poiseuille_from_rest(y_fine, t, u_max, MU / RHO, W) / u_max, y_fine, "-",
                        lw=1)
        ax.plot(u_row / u_max, (rows + 0.5) * dx, "o", ms=3, color=line.get_color(),
                label=f"t = {t:.0f} s")
    ax.set_xlabel("u / u_max (lines: series, Morris et al. 1997)")
    ax.set_ylabel("y (m)")
    ax.set_title(f"Channel from rest, Re = {a.re:g}, {a.n} particles across"
                 + (f", {a.label}" if a.label else ""))
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(a.series_png, dpi=110)
    print(f"wrote {a.series_png}")


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawTextHelpFormatter)
    p.add_argument("dump", nargs="?", default="channel.dump")
    p.add_argument("--walls", choices=["dirichlet", "thick"], default="dirichlet")
    p.add_argument("--ksk", type=float, default=1.0)
    p.add_argument("--re", type=float, default=652.0)
    p.add_argument("--n", type=int, default=20, help="particles across W")
    p.add_argument("--open", action="store_true",
                   help="a true inlet and outlet: leave out the buffers and the walls beside them")
    p.add_argument("--ref-nx", type=int, default=None, help="reference cells along x (its default)")
    p.add_argument("--ref-ny", type=int, default=None, help="reference cells across W (its default)")
    p.add_argument("--png", default="channel.png")
    p.add_argument("--label", default="")
    p.add_argument("--max-t-error", type=float, help="fail if the largest T error (%%) is above")
    p.add_argument("--max-vy", type=float, help="fail if the largest |v| (%% of u_max) is above")
    p.add_argument("--series", action="store_true",
                   help="compare every frame's u with the flow started from rest")
    p.add_argument("--series-png", help="with --series: u(y) against the series, as a PNG")
    a = p.parse_args()

    frames = read_frames(a.dump)
    step, d = frames[-1]
    if a.open:
        inside = (d["x"] >= 0.0) & (d["x"] < LENGTH)
        d = {key: value[inside] for key, value in d.items()}
    dx = W / a.n
    u_max = a.re * MU / (RHO * W)
    if a.series:
        times = frame_times(a.dump)
        if None in times:
            sys.exit(f"{a.dump}: --series needs every frame's time (dump_modify time yes)")
        print(f"{'t (s)':>8} {'mean |u err| %':>15} {'max |u err| %':>14} {'rows: max %':>12} "
              f"{'centre %':>9} {'max |v| %':>10}  (of u_max)")
        for t, (fstep, f) in zip(times[1:], frames[1:]):
            fl = f["type"] == 1
            series = poiseuille_from_rest(f["y"][fl], t, u_max, MU / RHO, W)
            err = 100.0 * np.abs(f["vx"][fl] - series) / u_max
            # the profile: u and the series averaged over the same particles, rows of one spacing
            rows = 100.0 * row_means(f["y"][fl], f["vx"][fl] - series, dx, a.n) / u_max
            centre = rows[(a.n - 1) // 2: a.n // 2 + 1].mean()
            print(f"{t:8.1f} {err.mean():15.3f} {err.max():14.3f} {np.abs(rows).max():12.3f} "
                  f"{centre:+9.3f} {100.0 * np.abs(f['vy'][fl]).max() / u_max:10.4f}")
        if a.series_png:
            plot_series(a, frames, times, dx, u_max)
    fluid = d["type"] == 1
    ref = reference(a)
    dT = T_W - T_IN

    # columns: particles of one lattice column share x to within the drift
    x = np.mod(d["x"], LENGTH)
    worst_t = 0.0
    rows = []
    for xs in STATIONS:
        # the fluid within half a spacing of the station; the solid (which
        # does not move) of the lattice column nearest to it
        solid_x = (np.floor(xs / dx) + 0.5) * dx
        col = (fluid & (np.abs(x - xs) < 0.5 * dx)) | \
            ((d["type"] == 2) & (np.abs(x - solid_x) < 1e-6 * dx))
        y = d["y"][col]
        t = d["c_T"][col]
        # the reference at each particle's own place
        t_ref = np.array([channel_fv.profile_at(ref, xp, [yp])[1][0]
                          for xp, yp in zip(x[col], y)])
        err = 100.0 * np.abs(t - t_ref).max() / dT
        worst_t = max(worst_t, err)
        rows.append((xs, y, t, t_ref, err))
        print(f"x = {xs:5.0f} m: {col.sum():3d} particles, T from {t.min():.2f} to {t.max():.2f} K, "
              f"largest error {err:.3f} % of T_w - T_in")

    # the flow
    u_exact = 4.0 * u_max * d["y"][fluid] * (W - d["y"][fluid]) / W**2
    u_err = 100.0 * np.abs(d["vx"][fluid] - u_exact).max() / u_max
    vy = 100.0 * np.abs(d["vy"][fluid]).max() / u_max
    # the flow rate decides how far the heat is carried
    rate_err = 100.0 * (d["vx"][fluid].mean() / u_exact.mean() - 1.0)
    print(f"flow: largest |u - u_Poiseuille| {u_err:.3f} % of u_max, largest |v| {vy:.4f} % of u_max, "
          f"flow rate {rate_err:+.2f} % of Poiseuille's")

    # bulk temperature and local Nu per column (walls = dirichlet: the dummies' heat)
    ncol = int(round(LENGTH / dx))
    centres = (np.arange(ncol) + 0.5) * dx
    index = np.clip((x / dx).astype(int), 0, ncol - 1)
    uf = d["vx"][fluid]
    t_bulk = np.bincount(index[fluid], uf * d["c_T"][fluid], ncol) / \
        np.bincount(index[fluid], uf, ncol)
    nu = None
    if a.walls == "dirichlet" and "f_hot[1]" in d:
        dummy = d["type"] == 3
        # heat per unit depth from both walls into the fluid, per column
        q = -np.bincount(index[dummy], d["f_hot[1]"][dummy], ncol) / (2.0 * dx)
        nu = q * 2.0 * W / (K * (T_W - t_bulk))
    ref_bulk = channel_fv.bulk_at(ref, 0, centres)
    bulk_err = 100.0 * np.abs(t_bulk - ref_bulk).max() / dT
    print(f"bulk temperature: largest error {bulk_err:.3f} % of T_w - T_in; outlet "
          f"{t_bulk[-1]:.2f} K (reference {ref_bulk[-1]:.2f} K)")
    if nu is not None:
        ref_nu = channel_fv.nu_at(ref, centres)
        for xs in (50.0, 100.0, 150.0, 195.0):
            k = int(xs / dx)
            near = np.abs(centres - xs) <= 2.5
            print(f"  Nu at x = {xs:5.0f} m: {nu[k]:.3f} (reference {ref_nu[k]:.3f}); over "
                  f"{near.sum()} columns within 2.5 m: {nu[near].mean():.3f} "
                  f"(reference {ref_nu[near].mean():.3f})")

    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        fig, ax = plt.subplots(1, 3, figsize=(15, 4.5))
        for xs, y, t, t_ref, err in rows:
            yr, tr = channel_fv.profile_at(ref, xs)
            line, = ax[0].plot((tr - T_IN) / dT, yr, "-", lw=1)
            ax[0].plot((t - T_IN) / dT, y, "o", ms=3, color=line.get_color(), label=f"x = {xs:g} m")
        ax[0].set_xlabel("(T - T_in) / (T_w - T_in)")
        ax[0].set_ylabel("y (m)")
        ax[0].legend(fontsize=8)
        ax[1].plot(centres, (t_bulk - T_IN) / dT, "o", ms=2, label="SPH")
        ax[1].plot(centres, (ref_bulk - T_IN) / dT, "-", label="finite volume")
        ax[1].set_xlabel("x (m)")
        ax[1].set_ylabel("bulk (T - T_in) / (T_w - T_in)")
        ax[1].legend()
        if nu is not None:
            ax[2].plot(centres, nu, "o", ms=2, label="SPH")
            ax[2].plot(centres, ref_nu, "-", label="finite volume")
            ax[2].axhline(7.541, ls=":", color="k", label="7.541 (fully developed)")
            ax[2].set_ylim(0, 30)
            ax[2].set_xlabel("x (m)")
            ax[2].set_ylabel("local Nu (D_h = 2W)")
            ax[2].legend()
        else:
            ax[2].set_visible(False)
        fig.suptitle(f"Heated channel, Re = {a.re:g}, {a.walls} walls"
                     + (f", k_s/k = {a.ksk:g}" if a.walls == "thick" else "")
                     + (f", {a.label}" if a.label else "") + f": step {step}")
        fig.tight_layout()
        fig.savefig(a.png, dpi=110)
        print(f"wrote {a.png}")
    except ImportError:
        print("no matplotlib: no PNG")

    ok = True
    if a.max_t_error is not None and not worst_t <= a.max_t_error:
        print(f"FAIL: largest T error {worst_t:.3f} % above {a.max_t_error} %")
        ok = False
    if a.max_vy is not None and not vy <= a.max_vy:
        print(f"FAIL: largest |v| {vy:.4f} % of u_max above {a.max_vy} %")
        ok = False
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
