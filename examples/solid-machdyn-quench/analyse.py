"""The quenched plate (in.quench): how far its free end has curled up, against
the thermal bending of a beam with the plate's own temperatures.

Beam theory (plane sections, a clamped end, no load): the thermal strain
eps = alpha_lin T (alpha_lin = expansion / 3) bends each cross-section to
the curvature kappa = -d(eps)/dy, the slope of the least-squares line of
eps through the thickness (the part of eps that plane sections cannot
follow makes only stress), and the free end rises by
    w_tip = integral from the clamp to the tip of kappa(x) (x_tip - x) dx.
The SPH temperatures of each column of plate particles give kappa(x); the
rise of the last column's mean height is the measured w_tip. The beam is
quasi-static: the plate's lowest bending period is about 0.12 s against a
cooling through its thickness of about 1.6 s.
Writes quench.png (a slice of the tank at the last frame, the tip against
time) and prints 'quench:' lines.
usage: analyse.py DUMP [--expansion B] [--png FILE] [--max-difference F]
"""

import argparse
import sys

import numpy as np

from sphthermal_tools.dump import frame_times, read_frames


def columns_and_layers(first, plate):
    """Column (along x) and layer (along y) index of each plate particle, from
    the first frame's lattice, and the spacing."""
    x0, y0 = first["x"][plate], first["y"][plate]
    dx = np.min(np.diff(np.unique(np.round(y0, 12))))
    column = np.rint((x0 - x0.min()) / dx).astype(int)
    layer = np.rint((y0 - y0.min()) / dx).astype(int)
    return column, layer, dx


def tip_from_temperature(temperature, column, layer, y0, dx, alpha_lin):
    """w_tip of a clamped beam whose cross-sections take the curvature of the
    least-squares line of the thermal strain through their thickness."""
    ncol = column.max() + 1
    kappa = np.zeros(ncol)
    for c in range(ncol):
        here = column == c
        ys, strains = [], []
        for j in np.unique(layer[here]):
            one = here & (layer == j)
            ys.append(y0[one].mean())
            strains.append(alpha_lin * temperature[one].mean())
        slope = np.polyfit(ys, strains, 1)[0]
        kappa[c] = -slope
    x = (np.arange(ncol) + 0.5) * dx
    f = kappa * (x[-1] - x)
    return float(np.sum(0.5 * (f[1:] + f[:-1]) * dx))


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("dump")
    parser.add_argument("--expansion", type=float, default=0.18, help="volumetric expansion of the plate (1/K)")
    parser.add_argument("--png", default="quench.png")
    parser.add_argument("--max-difference", type=float, default=None,
                        help="fail when the tip at the last frame differs from beam theory by more than this "
                        "fraction")
    args = parser.parse_args()
    frames = read_frames(args.dump)
    times = frame_times(args.dump)
    first = frames[0][1]
    plate = first["type"] == 2
    column, layer, dx = columns_and_layers(first, plate)
    y0 = first["y"][plate]
    last_column = column == column.max()
    alpha_lin = args.expansion / 3.0
    rows = []
    for (step, f), t in zip(frames, times):
        measured = float((f["y"][plate][last_column] - y0[last_column]).mean())
        theory = tip_from_temperature(f["c_th"][plate], column, layer, y0, dx, alpha_lin)
        rows.append((t, measured, theory, float(f["c_th"][plate].mean())))
    rows = np.array(rows)
    t, measured, theory, plate_t = rows.T
    for row in rows[:: max(1, len(rows) // 6)]:
        off = f" ({100 * (row[1] - row[2]) / row[2]:+.1f} %)" if row[2] > 0 else ""
        print(f"quench: t = {row[0]:.3f} s: plate mean T {row[3]:.4f}, tip rise {row[1] * 1e3:.4f} mm, "
              f"beam theory {row[2] * 1e3:.4f} mm{off}")
    difference = (measured[-1] - theory[-1]) / theory[-1]
    print(f"quench: at t = {t[-1]:.3f} s the tip has risen {measured[-1] * 1e3:.4f} mm, beam theory with the "
          f"plate's temperatures {theory[-1] * 1e3:.4f} mm ({100 * difference:+.1f} %)")

    from sphplot import pyplot
    plt = pyplot()
    fig, (ax_scene, ax_tip) = plt.subplots(1, 2, figsize=(11, 4.2), gridspec_kw={"width_ratios": [1.3, 1]})
    last = frames[-1][1]
    plate_z = first["z"][plate]
    zmid = plate_z[np.argmin(np.abs(plate_z - np.median(plate_z)))]    # a layer of the plate
    x0, y0_all = first["x"], first["y"]
    in_tank = (x0 > 0) & (x0 < x0.max() - 3 * dx) & (y0_all > 0) & (y0_all < y0_all.max() - 3 * dx)
    shown = in_tank & (np.abs(first["z"] - zmid) < 0.5 * dx)
    fluid = shown & (last["type"] != 2)
    solid = shown & (last["type"] == 2)
    scale = 1e3
    im = ax_scene.scatter(last["x"][fluid] * scale, last["y"][fluid] * scale, c=last["c_th"][fluid], s=28,
                          cmap="coolwarm", vmin=0.0, vmax=1.0, marker="o")
    ax_scene.scatter(last["x"][solid] * scale, last["y"][solid] * scale, c=last["c_th"][solid], s=46,
                     cmap="coolwarm", vmin=0.0, vmax=1.0, marker="s", edgecolors="k", linewidths=0.6)
    ax_scene.quiver(last["x"][fluid] * scale, last["y"][fluid] * scale, last["vx"][fluid], last["vy"][fluid],
                    color="0.25", width=0.003)
    ax_scene.set_aspect("equal")
    ax_scene.set_xlabel("x (mm)")
    ax_scene.set_ylabel("y (mm)")
    ax_scene.set_title(f"t = {t[-1]:.2f} s: plate (squares) and liquid, T and velocity")
    fig.colorbar(im, ax=ax_scene, label="T", shrink=0.8)
    ax_tip.plot(t, measured * scale, "o-", ms=3, label="SPH: rise of the free end")
    ax_tip.plot(t, theory * scale, "k--", label="beam theory with the SPH temperatures")
    ax_tip.set_xlabel("t (s)")
    ax_tip.set_ylabel("tip rise (mm)")
    ax_tip.legend(loc="lower right", fontsize=8)
    ax_tip2 = ax_tip.twinx()
    ax_tip2.plot(t, plate_t, color="tab:red", lw=1)
    ax_tip2.set_ylabel("plate mean T", color="tab:red")
    fig.tight_layout()
    fig.savefig(args.png, dpi=120)
    print(f"wrote {args.png}")
    if args.max_difference is not None and not abs(difference) <= args.max_difference:
        print(f"quench: FAIL, tip differs from beam theory by {100 * difference:+.1f} % "
              f"(more than {100 * args.max_difference:.0f} %)")
        sys.exit(1)


if __name__ == "__main__":
    main()
