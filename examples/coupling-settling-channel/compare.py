"""The settling disc of in.channel against the quasi-steady Stokes drag of
tools/cylinder_stokes.py: at each height of the disc's centre the reference
terminal velocity is

    U(y) = (rho_s - rho_f) g pi R^2 / (mu C(y)),

with C(y) the drag per unit length and unit mu U on a cylinder of radius R
(the disc's equal-area radius) in the closed channel of the run (walls at
the fluid's edges, x = 0, W and y = 0, H), computed on two finite-element
meshes and extrapolated. Creeping flow: the run's Reynolds number is printed
(about 0.02), and the drag's inertial correction is of second order in it
(the channel is symmetric fore and aft of the disc).

    compare.py RUN [RUN ...] [--skip 0.05] [--until 0.1] [--max-error 0.1] [--max-drift 0.015]
               [--max-body 0.8] [--png settling.png]

RUN is the prefix of a run: <RUN>.series (t, x, y, vx, vy, spin of the disc)
and log.<RUN> (its 'disc of' line). Compared from --skip seconds after the
release (the slowest mode of the channel's flow decays as exp(-t / 16 ms):
(2 l)^2 / (pi^2 nu)) up to --until (default: the end); exits 1 when the
largest relative velocity error of the last run exceeds --max-error, or
when its error changes by more than --max-drift between the first and the
last fifth of the window (the speed must settle at a terminal value), or
when the mean error of any run, less the lattice error of the viscous
term (lattice_viscosity_factor), exceeds --max-body times (dx / R)^2.
"""

import argparse
import math
import re
import sys

import numpy as np

import cylinder_stokes as cs
import wendland2d

# the materials and the geometry of in.channel
RHO_S, RHO_F, MU, G = 7850.0, 970.0, 10.0, 9.81
# its kernel: Wendland C2 with h = 1.3 dx; the pair style's eta = 0.01 h
H_OVER_DX, ETA_OVER_H = 1.3, 0.01


def lattice_viscosity_factor(h_over_dx=H_OVER_DX, eta_over_h=ETA_OVER_H):
    """The viscous term of pair sph/harmonic/visc (adami form; morris is the
    same for one fluid) on a square lattice, applied to u = (0, x^2), over
    the exact mu laplace(u) = (0, 2 mu): sum_j V (u_i - u_j) 2 (dW/dr) r /
    (r^2 + eta^2) / 2 = -sum_j V x_ij^2 (dW/dr) r / (r^2 + eta^2) in units
    of dx (V = 1). The viscosity the particles feel is this factor times mu,
    whatever the spacing: a lattice error, not a discretisation error that
    refinement at fixed h / dx removes."""
    h = h_over_dx
    n = int(math.ceil(2.0 * h)) + 1
    i = np.arange(-n, n + 1, dtype=float)
    x, y = np.meshgrid(i, i)
    r = np.hypot(x, y)
    inside = (r > 0.0) & (r < 2.0 * h)
    rr = r[inside]
    dwdr = wendland2d.dwdr(rr, h)
    return float(-np.sum(x[inside] ** 2 * dwdr * rr / (rr * rr + (eta_over_h * h) ** 2)))


def read_run(prefix):
    with open("log." + prefix) as f:
        text = f.read()
    m = re.search(r"disc of (\d+) particles, equal-area radius R ([0-9.eE+-]+) m, dx ([0-9.eE+-]+) m, "
                  r"channel ([0-9.eE+-]+) x ([0-9.eE+-]+) m", text)
    if not m:
        sys.exit(f"compare.py: no 'disc of' line in log.{prefix}")
    data = np.loadtxt(prefix + ".series")
    return {"name": prefix, "particles": int(m.group(1)), "R": float(m.group(2)), "dx": float(m.group(3)),
            "W": float(m.group(4)), "H": float(m.group(5)), "t": data[:, 1] - data[0, 1], "x": data[:, 2],
            "y": data[:, 3], "vx": data[:, 4], "vy": data[:, 5], "spin": data[:, 6]}


def reference_speed(run, heights):
    """Quasi-steady terminal speed at each centre height (a few heights
    computed, quadratic in between), and the error of the drag's
    extrapolation."""
    R, l, H = run["R"], 0.5 * run["W"], run["H"]
    ys = np.linspace(min(heights), max(heights), 3)
    coeff, errors = [], []
    for y in ys:
        outer = cs.Channel(l / R, below=y / R, above=(H - y) / R)
        _, C, err, _ = cs.drag_converged(1.0, outer, 1.0 / 8, 1.0 / 3, levels=2)
        coeff.append(C)
        errors.append(err / C)
    fit = np.polyfit(ys, coeff, 2)
    drive = (RHO_S - RHO_F) * G * math.pi * R * R
    return drive / (MU * np.polyval(fit, heights)), max(errors), coeff


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("runs", nargs="+")
    ap.add_argument("--skip", type=float, default=0.05)
    ap.add_argument("--until", type=float, default=math.inf)
    ap.add_argument("--max-error", type=float)
    ap.add_argument("--max-drift", type=float)
    ap.add_argument("--max-body", type=float)
    ap.add_argument("--png")
    args = ap.parse_args()
    results = []
    failed_body = False
    lattice_factor = lattice_viscosity_factor()
    for prefix in args.runs:
        run = read_run(prefix)
        window = (run["t"] >= args.skip) & (run["t"] <= args.until)
        if window.sum() < 2:
            sys.exit(f"compare.py: {prefix}: fewer than two samples after {args.skip} s")
        U, ref_err, coeff = reference_speed(run, run["y"][window])
        speed = -run["vy"][window]
        rel = speed / U - 1.0
        Re = RHO_F * float(np.max(speed)) * 2.0 * run["R"] / MU
        worst = float(np.max(np.abs(rel)))
        fifth = max(1, len(rel) // 5)
        drift = float(np.mean(rel[-fifth:]) - np.mean(rel[:fifth]))
        # the error less that of the lattice viscosity: the body's own
        # discretisation error, (dx / R)^2 times this
        body = float(np.mean((1.0 + rel) * lattice_factor - 1.0))
        n = run["R"] / run["dx"]
        print(f"{prefix}: {run['particles']} particles, R = {run['R']:.6g} m ({n:.2f} dx), l/R = "
              f"{0.5 * run['W'] / run['R']:.4f}, Re = {Re:.3f}; drag/(mu U) {coeff[0]:.5f} .. {coeff[-1]:.5f} "
              f"(reference error {ref_err:.1e})")
        print(f"  t in [{args.skip}, {min(args.until, run['t'][-1]):.3g}] s: fell {run['y'][window][0] - run['y'][window][-1]:.4e} m; speed {speed[0]:.5e} .. "
              f"{speed[-1]:.5e} m/s against {U[0]:.5e} .. {U[-1]:.5e}: error {rel[0]:+.4f} .. {rel[-1]:+.4f}, "
              f"largest {worst:.4f}, drift {drift:+.4f}; |x - W/2| <= {np.max(np.abs(run['x'] - 0.5 * run['W'])):.1e} m, "
              f"|spin| <= {np.max(np.abs(run['spin'])):.1e} 1/s")
        print(f"  mean error {np.mean(rel):+.4f}; with the lattice's viscosity "
              f"{lattice_factor:.4f} mu: {body:+.4f} = {body * n * n:.3f} (dx/R)^2")
        results.append((run, window, U, rel, worst, drift))
        if args.max_body is not None and abs(body) > args.max_body / (n * n):
            print(f"FAIL: {prefix}: the error less the lattice's, {body:+.4f}, is above "
                  f"{args.max_body} (dx/R)^2 = {args.max_body / (n * n):.4f}")
            failed_body = True
    if args.png:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(10, 4))
        for run, window, U, rel, _, _ in results:
            label = f"SPH, R = {run['R'] / run['dx']:.2f} dx"
            line, = ax1.plot(run["t"], -run["vy"] * 1e3, label=label)
            ax1.plot(run["t"][window], U * 1e3, "--", color=line.get_color())
            ax2.plot(run["t"][window], rel * 100, color=line.get_color(), label=label)
        ax1.set_xlabel("t after release (s)")
        ax1.set_ylabel("settling speed (mm/s)")
        ax1.set_title("disc in a closed channel; dashed: Stokes reference")
        ax1.legend()
        ax2.axhline(0.0, color="k", lw=0.5)
        ax2.set_xlabel("t after release (s)")
        ax2.set_ylabel("speed error (%)")
        ax2.legend()
        fig.tight_layout()
        fig.savefig(args.png, dpi=110)
        print(f"wrote {args.png}")
    status = 1 if failed_body else 0
    if args.max_error is not None and results[-1][4] > args.max_error:
        print(f"FAIL: largest relative error {results[-1][4]:.4f} above {args.max_error}")
        status = 1
    if args.max_drift is not None and abs(results[-1][5]) > args.max_drift:
        print(f"FAIL: the error drifts by {results[-1][5]:+.4f} (more than {args.max_drift}): no terminal speed")
        status = 1
    return status


if __name__ == "__main__":
    sys.exit(main())
