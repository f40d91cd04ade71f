"""The heated cavity against the benchmark and the reference solver.

Reads the final dump (id x y vx vy c_T) and the log of in.cavity; prints
the mean Nusselt numbers (averaged over the last third of the run, where
the flow is steady but for the particles' noise) against de Vahl Davis
(1983) and the centre-line
errors against tools/cavity_fv.py (steady, 64 x 64 cells: its own Nu
error is 2.6e-4 at Ra = 1e4); writes a PNG of isotherms, streamlines and
the centre-line profiles.

Centre-line values of SPH: Shepard averages (Wendland C2 kernel, radius
2 dx) at the points of the line. L2 errors as Reece et al. 2024, eqs 35-36:
sqrt(sum (f_SPH - f_ref)^2 / sum f_ref^2) over the points.
"""

import argparse
import os
import sys

import numpy as np

from sphthermal_tools.dump import read_frames
from sphthermal_tools.log import final_nusselt, late_rows, longest_thermo_table
import cavity_fv


def shepard(px, py, x, y, f, radius):
    """Kernel-weighted average of f at the points (px, py)."""
    out = np.empty(len(px))
    for k, (a, b) in enumerate(zip(px, py)):
        q = np.hypot(x - a, y - b) / radius
        w = np.where(q < 1.0, (1.0 - q) ** 4 * (1.0 + 4.0 * q), 0.0)
        out[k] = (w * f).sum() / w.sum()
    return out


def l2(sph, ref):
    return np.sqrt(((sph - ref) ** 2).sum() / (ref ** 2).sum())


def final_state(dump, si):
    """The last frame of a dump, in the cavity's units (x / L, v L / alpha,
    theta) when si = (L, alpha, T_C, dT) is given."""
    c = read_frames(dump)[-1][1]
    state = {k: c[k] for k in ("x", "y", "z", "vx", "vy", "c_T") if k in c}
    if si:
        length, alpha, t_cold, t_diff = si
        for k in ("x", "y", "z"):
            if k in state:
                state[k] = state[k] / length
        for k in ("vx", "vy"):
            state[k] = state[k] * length / alpha
        state["c_T"] = (state["c_T"] - t_cold) / t_diff
    return state


def centre_lines(s, line, dx, keep=None):
    """theta and v on y = 0.5, theta and u on x = 0.5 (Shepard averages at
    the points of line) of the particles in keep (all if None)."""
    x, y, vx, vy, T = (s[k] if keep is None else s[k][keep] for k in ("x", "y", "vx", "vy", "c_T"))
    half = np.full(len(line), 0.5)
    return (shepard(line, half, x, y, T, 2 * dx), shepard(line, half, x, y, vy, 2 * dx),
            shepard(half, line, x, y, T, 2 * dx), shepard(half, line, x, y, vx, 2 * dx))


def print_profile_differences(what, a, b):
    """L2 differences (eqs 35-36, b as the reference) of two sets of centre
    lines; what names them and ends with the line y = 0.5."""
    print(f"{what}: theta {l2(a[0], b[0]):.4f}, v {l2(a[1], b[1]):.4f}; "
          f"on x = 0.5: theta {l2(a[2], b[2]):.4f}, u {l2(a[3], b[3]):.4f}")


def main():
    p = argparse.ArgumentParser(description=__doc__)
    p.add_argument("dump", nargs="?", default="cavity.dump")
    p.add_argument("--log", default="log.cavity")
    p.add_argument("--ra", type=float, default=1e4)
    p.add_argument("--pr", type=float, default=0.71)
    p.add_argument("--ref-cells", type=int, default=64)
    p.add_argument("--png", default="cavity.png")
    p.add_argument("--nz", type=int, default=0,
                   help="layers in the periodic depth of a quasi-2-D run (values are averaged over z)")
    p.add_argument("--si", type=float, nargs=4, metavar=("L", "ALPHA", "T_C", "DT"),
                   help="a run in SI units (in.air): scale x by L, v by alpha / L and T to "
                        "(T - T_C) / DT")
    p.add_argument("--average-from", type=float, default=2.0 / 3.0,
                   help="average Nu over the thermo rows from this fraction of the run's time on")
    p.add_argument("--compare", metavar="DUMP",
                   help="another run's final dump (e.g. the 2-D run beside a quasi-2-D one): "
                        "L2 differences of the centre lines, that run as the reference")
    p.add_argument("--max-nu-error", type=float, help="fail (exit 1) above this error of mean Nu, %%")
    args = p.parse_args()

    with open(args.log) as f:
        log_text = f.read()
    final = final_nusselt(log_text)
    if final is None:
        sys.exit(f"analyse: no 'final:' line in {args.log}")
    (nu_hot, nu_cold), t_end, grad = final["heat"], final["time"], final["gradient"]
    table = longest_thermo_table(log_text)
    if table is None or "Time" not in table:
        sys.exit(f"analyse: no thermo table with Time in {args.log}")
    late = late_rows(table, args.average_from)
    mean = {k: table[k][late].mean() for k in table if k.startswith("c_nu_")}
    spread = {k: table[k][late].std() for k in table if k.startswith("c_nu_")}
    state = final_state(args.dump, args.si)
    x, y, vx, vy, T = (state[k] for k in ("x", "y", "vx", "vy", "c_T"))
    n = int(round(np.sqrt(len(x) / max(args.nz, 1))))
    dx = 1.0 / n

    ref = cavity_fv.solve(args.ra, args.pr, n=args.ref_cells)
    bench = cavity_fv.DE_VAHL_DAVIS.get(args.ra)
    nu_ref = bench[0] if bench else ref["nu_mean_hot"]
    nu = 0.5 * (mean["c_nu_hot[1]"] + mean["c_nu_cold[1]"])
    err = 100.0 * (nu / nu_ref - 1.0)
    print(f"Ra = {args.ra:g}, {n} x {n} particles, t = {t_end:g}")
    print(f"at t = {t_end:g}: Nu from the walls' heat: hot {nu_hot:.4f}, cold {nu_cold:.4f}" +
          (f"; from the wall gradient: hot {grad[0]:.4f}, cold {grad[1]:.4f}" if grad else ""))
    print(f"averaged over t >= {args.average_from * t_end:g} ({late.sum()} thermo rows):")
    print(f"  mean Nu from the walls' heat: hot {mean['c_nu_hot[1]']:.4f} (std "
          f"{spread['c_nu_hot[1]']:.4f}), cold {mean['c_nu_cold[1]']:.4f}, mean {nu:.4f} "
          f"({err:+.2f} %)")
    if "c_nu_hot[2]" in mean:
        g = 0.5 * (mean["c_nu_hot[2]"] + mean["c_nu_cold[2]"])
        print(f"  mean Nu from the wall gradient: hot {mean['c_nu_hot[2]']:.4f}, cold "
              f"{mean['c_nu_cold[2]']:.4f}, mean {g:.4f} ({100.0 * (g / nu_ref - 1.0):+.2f} %)")
    # in steady state the heat through every vertical line is Nu (units of
    # the cavity: L = alpha = dT = 1); averaged over x it is 1 + the mean of
    # u T over the cavity, a third estimate that needs no wall: the heat the
    # flow carries. T less its mean, as the particles' mean u is not exactly 0
    nu_flow = 1.0 + np.mean(vx * (T - T.mean()))
    print(f"  Nu from the flow at t = {t_end:g} (1 + mean of u T over the particles): "
          f"{nu_flow:.4f} ({100.0 * (nu_flow / nu_ref - 1.0):+.2f} %)")
    src = "de Vahl Davis (1983)" if bench else "tools/cavity_fv.py"
    print(f"{src}: Nu {nu_ref}; cavity_fv.py ({args.ref_cells} cells): {ref['nu_mean_hot']:.4f}")
    print(f"error of the mean Nu from the heat (time average): {err:+.2f} %")

    # centre lines: y = 0.5 (theta, v) and x = 0.5 (theta, u)
    line = np.linspace(0.5 * dx, 1.0 - 0.5 * dx, n)
    lines = centre_lines(state, line, dx)
    th_h, v_h = lines[0], lines[1]
    rth_h, rv_h = cavity_fv.profiles_at(ref, line)
    rth_v, ru_v = cavity_fv.vertical_profiles_at(ref, line)
    print_profile_differences("L2 errors on y = 0.5 (Reece et al. 2024, eqs 35-36)", lines,
                              (rth_h, rv_h, rth_v, ru_v))
    print(f"largest v on y = 0.5: {v_h.max():.3f} (reference {rv_h.max():.3f})")
    if args.nz and "z" in state:
        # a quasi-2-D flow is the same in every slice of the depth: the
        # front and back halves of the particles against each other
        depth = args.nz * dx
        front = (state["z"] % depth) < 0.5 * depth
        print_profile_differences(f"quasi-2-D, z < {args.nz / 2:g} spacings against the rest: "
                                  "L2 on y = 0.5",
                                  centre_lines(state, line, dx, front),
                                  centre_lines(state, line, dx, ~front))
    if args.compare:
        other = final_state(args.compare, args.si)
        n_other = int(round(np.sqrt(len(other["x"]))))
        print_profile_differences(f"against {args.compare} ({n_other} x {n_other}): L2 on y = 0.5",
                                  lines,
                                  centre_lines(other, line, 1.0 / n_other))

    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from scipy.interpolate import griddata

    gx, gy = np.meshgrid(np.linspace(0, 1, 101), np.linspace(0, 1, 101))
    tg = griddata((x, y), T, (gx, gy), method="linear")
    ug = griddata((x, y), vx, (gx, gy), method="linear", fill_value=0.0)
    vg = griddata((x, y), vy, (gx, gy), method="linear", fill_value=0.0)
    cen = ref["centres"]
    fig, ax = plt.subplots(1, 3, figsize=(15, 4.8))
    levels = np.linspace(0.05, 0.95, 10)
    ax[0].contour(cen["x"], cen["y"], np.asarray(cen["theta"]).T, levels, colors="k",
                  linewidths=0.8, linestyles="--")
    cs = ax[0].contour(gx, gy, tg, levels, cmap="coolwarm")
    ax[0].clabel(cs, fmt="%.1f", fontsize=7)
    ax[0].set_title("isotherms: SPH (colour), cavity_fv.py (dashed)")
    speed = np.hypot(ug, vg)
    ax[1].streamplot(gx, gy, ug, vg, color=speed, cmap="viridis", density=1.2, linewidth=0.8)
    ax[1].set_title("streamlines of SPH (colour: speed)")
    for a in ax[:2]:
        a.set_aspect("equal")
        a.set_xlim(0, 1)
        a.set_ylim(0, 1)
    ax[2].plot(line, th_h, "o", ms=3, label="theta, SPH")
    ax[2].plot(ref["hmid"]["x"], ref["hmid"]["theta"], "-", label="theta, cavity_fv.py")
    scale = max(1.0, np.abs(rv_h).max())
    ax[2].plot(line, v_h / scale, "s", ms=3, label=f"v / {scale:.3g}, SPH")
    ax[2].plot(ref["hmid"]["x"], np.asarray(ref["hmid"]["v"]) / scale, "-", label="v, cavity_fv.py")
    ax[2].set_xlabel("x (y = 0.5)")
    ax[2].legend(fontsize=8)
    ax[2].set_title(f"Nu {nu:.3f} (heat) vs {nu_ref:.4g} ({err:+.1f} %)")
    depth = f" x {args.nz} (quasi-2-D, averaged over the depth)" if args.nz else ""
    fig.suptitle(f"differentially heated cavity, Ra = {args.ra:g}, Pr = {args.pr}, "
                 f"{n} x {n}{depth} particles")
    fig.tight_layout()
    fig.savefig(args.png, dpi=110)
    print(f"wrote {os.path.abspath(args.png)}")
    if args.max_nu_error is not None and abs(err) > args.max_nu_error:
        print(f"FAIL: |error of mean Nu| {abs(err):.2f} % > {args.max_nu_error} %")
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
