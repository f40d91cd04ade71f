#!/usr/bin/env python3
"""Analysis of the heated tanks of examples/mixing-tank-2d and -3d (Reece et
al. 2024, section 3.4): the mixing measures against time, the fields, the
particles lost, and the symmetry of temperature and density.

  mixing_tank.py DUMP --mixing FILE [--dim 2|3] [--png PREFIX]

DUMP: dump custom with id type x y [z] ... c_T c_rho c_mix[1..4] (fluid
types 1 and 2 in 2-D, 1 and 6 in 3-D); FILE: the fix ave/time file of
c_mix[*] and the mean temperature (its columns are named in its header).

Symmetry: in 2-D the tank is a mirror image about its vertical centre line;
each particle's T is compared with the mean T of the particles around its
mirror point. In 3-D it is axisymmetric: the fluid is binned in rings of
two spacings (radius x height) and four quadrants; the asymmetry is the
largest spread of the quadrants' means in a ring, in units of theta_H -
theta_C for T and of the axisymmetric density's range for rho.
Writes PREFIX_measures.png (global measures against time) and
PREFIX_fields.png (T, rho, F, FTLE, Robinson, VF-FTLE at the last dump: the
tank in 2-D, the planes y = 0 and x = 0 in 3-D).
"""

import argparse
import os
import sys

import numpy as np

from sphthermal_tools.dump import frame_times, read_frames

R, H = 0.0193, 0.0386
T_HOT, T_COLD = 303.0, 283.0
RHO0 = 1.204    # the air's rest density in both examples (kg/m^3)
FIELDS = [("c_T", "T (K)"), ("c_rho", "rho (kg/m^3)"), ("c_mix[1]", "F (volume fraction of A)"),
          ("c_mix[2]", "FTLE (1/s)"), ("c_mix[3]", "Robinson's M"), ("c_mix[4]", "VF-FTLE")]


def write_tank_data(n, path, ring_multiple=1):
    """The particles of examples/mixing-tank-3d/in.tank3d, n spacings across
    the diameter and the height, written to path (tools/sph_boundary.py);
    returns the spacing. The wall surface lies half a spacing inside the
    first ring of wall particles (radius R + dx/2, lids dx/2 beyond the
    surface), and no fluid particle is closer than a spacing to a wall
    particle (eps 0.99, as on a lattice; with Cleary's 0.42 fluid starts
    where the kernel's gradient is weak). The lids are the fluid's lattice,
    so that every column of fluid ends under a lid particle. n layers of
    fluid, the components split at mid-height; three wall layers fill the
    Wendland support (4 dx) of the outermost fluid. ring_multiple: that of
    sph_boundary.cylinder (4: the tank the same after a quarter turn)."""
    import sph_boundary
    dx = H / n
    tank = sph_boundary.cylinder(R + dx / 2, H + dx, dx, eps=0.99, layers=3, offset=(0.5, 0.5, 0.0),
                                 z_split=(H + dx) / 2, lids="lattice", ring_multiple=ring_multiple)
    tank.write_data(path, rho=RHO0, cv=1006.0, T=T_COLD)
    return dx


def read_mixing(path):
    """The fix ave/time file of the inputs: {column name of its header: values}."""
    with open(path) as f:
        names = [line for line in f if line.startswith("#")][-1].lstrip("# ").split()
    rows = np.loadtxt(path, comments="#", ndmin=2)
    if len(names) != rows.shape[1]:
        sys.exit(f"FAIL: {path}: the header names {len(names)} columns, the rows have {rows.shape[1]}")
    return {name: rows[:, k] for k, name in enumerate(names)}


def fluid_of(frame, dim):
    top = 2 if dim == 2 else 6
    return (frame["type"] == 1) | (frame["type"] == top)


def symmetry_2d(frame, dx):
    """Largest |T(x) - T(L - x)| / (theta_H - theta_C) and the same for rho /
    its range, each particle against the kernel-free mean of the particles
    within one spacing of its mirror point."""
    x, y = frame["x"], frame["y"]
    mx = 2 * R - x
    worst = {"c_T": 0.0, "c_rho": 0.0}
    scale = {"c_T": T_HOT - T_COLD, "c_rho": np.ptp(frame["c_rho"]) or 1.0}
    for i in range(len(x)):
        near = (x - mx[i]) ** 2 + (y - y[i]) ** 2 < dx * dx
        if not near.any():
            continue
        for name in worst:
            worst[name] = max(worst[name], abs(frame[name][near].mean() - frame[name][i]) / scale[name])
    return worst["c_T"], worst["c_rho"]


def symmetry_3d(frame, dx, rho_scale=None):
    """The largest spread of the four quadrants' means in a ring (radius x
    height, two spacings each): T in theta_H - theta_C, rho in rho_scale
    (default: the range of the rings' means)."""
    x, y, z = frame["x"], frame["y"], frame["z"]
    r = np.hypot(x, y)
    ring = (np.minimum(r // (2 * dx), R // (2 * dx)) * 1000 + z // (2 * dx)).astype(int)
    quadrant = ((x >= 0).astype(int) + 2 * (y >= 0)).astype(int)
    result = []
    for name, scale in (("c_T", T_HOT - T_COLD), ("c_rho", rho_scale)):
        spreads, means = [], []
        for b in np.unique(ring):
            inside = ring == b
            q_means = [frame[name][inside & (quadrant == q)].mean() for q in range(4)
                       if (inside & (quadrant == q)).any()]
            if len(q_means) == 4:
                spreads.append(max(q_means) - min(q_means))
                means.append(frame[name][inside].mean())
        s = scale if scale else (np.ptp(means) or 1.0)
        result.append((max(spreads) / s, float(np.mean(spreads)) / s))
    return result


def save_png(fig, path, dpi):
    """Write a figure as PNG, in a palette of 64 colours when PIL is there
    (a quarter of the file)."""
    fig.savefig(path, dpi=dpi)
    try:
        from PIL import Image
        Image.open(path).convert("RGB").quantize(64).save(path)
    except ImportError:
        pass


def plot_measures(m, prefix):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    t = m["time"]
    fig, axes = plt.subplots(1, 2, figsize=(11, 4))
    for label in ("S*_A", "S*_B", "VF-FTLE", "Robinson"):
        axes[0].plot(t, m[label], label=label)
    axes[0].set_xlabel("t (s)")
    axes[0].set_ylabel("global measure")
    axes[0].legend()
    axes[0].set_title("mixing (Reece et al. 2024, Table 4)")
    axes[1].plot(t, m["T_mean"], "k")
    axes[1].set_xlabel("t (s)")
    axes[1].set_ylabel("mean fluid T (K)")
    fig.tight_layout()
    save_png(fig, f"{prefix}_measures.png", 90)
    plt.close(fig)


def plot_fields(frame, dim, dx, prefix, when):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fluid = fluid_of(frame, dim)
    if dim == 2:
        planes = [("", fluid, frame["x"], frame["y"])]
    else:
        planes = [("y = 0", fluid & (np.abs(frame["y"]) < 0.75 * dx), frame["x"], frame["z"]),
                  ("x = 0", fluid & (np.abs(frame["x"]) < 0.75 * dx), frame["y"], frame["z"])]
    fig, axes = plt.subplots(len(planes), len(FIELDS), figsize=(3.0 * len(FIELDS), 3.1 * len(planes)),
                             squeeze=False)
    for p, (plane, keep, u, v) in enumerate(planes):
        for f, (name, label) in enumerate(FIELDS):
            ax = axes[p][f]
            sc = ax.scatter(u[keep], v[keep], c=frame[name][keep], s=12 if dim == 3 else 4, cmap="viridis")
            fig.colorbar(sc, ax=ax, shrink=0.8)
            ax.set_aspect("equal")
            ax.set_title(f"{label}{', ' + plane if plane else ''}", fontsize=8)
            ax.tick_params(labelsize=6)
    fig.suptitle(f"t = {when:.1f} s")
    fig.tight_layout()
    save_png(fig, f"{prefix}_fields.png", 80)
    plt.close(fig)


def main():
    if len(sys.argv) > 1 and sys.argv[1] == "setup":
        p = argparse.ArgumentParser(prog="mixing_tank.py setup",
                                    description="write the 3-D tank's data file; print its spacing")
        p.add_argument("n", type=int, help="spacings across the diameter and the height")
        p.add_argument("data")
        a = p.parse_args(sys.argv[2:])
        print(write_tank_data(a.n, a.data))
        return
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("dump")
    p.add_argument("--mixing", required=True)
    p.add_argument("--dim", type=int, choices=[2, 3], default=3)
    p.add_argument("--dx", type=float, required=True)
    p.add_argument("--png", default=None, help="prefix of the PNG files")
    a = p.parse_args()

    m = read_mixing(a.mixing)
    print(f"{'t (s)':>8} {'T mean':>9} {'S*_A':>7} {'S*_B':>7} {'VF-FTLE':>8} {'Robinson':>8} {'fluid':>6}")
    n_rows = len(m["time"])
    stride = max(1, n_rows // 12)
    for k in list(range(0, n_rows, stride)) + ([n_rows - 1] if (n_rows - 1) % stride else []):
        print(f"{m['time'][k]:8.2f} {m['T_mean'][k]:9.4f} {m['S*_A'][k]:7.4f} {m['S*_B'][k]:7.4f} "
              f"{m['VF-FTLE'][k]:8.4f} {m['Robinson'][k]:8.4f} {int(m['fluid_inside'][k]):6d}")
    for label in ("S*_A", "S*_B"):
        series = m[label]
        if len(series) < 2:
            continue
        drops = np.diff(series)
        print(f"{label}: from {series[0]:.4f} to {series[-1]:.4f}; largest drop between outputs "
              f"{max(0.0, -drops.min()):.2e} ({'monotonic' if drops.min() >= 0 else 'not monotonic'})")

    frames = read_frames(a.dump)
    times = frame_times(a.dump)
    final = a.dump + ".final"    # the state at the end
    if os.path.exists(final):
        frames += read_frames(final)
        times += frame_times(final)
    # a frame without ITEM: TIME: its time from the mixing file's steps and times
    times = [t if t is not None else float(np.interp(step, m["step"], m["time"]))
             for t, (step, _) in zip(times, frames)]

    n0 = int(fluid_of(frames[0][1], a.dim).sum())
    print(f"fluid particles: {n0} at the start, {int(fluid_of(frames[-1][1], a.dim).sum())} at the end "
          f"(the paper loses 7 % in 2-D over 300 s)")
    for k, ((step, frame), when) in enumerate(zip(frames, times)):
        fluid = {name: col[fluid_of(frame, a.dim)] for name, col in frame.items()}
        print(f"dump {k} (t = {when:g}): fluid density {100 * (fluid['c_rho'].min() / RHO0 - 1):+.2f} % "
              f"to {100 * (fluid['c_rho'].max() / RHO0 - 1):+.2f} % of rho0, mean "
              f"{100 * (fluid['c_rho'].mean() / RHO0 - 1):+.3f} %")
        if a.dim == 2:
            t_asym, rho_asym = symmetry_2d(fluid, a.dx)
            print(f"dump {k} (t = {when:g}): mirror asymmetry: T {t_asym:.2e} of theta_H - theta_C, "
                  f"rho {rho_asym:.2e} of its range")
        else:
            (t_max, t_mean), (rho_max, rho_mean) = symmetry_3d(fluid, a.dx)
            _, (rho0_max, _) = symmetry_3d(fluid, a.dx, RHO0)
            print(f"dump {k} (t = {when:g}): quadrant spread, largest (mean) over rings: T {t_max:.2e} "
                  f"({t_mean:.2e}) of theta_H - theta_C, rho {rho_max:.2e} ({rho_mean:.2e}) of the rings' range, "
                  f"{rho0_max:.2e} of rho0")
    if a.png:
        plot_measures(m, a.png)
        plot_fields(frames[-1][1], a.dim, a.dx, a.png, times[-1])
        print(f"wrote {a.png}_measures.png and {a.png}_fields.png")


if __name__ == "__main__":
    main()
