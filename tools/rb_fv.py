#!/usr/bin/env python3
"""Fine-grid reference for steady 2-D Rayleigh-Benard convection above onset.

A Boussinesq fluid layer of height H between no-slip isothermal plates,
theta = 1 on the bottom y = 0 and theta = 0 on the top y = 1, periodic in x
with width W (default 2H). Units H, alpha/H, H^2/alpha,
theta = (T - T_cold)/(T_hot - T_cold):

    div u = 0
    du/dt + (u.grad)u = -grad p + Pr lap u + Ra Pr theta e_y
    dtheta/dt + u.grad theta = lap theta

The steady solution sought is one pair of counter-rotating rolls of
wavelength W. It is mirror-symmetric about the planes between the rolls
(u = 0, dv/dx = 0, dtheta/dx = 0 there), so it equals one roll in a cell of
width W/2 with free-slip, adiabatic side walls. Solving in that cell removes
the periodic problem's translation invariance, which would leave Newton's
Jacobian singular. The roll rises at x = 0 and sinks at x = W/2, as the
perturbation cos(2 pi x / W) sin(pi y) of the SPH example
(examples/convection-rayleigh-benard) grows.

Method: cavity_fv.py's staggered finite volumes and Newton solver (its Grid
with heated plates and free-slip sides): second order in space, the exact
Jacobian, a sparse LU per iteration. The conduction state is a solution too
and draws Newton's iteration from a mere guess, so the start is a small roll
marched in time (BDF2, cavity_fv.march) on a 16-cell grid to t = 0.3 and
then Newton; the grids n_start, 2 n_start, ..., n follow by grid sequencing.
Above the box's onset (rb_linear.py) the result must have Nu > 1. converge()
extrapolates over three or more grids (Richardson, observed order) and
states the error of the extrapolated values.

Quantities: Nu, the mean heat flux through the bottom and through the top
plate (the exact discrete wall fluxes, equal to round-off at convergence);
u_max, the largest u on the roll's vertical centre line x = W/4; v_max, the
largest v on the mid-plane y = 1/2 (at the rising plume, x = 0); u_rms, the
root mean square speed over the layer; psi_max, the largest stream function
(the volume flux of one roll).

As a module: solve(ra, pr=0.71, n=64, width=2.0, ...) returns a dict (see
solve); converge(ra, pr, grids=(32, 64, 128), ...) solves on a doubling
sequence of grids and extrapolates; read_results(path) reads the
extrapolated values and their errors back from a --converge --out file
(tools/rb_fv_results.txt). As a script, see --help.
"""

import argparse
import math
import sys
import time

import numpy as np

import rb_linear
from cavity_fv import Grid, NoConvergence, _chain, _max_poly, extrapolate, march, newton

QUANTITIES = ("nu", "umax", "vmax", "urms", "psi_max")
LABELS = {"nu": "Nu", "umax": "u_max", "vmax": "v_max", "urms": "u_rms", "psi_max": "psi_max"}
CONVERGE_RA = (5e3, 1e4, 2e4, 3e4)
# the stated error of an extrapolation is this times its order-2 correction;
# 3 covers the shift from the 32-64-128 to the 64-128-256 extrapolation at
# Ra 1e4 and 2e4 (rb_fv.md)
SAFETY = 3.0
N_MARCH = 16          # cells across the layer of the grid the start is marched on


def cell(n, width=2.0, stretch=1.5, stretch_x=0.0):
    """The half-wavelength cell [0, W/2] x [0, 1] with n cells across the
    layer; x is uniform by default (the periodic layer has no wall there)."""
    nx = int(round(n * width / 2.0))
    if abs(nx - n * width / 2.0) > 1e-9 or nx % 2:
        raise ValueError("n W / 2 must be an even integer (the roll's centre line is a face)")
    return Grid(n, stretch, heated="plates", nx=nx, width=width / 2.0, stretch_x=stretch_x,
                slip_sides=True)


def onset(width=2.0):
    """Critical Ra of the box's mode (wavelength W) from linear theory."""
    return rb_linear.rayleigh_at(2.0 * math.pi / width)


def roll(grid, amplitude, ra, pr):
    """Conduction (with its hydrostatic pressure) plus one roll rising at
    x = 0: theta' = A cos(k x) sin(pi y) and the stream function of
    v = (k^2 + pi^2) A cos(k x) sin^2(pi y), the linear mode's balance
    v = -lap theta' at its size; k = pi / (W/2)."""
    ax, ay = grid.ax, grid.ay
    k = math.pi / ax.length
    vel = (k * k + math.pi ** 2) * amplitude
    q = grid.conduction()
    o = grid.offsets
    # the conduction state's hydrostatic pressure: only the roll is out of balance
    p = ra * pr * (ay.c - 0.5 * ay.c ** 2)
    q[o[2]:o[3]] = np.outer(np.ones(grid.nx), p - p[0]).ravel()
    X, Y = np.meshgrid(ax.f[1:-1], ay.c, indexing="ij")       # u faces
    q[o[0]:o[1]] = (-vel / k * np.sin(k * X) * math.pi * np.sin(2.0 * math.pi * Y)).ravel()
    X, Y = np.meshgrid(ax.c, ay.f[1:-1], indexing="ij")       # v faces
    q[o[1]:o[2]] = (vel * np.cos(k * X) * np.sin(math.pi * Y) ** 2).ravel()
    X, Y = np.meshgrid(ax.c, ay.c, indexing="ij")
    q[o[3]:] += (amplitude * np.cos(k * X) * np.sin(math.pi * Y)).ravel()
    return q


def _start(ra, pr, n, width, stretch, stretch_x, tol, verbose):
    """A solution on the convecting branch of a coarse grid of n cells: from
    a small roll, BDF2 in time to t = 0.3, then Newton. Newton from a guess
    alone is drawn to the conduction state, which solves every Ra exactly;
    the march follows the roll's growth instead (above onset the conduction
    state is unstable). dt = 2 / sqrt(Ra) keeps the step near a third of the
    turnover time (v_max is about 0.3 sqrt(Ra))."""
    grid = cell(n, width, stretch, stretch_x)
    q = roll(grid, 0.1, ra, pr)
    if ra > 0:
        q = march(grid, q, ra, pr, 0.3, min(0.05, 2.0 / math.sqrt(ra)), tol)
    q, _ = newton(grid, q, ra, pr, tol=tol, verbose=verbose)
    return grid, q


def analyse(grid, q, ra, pr, width):
    """The result dict of a solution q on grid (see solve)."""
    u, v, p, t = grid.split(q)
    ax, ay, nx, ny = grid.ax, grid.ay, grid.nx, grid.n
    length = ax.length
    nu_local = (1.0 - t[:, 0]) / ay.h[0]
    nu_top = t[:, -1] / ay.h[-1]
    # u on the centre line x = W/4 (a face: nx even), with the plates' zeros
    yu = np.concatenate(([0.0], ay.c, [1.0]))
    u_mid = np.concatenate(([0.0], u[nx // 2 - 1, :], [0.0]))
    umax, y_umax = _max_poly(yu, u_mid)
    # v on y = 1/2 (a face: n even), mirrored about x = 0 so that the quartic
    # sees the plume's centre from both sides
    v_mid = v[:, ny // 2 - 1]
    vmax, x_vmax = _max_poly(np.concatenate((-ax.c[::-1], ax.c)), np.concatenate((v_mid[::-1], v_mid)))
    urms = math.sqrt((np.sum(grid.area_u * u.ravel() ** 2) + np.sum(grid.area_v * v.ravel() ** 2))
                     / grid.area_c.sum())
    # stream function at the nodes, u = dpsi/dy, v = -dpsi/dx, psi = 0 on the walls
    psi = np.zeros((nx + 1, ny + 1))
    psi[1:-1, 1:] = np.cumsum(u * ay.d, axis=1)
    # the two energy balances: <v theta> = Nu - 1 (exact in the discrete
    # scheme, it conserves heat) and <|grad u|^2> = Ra (Nu - 1) (work of the
    # buoyancy = viscous dissipation; the scheme's own viscous operator)
    area = grid.area_c.sum()
    ur, vr, tr = u.ravel(), v.ravel(), t.ravel()
    vtheta = float(np.sum(grid.area_v * vr * (grid.t_to_v_face @ tr)) / area)
    dissipation = float(-(ur @ (grid.u_visc @ ur) + vr @ (grid.v_visc @ vr)) / area)
    return {
        "ra": float(ra), "pr": float(pr), "n": int(ny), "nx": int(nx), "width": float(width),
        "stretch": float(grid.stretch),
        "nu": float(np.sum(nu_local * ax.d) / length),
        "nu_bottom": float(np.sum(nu_local * ax.d) / length),
        "nu_top": float(np.sum(nu_top * ax.d) / length),
        "umax": umax, "y_umax": y_umax, "vmax": vmax, "x_vmax": x_vmax, "urms": urms,
        "psi_max": float(np.abs(psi).max()), "vtheta": vtheta, "dissipation": dissipation,
        "bottom": {"x": ax.c.copy(), "nu_local": nu_local},
        "centres": {"x": ax.c.copy(), "y": ay.c.copy(), "theta": t.copy(),
                    "u": (grid.u_to_c @ u.ravel()).reshape(nx, ny),
                    "v": (grid.v_to_c @ v.ravel()).reshape(nx, ny), "p": p.copy()},
    }


def solve(ra, pr=0.71, n=64, width=2.0, stretch=1.5, stretch_x=0.0, tol=1e-9, n_start=32,
          verbose=False, _grids=None):
    """Steady two-roll solution at Rayleigh number ra, Prandtl number pr,
    periodic width `width` (units H), n cells across the layer.

    Solved in the cell [0, W/2] x [0, 1] (one roll, free-slip adiabatic
    sides; the full period is its mirror image), on n W/2 x n cells; stretch
    and stretch_x: the b of cavity_fv's tanh map in y and x (0: uniform).
    Below the onset of the box the result is the conduction state. Returns a
    dict: ra, pr, n, nx, width, stretch,
      nu (= nu_bottom), nu_bottom, nu_top: mean Nusselt number of the plates
      umax, y_umax: largest u on the roll's centre line x = W/4
      vmax, x_vmax: largest v on y = 1/2 (x_vmax = 0: the rising plume)
      urms: sqrt of the mean of u^2 + v^2 over the layer
      psi_max: largest stream function, the volume flux of one roll
      vtheta: mean of v theta over the layer (= Nu - 1 to round-off)
      dissipation: mean of |grad u|^2 (= Ra (Nu - 1) up to the grid error)
      bottom: {x, nu_local}  -dtheta/dy on y = 0 at the cell-centre x
      centres: {x, y, theta, u, v, p}  fields at the cell centres, [i_x, j_y]
    Raises NoConvergence if Newton fails or a solution above onset has lost
    its roll (Nu not above 1)."""
    if pr <= 0 or ra < 0:
        raise ValueError("need Pr > 0 and Ra >= 0")
    ra_c = onset(width)
    chain = _chain(n, n_start)
    coarse, qc = _start(ra, pr, min(N_MARCH, chain[0]), width, stretch, stretch_x, tol, verbose)
    for m in chain:
        grid = cell(m, width, stretch, stretch_x)
        q, _ = newton(grid, grid.prolong(coarse, qc), ra, pr, tol=tol, verbose=verbose)
        coarse, qc = grid, q
        if _grids is not None:
            _grids[m] = analyse(grid, q, ra, pr, width)
    res = analyse(grid, q, ra, pr, width)
    # well above onset of the continuum the discrete onset is passed too
    if ra > 1.05 * ra_c and not res["nu"] > 1.0 + 1e-6:
        raise NoConvergence(f"Ra {ra:g}: converged on the conduction state (Nu {res['nu']:.6f})")
    return res


def converge(ra, pr=0.71, grids=(32, 64, 128), width=2.0, stretch=1.5, stretch_x=0.0, tol=1e-9,
             verbose=False):
    """Solve on a doubling sequence of grids (one chain, grid sequencing) and
    extrapolate. Returns (results by n, {quantity: (extrapolated value,
    observed order, stated error)}). The extrapolation is Richardson's over
    the three finest grids a, b, c (cavity_fv.extrapolate). Its stated error
    is SAFETY times the change made by extrapolating with the observed
    instead of the nominal order 2, and with four or more grids at least the
    change from the extrapolation over the next coarser three; where the
    observed order is not between 1 and 4 it is |c - b|, the last change."""
    grids = sorted(grids)
    if len(grids) < 3 or any(b != 2 * a for a, b in zip(grids, grids[1:])):
        raise ValueError("need at least three grids, each twice the last")
    res = {}
    solve(ra, pr, grids[-1], width, stretch, stretch_x, tol, n_start=grids[0], verbose=verbose, _grids=res)
    table = {}
    for key in QUANTITIES:
        a, b, c = (res[m][key] for m in grids[-3:])
        extra, order = extrapolate(a, b, c)
        if 1.0 < order < 4.0:
            err = SAFETY * abs(extra - (c + (c - b) / 3.0))
            if len(grids) > 3:
                err = max(err, abs(extra - extrapolate(*(res[m][key] for m in grids[-4:-1]))[0]))
        else:
            err = abs(c - b)
        table[key] = (extra, order, err)
    return res, table


def converge_report(ra, pr, res, table, width, stretch, stretch_x):
    """The text of a --converge run at one Ra."""
    grids = sorted(res)
    out = [f"Ra = {ra:g}, Pr = {pr:g}, W = {width:g} H (cell W/2 x H, n x n W/2 cells, stretch "
           f"{stretch:g} in y, {stretch_x:g} in x)",
           f"  {'n':>5s} " + " ".join(f"{LABELS[k]:>13s}" for k in QUANTITIES) + f" {'Nu top-bottom':>14s}"]
    for m in grids:
        r = res[m]
        out.append(f"  {m:5d} " + " ".join(f"{r[k]:13.7f}" for k in QUANTITIES)
                   + f" {r['nu_top'] - r['nu_bottom']:14.1e}")
    out.append(f"  {'extrap.':>5s} " + " ".join(f"{table[k][0]:13.7f}" for k in QUANTITIES))
    out.append(f"  {'error':>5s} " + " ".join(f"{table[k][2]:13.1e}" for k in QUANTITIES)
               + "   (stated absolute error of the extrapolated value)")
    out.append(f"  {'order':>5s} " + " ".join(f"{table[k][1]:13.2f}" for k in QUANTITIES)
               + "   (observed, three finest grids)")
    out.append("  relative error of each grid, value / extrapolated - 1:")
    for m in grids:
        out.append(f"  {m:5d} " + " ".join(f"{res[m][k] / table[k][0] - 1.0:+13.2e}" for k in QUANTITIES))
    return "\n".join(out)


def read_results(path):
    """The extrapolated values of a --converge --out file:
    {(ra, pr, width): {quantity: (value, stated error)}}, quantity in QUANTITIES."""
    out, key = {}, None
    with open(path) as f:
        for line in f:
            words = line.split()
            if line.startswith("Ra = "):
                head = dict(part.split(" = ") for part in line.split(" (")[0].split(", "))
                key = (float(head["Ra"]), float(head["Pr"]), float(head["W"].split()[0]))
            elif words and words[0] == "extrap.":
                values = [float(w) for w in words[1:1 + len(QUANTITIES)]]
            elif words and words[0] == "error" and key is not None:
                errors = [float(w) for w in words[1:1 + len(QUANTITIES)]]
                out[key] = {k: (v, e) for k, v, e in zip(QUANTITIES, values, errors)}
    return out


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--ra", type=float, nargs="+",
                   help="Rayleigh number(s) (default with --converge: 5e3 1e4 2e4 3e4)")
    p.add_argument("--pr", type=float, default=0.71, help="Prandtl number (default 0.71)")
    p.add_argument("--n", type=int, default=64, help="cells across the layer (default 64)")
    p.add_argument("--width", type=float, default=2.0, help="periodic width W / H, one roll pair (default 2)")
    p.add_argument("--stretch", type=float, default=1.5,
                   help="clustering b of the tanh map towards the plates, 0 = uniform (default 1.5)")
    p.add_argument("--stretch-x", type=float, default=0.0,
                   help="the same in x, towards the plumes' centres (default 0, uniform)")
    p.add_argument("--tol", type=float, default=1e-9, help="Newton stopping tolerance (default 1e-9)")
    p.add_argument("--converge", action="store_true",
                   help="solve on the grids of --grids, extrapolate, print the error of each grid")
    p.add_argument("--grids", type=int, nargs="+", default=[32, 64, 128],
                   help="the doubling sequence of --converge (default 32 64 128)")
    p.add_argument("--out", help="with --converge: also write the report to this file")
    p.add_argument("--verbose", action="store_true", help="print the Newton iterations to stderr")
    args = p.parse_args()

    ras = args.ra or (list(CONVERGE_RA) if args.converge else None)
    if not ras:
        p.error("--ra is required without --converge")
    if not args.converge:
        for ra in ras:
            t0 = time.time()
            r = solve(ra, args.pr, args.n, args.width, args.stretch, args.stretch_x, args.tol,
                      verbose=args.verbose)
            print(f"Ra = {ra:g}, Pr = {args.pr:g}, W = {args.width:g} H, n = {r['n']} "
                  f"(cell {r['nx']} x {r['n']}, stretch {args.stretch:g})")
            print(f"Nu bottom plate   = {r['nu_bottom']:.6f}")
            print(f"Nu top plate      = {r['nu_top']:.6f}")
            print(f"u_max on x = W/4  = {r['umax']:.5f} at y = {r['y_umax']:.5f}")
            print(f"v_max on y = 1/2  = {r['vmax']:.5f} at x = {r['x_vmax']:.5f}")
            print(f"u_rms             = {r['urms']:.5f}")
            print(f"psi_max           = {r['psi_max']:.5f}")
            print(f"# {time.time() - t0:.1f} s")
        return 0

    report = [f"# rb_fv.py --converge --grids {' '.join(map(str, args.grids))} (Pr {args.pr:g}, "
              f"W {args.width:g} H): steady two-roll Rayleigh-Benard reference, see tools/rb_fv.md"]
    for ra in ras:
        t0 = time.time()
        res, table = converge(ra, args.pr, args.grids, args.width, args.stretch, args.stretch_x, args.tol,
                              verbose=args.verbose)
        text = converge_report(ra, args.pr, res, table, args.width, args.stretch, args.stretch_x)
        text += f"\n  # {time.time() - t0:.1f} s for the chain {'-'.join(map(str, sorted(args.grids)))}"
        print(text, flush=True)
        report.append(text)
    if args.out:
        with open(args.out, "w") as f:
            f.write("\n".join(report) + "\n")
    return 0


if __name__ == "__main__":
    sys.exit(main())
