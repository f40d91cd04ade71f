"""Xu's Taylor bar (in.taylor): the bar's final length and mushroomed radius
against the published results of the same benchmark, and the temperature
of each particle against the heat of its own plastic work.

The benchmark (Wilkins and Guinan 1973, as set by Simo 1992: a copper bar
32.4 mm long, radius 3.2 mm, at 227 m/s against a rigid frictionless wall,
yield stress 400 MPa, linear hardening of modulus 100 MPa, at 80 us):
final radius of the impact end 7.12 mm (Simo 1992), 7.11 mm (Zienkiewicz
et al. 1998); finite-element runs of the same problem in the public
Taylor-bar benchmark of the Carina code (Sierra/SM's composite tetrahedron
and Carina's TET15 elements, converged) end at a radius of 7.22 to 7.23 mm
and a length of 21.42 to 21.48 mm.

Adiabatic heating (Xu, eq. 13): with linear hardening the flow stress at
plastic strain e is s0 + H e, and a particle whose plastic strain rose from
0 to e took the plastic work s0 e + H e^2 / 2 per unit volume, fwork of it
as heat: dT = fwork (s0 e + H e^2 / 2) / (rho0 cv) (rho0: the density at
which it was made; the plastic flow keeps the volume, the elastic
compression changes it by under 2 %).

The material and the bar's diameter are read from the run's log (the
'taylor: material' line of in.taylor; OUT/taylor-LABEL.dump was written
with the log OUT/log.taylor-LABEL, as run.sh names them). Writes a PNG (the
bar's final section coloured by temperature, and its length and radius
against time) and prints 'taylor:' lines.
With --converge (the dumps one scene at three or more spacings h), the
length and the radius extrapolated to h = 0: least-squares lines in h (the
artificial viscosity, the hourglass control and the half spacing added to
the outermost centres are all first order in h) through every spacing and
through the finest three; their difference is the extrapolation's
uncertainty.
usage: analyse.py DUMP [DUMP ...] [--png FILE] [--converge]
                  [--max-length-error F] [--max-radius-error F] [--max-heat-error F]
                  [--expect LENGTH RADIUS [--expect-within F]]
"""

import argparse
import os
import re
import sys

import numpy as np

from sphthermal_tools.dump import frame_times, read_frames

L_REFERENCE = (21.42, 21.48)   # mm, finite-element runs of the benchmark
R_REFERENCE = {"Simo (1992)": 7.12, "Zienkiewicz et al. (1998)": 7.11, "finite elements, converged": 7.23}
R_MEAN = float(np.mean(list(R_REFERENCE.values())))
L_MEAN = float(np.mean(L_REFERENCE))


def material(dump):
    """The 'taylor: material' line of the dump's log, as a dict of floats,
    and the particles across the bar (n) from its 'taylor: n' line."""
    folder, name = os.path.split(dump)
    log = os.path.join(folder, "log." + name.removesuffix(".dump"))
    with open(log) as f:
        text = f.read()
    line = re.search(r"^taylor: material (.*)$", text, re.M)
    across = re.search(r"^taylor: n (\d+) t", text, re.M)
    if line is None or across is None:
        sys.exit(f"analyse.py: no 'taylor: material' or 'taylor: n' line in {log}")
    words = line.group(1).split()
    m = {key: float(value) for key, value in zip(words[::2], words[1::2])}
    m["n"] = int(across.group(1))
    return m


def layer_spacing(first):
    """The spacing of the particles' layers along the bar, from the first frame."""
    z = np.unique(np.round(first["z"], 12))
    return float(np.min(np.diff(z)))


def shape(frame, dx, dz):
    """Length and mushroom radius (mm) to the particles' outer faces."""
    r = np.hypot(frame["x"], frame["y"])
    return 1e3 * (frame["z"].max() + 0.5 * dz), 1e3 * (r.max() + 0.5 * dx)


def heat_check(frame, m):
    """Largest difference between each plastic particle's temperature and the
    heat of its plastic work, in % of the largest temperature."""
    e = frame["c_ep"]
    predicted = m["fwork"] * (m["yield"] * e + 0.5 * m["hardening"] * e * e) / (m["rho0"] * m["cv"])
    plastic = e > 0.05
    error = np.abs(frame["c_th"][plastic] - predicted[plastic])
    return float(100 * error.max() / frame["c_th"].max()), float(frame["c_th"].max()), float(predicted.max())


# the final shape's measures, the band of their references and its mean (mm)
BANDS = (("length", L_REFERENCE, L_MEAN), ("radius", tuple(R_REFERENCE.values()), R_MEAN))


def finest_line(spacing, values):
    """The least-squares line in the spacing through the finest three points."""
    finest = np.argsort(spacing)[:3]
    return np.polyfit(np.asarray(spacing)[finest], np.asarray(values)[finest], 1)


def extrapolated(spacing, values):
    """The value at zero spacing of least-squares lines in the spacing through
    the finest three points and through every point, and their difference."""
    finest = finest_line(spacing, values)[1]
    every = np.polyfit(spacing, values, 1)[1]
    return finest, abs(finest - every)


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("dumps", nargs="+")
    parser.add_argument("--png", default="")
    parser.add_argument("--converge", action="store_true", help="extrapolate the shape to zero spacing")
    parser.add_argument("--max-length-error", type=float, default=None, help="fraction of the reference mean")
    parser.add_argument("--max-radius-error", type=float, default=None, help="fraction of the reference mean")
    parser.add_argument("--max-heat-error", type=float, default=None, help="percent of the largest temperature")
    parser.add_argument("--expect", type=float, nargs=2, default=None, metavar=("LENGTH", "RADIUS"),
                        help="the final length and radius (mm) a run at the same spacing gave")
    parser.add_argument("--expect-within", type=float, default=0.01, help="fraction of the expected values")
    args = parser.parse_args()

    runs = []
    bad = False
    for path in args.dumps:
        frames = read_frames(path)
        times = frame_times(path)
        first, last = frames[0][1], frames[-1][1]
        m = material(path)
        n = m["n"]
        dx, dz = m["diameter"] / n, layer_spacing(first)
        history = np.array([shape(f, dx, dz) for _, f in frames])
        length, radius = history[-1]
        heat, tmax, tpredicted = heat_check(last, m)
        dl = (length - L_MEAN) / L_MEAN
        dr = (radius - R_MEAN) / R_MEAN
        name = path.rsplit("/", 1)[-1].removesuffix(".dump").removeprefix("taylor-")
        print(f"taylor: ({name}) n {n} ({len(first['x'])} particles) t {1e6 * times[-1]:.1f} us: length {length:.3f} mm "
              f"({100 * dl:+.1f} % of {L_MEAN:.2f}), radius {radius:.3f} mm ({100 * dr:+.1f} % of {R_MEAN:.2f}); "
              f"particles lost {len(first['x']) - len(last['x'])}")
        print(f"taylor: ({name}) n {n} heat of the plastic work: largest temperature {tmax:.1f} K (predicted {tpredicted:.1f} K), "
              f"largest difference {heat:.2f} % of it")
        if len(last["x"]) != len(first["x"]):
            bad = True
        if args.max_length_error is not None and abs(dl) > args.max_length_error:
            print(f"taylor: FAIL, length off by more than {args.max_length_error}")
            bad = True
        if args.max_radius_error is not None and abs(dr) > args.max_radius_error:
            print(f"taylor: FAIL, radius off by more than {args.max_radius_error}")
            bad = True
        if args.expect is not None:
            for name, value, expected in zip(("length", "radius"), (length, radius), args.expect):
                if not abs(value - expected) <= args.expect_within * expected:
                    print(f"taylor: FAIL, {name} {value:.3f} mm, not within {args.expect_within} of {expected} mm")
                    bad = True
        if args.max_heat_error is not None and not heat < args.max_heat_error:
            print(f"taylor: FAIL, temperatures off the plastic work's heat by more than {args.max_heat_error} %")
            bad = True
        runs.append((n, np.array(times) * 1e6, history, last))

    if args.converge:
        if len(runs) < 3:
            sys.exit("analyse.py: --converge needs three or more spacings")
        spacing = [1.0 / n for n, *_ in runs]
        shapes = np.array([history[-1] for _, _, history, _ in runs])
        names = ", ".join(str(n) for n, *_ in runs)
        for k, (name, band, mean) in enumerate(BANDS):
            value, uncertainty = extrapolated(spacing, shapes[:, k])
            print(f"taylor: {name} at zero spacing (lines in the spacing through {names} across and through the finest three) "
                  f"{value:.3f} mm +- {uncertainty:.3f} mm ({100 * (value - mean) / mean:+.1f} % of {mean:.2f}; "
                  f"references {min(band):.2f} to {max(band):.2f} mm)")

    if args.png:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        panels = 4 if args.converge else 3
        fig, axes = plt.subplots(1, panels, figsize=(4.4 * panels, 4.6))
        n, _, _, last = runs[-1]
        # every particle at its distance from the axis, on the side of its x:
        # the bar's silhouette, the hottest drawn last
        side = np.where(last["x"] < 0, -1.0, 1.0) * np.hypot(last["x"], last["y"])
        order = np.argsort(last["c_th"])
        sc = axes[0].scatter(1e3 * side[order], 1e3 * last["z"][order], c=last["c_th"][order], s=6, cmap="inferno")
        fig.colorbar(sc, ax=axes[0], label="temperature rise (K)")
        axes[0].set_aspect("equal")
        axes[0].set_xlabel("distance from the axis (mm)")
        axes[0].set_ylabel("z (mm)")
        axes[0].set_title(f"{runs[-1][1][-1]:.0f} us, {n} across")
        for n, t, history, _ in runs:
            axes[1].plot(t, history[:, 0], "o-", ms=3, label=f"{n} across")
            axes[2].plot(t, history[:, 1], "o-", ms=3, label=f"{n} across")
        axes[1].axhspan(*L_REFERENCE, color="0.8", label="finite elements")
        for name, value in R_REFERENCE.items():
            axes[2].axhline(value, ls=":", lw=1, color="k")
        axes[2].axhspan(min(R_REFERENCE.values()), max(R_REFERENCE.values()), color="0.8", label="published")
        axes[1].set_ylabel("length (mm)")
        axes[2].set_ylabel("radius of the mushroom (mm)")
        for ax in axes[1:3]:
            ax.set_xlabel("t (us)")
            ax.legend(fontsize=8)
        if args.converge:
            # the final shape against the spacing (in units of the bar's
            # diameter), the lines through the finest three to zero spacing
            ax = axes[3]
            h = np.array(spacing)
            line = np.linspace(0.0, h.max(), 20)
            for k, ((name, band, mean), colour) in enumerate(zip(BANDS, ("C0", "C3"))):
                scale = 1.0 / mean
                ax.plot(h, scale * shapes[:, k], "o", color=colour, label=f"{name}")
                ax.plot(line, scale * np.polyval(finest_line(h, shapes[:, k]), line), "--", color=colour, lw=1)
                ax.axhspan(scale * min(band), scale * max(band), color=colour, alpha=0.15)
            ax.set_xlim(0.0, 1.05 * h.max())
            ax.set_xlabel("spacing / diameter")
            ax.set_ylabel("final shape / the references' mean")
            ax.legend(fontsize=8)
        fig.tight_layout()
        fig.savefig(args.png, dpi=110)
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
