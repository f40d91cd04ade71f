#!/usr/bin/env python3
"""Finite-volume reference for melting and solidification with natural
convection in a rectangle: the enthalpy-porosity method (Voller and Prakash,
Int. J. Heat Mass Transfer 30 (1987) 1709-1719; Brent, Voller and Reid,
Numer. Heat Transfer 13 (1988) 297-318), the same model as fix sph/phase.

The model: a rectangle [0, W] x [0, H], no-slip walls, the left wall x = 0
at T_left, the right wall x = W at T_right, top and bottom adiabatic; at rest
and at T0 everywhere at t = 0. Incompressible Boussinesq flow with a
Carman-Kozeny (Darcy) sink, and the enthalpy equation:

    div u = 0
    rho0 (du/dt + (u.grad)u) = -grad p + mu lap u
                               + rho0 g beta (T - T_ref) e_y - D(f) u
    D(f) = C (1 - f)^2 / (f^3 + eps)
    rho0 (de/dt + u.grad e) = div(k grad T)
    e = cp T + L f(T),  pure substance (melting point Tm):
        f = 0 for e <= cp Tm, (e - cp Tm)/L in between, 1 for e >= cp Tm + L
        T = (e - L f)/cp   (T = Tm in the mushy range)

k may differ in the phases (k = k_s + (k_l - k_s) f in a cell, harmonic mean
at a face); rho0, cp and mu are the same in both.

Method: finite volumes on a uniform staggered (MAC) grid nx x ny, u on the
vertical faces, v on the horizontal faces, p, e, T, f at the cell centres.
- Diffusion (heat and momentum): two-point central fluxes, the half cell at
  a Dirichlet wall (the no-slip wall by the mirrored ghost value -u): second
  order.
- Advection (enthalpy and momentum): conservative fluxes through the faces
  with the face (mass-conserving) velocities; the face value by van Leer's
  limited upwind-biased reconstruction (a TVD, bounded scheme: second order
  where the solution is smooth and monotone, first order at extrema).
- Time: explicit (forward Euler) for the enthalpy and the momentum
  predictor, the Darcy sink implicit pointwise (u** = (u + dt R)/(1 + dt D/
  rho0): stable for any C), buoyancy and Darcy evaluated with the new T and
  f; then an incremental pressure projection (Poisson with Neumann walls,
  factorised once by scipy's SuperLU, the pressure pinned in one cell) that
  makes the face velocities discretely divergence-free. The step is
  dt = safety / max over (heat, momentum) of
  [2 kappa (1/dx^2 + 1/dy^2) + 2 (|u|max/dx + |v|max/dy)],
  kappa = max alpha resp. nu, safety 0.9: in all the cases here the thermal
  diffusion limit dominates, dt ~ dx^2, so the O(dt) error of forward Euler
  is O(dx^2): the scheme is second order in dx overall, except for the
  enthalpy method's own first-order error at the front of a pure substance
  (the mushy cell).
Wall heat flux: k (T_wall - T_cell) / (dx/2), exactly the flux the enthalpy
update uses, so the energy balance (reported) closes to round-off.

Outputs at the requested times: liquid fraction (mean f), front x_f(y) (f
interpolated linearly in y between cell rows to the height y, then the first
crossing of f = 0.5 going from the left wall, linear between cell centres;
the wall itself counts as liquid when T_left > Tm, solid otherwise), wall heat
flows and Nusselt numbers Nu = Q W / (k_l H (T_left - T_right)) through the
left and right walls (Q the heat flow in +x through that wall per unit
depth), the largest speed, and optionally the fields.

Cases (--case): stefan (1-D two-phase Stefan problem against Neumann's exact
solution, tools/stefan.py), cavity (de Vahl Davis 1983, no phase change),
gallium (Gau and Viskanta 1986 as set up by Brent et al. 1988), freezing
(a liquid frozen from a cooled wall in a square cavity, Ra 1e5, Pr 1, Ste 1;
--g 0 for pure conduction).

    python3 tools/phase_fv.py --case gallium --nx 42 --ny 30 --out g42.json
    python3 tools/phase_fv.py --case freezing --nx 64 --ny 64 --npz f64.npz
    python3 tools/phase_fv.py --write-results stefan cavity gallium freezing
        # all the validation and reference runs -> tools/phase_fv_results.json
        # and the tables in tools/phase_fv.md (between the RESULTS markers)
"""

import argparse
import json
import math
import os
import sys
import time

import numpy as np
import scipy.sparse as sp
import scipy.sparse.linalg as spla

import gallium_reference as gref
import stefan

HERE = os.path.dirname(os.path.abspath(__file__))

RESULTS = os.path.join(HERE, "phase_fv_results.json")
MARKDOWN = os.path.join(HERE, "phase_fv.md")


# ----------------------------------------------------------------- cases

def reference_series(name, kind=None):
    """The stored series of a case from RESULTS, for the comparisons of the
    examples and tests: name 'gallium', or 'freezing' with kind
    'convection' or 'conduction'. Returns ({t: sample} on the finest grid,
    {t: sample} on the next coarser one, the two grids' labels); a sample
    has liquid_fraction, fronts (by height key, see front_heights), Nu_left
    and Nu_right."""
    with open(RESULTS) as f:
        runs = json.load(f)[name]
    runs = runs["grids"] if kind is None else runs[kind]
    size = lambda label: int(label.split("x")[0])  # noqa: E731
    grids = sorted(runs, key=size)
    fine, coarse = ({s["t"]: s for s in runs[g]["series"]} for g in (grids[-1], grids[-2]))
    return fine, coarse, grids[-1], grids[-2]


def make_case(name, **over):
    """The named scene as a dict of parameters (SI or dimensionless)."""
    if name == "gallium":
        c = dict(W=gref.WIDTH, H=gref.HEIGHT, rho=gref.RHO, cp=gref.CP, k_s=gref.K, k_l=gref.K,
                 mu=1.81e-3, beta=1.2e-4, g=9.81, L=gref.LATENT, Tm=gref.T_MELT, Tref=gref.T_MELT,
                 T_left=gref.T_HOT, T_right=gref.T_INITIAL, T0=gref.T_INITIAL, C=1.6e6, eps=1e-3,
                 times=[60.0 * m for m in (1, 2, 3, 4.5, 6, 8, 10, 12.5, 15, 17, 19)])
    elif name == "freezing":
        a = math.sqrt(2e-5)
        c = dict(W=1.0, H=1.0, rho=1.0, cp=1.0, k_s=a, k_l=a, mu=a, beta=1.0, g=1.0, L=1.0,
                 Tm=0.0, Tref=0.0, T_left=-1.0, T_right=1.0, T0=1.0, C=1e6, eps=1e-3,
                 times=[10.0, 20.0, 40.0, 80.0, 160.0, 320.0])
    elif name == "stefan":
        # examples/phase-stefan's two-phase case: every property 1, Tm = 0,
        # L = 1 (St_l = 1), solid at -0.5 (St_s = 0.5), wall at 1, strip [0, 4]
        c = dict(W=4.0, H=1.0, rho=1.0, cp=1.0, k_s=1.0, k_l=1.0, mu=1.0, beta=0.0, g=0.0,
                 L=1.0, Tm=0.0, Tref=0.0, T_left=1.0, T_right=-0.5, T0=-0.5, C=0.0, eps=1e-3,
                 times=[round(0.05 * i, 10) for i in range(1, 21)])
    elif name == "cavity":
        # de Vahl Davis: unit square, alpha = 1, nu = Pr, g beta = Ra Pr,
        # theta 1 (left) and 0 (right), Tm far below: all liquid, no Darcy
        ra, pr = over.pop("ra", 1e5), over.pop("pr", 0.71)
        c = dict(W=1.0, H=1.0, rho=1.0, cp=1.0, k_s=1.0, k_l=1.0, mu=pr, beta=1.0, g=ra * pr,
                 L=0.0, Tm=-100.0, Tref=0.5, T_left=1.0, T_right=0.0, T0=0.5, C=0.0, eps=1e-3,
                 times=[0.1, 0.2, 0.3, 0.4, 0.5, 0.6], ra=ra, pr=pr)
    else:
        raise ValueError(f"unknown case {name}")
    c["name"] = name
    c.update(over)
    return c


# ----------------------------------------------------------------- numerics

def _slope(a, b):
    """van Leer's limited slope 2ab/(a+b) where a, b have one sign, else 0."""
    ab = a * b
    s = a + b
    out = np.zeros_like(a)
    np.divide(2.0 * ab, s, out=out, where=ab > 0.0)
    return out


def tvd_face(q, a):
    """Face values between q[k] and q[k+1] (axis 0) for face velocities a
    (shape of q minus one along axis 0): van Leer-limited upwind
    reconstruction, first-order upwind at the first and last face."""
    dq = q[1:] - q[:-1]
    z = np.zeros_like(dq[:1])
    dm = np.concatenate([z, dq[:-1]])
    dp = np.concatenate([dq[1:], z])
    pos = q[:-1] + 0.5 * _slope(dm, dq)
    neg = q[1:] - 0.5 * _slope(dp, dq)
    return np.where(a >= 0.0, pos, neg)


def poisson_solver(nx, ny, dx, dy):
    """Factorised Neumann Laplacian on the cells (index i * ny + j), the
    first cell's equation replaced by phi = 0."""
    def lap1(n, h):
        d = -2.0 * np.ones(n)
        d[0] = d[-1] = -1.0
        return sp.diags([np.ones(n - 1), d, np.ones(n - 1)], [-1, 0, 1]) / h ** 2
    A = sp.kron(lap1(nx, dx), sp.identity(ny)) + sp.kron(sp.identity(nx), lap1(ny, dy))
    A = A.tolil()
    A[0, :] = 0.0
    A[0, 0] = 1.0
    return spla.factorized(A.tocsc())


class State:
    """The fields and the step of the scheme for one case on one grid."""

    def __init__(self, case, nx, ny):
        self.c = case
        self.nx, self.ny = nx, ny
        self.dx, self.dy = case["W"] / nx, case["H"] / ny
        self.xc = (np.arange(nx) + 0.5) * self.dx
        self.yc = (np.arange(ny) + 0.5) * self.dy
        cp, L, Tm = case["cp"], case["L"], case["Tm"]
        T0 = case["T0"]
        f0 = 1.0 if T0 > Tm else 0.0
        self.e = np.full((nx, ny), cp * T0 + L * f0)
        self.u = np.zeros((nx + 1, ny))
        self.v = np.zeros((nx, ny + 1))
        self.p = np.zeros((nx, ny))
        self.t = 0.0
        self.steps = 0
        self.flow = case["g"] != 0.0 and case["beta"] != 0.0
        self.solve_p = poisson_solver(nx, ny, self.dx, self.dy) if self.flow else None
        self.e_init = self.e.sum() * self.dx * self.dy
        self.heat_in = 0.0  # time integral of (Q_left - Q_right)
        self.update_phase()

    # enthalpy -> f, T, k
    def update_phase(self):
        c = self.c
        es = c["cp"] * c["Tm"]
        if c["L"] > 0.0:
            self.f = np.clip((self.e - es) / c["L"], 0.0, 1.0)
        else:
            self.f = (self.e > es).astype(float)
        self.T = (self.e - c["L"] * self.f) / c["cp"]
        self.k = c["k_s"] + (c["k_l"] - c["k_s"]) * self.f

    def wall_flows(self):
        """Heat flows in +x through the left and right walls, per unit depth."""
        c, dx, dy = self.c, self.dx, self.dy
        ql = -self.k[0] * (self.T[0] - c["T_left"]) / (0.5 * dx)
        qr = -self.k[-1] * (c["T_right"] - self.T[-1]) / (0.5 * dx)
        return ql.sum() * dy, qr.sum() * dy

    def timestep(self):
        c = self.c
        idx2 = 1.0 / self.dx ** 2 + 1.0 / self.dy ** 2
        adv = 2.0 * (np.abs(self.u).max() / self.dx + np.abs(self.v).max() / self.dy)
        alpha = max(c["k_s"], c["k_l"]) / (c["rho"] * c["cp"])
        nu = c["mu"] / c["rho"] if self.flow else 0.0
        return 0.9 / (2.0 * max(alpha, nu) * idx2 + adv)

    def step(self, dt):
        c = self.c
        dx, dy = self.dx, self.dy
        rho = c["rho"]
        u, v, e, T, k = self.u, self.v, self.e, self.T, self.k
        # ---- enthalpy: conduction fluxes (in +x, +y) and advection
        kx = 2.0 * k[1:] * k[:-1] / (k[1:] + k[:-1])
        ky = 2.0 * k[:, 1:] * k[:, :-1] / (k[:, 1:] + k[:, :-1])
        qx = np.empty((self.nx + 1, self.ny))
        qx[1:-1] = -kx * (T[1:] - T[:-1]) / dx
        qx[0] = -k[0] * (T[0] - c["T_left"]) / (0.5 * dx)
        qx[-1] = -k[-1] * (c["T_right"] - T[-1]) / (0.5 * dx)
        qy = np.zeros((self.nx, self.ny + 1))
        qy[:, 1:-1] = -ky * (T[:, 1:] - T[:, :-1]) / dy
        rhs = -((qx[1:] - qx[:-1]) / dx + (qy[:, 1:] - qy[:, :-1]) / dy) / rho
        if self.flow:
            fx = np.zeros_like(u)
            fx[1:-1] = u[1:-1] * tvd_face(e, u[1:-1])
            fy = np.zeros_like(v)
            fy[:, 1:-1] = v[:, 1:-1] * tvd_face(e.T, v[:, 1:-1].T).T
            rhs -= (fx[1:] - fx[:-1]) / dx + (fy[:, 1:] - fy[:, :-1]) / dy
        self.heat_in += dt * (qx[0].sum() - qx[-1].sum()) * dy
        self.e = e + dt * rhs
        self.update_phase()
        if self.flow:
            self.momentum(dt)
        self.t += dt
        self.steps += 1

    def momentum(self, dt):
        c = self.c
        dx, dy = self.dx, self.dy
        rho, nu = c["rho"], c["mu"] / c["rho"]
        u, v, p, T, f = self.u, self.v, self.p, self.T, self.f
        # u on the interior vertical faces (nx - 1, ny)
        ac = 0.5 * (u[:-1] + u[1:])
        Fx = ac * tvd_face(u, ac)
        av = 0.5 * (v[:-1, 1:-1] + v[1:, 1:-1])
        ui = u[1:-1]
        Fy = np.zeros((self.nx - 1, self.ny + 1))
        Fy[:, 1:-1] = av * tvd_face(ui.T, av.T).T
        ue = np.concatenate([-ui[:, :1], ui, -ui[:, -1:]], axis=1)
        ru = (-(Fx[1:] - Fx[:-1]) / dx - (Fy[:, 1:] - Fy[:, :-1]) / dy
              + nu * ((u[2:] - 2.0 * ui + u[:-2]) / dx ** 2
                      + (ue[:, 2:] - 2.0 * ui + ue[:, :-2]) / dy ** 2)
              - (p[1:] - p[:-1]) / (rho * dx))
        fu = 0.5 * (f[1:] + f[:-1])
        du = c["C"] * (1.0 - fu) ** 2 / (fu ** 3 + c["eps"]) / rho
        # v on the interior horizontal faces (nx, ny - 1)
        ac = 0.5 * (v[:, :-1] + v[:, 1:])
        Gy = ac * tvd_face(v.T, ac.T).T
        au = 0.5 * (u[1:-1, :-1] + u[1:-1, 1:])
        vi = v[:, 1:-1]
        Gx = np.zeros((self.nx + 1, self.ny - 1))
        Gx[1:-1] = au * tvd_face(vi, au)
        ve = np.concatenate([-vi[:1], vi, -vi[-1:]], axis=0)
        Tv = 0.5 * (T[:, 1:] + T[:, :-1])
        rv = (-(Gx[1:] - Gx[:-1]) / dx - (Gy[:, 1:] - Gy[:, :-1]) / dy
              + nu * ((ve[2:] - 2.0 * vi + ve[:-2]) / dx ** 2
                      + (v[:, 2:] - 2.0 * vi + v[:, :-2]) / dy ** 2)
              - (p[:, 1:] - p[:, :-1]) / (rho * dy)
              + c["g"] * c["beta"] * (Tv - c["Tref"]))
        fv = 0.5 * (f[:, 1:] + f[:, :-1])
        dv = c["C"] * (1.0 - fv) ** 2 / (fv ** 3 + c["eps"]) / rho
        un = u.copy()
        vn = v.copy()
        un[1:-1] = (ui + dt * ru) / (1.0 + dt * du)
        vn[:, 1:-1] = (vi + dt * rv) / (1.0 + dt * dv)
        # projection
        div = (un[1:] - un[:-1]) / dx + (vn[:, 1:] - vn[:, :-1]) / dy
        b = (rho / dt) * div.ravel()
        b[0] = 0.0
        phi = self.solve_p(b).reshape(self.nx, self.ny)
        un[1:-1] -= dt / rho * (phi[1:] - phi[:-1]) / dx
        vn[:, 1:-1] -= dt / rho * (phi[:, 1:] - phi[:, :-1]) / dy
        self.u, self.v = un, vn
        self.p = p + phi

    # ---- measures
    def centre_velocity(self):
        return 0.5 * (self.u[1:] + self.u[:-1]), 0.5 * (self.v[:, 1:] + self.v[:, :-1])

    def _row(self, q, y):
        if self.ny == 1:
            return q[:, 0]
        j = np.clip((y - self.yc[0]) / self.dy, 0.0, self.ny - 1.0)
        j0 = min(int(j), self.ny - 2)
        return q[:, j0] * (1.0 - (j - j0)) + q[:, j0 + 1] * (j - j0)

    @staticmethod
    def _crossing(xs, qs, level, end):
        side = qs[0] > level
        for i in range(1, len(qs)):
            if (qs[i] > level) != side:
                return float(xs[i - 1] + (qs[i - 1] - level) / (qs[i - 1] - qs[i]) * (xs[i] - xs[i - 1]))
        return float(end)

    def front(self, y):
        """x of the first crossing of f = 0.5 from the left wall at height y."""
        fw = 1.0 if self.c["T_left"] > self.c["Tm"] else 0.0
        xs = np.concatenate([[0.0], self.xc])
        return self._crossing(xs, np.concatenate([[fw], self._row(self.f, y)]), 0.5, self.c["W"])

    def front_T(self, y):
        """x of the first crossing of T = Tm (the melting isotherm, linear
        between the wall and the cell centres) from the left wall."""
        xs = np.concatenate([[0.0], self.xc])
        ts = np.concatenate([[self.c["T_left"]], self._row(self.T, y)])
        return self._crossing(xs, ts, self.c["Tm"], self.c["W"])

    def sample(self, front_heights):
        c = self.c
        ql, qr = self.wall_flows()
        dT = c["T_left"] - c["T_right"]
        nu_scale = c["W"] / (c["k_l"] * c["H"] * dT) if dT != 0 else float("nan")
        uc, vc = self.centre_velocity()
        stored = c["rho"] * (self.e.sum() * self.dx * self.dy - self.e_init)
        out = dict(t=self.t, steps=self.steps, liquid_fraction=float(self.f.mean()),
                   Q_left=ql, Q_right=qr, Nu_left=ql * nu_scale, Nu_right=qr * nu_scale,
                   max_speed=float(np.sqrt(uc ** 2 + vc ** 2).max()),
                   energy_balance=(stored - self.heat_in) / max(abs(self.heat_in), 1e-300),
                   fronts={name: self.front(y) / c["W"] for name, y in front_heights.items()},
                   fronts_T={name: self.front_T(y) / c["W"] for name, y in front_heights.items()})
        return out

    def fields(self):
        uc, vc = self.centre_velocity()
        X, Y = np.meshgrid(self.xc, self.yc, indexing="ij")
        return dict(x=X, y=Y, T=self.T, f=self.f, u=uc, v=vc, p=self.p, t=self.t)


def front_heights(case, rows=(20, 28, 40)):
    """The heights of the fronts: top (H - dy/2), middle (H/2) and bottom
    (dy/2) for the SPH rows dy = H/n, n in rows; 'mid_row' is the row centre
    next below H/2 (the row gallium_reference.front_positions takes)."""
    H = case["H"]
    out = {"middle": 0.5 * H}
    for n in rows:
        dy = H / n
        out[f"top_{n}"] = H - 0.5 * dy
        out[f"bottom_{n}"] = 0.5 * dy
        centres = (np.arange(n) + 0.5) * dy
        out[f"mid_row_{n}"] = float(centres[np.argmin(np.abs(centres - 0.5 * H))])
    return out


def run(case, nx, ny, times=None, rows=(20, 28, 40), npz=None, steady_every=None, steady_tol=1e-4,
        t_max=None, verbose=False):
    """Integrate the case on an nx x ny grid; a dict with the samples at
    the times (and, with steady_every, the first time at which the mean f
    changed by less than steady_tol over steady_every, integrating on to
    t_max at most)."""
    times = sorted(case["times"] if times is None else times)
    s = State(case, nx, ny)
    heights = front_heights(case, rows)
    t_start = time.time()
    series = []
    stops = list(times)
    steady = None
    if steady_every:
        t_end = max(times[-1], t_max or times[-1])
        checks = list(np.arange(steady_every, t_end + 0.5 * steady_every, steady_every))
        stops = sorted(set(stops) | set(float(x) for x in checks))
        last_f = s.f.mean()
    for stop in stops:
        while s.t < stop - 1e-12 * max(stop, 1.0):
            dt = min(s.timestep(), stop - s.t)
            s.step(dt)
            if not np.isfinite(s.e[0, 0]):
                raise FloatingPointError("diverged")
        if any(abs(stop - t) < 1e-9 for t in times):
            smp = s.sample(heights)
            series.append(smp)
            if npz:
                np.savez(npz.replace(".npz", f"_t{stop:g}.npz"), **s.fields())
            if verbose:
                print(f"t {s.t:9.3f} steps {s.steps:7d} f {smp['liquid_fraction']:.5f} "
                      f"Nu {smp['Nu_left']:.4f} {smp['Nu_right']:.4f} |u| {smp['max_speed']:.4g} "
                      "fronts " + " ".join(f"{smp['fronts'][k]:.4f}" for k in sorted(smp['fronts'])
                                           if k[-2:] in ("28", "40", "le"))
                      + f"  {time.time() - t_start:.0f} s",
                      file=sys.stderr, flush=True)
        if steady_every and any(abs(stop - x) < 1e-9 for x in checks):
            fm = s.f.mean()
            if steady is None and abs(fm - last_f) < steady_tol:
                steady = dict(t=s.t, sample=s.sample(heights))
                if stop >= times[-1]:
                    break
            last_f = fm
    res = dict(case=case["name"], nx=nx, ny=ny, dx=s.dx, dy=s.dy, steps=s.steps,
               seconds=time.time() - t_start, heights=heights, series=series)
    if steady_every:
        res["steady"] = steady
        res["t_end"] = s.t
    return res, s


# ----------------------------------------------------------------- validation / reference runs

def stefan_runs(grids=(40, 80, 160, 320, 640)):
    c = make_case("stefan")
    st_l = c["cp"] * (c["T_left"] - c["Tm"]) / c["L"]
    st_s = c["cp"] * (c["Tm"] - c["T0"]) / c["L"]
    lam = stefan.neumann_lambda(st_l, st_s, 1.0)
    out = dict(lam=lam, st_l=st_l, st_s=st_s, grids={})
    for n in grids:
        res, _ = run(make_case("stefan", H=2.0 * 4.0 / n), n, 2, rows=(2,))
        rows = []
        for smp in res["series"]:
            exact = stefan.front(smp["t"], lam, 1.0)
            depth = smp["liquid_fraction"] * c["W"]
            xf = smp["fronts"]["middle"] * c["W"]
            rows.append(dict(t=smp["t"], exact=exact, melt_depth=depth, x_front=xf,
                             err_depth=depth - exact, err_front=xf - exact,
                             energy_balance=smp["energy_balance"]))
        late = [r for r in rows if r["t"] >= 0.25 - 1e-9]
        out["grids"][str(n)] = dict(dx=c["W"] / n, steps=res["steps"], seconds=res["seconds"], rows=rows,
                                    max_err_depth=max(abs(r["err_depth"]) for r in late),
                                    max_err_front=max(abs(r["err_front"]) for r in late),
                                    max_energy_balance=max(abs(r["energy_balance"]) for r in rows))
        print(f"stefan n {n}: max err depth {out['grids'][str(n)]['max_err_depth']:.2e} "
              f"front {out['grids'][str(n)]['max_err_front']:.2e}", flush=True)
    return out


DVD_NU = {1e4: 2.243, 1e5: 4.519}


def cavity_runs(cases=((1e4, (32, 64)), (1e5, (32, 64)))):
    out = {}
    for ra, grids in cases:
        out[f"{ra:g}"] = {}
        for n in grids:
            c = make_case("cavity", ra=ra)
            res, s = run(c, n, n, rows=(20,))
            last, prev = res["series"][-1], res["series"][-2]
            uc, vc = s.centre_velocity()
            out[f"{ra:g}"][str(n)] = dict(
                t=last["t"], Nu_left=last["Nu_left"], Nu_right=last["Nu_right"],
                Nu_left_prev=prev["Nu_left"], t_prev=prev["t"], reference=DVD_NU[ra],
                err_left=last["Nu_left"] / DVD_NU[ra] - 1.0, err_right=last["Nu_right"] / DVD_NU[ra] - 1.0,
                steps=res["steps"], seconds=res["seconds"],
                series=[(x["t"], x["Nu_left"], x["Nu_right"]) for x in res["series"]])
            print(f"cavity Ra {ra:g} n {n}: Nu {last['Nu_left']:.4f} {last['Nu_right']:.4f} "
                  f"(t {prev['t']:g}: {prev['Nu_left']:.4f}) {res['seconds']:.0f} s", flush=True)
    return out


def gallium_runs(grids=((42, 30), (63, 45), (84, 60), (126, 90))):
    out = {"conduction_1min": gref.conduction_melt_fraction(60.0), "grids": {}}
    for nx, ny in grids:
        res, _ = run(make_case("gallium"), nx, ny, verbose=True)
        out["grids"][f"{nx}x{ny}"] = res
        print(f"gallium {nx}x{ny}: {res['seconds']:.0f} s", flush=True)
    return out


def freezing_runs(grids=(32, 64, 96), g0_grids=(32, 64, 128), steady_grid=32):
    out = {"convection": {}, "conduction": {}}
    for n in grids:
        res, _ = run(make_case("freezing"), n, n, rows=(20, 30, 40), verbose=True, steady_every=10.0,
                     t_max=(1000.0 if n == steady_grid else None))
        out["convection"][str(n)] = res
        print(f"freezing {n}: {res['seconds']:.0f} s steady {res['steady'] and res['steady']['t']}", flush=True)
    for n in g0_grids:
        c = make_case("freezing", g=0.0, H=2.0 / n)
        res, _ = run(c, n, 2, times=c["times"] + [1000.0, 2000.0], rows=(2,), steady_every=10.0)
        out["conduction"][str(n)] = res
        print(f"freezing g=0 {n}: thickness {1 - res['series'][-1]['liquid_fraction']:.6f} "
              f"{res['seconds']:.0f} s", flush=True)
    return out


# ----------------------------------------------------------------- tables

def _fmt(x, p=4):
    return f"{x:.{p}f}"


def markdown(results):
    L = []
    if "stefan" in results:
        r = results["stefan"]
        L.append(f"### Stefan problem (two-phase, St_l = {r['st_l']:g}, St_s = {r['st_s']:g}, "
                 f"lam = {r['lam']:.6f})\n")
        L.append("Errors against Neumann's s(t) = 2 lam sqrt(t): the melt depth (liquid volume per "
                 "height, mean f x W) and the front x_f (f = 0.5 crossing).\n")
        L.append("| dx | depth err t = 0.5 | depth err t = 1 | max depth err (t in [0.25, 1]) | "
                 "x_f err t = 1 | max x_f err | energy balance | steps | run (s) |")
        L.append("|---|---|---|---|---|---|---|---|---|")
        for n, g in r["grids"].items():
            rows = {round(row["t"], 6): row for row in g["rows"]}
            L.append(f"| {g['dx']:g} | {rows[0.5]['err_depth']:+.2e} | {rows[1.0]['err_depth']:+.2e} | "
                     f"{g['max_err_depth']:.2e} | {rows[1.0]['err_front']:+.2e} | {g['max_err_front']:.2e} | "
                     f"{g['max_energy_balance']:.0e} | {g['steps']} | {g['seconds']:.1f} |")
        L.append(f"\n(exact s(0.5) = {rows[0.5]['exact']:.6f}, s(1) = {rows[1.0]['exact']:.6f}; errors "
                 "sampled every 0.05.)\n")
    if "cavity" in results:
        L.append("### de Vahl Davis cavity (Pr = 0.71), no phase change\n")
        L.append("| Ra | N | t | Nu left | Nu right | Nu left at t - 0.1 | de Vahl Davis | error | run (s) |")
        L.append("|---|---|---|---|---|---|---|---|---|")
        for ra, gs in results["cavity"].items():
            for n, g in gs.items():
                L.append(f"| {ra} | {n} | {g['t']:g} | {g['Nu_left']:.4f} | {g['Nu_right']:.4f} | "
                         f"{g['Nu_left_prev']:.4f} | {g['reference']} | {100 * g['err_left']:+.2f} % | "
                         f"{g['seconds']:.0f} |")
            ns = sorted(gs, key=int)
            if len(ns) >= 2 and int(ns[-1]) == 2 * int(ns[-2]):
                a, b = gs[ns[-2]]["Nu_left"], gs[ns[-1]]["Nu_left"]
                ex = (4.0 * b - a) / 3.0
                L.append(f"| {ra} | Richardson ({ns[-2]}, {ns[-1]}; order 2) | | {ex:.4f} | | | "
                         f"{gs[ns[-1]]['reference']} | {100 * (ex / gs[ns[-1]]['reference'] - 1):+.2f} % | |")
        L.append("")
    if "gallium" in results:
        r = results["gallium"]
        grids = list(r["grids"])
        L.append("### Gallium (Gau and Viskanta 1986; Brent, Voller and Reid 1988)\n")
        L.append(f"Pure conduction's melted fraction at 1 min (two-phase Neumann): "
                 f"{r['conduction_1min']:.4f}; FV at 1 min: " +
                 ", ".join(f"{g} {r['grids'][g]['series'][0]['liquid_fraction']:.4f}" for g in grids) + ".\n")
        for n in (28, 20, 40):
            L.append(f"Fronts (fraction of W) at top y = H - dy/2, middle y = H/2, bottom y = dy/2, "
                     f"dy = H/{n}; melted fraction; Nu of the hot wall:\n")
            L.append("| t (min) | grid | melted | top | middle | bottom | middle (T = Tm) | Nu hot | max speed (mm/s) |")
            L.append("|---|---|---|---|---|---|---|---|---|")
            for it in range(len(r["grids"][grids[0]]["series"])):
                for g in grids:
                    s = r["grids"][g]["series"][it]
                    fr = s["fronts"]
                    L.append(f"| {s['t'] / 60:g} | {g} | {s['liquid_fraction']:.4f} | {fr[f'top_{n}']:.4f} | "
                             f"{fr['middle']:.4f} | {fr[f'bottom_{n}']:.4f} | {s['fronts_T']['middle']:.4f} | "
                             f"{s['Nu_left']:.3f} | "
                             f"{1e3 * s['max_speed']:.2f} |")
            L.append("")
            if n != 28:
                break
        L.append("Grid differences (dy = H/28 fronts): largest |difference| over the times, "
                 "finest grid minus each coarser one:\n")
        L.append("| grids | melted | top | middle | bottom | middle (T = Tm) |")
        L.append("|---|---|---|---|---|---|")
        fine = r["grids"][grids[-1]]["series"]
        for g in grids[:-1]:
            co = r["grids"][g]["series"]
            d = lambda key: max(abs(a[key] - b[key]) for a, b in zip(fine, co))  # noqa: E731
            dfr = lambda key: max(abs(a["fronts"][key] - b["fronts"][key]) for a, b in zip(fine, co))  # noqa: E731
            dT = lambda key: max(abs(a["fronts_T"][key] - b["fronts_T"][key]) for a, b in zip(fine, co))  # noqa: E731
            L.append(f"| {grids[-1]} - {g} | {d('liquid_fraction'):.4f} | {dfr('top_28'):.4f} | "
                     f"{dfr('middle'):.4f} | {dfr('bottom_28'):.4f} | {dT('middle'):.4f} |")
        L.append("")
        L.append("Run times (one core): " + ", ".join(f"{g} {r['grids'][g]['seconds']:.0f} s "
                                                    f"({r['grids'][g]['steps']} steps)" for g in grids) + ".\n")
    if "freezing" in results:
        r = results["freezing"]
        grids = list(r["convection"])
        L.append("### Freezing in a square cavity (Ra 1e5, Pr 1, Ste 1)\n")
        L.append("Solid fraction 1 - mean f; fronts (fraction of W) at y = H - dy/2, H/2, dy/2 for dy = 1/40; "
                 "Nu = Q W / (k H (T_left - T_right)) through the cold (left) and hot (right) walls.\n")
        L.append("| t | grid | solid | top | middle | bottom | middle (T = Tm) | Nu cold | Nu hot | max speed |")
        L.append("|---|---|---|---|---|---|---|---|---|---|")
        for it in range(len(r["convection"][grids[0]]["series"])):
            for g in grids:
                s = r["convection"][g]["series"][it]
                fr = s["fronts"]
                L.append(f"| {s['t']:g} | {g}^2 | {1 - s['liquid_fraction']:.4f} | {fr['top_40']:.4f} | "
                         f"{fr['middle']:.4f} | {fr['bottom_40']:.4f} | {s['fronts_T']['middle']:.4f} | "
                         f"{s['Nu_left']:.4f} | "
                         f"{s['Nu_right']:.4f} | {s['max_speed']:.4f} |")
        L.append("")
        L.append("Fronts for the other SPH rows (dy = 1/20 and 1/30: top and bottom), finest grid:\n")
        L.append("| t | top 1/20 | bottom 1/20 | top 1/30 | bottom 1/30 |")
        L.append("|---|---|---|---|---|")
        for s in r["convection"][grids[-1]]["series"]:
            fr = s["fronts"]
            L.append(f"| {s['t']:g} | {fr['top_20']:.4f} | {fr['bottom_20']:.4f} | {fr['top_30']:.4f} | "
                     f"{fr['bottom_30']:.4f} |")
        L.append("")
        L.append("Grid differences: largest |difference| over the times, finest grid minus each coarser one:\n")
        L.append("| grids | solid | top 1/40 | middle | bottom 1/40 | middle (T = Tm) | Nu cold | Nu hot |")
        L.append("|---|---|---|---|---|---|---|---|")
        fine = r["convection"][grids[-1]]["series"]
        for g in grids[:-1]:
            co = r["convection"][g]["series"]
            d = lambda key: max(abs(a[key] - b[key]) for a, b in zip(fine, co))  # noqa: E731
            dfr = lambda key: max(abs(a["fronts"][key] - b["fronts"][key]) for a, b in zip(fine, co))  # noqa: E731
            dT = lambda key: max(abs(a["fronts_T"][key] - b["fronts_T"][key]) for a, b in zip(fine, co))  # noqa: E731
            L.append(f"| {grids[-1]} - {g} | {d('liquid_fraction'):.4f} | {dfr('top_40'):.4f} | "
                     f"{dfr('middle'):.4f} | {dfr('bottom_40'):.4f} | {dT('middle'):.4f} | {d('Nu_left'):.4f} | "
                     f"{d('Nu_right'):.4f} |")
        L.append("")
        st = ", ".join(f"{g}^2: " + (f"t = {r['convection'][g]['steady']['t']:g} (solid "
                                    f"{1 - r['convection'][g]['steady']['sample']['liquid_fraction']:.4f})"
                                    if r["convection"][g]["steady"] else
                                    f"not by t = {r['convection'][g]['t_end']:g}")
                       for g in grids)
        L.append(f"Steady state (mean f changes by < 1e-4 over 10 time units): {st}.\n")
        L.append("Run times (one core): " + ", ".join(f"{g}^2 {r['convection'][g]['seconds']:.0f} s "
                                                    f"({r['convection'][g]['steps']} steps)" for g in grids) + ".\n")
        L.append("Pure conduction (g = 0; steady solid thickness exactly 0.5, Nu 1):\n")
        L.append("| nx | t | solid thickness (1 - mean f) | Tm isotherm | Nu cold | Nu hot |")
        L.append("|---|---|---|---|---|---|")
        for g, res in r["conduction"].items():
            for s in res["series"]:
                if s["t"] in (80.0, 320.0, 1000.0, 2000.0):
                    L.append(f"| {g} | {s['t']:g} | {1 - s['liquid_fraction']:.6f} | "
                             f"{s['fronts_T']['middle']:.6f} | {s['Nu_left']:.6f} | "
                             f"{s['Nu_right']:.6f} |")
        L.append("")
    return "\n".join(L)


def write_markdown(results):
    if not os.path.exists(MARKDOWN):
        return
    text = open(MARKDOWN).read()
    a, b = "<!-- BEGIN RESULTS (phase_fv.py --write-results) -->", "<!-- END RESULTS -->"
    if a in text and b in text:
        head, rest = text.split(a, 1)
        tail = rest.split(b, 1)[1]
        new = head + a + "\n\n" + markdown(results) + "\n" + b + tail
        with open(MARKDOWN, "w") as fh:
            fh.write(new)


def _jsonable(x):
    if isinstance(x, dict):
        return {k: _jsonable(v) for k, v in x.items()}
    if isinstance(x, (list, tuple)):
        return [_jsonable(v) for v in x]
    if isinstance(x, np.generic):
        return x.item()
    if isinstance(x, np.ndarray):
        return x.tolist()
    return x


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--case", choices=["gallium", "freezing", "stefan", "cavity"])
    p.add_argument("--nx", type=int, default=42)
    p.add_argument("--ny", type=int, default=30)
    p.add_argument("--times", type=float, nargs="*", help="output times (default: the case's)")
    p.add_argument("--ra", type=float, default=1e5, help="cavity: Rayleigh number")
    p.add_argument("--g", type=float, help="override gravity (0: pure conduction)")
    p.add_argument("--C", type=float, help="override the Carman-Kozeny constant")
    p.add_argument("--ks", type=float, help="override the solid's conductivity")
    p.add_argument("--out", help="write the series as JSON")
    p.add_argument("--npz", help="write the fields at each output time to NAME_tT.npz")
    p.add_argument("--write-results", nargs="*", metavar="CASE",
                   help="run the reference/validation set of these cases (default all), merge into "
                        "tools/phase_fv_results.json and refresh the tables of tools/phase_fv.md")
    p.add_argument("--tables", action="store_true",
                   help="print the markdown tables of the results file and refresh tools/phase_fv.md")
    a = p.parse_args()
    if a.tables:
        results = json.load(open(RESULTS))
        print(markdown(results))
        write_markdown(results)
        return 0
    if a.write_results is not None:
        todo = a.write_results or ["stefan", "cavity", "gallium", "freezing"]
        results = json.load(open(RESULTS)) if os.path.exists(RESULTS) else {}
        funcs = dict(stefan=stefan_runs, cavity=cavity_runs, gallium=gallium_runs, freezing=freezing_runs)
        for name in todo:
            t0 = time.time()
            results[name] = _jsonable(funcs[name]())
            results.setdefault("seconds", {})[name] = time.time() - t0
            with open(RESULTS, "w") as fh:
                json.dump(results, fh, indent=1)
        write_markdown(results)
        return 0
    if not a.case:
        p.error("--case or --write-results")
    over = {}
    if a.case == "cavity":
        over["ra"] = a.ra
    for key, val in (("g", a.g), ("C", a.C), ("k_s", a.ks)):
        if val is not None:
            over[key] = val
    case = make_case(a.case, **over)
    res, _ = run(case, a.nx, a.ny, times=a.times, npz=a.npz, verbose=True)
    print(json.dumps(_jsonable({k: v for k, v in res.items() if k != "series"})))
    if a.out:
        with open(a.out, "w") as fh:
            json.dump(_jsonable(dict(case=case, result=res)), fh, indent=1)
    return 0


if __name__ == "__main__":
    sys.exit(main())
