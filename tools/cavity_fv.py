#!/usr/bin/env python3
"""Fine-grid reference for the steady differentially heated square cavity.

The de Vahl Davis benchmark (de Vahl Davis, G. (1983) Natural convection of
air in a square cavity: a bench mark numerical solution, Int. J. Numer.
Methods Fluids 3, 249-264): Boussinesq fluid in [0,1]^2, no-slip walls,
theta = 1 on x = 0 (hot), theta = 0 on x = 1 (cold), adiabatic top and bottom.
Lengths in units of L, velocities of alpha/L, time of L^2/alpha,
theta = (T - T_C)/(T_H - T_C):

    div u = 0
    du/dt + (u.grad)u = -grad p + Pr lap u + Ra Pr theta e_y
    dtheta/dt + u.grad theta = lap theta

Method: finite volumes on a staggered (MAC) grid, N x N cells, u on the
vertical faces, v on the horizontal faces, p and theta at the cell centres.
The faces are x_i = X(i/N) with the wall-clustering map
X(s) = (1 + tanh(b (2s - 1)) / tanh(b)) / 2 (b = --stretch; b = 0 uniform),
the same in y. Central (linear) interpolation for every convective flux,
in conservative form with mass fluxes that satisfy the discrete continuity
of the momentum control volumes; two-point diffusive fluxes, with the half
cell next to a wall. Second order in space on the fixed map X (checked by
Richardson extrapolation over N/4, N/2, N, see cavity_fv.md).
The steady equations, all unknowns coupled (u, v, p, theta; p pinned in one
cell), are solved by Newton's method with the exact Jacobian and a sparse LU
(scipy SuperLU) per iteration, with a backtracking line search; high Ra is
reached by continuation in Ra on a coarse grid and then by grid sequencing
(the coarse solution interpolated as the start on the finer grid). Iteration
stops when the Newton update is below tol relative to the solution, after
which the residual is of order tol^2: the hot-wall and cold-wall Nusselt
numbers (the exact discrete heat fluxes) then agree to round-off.
The optional transient mode (--t-end) integrates from rest at theta = 0.5
with BDF2 (a first backward Euler step) at a fixed step, Newton per step.

Quantities: Nu = int_0^1 -dtheta/dx dy on the hot wall (and the flux through
the cold wall); u_max on x = 0.5 and v_max on y = 0.5, the maximum of the
quartic through the largest grid value and two neighbours on each side.

As a module: solve(ra, pr=0.71, n=64, stretch=1.5, ...) returns a dict (see
solve), profiles_at(result, xs) interpolates theta and v on y = 0.5 at
arbitrary x, richardson(ra, pr, n, ...) solves on N/4, N/2, N and estimates
the error of the N result (extrapolate(a, b, c) is its Richardson step).
Grid also takes heated plates, a rectangle and free-slip sides, and march()
integrates any Grid in time: rb_fv.py (Rayleigh-Benard rolls) uses both.
As a script, see --help.
"""

import argparse
import json
import math
import sys
import time

import numpy as np
import scipy.sparse as sp
import scipy.sparse.linalg as spla
from scipy.interpolate import RegularGridInterpolator

# de Vahl Davis (1983), Pr = 0.71: mean Nu, u_max on x = 0.5, v_max on y = 0.5
DE_VAHL_DAVIS = {1e3: (1.118, 3.649, 3.697), 1e4: (2.243, 16.178, 19.617),
                 1e5: (4.519, 34.73, 68.59), 1e6: (8.800, 64.63, 219.36)}


LAYOUT = ("hmid: y = 0.5, x at the cell centres plus both walls; vmid: x = 0.5, y at the "
          "cell centres plus both walls; hot_wall: local Nu at the cell-centre y; centres: "
          "fields at the cell centres, indexed [i_x][j_y] (u, v averaged from the faces); "
          "nodes: psi at the cell corners x = nodes.x[i], y = nodes.y[j], u = dpsi/dy")


# --------------------------------------------------------------------- grid

class Axis:
    """One direction of the grid, [0, length]: faces f (n + 1), centres c (n),
    widths d (n) and the centre-to-centre distances h (n + 1), half cells at
    the walls."""

    def __init__(self, n, stretch, length=1.0):
        s = np.linspace(0.0, 1.0, n + 1)
        if stretch > 0:
            f = 0.5 * (1.0 + np.tanh(stretch * (2.0 * s - 1.0)) / math.tanh(stretch))
        else:
            f = s.copy()
        f = f * length
        f[0], f[-1] = 0.0, length
        self.n, self.f, self.length = n, f, length
        self.c = 0.5 * (f[:-1] + f[1:])
        self.d = np.diff(f)
        self.h = np.diff(np.concatenate(([0.0], self.c, [length])))
        one = np.ones(n)
        # cells <- interior faces: face i+1 minus face i (wall faces are 0)
        self.div = sp.diags([one[:n - 1], -one[:n - 1]], [0, -1], shape=(n, n - 1), format="csr")
        # interior faces <- cells: c_k - c_(k-1)
        self.grad = (-self.div.T).tocsr()
        # interior faces <- cells, linear interpolation
        w = (f[1:-1] - self.c[:-1]) / (self.c[1:] - self.c[:-1])
        self.c2f = sp.diags([1.0 - w, w], [0, 1], shape=(n - 1, n), format="csr")
        # interior faces <- cells, half widths (mass flux through a node segment)
        self.c2f_len = sp.diags([0.5 * self.d[:-1], 0.5 * self.d[1:]], [0, 1], shape=(n - 1, n), format="csr")
        # cells <- interior faces, average (cell centre is mid-way between its faces)
        self.f2c = abs(self.div) * 0.5
        # diffusion of a cell field with walls: sum of face fluxes (c_k - c_(k-1)) / h_k
        self.lap_dirichlet = self._lap_cells(True)
        self.lap_neumann = self._lap_cells(False)
        # diffusion of an interior-face field with zero at the wall faces
        self.lap_faces = (self.grad @ sp.diags(1.0 / self.d) @ self.div).tocsr()

    def _lap_cells(self, dirichlet):
        n, h = self.n, self.h
        g = 1.0 / h                       # conductance of face k (0..n)
        if not dirichlet:
            g = g.copy()
            g[0] = g[-1] = 0.0
        main = -(g[:-1] + g[1:])
        return sp.diags([main, g[1:-1], g[1:-1]], [0, 1, -1], shape=(n, n), format="csr")


class Grid:
    """Staggered grid of nx x n cells on [0, width] x [0, 1]; unknown vector
    q = [u, v, p, theta] with u[(nx-1), n] on the interior vertical faces
    (x = f[1:-1], y = c), v[nx, (n-1)] on the interior horizontal faces
    (x = c, y = f[1:-1]), p[nx, n] and theta[nx, n] at the centres; arrays
    indexed [i_x, j_y]. Every wall has u.n = 0.

    heated = "sides": theta = 1 on x = 0, 0 on x = width, top and bottom
    adiabatic (the cavity); "plates": theta = 1 on y = 0, 0 on y = 1, the
    sides adiabatic (a Rayleigh-Benard cell). slip_sides: the side walls
    x = 0, width are free-slip (dv/dx = 0) instead of no-slip; top and
    bottom are always no-slip. stretch_x: the map's b in x (default stretch)."""

    def __init__(self, n, stretch, heated="sides", nx=None, width=1.0, stretch_x=None, slip_sides=False):
        nx = n if nx is None else nx
        if min(n, nx) < 4:
            raise ValueError("need at least 4 cells per side")
        if heated not in ("sides", "plates"):
            raise ValueError("heated is 'sides' or 'plates'")
        self.n, self.nx, self.stretch, self.heated = n, nx, stretch, heated
        self.slip_sides = slip_sides
        self.ax = ax = Axis(nx, stretch if stretch_x is None else stretch_x, width)
        self.ay = ay = Axis(n, stretch)
        ny = n
        nu, nv, nc = (nx - 1) * ny, nx * (ny - 1), nx * ny
        self.sizes = (nu, nv, nc, nc)
        self.offsets = np.cumsum((0,) + self.sizes)
        I = lambda m: sp.identity(m, format="csr")  # noqa: E731,E741
        Inx, Imx, Iny, Imy = I(nx), I(nx - 1), I(ny), I(ny - 1)
        K = lambda a, b: sp.kron(a, b, format="csr")  # noqa: E731

        # control-volume areas
        self.area_u = np.outer(ax.h[1:-1], ay.d).ravel()
        self.area_v = np.outer(ax.d, ay.h[1:-1]).ravel()
        self.area_c = np.outer(ax.d, ay.d).ravel()
        dy_u = np.outer(np.ones(nx - 1), ay.d).ravel()    # face length of a u face
        dx_v = np.outer(ax.d, np.ones(ny - 1)).ravel()    # face length of a v face
        dy_c = np.outer(np.ones(nx), ay.d).ravel()
        dx_c = np.outer(ax.d, np.ones(ny)).ravel()
        D = sp.diags

        # u momentum: x fluxes at the cell centres, y fluxes at the nodes
        self.u_to_c = K(ax.f2c, Iny)                      # u -> centres (nx, ny)
        self.u_xflux_div = K(ax.grad, Iny) @ D(dy_c)      # centres -> u CVs
        self.v_to_node_mass = K(ax.c2f_len, Imy)          # v -> nodes (nx-1, ny-1)
        self.u_to_node = K(Imx, ay.c2f)                   # u -> nodes
        self.u_yflux_div = K(Imx, ay.div)                 # nodes -> u CVs
        self.u_grad_p = D(dy_u) @ K(ax.grad, Iny)
        self.u_visc = (D(dy_u) @ K(ax.lap_faces, Iny)
                       + D(np.outer(ax.h[1:-1], np.ones(ny)).ravel()) @ K(Imx, ay.lap_dirichlet))
        # v momentum; a free-slip side wall passes no shear stress (Neumann)
        self.v_to_c = K(Inx, ay.f2c)
        self.v_yflux_div = K(Inx, ay.grad) @ D(dx_c)
        self.u_to_node_mass = K(Imx, ay.c2f_len)
        self.v_to_node = K(ax.c2f, Imy)
        self.v_xflux_div = K(ax.div, Imy)
        self.v_grad_p = D(dx_v) @ K(Inx, ay.grad)
        lap_vx = ax.lap_neumann if slip_sides else ax.lap_dirichlet
        self.v_visc = (D(np.outer(np.ones(nx), ay.h[1:-1]).ravel()) @ K(lap_vx, Imy)
                       + D(dx_v) @ K(Inx, ay.lap_faces))
        self.t_to_v = D(self.area_v) @ K(Inx, ay.c2f)     # buoyancy, integrated
        # continuity (integrated divergence) = -(pressure gradient)^T
        self.div_u = D(dy_c) @ K(ax.div, Iny)
        self.div_v = D(dx_c) @ K(Inx, ay.div)
        # energy
        self.t_to_u = K(ax.c2f, Iny)
        self.t_xflux_div = K(ax.div, Iny) @ D(dy_u)
        self.t_to_v_face = K(Inx, ay.c2f)
        self.t_yflux_div = K(Inx, ay.div) @ D(dx_v)
        plates = heated == "plates"
        self.t_diff = (D(dy_c) @ K(ax.lap_neumann if plates else ax.lap_dirichlet, Iny)
                       + D(dx_c) @ K(Inx, ay.lap_dirichlet if plates else ay.lap_neumann))
        # theta = 1 on the hot wall (x = 0 or y = 0), 0 on the opposite one
        if plates:
            by = np.zeros(ny)
            by[0] = 1.0 / ay.h[0]
            self.t_diff_b = np.outer(ax.d, by).ravel()
        else:
            bx = np.zeros(nx)
            bx[0] = 1.0 / ax.h[0]
            self.t_diff_b = np.outer(bx, ay.d).ravel()
        self.mass = np.concatenate((self.area_u, self.area_v, np.zeros(nc), self.area_c))
        self.pin = self.offsets[2]         # p of cell (0, 0) is held at 0

    def split(self, q):
        o, nx, ny = self.offsets, self.nx, self.n
        return (q[o[0]:o[1]].reshape(nx - 1, ny), q[o[1]:o[2]].reshape(nx, ny - 1),
                q[o[2]:o[3]].reshape(nx, ny), q[o[3]:o[4]].reshape(nx, ny))

    def residual(self, q, ra, pr, jacobian=True):
        """Integrated residuals of the four equations, and the Jacobian."""
        o = self.offsets
        u, v, p, t = q[o[0]:o[1]], q[o[1]:o[2]], q[o[2]:o[3]], q[o[3]:o[4]]
        D = sp.diags
        uc = self.u_to_c @ u
        mv = self.v_to_node_mass @ v
        un = self.u_to_node @ u
        vc = self.v_to_c @ v
        mu = self.u_to_node_mass @ u
        vn = self.v_to_node @ v
        tu = self.t_to_u @ t
        tv = self.t_to_v_face @ t
        ru = (self.u_xflux_div @ (uc * uc) + self.u_yflux_div @ (mv * un)
              + self.u_grad_p @ p - pr * (self.u_visc @ u))
        rv = (self.v_yflux_div @ (vc * vc) + self.v_xflux_div @ (mu * vn)
              + self.v_grad_p @ p - pr * (self.v_visc @ v) - ra * pr * (self.t_to_v @ t))
        rc = -(self.div_u @ u + self.div_v @ v)
        rt = (self.t_xflux_div @ (u * tu) + self.t_yflux_div @ (v * tv)
              - self.t_diff @ t - self.t_diff_b)
        r = np.concatenate((ru, rv, rc, rt))
        r[self.pin] = p[0]
        if not jacobian:
            return r, None
        Juu = (self.u_xflux_div @ D(2.0 * uc) @ self.u_to_c + self.u_yflux_div @ D(mv) @ self.u_to_node
               - pr * self.u_visc)
        Juv = self.u_yflux_div @ D(un) @ self.v_to_node_mass
        Jvv = (self.v_yflux_div @ D(2.0 * vc) @ self.v_to_c + self.v_xflux_div @ D(mu) @ self.v_to_node
               - pr * self.v_visc)
        Jvu = self.v_xflux_div @ D(vn) @ self.u_to_node_mass
        Jtu = self.t_xflux_div @ D(tu)
        Jtv = self.t_yflux_div @ D(tv)
        Jtt = (self.t_xflux_div @ D(u) @ self.t_to_u + self.t_yflux_div @ D(v) @ self.t_to_v_face
               - self.t_diff)
        J = sp.bmat([[Juu, Juv, self.u_grad_p, None],
                     [Jvu, Jvv, self.v_grad_p, -ra * pr * self.t_to_v],
                     [-self.div_u, -self.div_v, None, None],
                     [Jtu, Jtv, None, Jtt]], format="csr")
        # replace the continuity of cell (0, 0), redundant, by p(0, 0) = 0
        row = self.pin
        start, end = J.indptr[row], J.indptr[row + 1]
        J.data[start:end] = 0.0
        J = J + sp.csr_matrix(([1.0], ([row], [row])), shape=J.shape)
        J.eliminate_zeros()
        return r, J

    def conduction(self):
        """Rest, linear theta: the Ra = 0 solution (also the exact p = 0)."""
        q = np.zeros(self.offsets[-1])
        if self.heated == "plates":
            t = np.outer(np.ones(self.nx), 1.0 - self.ay.c)
        else:
            t = np.outer(1.0 - self.ax.c / self.ax.length, np.ones(self.n))
        q[self.offsets[3]:] = t.ravel()
        return q

    def uniform(self, value):
        q = np.zeros(self.offsets[-1])
        q[self.offsets[3]:] = value
        return q

    def padded(self, q):
        """Fields with their wall values, for interpolation: ((x, y, values), ...)."""
        u, v, p, t = self.split(q)
        ax, ay, nx, ny = self.ax, self.ay, self.nx, self.n
        yc_w = np.concatenate(([0.0], ay.c, [ay.length]))
        xc_w = np.concatenate(([0.0], ax.c, [ax.length]))
        uf = np.zeros((nx + 1, ny + 2))
        uf[1:-1, 1:-1] = u
        vf = np.zeros((nx + 2, ny + 1))
        vf[1:-1, 1:-1] = v
        if self.slip_sides:
            vf[0, 1:-1], vf[-1, 1:-1] = v[0, :], v[-1, :]
        tf = np.empty((nx + 2, ny + 2))
        tf[1:-1, 1:-1] = t
        if self.heated == "plates":
            tf[:, 0], tf[:, -1] = 1.0, 0.0
            tf[0, 1:-1], tf[-1, 1:-1] = t[0, :], t[-1, :]
        else:
            tf[0, :], tf[-1, :] = 1.0, 0.0
            tf[1:-1, 0], tf[1:-1, -1] = t[:, 0], t[:, -1]
        return ((ax.f, yc_w, uf), (xc_w, ay.f, vf), (ax.c, ay.c, p), (xc_w, yc_w, tf))

    def prolong(self, coarse, qc):
        """Interpolate the solution qc of Grid `coarse` to this grid."""
        ax, ay = self.ax, self.ay
        targets = ((ax.f[1:-1], ay.c), (ax.c, ay.f[1:-1]), (ax.c, ay.c), (ax.c, ay.c))
        parts = []
        for (xs, ys, val), (xt, yt) in zip(coarse.padded(qc), targets):
            f = RegularGridInterpolator((xs, ys), val, bounds_error=False, fill_value=None)
            X, Y = np.meshgrid(xt, yt, indexing="ij")
            parts.append(f(np.stack((X.ravel(), Y.ravel()), axis=-1)))
        q = np.concatenate(parts)
        q[self.pin:self.offsets[3]] -= q[self.pin]
        return q


# ------------------------------------------------------------------ solvers

class NoConvergence(RuntimeError):
    pass


def _factor(J):
    return spla.splu(J.tocsc(), permc_spec="COLAMD", options={"SymmetricMode": False})


def _norms(grid, q, dq):
    """Largest update of velocity (relative to the largest speed) and theta."""
    o = grid.offsets
    vel = np.abs(q[o[0]:o[2]]).max() + 1.0
    return max(np.abs(dq[o[0]:o[2]]).max() / vel, np.abs(dq[o[3]:]).max())


def _merit(grid, r):
    """RMS of the residuals per unit control-volume area."""
    o = grid.offsets
    s = r / np.where(grid.mass > 0, grid.mass, 1.0)
    s[o[2]:o[3]] = r[o[2]:o[3]] / grid.area_c
    return float(np.sqrt(np.mean(s * s)))


def damped_newton(residual, merit, step_norm, q, where, tol, maxit, floor, verbose=False):
    """Newton's method with a backtracking line search (Armijo on the merit,
    steps halved down to 1/64): residual(q, jacobian) returns (r, J), J None
    without the Jacobian; merit(r) the norm searched on; step_norm(q, dq)
    the update's size that stops the iteration below tol at a full step;
    floor a merit accepted whatever the decrease; where names the case in
    the messages. Returns (q, iterations). Shared by the MAC solvers here
    and in channel_entrance.py."""
    q = q.copy()
    r, J = residual(q, True)
    m = merit(r)
    for it in range(1, maxit + 1):
        dq = _factor(J).solve(-r)
        lam = 1.0
        while True:
            qn = q + lam * dq
            rn, _ = residual(qn, False)
            mn = merit(rn)
            if np.isfinite(mn) and (mn <= (1.0 - 1e-4 * lam) * m or mn < floor):
                break
            lam *= 0.5
            if lam < 1.0 / 64:
                raise NoConvergence(f"line search failed at {where}")
        step = step_norm(q, lam * dq)
        q, m = qn, mn
        if verbose:
            print(f"#   {where} it {it}: step {step:.2e} damping {lam:g} residual {m:.2e}",
                  file=sys.stderr)
        if lam == 1.0 and step < tol:
            return q, it
        r, J = residual(q, True)
    raise NoConvergence(f"no convergence in {maxit} Newton iterations at {where}")


def newton(grid, q, ra, pr, tol=1e-9, maxit=30, verbose=False):
    """Steady Newton iteration from q; returns (q, iterations)."""
    return damped_newton(lambda x, jac: grid.residual(x, ra, pr, jacobian=jac),
                         lambda r: _merit(grid, r), lambda x, dx: _norms(grid, x, dx), q,
                         f"Ra {ra:g}, N {grid.n}", tol, maxit, 1e-9, verbose)


def _continuation(grid, q, ra_from, ra, pr, tol, verbose):
    """Newton along a path in Ra from a converged solution at ra_from."""
    cur = ra_from
    step = 0.5 if ra_from > 0 else None
    while cur < ra:
        target = ra if step is None else min(ra, cur * 10.0 ** step)
        try:
            q_new, _ = newton(grid, q, target, pr, tol=tol, verbose=verbose)
        except NoConvergence:
            if step is None:
                cur, step = min(ra, 1e3), 0.5
                q, _ = newton(grid, q, cur, pr, tol=tol, verbose=verbose)
                continue
            step *= 0.5
            if step < 0.02:
                raise
            continue
        q, cur = q_new, target
        if step is not None and step < 0.5:
            step = min(0.5, 1.5 * step)
    return q


def _steady(grid, ra, pr, tol, start=None, verbose=False):
    """Steady solution on `grid`; start = (coarse grid, its solution) or None."""
    if ra == 0:    # linear: one Newton step from uniform theta = 0.5 (checks the discretisation)
        q, _ = newton(grid, grid.uniform(0.5), 0.0, pr, tol=tol, verbose=verbose)
        return q
    if start is not None:
        coarse, qc = start
        try:
            q, _ = newton(grid, grid.prolong(coarse, qc), ra, pr, tol=tol, verbose=verbose)
            return q
        except NoConvergence:
            if verbose:
                print("#   grid sequencing failed; continuation in Ra", file=sys.stderr)
    q = grid.conduction()
    first = min(ra, 1e4)
    try:
        q, _ = newton(grid, q, first, pr, tol=tol, verbose=verbose)
    except NoConvergence:
        q = _continuation(grid, q, 0.0, first, pr, tol, verbose)
    return _continuation(grid, q, first, ra, pr, tol, verbose)


def _chain(n, n_start):
    """Grids from the coarse start up to n by halving: [.., n/2, n]."""
    chain = [n]
    while chain[0] // 2 >= n_start and chain[0] % 2 == 0:
        chain.insert(0, chain[0] // 2)
    return chain


# ---------------------------------------------------------------- analysis

def _max_poly(pos, val):
    """Largest value of val(pos): the maximum, between the neighbours of the
    largest sample, of the quartic through it and its two neighbours on each
    side (fewer next to the ends); returns (value, position)."""
    k = int(np.argmax(val))
    if k == 0 or k == len(val) - 1:
        return float(val[k]), float(pos[k])
    lo, hi = max(0, k - 2), min(len(val), k + 3)
    x0 = pos[k]
    scale = pos[k + 1] - pos[k - 1]
    s = (pos[lo:hi] - x0) / scale
    c = np.polynomial.polynomial.polyfit(s, val[lo:hi], hi - lo - 1)
    cand = [(pos[k - 1] - x0) / scale, 0.0, (pos[k + 1] - x0) / scale]
    for r in np.polynomial.polynomial.polyroots(np.polynomial.polynomial.polyder(c)):
        if abs(r.imag) < 1e-12 and cand[0] <= r.real <= cand[2]:
            cand.append(r.real)
    vals = np.polynomial.polynomial.polyval(np.array(cand), c)
    best = int(np.argmax(vals))
    return float(vals[best]), float(x0 + cand[best] * scale)


def _line(pos, vals, at):
    """Values of vals[k, :] (sampled at pos[k]) linearly interpolated at `at`."""
    k = int(np.clip(np.searchsorted(pos, at) - 1, 0, len(pos) - 2))
    w = (at - pos[k]) / (pos[k + 1] - pos[k])
    return (1.0 - w) * vals[k] + w * vals[k + 1]


def analyse(grid, q, ra, pr):
    """The result dict of a solution q on grid (see solve)."""
    u, v, p, t = grid.split(q)
    ax, ay, n = grid.ax, grid.ay, grid.n
    (xu, yu, uf), (xv, yv, vf), _, (xt, yt, tf) = grid.padded(q)
    nu_local = (1.0 - t[0, :]) / ax.h[0]
    nu_cold = t[-1, :] / ax.h[-1]
    # vertical centre line x = 0.5: y at the centres plus the walls
    u_mid = _line(xu, uf, 0.5)
    t_vmid = _line(xt, tf, 0.5)
    # horizontal centre line y = 0.5: x at the centres plus the walls
    v_mid = _line(yv, vf.T, 0.5)
    t_hmid = _line(yt, tf.T, 0.5)
    umax, y_umax = _max_poly(yu, u_mid)
    vmax, x_vmax = _max_poly(xv, v_mid)
    # stream function at the nodes, u = dpsi/dy, v = -dpsi/dx, psi = 0 on the walls
    psi = np.zeros((n + 1, n + 1))
    psi[1:-1, 1:] = np.cumsum(u * ay.d, axis=1)
    psi_mid = float(_line(ay.f, _line(ax.f, psi, 0.5), 0.5))
    return {
        "ra": float(ra), "pr": float(pr), "n": int(n), "stretch": float(grid.stretch),
        "nu_mean_hot": float(np.sum(nu_local * ay.d)),
        "nu_mean_cold": float(np.sum(nu_cold * ay.d)),
        "umax": umax, "y_umax": y_umax, "vmax": vmax, "x_vmax": x_vmax,
        "psi_mid": abs(psi_mid), "psi_abs_max": float(np.abs(psi).max()),
        "hmid": {"x": xt, "theta": t_hmid, "v": v_mid},
        "vmid": {"y": yt, "theta": t_vmid, "u": u_mid},
        "hot_wall": {"y": ay.c.copy(), "nu_local": nu_local},
        "centres": {"x": ax.c.copy(), "y": ay.c.copy(), "theta": t.copy(),
                    "u": (grid.u_to_c @ u.ravel()).reshape(n, n),
                    "v": (grid.v_to_c @ v.ravel()).reshape(n, n), "p": p.copy()},
        "nodes": {"x": ax.f.copy(), "y": ay.f.copy(), "psi": psi},
        "layout": LAYOUT,
    }


def solve(ra, pr=0.71, n=64, stretch=1.5, tol=1e-9, n_start=32, verbose=False, _grids=None):
    """Steady solution at Rayleigh number ra, Prandtl number pr on n x n cells.

    stretch: the b of the wall-clustering map (0: uniform). The solution is
    reached by Ra continuation on the coarsest grid of n, n/2, n/4, ... that
    is >= n_start, then by grid sequencing. Returns a dict:
      ra, pr, n, stretch, t (only transient), nu_mean_hot, nu_mean_cold,
      umax, y_umax (on x = 0.5), vmax, x_vmax (on y = 0.5),
      psi_mid (|psi| at the centre), psi_abs_max,
      hmid: {x, theta, v}   along y = 0.5, x = cell centres plus the walls
      vmid: {y, theta, u}   along x = 0.5, y = cell centres plus the walls
      hot_wall: {y, nu_local}  -dtheta/dx on x = 0 at the cell-centre y
      centres: {x, y, theta, u, v, p}  cell-centre fields, [i_x, j_y]
               (u, v averaged from the faces)
      nodes: {x, y, psi}  stream function at the cell corners, [i_x, j_y],
             u = dpsi/dy, v = -dpsi/dx (negative: clockwise circulation)
    Arrays are numpy arrays (to_json() makes lists)."""
    if pr <= 0 or ra < 0:
        raise ValueError("need Pr > 0 and Ra >= 0")
    start = None
    for m in _chain(n, n_start):
        grid = Grid(m, stretch)
        q = _steady(grid, ra, pr, tol, start, verbose)
        start = (grid, q)
        if _grids is not None:
            _grids[m] = analyse(grid, q, ra, pr)
    return analyse(grid, q, ra, pr)


def transient(ra, pr=0.71, n=32, t_end=0.5, dt=1e-3, stretch=1.5, tol=1e-9, theta0=0.5, verbose=False):
    """From rest at uniform theta = theta0 to t_end by BDF2 (first step
    backward Euler) with a fixed step dt; returns the dict of solve at t_end
    with the time as 't'."""
    grid = Grid(n, stretch)
    report = None
    if verbose:
        def report(t, q):
            res = analyse(grid, q, ra, pr)
            print(f"#   t {t:.4g}: Nu hot {res['nu_mean_hot']:.5f} cold {res['nu_mean_cold']:.5f}",
                  file=sys.stderr)
    q = march(grid, grid.uniform(theta0), ra, pr, t_end, dt, tol, report)
    res = analyse(grid, q, ra, pr)
    res["t"] = float(t_end)
    return res


def march(grid, q, ra, pr, t_end, dt, tol=1e-9, report=None):
    """Integrate the solution q on grid over the time t_end by BDF2 (first
    step backward Euler) with a fixed step near dt, Newton per step; returns
    the final q. report(t, q), if given, is called ten times on the way."""
    M = sp.diags(grid.mass)
    steps = max(1, int(math.ceil(t_end / dt - 1e-9)))
    dt = t_end / steps
    q_old = None
    for k in range(steps):
        if q_old is None:
            a0, hist = 1.0 / dt, q / dt                      # backward Euler
        else:
            a0, hist = 1.5 / dt, (2.0 * q - 0.5 * q_old) / dt  # BDF2
        qn = q.copy() if q_old is None else 2.0 * q - q_old
        for it in range(20):
            r, J = grid.residual(qn, ra, pr)
            r = r + grid.mass * (a0 * qn - hist)
            dq = _factor(J + a0 * M).solve(-r)
            qn += dq
            if _norms(grid, qn, dq) < tol:
                break
        else:
            raise NoConvergence(f"time step {k} did not converge")
        q_old, q = q, qn
        if report is not None and (k + 1) % max(1, steps // 10) == 0:
            report((k + 1) * dt, q)
    return q


def profiles_at(result, xs):
    """theta and v on y = 0.5 at the positions xs (linear interpolation
    between the cell centres and the walls); returns (theta, v)."""
    h = result["hmid"]
    xs = np.asarray(xs, dtype=float)
    return np.interp(xs, h["x"], h["theta"]), np.interp(xs, h["x"], h["v"])


def vertical_profiles_at(result, ys):
    """theta and u on x = 0.5 at the positions ys; returns (theta, u)."""
    h = result["vmid"]
    ys = np.asarray(ys, dtype=float)
    return np.interp(ys, h["y"], h["theta"]), np.interp(ys, h["y"], h["u"])


QUANTITIES = ("nu_mean_hot", "umax", "vmax", "psi_mid")


def richardson(ra, pr=0.71, n=128, stretch=1.5, tol=1e-9, n_start=32, verbose=False):
    """Solve on n/4, n/2, n (same map) and extrapolate. Returns (results by
    n, {quantity: (value_n, extrapolated, estimated error of value_n,
    observed order)}). The extrapolation uses the observed order p when
    1 < p < 4, else 2."""
    if n % 4:
        raise ValueError("--richardson needs n divisible by 4")
    grids = {}
    solve(ra, pr, n, stretch, tol, n_start=min(n_start, n // 4), verbose=verbose, _grids=grids)
    f1, f2, f3 = (grids[n // 4], grids[n // 2], grids[n])
    table = {}
    for key in QUANTITIES:
        c = f3[key]
        extra, order = extrapolate(f1[key], f2[key], c)
        table[key] = (c, extra, c - extra, order)
    return grids, table


def extrapolate(a, b, c):
    """Richardson extrapolation of the values a, b, c on grids of spacing
    4h, 2h, h: returns (extrapolated value, observed order). The observed
    order p = log2((b - a) / (c - b)) is used when 1 < p < 4, else 2 (the
    scheme's), so that a noisy or non-monotone sequence is not extrapolated
    with a wild exponent; the order is nan when the sequence is not monotone."""
    order = float("nan")
    if (b - a) * (c - b) > 0 and c != b:
        order = math.log((b - a) / (c - b)) / math.log(2.0)
    p = order if 1.0 < order < 4.0 else 2.0
    return c + (c - b) / (2.0 ** p - 1.0), order


def to_json(result):
    def conv(v):
        if isinstance(v, dict):
            return {k: conv(x) for k, x in v.items()}
        if isinstance(v, np.ndarray):
            return v.tolist()
        return v
    return conv(result)


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--ra", type=float, required=True, help="Rayleigh number (0 for conduction)")
    p.add_argument("--pr", type=float, default=0.71, help="Prandtl number (default 0.71)")
    p.add_argument("--n", type=int, default=64, help="cells per side (default 64)")
    p.add_argument("--stretch", type=float, default=1.5,
                   help="wall clustering b of the tanh map, 0 = uniform (default 1.5)")
    p.add_argument("--tol", type=float, default=1e-9, help="Newton stopping tolerance (default 1e-9)")
    p.add_argument("--out", help="write the result (profiles, wall Nu, fields) as JSON to this file")
    p.add_argument("--richardson", action="store_true",
                   help="also solve on N/4 and N/2 and print the extrapolated values and the error of N")
    p.add_argument("--t-end", type=float,
                   help="transient from rest at theta = 0.5 to this time (units L^2/alpha) instead of steady")
    p.add_argument("--dt", type=float, default=1e-3, help="time step of --t-end (default 1e-3)")
    p.add_argument("--verbose", action="store_true", help="print the Newton iterations to stderr")
    args = p.parse_args()

    t0 = time.time()
    table = None
    if args.t_end is not None:
        res = transient(args.ra, args.pr, args.n, args.t_end, args.dt, args.stretch, args.tol,
                        verbose=args.verbose)
    elif args.richardson:
        grids, table = richardson(args.ra, args.pr, args.n, args.stretch, args.tol, verbose=args.verbose)
        res = grids[args.n]
    else:
        res = solve(args.ra, args.pr, args.n, args.stretch, args.tol, verbose=args.verbose)
    elapsed = time.time() - t0

    head = f"Ra = {res['ra']:g}, Pr = {res['pr']:g}, N = {res['n']} (stretch {res['stretch']:g})"
    if "t" in res:
        head += f", t = {res['t']:g}"
    print(head)
    print(f"Nu mean hot wall  = {res['nu_mean_hot']:.6f}")
    print(f"Nu mean cold wall = {res['nu_mean_cold']:.6f}")
    print(f"u_max on x = 0.5  = {res['umax']:.5f} at y = {res['y_umax']:.5f}")
    print(f"v_max on y = 0.5  = {res['vmax']:.5f} at x = {res['x_vmax']:.5f}")
    print(f"|psi| at centre   = {res['psi_mid']:.5f}")
    ref = DE_VAHL_DAVIS.get(res["ra"]) if abs(res["pr"] - 0.71) < 1e-12 and "t" not in res else None
    if ref:
        print(f"de Vahl Davis (1983): Nu {ref[0]}, u_max {ref[1]}, v_max {ref[2]}")
    if table:
        n = args.n
        print(f"Richardson over N = {n // 4}, {n // 2}, {n}:")
        for key, (value, extra, err, order) in table.items():
            print(f"  {key:12s} N {n}: {value:.6f}  extrapolated {extra:.6f}  "
                  f"error of N {err:+.2e} ({err / extra:+.2e} relative)  observed order {order:.2f}")
    print(f"# {elapsed:.1f} s")
    if args.out:
        with open(args.out, "w") as f:
            json.dump(to_json(res), f)
    return 0


if __name__ == "__main__":
    sys.exit(main())
