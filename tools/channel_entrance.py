#!/usr/bin/env python3
"""Reference for laminar developing flow in a 2-D plane channel.

The entrance problem: steady incompressible Navier-Stokes in the channel
0 < x < L, 0 < y < H between no-slip walls y = 0 and y = H that start at
the inlet x = 0. Units H, the mean speed U, rho U^2; Re = U H / nu:

    div u = 0,    (u.grad)u = -grad p + (1/Re) lap u

Inlet x = 0: u = u_in(y), v = 0, with u_in = 1 ("uniform", also in the
wall corners: the standard entrance problem, singular there) or
u_in = 6 y (1 - y) ("parabolic", Poiseuille's profile, which must stay).
Outlet x = L: du/dx = dv/dx = 0 and p = 0 (traction-free for developed
flow); L = 10 by default, long enough that x <= 6 does not feel it
(channel_entrance.md: the centre speed on x <= 6 changes by less than 1e-9
when the outlet moves from L = 10 to 15).

Method: finite volumes on a staggered (MAC) grid of nx x ny cells, u on the
vertical faces (the inlet face carries u_in, the outlet face x = L is an
unknown with a half control volume), v on the horizontal faces, p at the
cell centres; arrays indexed [i_x, j_y]. The faces in x are
x_i = X(i/nx), X(s) = L (exp(b s) - 1)/(exp(b) - 1) (b = --stretch,
0 uniform): the cells grow geometrically from the inlet, where the corners
are singular and the flow develops, to the outlet, where it is developed
and barely depends on x; b = 3 makes the first cell 0.16 and the last
3.2 times L/nx (default nx = 4 ny: the same accuracy as a uniform grid of
10 ny, see channel_entrance.md). In y the map of cavity_fv.py (tanh, clustered at both
walls, --stretch-y, default 0: uniform). Central (linear) interpolation for
every convective flux, conservative, with mass fluxes that satisfy the
discrete continuity of the momentum control volumes; two-point diffusive
fluxes, with the half cell next to a wall and at the inlet. The inlet values
are the cell means of u_in, so that the flow rate is exactly 1 at every x
(to round-off). At the outlet face the momentum flux is u^2 (no pressure,
no viscous stress), v is carried out at its last-cell value. Second order
in space on the fixed maps (Richardson extrapolation over ny/4, ny/2, ny,
see channel_entrance.md; order 1.6 - 1.8 within 0.25 H of the inlet, where
the singular corners pollute). All unknowns coupled (u, v, p; the outlet
condition fixes the level of p), solved by Newton's method with the exact
Jacobian and a sparse LU (scipy SuperLU) per iteration, with a backtracking
line search, from Poiseuille's flow (the coarser grid's solution when
solving a sequence; continuation in Re should Newton fail); iteration stops when the update is below tol relative
to the largest speed.

Quantities: the centre speed u_c(x) on y = 1/2 (the cubic through the four
cell centres nearest the centre line; along x the cubic through the four
nearest faces), the development length L_99 where u_c first reaches
0.99 x 1.5 (root of that cubic), the pressure gradient of the developed
part, -dp/dx from the section-mean pressure over --developed (default
3 to 6), against Poiseuille's 12/Re, the flow rate at every face, and the
profile's largest departure from 6 y (1 - y) at given x.

As a module: solve(re, inflow="uniform", nx=320, ny=80, length=10, ...)
returns a dict with x (the faces), u_c (centre speed there), l99, ...;
centre_speed(result, xs) interpolates u_c at any x; richardson(re, ...)
solves on ny/4, ny/2, ny and extrapolates; outflow_check(re, ...) compares
the outlet at L with one further downstream on the same grid. As a script,
see --help.
"""

import argparse
import math
import sys
import time

import numpy as np
import scipy.sparse as sp
from scipy.interpolate import RegularGridInterpolator
from scipy.optimize import brentq

from cavity_fv import Axis, NoConvergence, damped_newton, extrapolate

U_C_DEVELOPED = 1.5          # Poiseuille's centre speed / U
STATIONS = (0.1, 0.25, 0.5, 0.75, 1.0, 1.5, 2.0, 3.0)     # x / H of the summary line
RICHARDSON_STATIONS = (0.25, 0.5, 1.0, 2.0)


def durst(re):
    """Development length L/H of a plane channel, the correlation of Durst,
    Ray, Unsal & Bayoumi (2005), J. Fluids Eng. 127, 1154-1160."""
    return (0.631 ** 1.6 + (0.0442 * re) ** 1.6) ** (1.0 / 1.6)


def x_faces(nx, length=10.0, stretch=3.0):
    """Faces 0..nx of the geometric map X(s) = L (e^(b s) - 1)/(e^b - 1)."""
    s = np.arange(nx + 1) / nx
    if stretch > 0:
        f = length * np.expm1(stretch * s) / math.expm1(stretch)
    else:
        f = length * s
    f[0], f[-1] = 0.0, length
    return f


def extended_faces(nx, length, stretch, factor=1.5):
    """The faces of x_faces(nx, length, stretch) continued along the same
    map, by whole cells, to at least factor x length (the same grid up to
    L, an outlet further downstream)."""
    f = list(x_faces(nx, length, stretch))
    i = nx
    while f[-1] < factor * length * (1.0 - 1e-12):
        i += 1
        s = i / nx
        f.append(length * math.expm1(stretch * s) / math.expm1(stretch) if stretch > 0 else length * s)
    return np.array(f)


# --------------------------------------------------------------------- grid

class Grid:
    """Staggered grid of the channel: faces xf (nx + 1) in x, the y axis of
    cavity_fv (ny cells, walls at 0 and 1). Unknowns q = [u, v, p]:
    u[nx, ny] on the vertical faces 1..nx (x = xf[1:], y = centres; the
    inlet face 0 is given), v[nx, ny - 1] on the interior horizontal faces
    (x = centres, y = yf[1:-1]), p[nx, ny] at the centres."""

    def __init__(self, xf, ny, stretch_y=0.0):
        xf = np.asarray(xf, dtype=float)
        nx = len(xf) - 1
        if nx < 4 or ny < 4:
            raise ValueError("need at least 4 cells in x and y")
        self.nx, self.ny, self.xf, self.length = nx, ny, xf, float(xf[-1])
        self.stretch_y = stretch_y
        self.ay = ay = Axis(ny, stretch_y)
        d = np.diff(xf)
        c = 0.5 * (xf[:-1] + xf[1:])
        self.xd, self.xc = d, c
        hfull = np.diff(np.concatenate(([0.0], c, [self.length])))   # centre to centre, per face 0..nx
        hx = hfull[1:]                    # u control volume widths, faces 1..nx (half cell at the outlet)
        one = np.ones(nx)
        # cells <- faces 1..nx: u_(i+1) - u_i (face 0, the inlet, added as data)
        Dx = sp.diags([one, -one[:-1]], [0, -1], shape=(nx, nx), format="csr")
        Ax = abs(Dx) * 0.5                # cells <- faces 1..nx, average
        Gx = (-Dx.T).tocsr()              # faces 1..nx <- cells: c_k - c_(k-1), outlet: -c_(nx-1)
        Mx = (Ax.T @ sp.diags(d)).tocsr()  # faces 1..nx <- cells, half widths (mass through a node segment)
        # faces 1..nx <- cells, linear; the outlet face takes the last cell (dv/dx = 0)
        w = (xf[1:-1] - c[:-1]) / (c[1:] - c[:-1])
        rows = np.concatenate((np.arange(nx - 1), np.arange(nx - 1), [nx - 1]))
        cols = np.concatenate((np.arange(nx - 1), np.arange(1, nx), [nx - 1]))
        vals = np.concatenate((1.0 - w, w, [1.0]))
        Bx = sp.csr_matrix((vals, (rows, cols)), shape=(nx, nx))
        # x diffusion of a cell field: v = 0 at the inlet (half cell), dv/dx = 0 at the outlet
        g = 1.0 / hfull
        g[-1] = 0.0
        Lx = sp.diags([-(g[:-1] + g[1:]), g[1:-1], g[1:-1]], [0, 1, -1], shape=(nx, nx), format="csr")

        I = lambda m: sp.identity(m, format="csr")  # noqa: E731,E741
        K = lambda a, b: sp.kron(a, b, format="csr")  # noqa: E731
        D = sp.diags
        Ix, Iy, Imy = I(nx), I(ny), I(ny - 1)
        nu_, nv, nc = nx * ny, nx * (ny - 1), nx * ny
        self.sizes = (nu_, nv, nc)
        self.offsets = np.cumsum((0,) + self.sizes)
        self.dy_c = np.outer(one, ay.d).ravel()        # cell heights, also u CV heights
        self.dx_c = np.outer(d, np.ones(ny)).ravel()   # cell widths
        self.area_c = self.dx_c * self.dy_c
        hx_u = np.outer(hx, np.ones(ny)).ravel()
        self.area_u = hx_u * self.dy_c
        dx_v = np.outer(d, np.ones(ny - 1)).ravel()
        hy_v = np.outer(one, ay.h[1:-1]).ravel()
        self.area_v = dx_v * hy_v
        self.out_mask = np.zeros(nu_)
        self.out_mask[(nx - 1) * ny:] = 1.0

        # u momentum: x fluxes at the centres (+ the outlet face), y fluxes at the nodes
        self.u_to_c = K(Ax, Iy)
        self.u_xdiv = K(Gx, Iy) @ D(self.dy_c)          # centres -> u CVs (also the pressure gradient)
        self.u_dx = D(1.0 / self.dx_c) @ K(Dx, Iy)       # du/dx at the centres
        self.v_to_node_mass = K(Mx, Imy)
        self.u_to_node = K(Ix, ay.c2f)
        self.u_ydiv = K(Ix, ay.div)
        self.u_visc_y = D(hx_u) @ K(Ix, ay.lap_dirichlet)
        # v momentum
        self.v_to_c = K(Ix, ay.f2c)
        self.v_ydiv = K(Ix, ay.grad) @ D(self.dx_c)      # centres -> v CVs (also the pressure gradient)
        self.u_to_node_mass = K(Ix, ay.c2f_len)
        self.v_to_node = K(Bx, Imy)
        self.v_xdiv = K(Dx, Imy)
        self.v_visc = D(dx_v) @ K(Ix, ay.lap_faces) + D(hy_v) @ K(Lx, Imy)
        # continuity (integrated divergence, sign as -(pressure gradient)^T)
        self.div_u = D(self.dy_c) @ K(Dx, Iy)
        self.div_v = D(self.dx_c) @ K(Ix, ay.div)

    def inflow(self, kind):
        """Cell means of the inflow profile over the inlet cells (flow rate 1)."""
        yf = self.ay.f
        if kind == "uniform":
            return np.ones(self.ny)
        if kind == "parabolic":
            prim = 3.0 * yf ** 2 - 2.0 * yf ** 3           # int 6 y (1 - y) dy
            return np.diff(prim) / self.ay.d
        raise ValueError("inflow is 'uniform' or 'parabolic'")

    def split(self, q):
        o, nx, ny = self.offsets, self.nx, self.ny
        return (q[o[0]:o[1]].reshape(nx, ny), q[o[1]:o[2]].reshape(nx, ny - 1), q[o[2]:o[3]].reshape(nx, ny))

    def residual(self, q, re, u_in, jacobian=True):
        """Integrated residuals of the u, v momentum and continuity equations,
        and the Jacobian."""
        o, ny = self.offsets, self.ny
        u, v, p = q[o[0]:o[1]], q[o[1]:o[2]], q[o[2]:o[3]]
        D = sp.diags
        nu = 1.0 / re
        # the inlet face enters the first cells' average and difference
        b_avg = np.zeros(self.sizes[2])
        b_avg[:ny] = 0.5 * u_in
        b_dif = np.zeros(self.sizes[2])
        b_dif[:ny] = -u_in / self.dx_c[:ny]
        uc = self.u_to_c @ u + b_avg
        dudx = self.u_dx @ u + b_dif
        mv = self.v_to_node_mass @ v
        un = self.u_to_node @ u
        vc = self.v_to_c @ v
        mu = self.u_to_node_mass @ u
        vn = self.v_to_node @ v
        ru = (self.u_xdiv @ (uc * uc + p - nu * dudx) + self.out_mask * self.dy_c * u * u
              + self.u_ydiv @ (mv * un) - nu * (self.u_visc_y @ u))
        rv = (self.v_ydiv @ (vc * vc + p) + self.v_xdiv @ (mu * vn) - nu * (self.v_visc @ v))
        rc = -(self.div_u @ u + self.div_v @ v)
        rc[:ny] += self.ay.d * u_in
        r = np.concatenate((ru, rv, rc))
        if not jacobian:
            return r, None
        Juu = (self.u_xdiv @ (D(2.0 * uc) @ self.u_to_c - nu * self.u_dx)
               + D(2.0 * self.out_mask * self.dy_c * u) + self.u_ydiv @ D(mv) @ self.u_to_node
               - nu * self.u_visc_y)
        Juv = self.u_ydiv @ D(un) @ self.v_to_node_mass
        Jvv = self.v_ydiv @ D(2.0 * vc) @ self.v_to_c + self.v_xdiv @ D(mu) @ self.v_to_node - nu * self.v_visc
        Jvu = self.v_xdiv @ D(vn) @ self.u_to_node_mass
        J = sp.bmat([[Juu, Juv, self.u_xdiv],
                     [Jvu, Jvv, self.v_ydiv],
                     [-self.div_u, -self.div_v, None]], format="csr")
        return r, J

    def poiseuille(self, re):
        """Developed flow everywhere (u = 6 y (1 - y), p = 12 (L - x)/Re): the start."""
        q = np.zeros(self.offsets[-1])
        yc = self.ay.c
        u = np.outer(np.ones(self.nx), 6.0 * yc * (1.0 - yc))
        p = np.outer(12.0 / re * (self.length - self.xc), np.ones(self.ny))
        q[:self.offsets[1]] = u.ravel()
        q[self.offsets[2]:] = p.ravel()
        return q

    def padded(self, q, u_in):
        """u with the inlet and wall values, v with the walls, the inlet and
        the outlet, p: ((x, y, values), ...) for interpolation."""
        u, v, p = self.split(q)
        ay, nx, ny = self.ay, self.nx, self.ny
        yc_w = np.concatenate(([0.0], ay.c, [1.0]))
        xc_w = np.concatenate(([0.0], self.xc, [self.length]))
        uf = np.zeros((nx + 1, ny + 2))
        uf[0, 1:-1] = u_in
        uf[1:, 1:-1] = u
        vf = np.zeros((nx + 2, ny + 1))
        vf[1:-1, 1:-1] = v
        vf[-1, 1:-1] = v[-1]
        return ((self.xf, yc_w, uf), (xc_w, ay.f, vf), (self.xc, ay.c, p))

    def prolong(self, coarse, qc, u_in_coarse):
        """Interpolate the solution qc of Grid `coarse` to this grid."""
        ay = self.ay
        targets = ((self.xf[1:], ay.c), (self.xc, ay.f[1:-1]), (self.xc, ay.c))
        parts = []
        for (xs, ys, val), (xt, yt) in zip(coarse.padded(qc, u_in_coarse), targets):
            f = RegularGridInterpolator((xs, ys), val, bounds_error=False, fill_value=None)
            X, Y = np.meshgrid(xt, yt, indexing="ij")
            parts.append(f(np.stack((X.ravel(), Y.ravel()), axis=-1)))
        return np.concatenate(parts)


# ------------------------------------------------------------------ solver

def _merit(grid, r):
    """RMS of the residuals per unit control-volume area."""
    o = grid.offsets
    s = np.concatenate((r[o[0]:o[1]] / grid.area_u, r[o[1]:o[2]] / grid.area_v, r[o[2]:o[3]] / grid.area_c))
    return float(np.sqrt(np.mean(s * s)))


def newton(grid, q, re, u_in, tol=1e-10, maxit=30, verbose=False):
    """Steady Newton iteration from q (cavity_fv's damped Newton); returns (q, iterations)."""
    o = grid.offsets

    def step_norm(x, dx):
        return np.abs(dx[o[0]:o[2]]).max() / (np.abs(x[o[0]:o[2]]).max() + 1.0)

    return damped_newton(lambda x, jac: grid.residual(x, re, u_in, jacobian=jac),
                         lambda r: _merit(grid, r), step_norm, q,
                         f"Re {re:g}, {grid.nx} x {grid.ny}", tol, maxit, 1e-11, verbose)


def _steady(grid, re, u_in, tol, start=None, verbose=False):
    """Steady solution; start = (coarse grid, its solution, its u_in) or None.
    Falls back on continuation in Re from Re = 1 if Newton fails."""
    q0 = grid.prolong(*start) if start is not None else grid.poiseuille(re)
    try:
        return newton(grid, q0, re, u_in, tol, verbose=verbose)[0]
    except NoConvergence:
        if verbose:
            print("#   continuation in Re", file=sys.stderr)
    cur, q = 1.0, newton(grid, grid.poiseuille(1.0), min(re, 1.0), u_in, tol, verbose=verbose)[0]
    fac = 2.0
    while cur < re:
        target = min(re, cur * fac)
        try:
            q, _ = newton(grid, q, target, u_in, tol, verbose=verbose)
            cur = target
        except NoConvergence:
            fac = math.sqrt(fac)
            if fac < 1.01:
                raise
    return q


# ---------------------------------------------------------------- analysis

def _lagrange(nodes, vals, at):
    """Value at `at` of the polynomial through (nodes, vals)."""
    out = 0.0
    for k in range(len(nodes)):
        w = 1.0
        for m in range(len(nodes)):
            if m != k:
                w *= (at - nodes[m]) / (nodes[k] - nodes[m])
        out += w * vals[k]
    return out


def _cubic_at(pos, vals, at):
    """Cubic through the four samples of vals(pos) nearest `at` (vals may be
    2-d, the samples along axis 0); exact at a sample."""
    k = int(np.searchsorted(pos, at))
    if k < len(pos) and pos[k] == at:
        return vals[k]
    lo = min(max(k - 2, 0), len(pos) - 4)
    return _lagrange(pos[lo:lo + 4], vals[lo:lo + 4], at)


def centre_line(grid, u_full):
    """u on y = 1/2 from the cell-centre values u_full[:, ny] (any x rows)."""
    return _cubic_at(grid.ay.c, u_full.T, 0.5)


def centre_speed(result, xs):
    """u_c at the positions xs (cubic through the four nearest faces)."""
    x, uc = result["x"], result["u_c"]
    return np.array([_cubic_at(x, uc, float(a)) for a in np.atleast_1d(xs)])


def development_length(x, uc, frac=0.99):
    """First x where the centre speed reaches frac x 1.5 (root of the cubic
    through the four nearest faces); nan if it never does."""
    target = frac * U_C_DEVELOPED
    above = np.nonzero(uc >= target)[0]
    if len(above) == 0:
        return float("nan")
    k = int(above[0])
    if k == 0:
        return 0.0

    def f(a):
        return _cubic_at(x, uc, a) - target
    return float(brentq(f, x[k - 1], x[k], xtol=1e-13))


def analyse(grid, q, re, inflow, u_in, developed=(3.0, 6.0), profile_x=(2.0, 3.0, 6.0)):
    """The result dict of a solution q (see solve)."""
    u, v, p = grid.split(q)
    ay = grid.ay
    u_full = np.vstack((u_in[None, :], u))           # faces 0..nx
    uc = np.array(centre_line(grid, u_full), dtype=float)
    flux = u_full @ ay.d
    # section-mean pressure at the centres; -dp/dx over the developed window
    pm = p @ ay.d
    a, b = developed[0], min(developed[1], grid.xc[-1])
    if not 0.0 < a < b:
        raise ValueError(f"the developed window ({a:g}, {b:g}) is not inside the channel")
    pa, pb = _cubic_at(grid.xc, pm, a), _cubic_at(grid.xc, pm, b)
    gradient = (pa - pb) / (b - a)
    # spread of p across the channel in that window (0 for developed flow)
    inside = (grid.xc >= a) & (grid.xc <= b)
    spread = float((p[inside].max(axis=1) - p[inside].min(axis=1)).max()) if inside.any() else float("nan")
    poise = 6.0 * ay.c * (1.0 - ay.c)
    prof = {}
    for xp in profile_x:
        if xp <= grid.length:
            prof[float(xp)] = float(np.abs(_cubic_at(grid.xf, u_full, xp) - poise).max() / U_C_DEVELOPED)
    return {
        "re": float(re), "inflow": inflow, "nx": grid.nx, "ny": grid.ny, "length": grid.length,
        "stretch_y": float(grid.stretch_y),
        "x": grid.xf.copy(), "u_c": uc, "l99": development_length(grid.xf, uc),
        "mass_flux": flux, "dpdx": float(gradient), "dpdx_ratio": float(gradient / (12.0 / re)),
        "developed": (float(a), float(b)), "p_spread": spread, "profile_error": prof,
        "y": ay.c.copy(), "u": u_full, "v": v, "p": p, "xc": grid.xc.copy(),
    }


def solve(re, inflow="uniform", nx=320, ny=80, length=10.0, stretch=3.0, stretch_y=0.0, tol=1e-10,
          faces=None, developed=(3.0, 6.0), n_start=None, verbose=False, _grids=None):
    """Steady entrance flow at Reynolds number re (U H / nu) on nx x ny cells,
    x in [0, length] with the geometric map of stretch b (or the given x
    faces), y with the tanh map of stretch_y. n_start: solve first on the
    grids ny/2^k >= n_start (nx in proportion) and interpolate each solution
    as the start of the next (None: from Poiseuille's flow on this grid).
    Returns a dict:
      re, inflow, nx, ny, length, stretch_y
      x      the faces x_0 = 0 ... x_nx = length
      u_c    the centre speed u(x, 1/2) at x (not divided by 1.5)
      l99    the first x where u_c = 0.99 x 1.5 (nan if never)
      mass_flux  the flow rate int u dy at every face (1 exactly)
      dpdx, dpdx_ratio  -dp/dx of the section-mean pressure between
             developed = (a, b) and its ratio to 12/Re
      p_spread   the largest max - min of p across a column in (a, b)
      profile_error {x: max |u - 6 y (1 - y)| / 1.5} at x = 2, 3, 6
      y, u   the cell-centre y and u[faces, ny]; v[nx, ny - 1]; xc, p[nx, ny]."""
    if re <= 0:
        raise ValueError("need Re > 0")
    chain = [(nx, ny)]
    if n_start is not None and faces is None:
        while chain[0][1] % 2 == 0 and chain[0][0] % 2 == 0 and chain[0][1] // 2 >= n_start:
            chain.insert(0, (chain[0][0] // 2, chain[0][1] // 2))
    start = None
    for mx, my in chain:
        grid = Grid(faces if faces is not None else x_faces(mx, length, stretch), my, stretch_y)
        u_in = grid.inflow(inflow)
        q = _steady(grid, re, u_in, tol, start, verbose)
        start = (grid, q, u_in)
        if _grids is not None:
            _grids[my] = analyse(grid, q, re, inflow, u_in, developed)
    return analyse(grid, q, re, inflow, u_in, developed)


def richardson(re, inflow="uniform", nx=320, ny=80, length=10.0, stretch=3.0, stretch_y=0.0, tol=1e-10,
               stations=RICHARDSON_STATIONS, verbose=False):
    """Solve on (nx, ny)/4, /2 and (nx, ny) (same maps) and extrapolate.
    Returns (results by ny, {quantity: (value, extrapolated, error of value,
    observed order)}) for l99, dpdx and u_c/1.5 at the stations."""
    if ny % 4 or nx % 4:
        raise ValueError("richardson needs nx and ny divisible by 4")
    grids = {}
    solve(re, inflow, nx, ny, length, stretch, stretch_y, tol, n_start=ny // 4, verbose=verbose, _grids=grids)
    seq = [grids[ny // 4], grids[ny // 2], grids[ny]]
    table = {}
    vals = {"l99": [g["l99"] for g in seq], "dpdx": [g["dpdx"] for g in seq]}
    for xs in stations:
        vals[f"u_c({xs:g})/1.5"] = [float(centre_speed(g, xs)[0]) / U_C_DEVELOPED for g in seq]
    for key, (a, b, c) in vals.items():
        extra, order = extrapolate(a, b, c)
        table[key] = (c, extra, c - extra, order)
    return grids, table


def outflow_check(re, inflow="uniform", nx=320, ny=80, length=10.0, stretch=3.0, stretch_y=0.0, factor=1.5,
                  tol=1e-10, xs=None):
    """The same grid with its outlet at `length` and continued by whole cells
    to >= factor x length. Returns (length2, largest |u_c| difference on
    x <= 6 (at the faces), L_99 difference, -dp/dx difference)."""
    short = solve(re, inflow, nx, ny, length, stretch, stretch_y, tol)
    f2 = extended_faces(nx, length, stretch, factor)
    long_ = solve(re, inflow, len(f2) - 1, ny, f2[-1], stretch, stretch_y, tol, faces=f2)
    m = short["x"] <= 6.0 + 1e-12
    du = float(np.abs(short["u_c"][m] - long_["u_c"][:len(short["x"])][m]).max())
    return float(f2[-1]), du, long_["l99"] - short["l99"], long_["dpdx"] - short["dpdx"]


def write_table(path, result, step=0.05, x_max=6.0):
    """x and u_c/1.5 every `step` up to x_max, with a header."""
    xs = np.arange(0.0, x_max + 0.5 * step, step)
    uc = centre_speed(result, xs) / U_C_DEVELOPED
    with open(path, "w") as f:
        f.write(f"# channel_entrance.py: centre speed of the developing channel flow, Re = {result['re']:g}, "
                f"{result['inflow']} inflow, {result['nx']} x {result['ny']} cells, L = {result['length']:g} H\n")
        f.write(f"# L_99 = {result['l99']:.6f} H, -dp/dx / (12/Re) = {result['dpdx_ratio']:.6f}\n")
        f.write("# x/H  u_c/(1.5 U)\n")
        for a, b in zip(xs, uc):
            f.write(f"{a:.4f} {b:.8f}\n")


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--re", type=float, default=20.0, help="Reynolds number U H / nu (default 20)")
    p.add_argument("--inflow", choices=("uniform", "parabolic"), default="uniform",
                   help="inlet profile (default uniform)")
    p.add_argument("--ny", type=int, default=80, help="cells across the channel (default 80)")
    p.add_argument("--nx", type=int, help="cells along the channel (default 4 ny)")
    p.add_argument("--length", type=float, default=10.0, help="channel length L / H (default 10)")
    p.add_argument("--stretch", type=float, default=3.0,
                   help="b of the geometric map in x, 0 = uniform (default 3)")
    p.add_argument("--stretch-y", type=float, default=0.0,
                   help="b of the tanh wall clustering in y, 0 = uniform (default 0)")
    p.add_argument("--developed", type=float, nargs=2, default=(3.0, 6.0), metavar=("A", "B"),
                   help="x window of the developed pressure gradient (default 3 6)")
    p.add_argument("--step", type=float, default=0.05, help="x step of the printed centre speed (default 0.05)")
    p.add_argument("--x-max", type=float, default=6.0, help="last x of the printed centre speed (default 6)")
    p.add_argument("--tol", type=float, default=1e-10, help="Newton stopping tolerance (default 1e-10)")
    p.add_argument("--richardson", action="store_true",
                   help="also solve on ny/4 and ny/2 and print the extrapolated values and the error of ny")
    p.add_argument("--outflow", action="store_true",
                   help="also solve on the same grid continued to 1.5 L and print the differences")
    p.add_argument("--write", metavar="FILE", help="write x and u_c/1.5 every --step up to --x-max to FILE")
    p.add_argument("--verbose", action="store_true", help="print the Newton iterations to stderr")
    args = p.parse_args()
    nx = args.nx if args.nx else 4 * args.ny

    t0 = time.time()
    table = None
    if args.richardson:
        grids, table = richardson(args.re, args.inflow, nx, args.ny, args.length, args.stretch, args.stretch_y,
                                  args.tol, verbose=args.verbose)
        res = grids[args.ny]
    else:
        res = solve(args.re, args.inflow, nx, args.ny, args.length, args.stretch, args.stretch_y, args.tol,
                    developed=tuple(args.developed), verbose=args.verbose)
    elapsed = time.time() - t0

    print(f"Re = {res['re']:g}, {res['inflow']} inflow, {res['nx']} x {res['ny']} cells, L = {res['length']:g} H "
          f"(stretch {args.stretch:g}, y {args.stretch_y:g})")
    print(f"flow rate: largest departure from 1 over the faces {np.abs(res['mass_flux'] - 1.0).max():.1e}")
    line = f"L_99 (u_c = 0.99 x 1.5 U) = {res['l99']:.6f} H"
    if res["inflow"] == "uniform":
        line += f"   (Durst et al. 2005: {durst(res['re']):.4f} H)"
    elif res["l99"] == 0.0:
        line += "   (reached at the inlet)"
    print(line)
    a, b = res["developed"]
    print(f"-dp/dx over x = {a:g} ... {b:g} H = {res['dpdx']:.8f}, / (12/Re) = {res['dpdx_ratio']:.8f}; "
          f"p spread across {res['p_spread']:.1e}")
    for xp, e in res["profile_error"].items():
        print(f"profile at x = {xp:g} H: largest |u - 6 y (1 - y)| / 1.5 = {e:.2e}")
    print("u_c/(1.5 U) at x/H = " + ", ".join(f"{a:g}: {b:.6f}" for a, b in
                                           zip(STATIONS, centre_speed(res, STATIONS) / U_C_DEVELOPED)))
    print("x/H   u_c/(1.5 U)")
    xs = np.arange(0.0, args.x_max + 0.5 * args.step, args.step)
    for xp, val in zip(xs, centre_speed(res, xs) / U_C_DEVELOPED):
        print(f"{xp:.3f} {val:.6f}")
    if table:
        print(f"Richardson over ny = {args.ny // 4}, {args.ny // 2}, {args.ny}:")
        for key, (value, extra, err, order) in table.items():
            print(f"  {key:14s} ny {args.ny}: {value:.7f}  extrapolated {extra:.7f}  error of ny {err:+.2e}  "
                  f"observed order {order:.2f}")
    if args.outflow:
        l2, du, dl, dg = outflow_check(args.re, args.inflow, nx, args.ny, args.length, args.stretch,
                                       args.stretch_y, tol=args.tol)
        print(f"outlet at L = {res['length']:g} against {l2:.3f} H, same grid: largest u_c change on x <= 6 "
              f"{du:.1e}, L_99 {dl:+.1e}, -dp/dx {dg:+.1e}")
    print(f"# {elapsed:.1f} s")
    if args.write:
        write_table(args.write, res, args.step, args.x_max)
        print(f"wrote {args.write}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
