"""Numpy model of pair sph/cleary/heat on the two-material slab, for design work.

The operator of the pair style (Brookshaw's form, Cleary 1998 eq 6,
harmonic conductance, cubic kernel, h = 1.3 dx, eta = 0.1 h) on the slab of
examples/conduction-disorder (same particles: disorder.py's positions), in
a few hundred lines of numpy, so that variants can be tried in minutes:

  weights  'plain', or 'consistent' (sph_consistent.h: S and lambda, 5 sweeps,
           plain term where the smallest eigenvalue of M / V is below 0.7)
  interface conductance
           'harmonic' (the pair style), 'exact' (series conductance of the
           pair's two segments with the true interface x = 0.5: an upper bound
           of what knowing the interface gives), 'interface' (the pair
           style's 'mean interface': the interface estimated from the
           particles: normal from the Shepard-smoothed, gradient-corrected
           colour; plane halfway between the farthest own and nearest other
           particle along it, averaged over the own material)

Checked against LAMMPS (max error at t1 / 10 t1, jitter 0.2): consistent,
harmonic: 0.935 % / 0.312 % here, 0.942 % / 0.313 % with the pair style;
consistent, interface: 0.822 % / 0.223 % here, 0.837 % / 0.224 % with
'correction consistent mean interface'; at 36.9 degrees 0.426 % / 0.046 %
here, 0.443 % / 0.046 % there.
Explicit Euler with dt = 0.1 dx^2 / alpha_max.

  PYTHONPATH=examples/conduction-disorder tools/sphpython tools/research/disorder_prototype.py [--jitter J] [--angle A] [--k2 K] [--rhocv2 R]
      [--weights plain|consistent] [--conductance harmonic|exact|interface]
"""

import argparse
import math

import numpy as np
from scipy.spatial import cKDTree

import disorder    # examples/conduction-disorder, on PYTHONPATH (see the usage above)
import fv1d

SIGMA = 10.0 / (7.0 * math.pi)    # cubic B-spline, 2-D


def cubic_w(r, h):
    q = r / h
    return SIGMA / h**2 * np.where(q < 1, 1 - 1.5 * q * q + 0.75 * q**3,
                                   np.where(q < 2, 0.25 * (2 - q)**3, 0.0))


def cubic_dwdr(r, h):
    q = r / h
    return SIGMA / h**3 * np.where(q < 1, -3 * q + 2.25 * q * q, np.where(q < 2, -0.75 * (2 - q)**2, 0.0))


class Slab:
    """directed pairs (a, b) with r_ab = x_a - x_b; sums over b with sum_b()"""

    def __init__(self, p, spacing, height, k, rho, cv, T, h):
        self.p, self.n = p, len(p)
        self.k, self.rho, self.cv, self.T = k, rho, cv, T
        self.m = rho * spacing**2
        self.V = self.m / rho
        images = np.concatenate([p, p + [0, height], p - [0, height]])
        found = cKDTree(p).query_ball_tree(cKDTree(images), 2 * h)
        A, B, R = [], [], []
        for a, js in enumerate(found):
            for j in js:
                if j != a:
                    A.append(a)
                    B.append(j % self.n)
                    R.append(p[a] - images[j])
        self.A, self.B, self.R = np.array(A), np.array(B), np.array(R)
        self.r = np.linalg.norm(self.R, axis=1)
        self.e = self.R / self.r[:, None]
        self.h, self.eta2 = h, 0.01 * h * h
        self.dw = cubic_dwdr(self.r, h)
        self.g = -self.V[self.A] * self.V[self.B] * self.r * self.dw / (self.r**2 + self.eta2)

    def sum_b(self, v):
        out = np.zeros((self.n,) + v.shape[1:])
        np.add.at(out, self.A, v)
        return out

    def outer(self, w):
        return w[:, None, None] * self.R[:, :, None] * self.R[:, None, :]


def consistent_factors(s, sweeps=5, full_support=0.7):
    M = s.sum_b(s.outer(s.g))
    interior = np.linalg.eigvalsh(M).min(1) / s.V >= full_support
    S = np.where(interior[:, None, None], s.V[:, None, None] * np.linalg.inv(M), np.eye(2))
    second = 0.5 * (np.einsum("ni,nij,nj->n", s.e, S[s.A], s.e) +
                    np.einsum("ni,nij,nj->n", s.e, S[s.B], s.e))
    G = s.g * second
    deficit = s.sum_b(G[:, None] * s.R)
    K = s.outer(G)
    K_inv = np.linalg.inv(s.sum_b(K))
    lam = np.zeros((s.n, 2))
    for _ in range(sweeps):
        coupling = s.sum_b(np.einsum("nij,nj->ni", K, lam[s.B]))
        lam = np.where(interior[:, None], np.einsum("nij,nj->ni", K_inv, coupling - deficit), 0.0)
    first = np.maximum(1 + np.einsum("ni,ni->n", lam[s.A] - lam[s.B], s.R), 0.0)
    return second * first


def interface_distance(s):
    """each particle's distance from the interface with the other material,
    as pair sph/cleary/heat's 'mean interface' estimates it (inf: no other
    material within the support)"""
    same = s.k[s.A] == s.k[s.B]
    W = cubic_w(s.r, s.h) * s.V[s.B]
    W0 = cubic_w(0.0, s.h) * s.V
    M = s.sum_b(-s.V[s.B][:, None, None] * s.R[:, :, None] * (s.dw[:, None] * s.e)[:, None, :])
    L = np.linalg.inv(M)
    grad = s.sum_b((s.V[s.B] * (same - 1.0))[:, None] *
                   np.einsum("nij,nj->ni", L[s.A], s.dw[:, None] * s.e))
    grad = (s.sum_b((W * same)[:, None] * grad[s.B]) + W0[:, None] * grad) / \
        (s.sum_b(W * same) + W0)[:, None]
    normal = -grad / np.maximum(np.linalg.norm(grad, axis=1), 1e-30)[:, None]
    along = np.einsum("ni,ni->n", normal[s.A], -s.R)
    own_far = np.zeros(s.n)
    np.maximum.at(own_far, s.A[same], along[same])
    other_near = np.full(s.n, np.inf)
    np.minimum.at(other_near, s.A[~same], along[~same])
    d = 0.5 * (own_far + other_near)
    # the plane averaged over the own material, seen along each normal
    has = np.isfinite(d)
    use = same & has[s.B]
    with np.errstate(invalid="ignore"):
        seen = np.where(use, W * (d[s.B] + along), 0.0)
    plane = (s.sum_b(seen) + np.where(has, W0 * d, 0.0)) / (s.sum_b(W * use) + W0 * has)
    return np.where(has, np.maximum(plane, 1e-3 * s.h), np.inf)


def conductance(s, kind):
    ka, kb = s.k[s.A], s.k[s.B]
    harmonic = 4 * ka * kb / (ka + kb)
    if kind == "harmonic":
        return harmonic
    cross = ka != kb
    if kind == "exact":
        xa, xb = s.p[s.A, 0], s.p[s.A, 0] - s.R[:, 0]
        fa = np.abs(0.5 - xa) / np.maximum(np.abs(xb - xa), 1e-30)
    else:
        # particles without a neighbour of the other material have d = inf;
        # they are in no crossing pair
        d = np.minimum(interface_distance(s), 1e30)
        fa = d[s.A] / (d[s.A] + d[s.B])
    with np.errstate(invalid="ignore", divide="ignore"):
        series = 2.0 / (fa / ka + (1 - fa) / kb)
    return np.where(cross, series, harmonic)


def evolve(s, factor, conductance_kind, layers, nx):
    """explicit Euler (dt = 0.1 dx^2 / alpha_max) with pair weights g_ab *
    factor to t1 and 10 t1; returns each particle's |T - reference| at both
    times, the two temperature fields and the relative energy change"""
    dx = 1.0 / nx
    coefficient = conductance(s, conductance_kind) * factor * s.r * s.dw / \
        (s.rho[s.A] * s.rho[s.B] * (s.r**2 + s.eta2)) * s.m[s.B]
    t1 = disorder.t1_of(layers, nx)
    dt = 0.1 * dx * dx / max(disorder.diffusivities(layers))
    e, t, out = s.cv * s.T, 0.0, []
    for target in (t1, 10 * t1):
        steps = int(round((target - t) / dt))
        for _ in range(steps):
            T = e / s.cv
            e = e + dt * s.sum_b(coefficient * (T[s.A] - T[s.B]))
        t += steps * dt
        out.append(e / s.cv)
    x_fv, T_fv = fv1d.solve(layers, 1.0, 1000, [t1, 10 * t1])
    errors = [np.abs(T - np.interp(s.p[:, 0], x_fv, ref)) for T, ref in zip(out, T_fv)]
    drift = np.sum(s.m * e) / np.sum(s.m * s.cv * s.T) - 1
    return errors, out, drift


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--jitter", type=float, default=0.0)
    ap.add_argument("--angle", type=float, default=0.0, choices=disorder.ANGLES)
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--k2", type=float, default=3.0)
    ap.add_argument("--rhocv2", type=float, default=0.5)
    ap.add_argument("--weights", default="plain", choices=["plain", "consistent"])
    ap.add_argument("--conductance", default="harmonic", choices=["harmonic", "exact", "interface"])
    a = ap.parse_args()
    nx = 80
    dx = 1.0 / nx
    p, spacing, height = disorder.positions(nx, 20, a.jitter, a.angle, a.seed)
    layers = disorder.layers_for(a.k2, a.rhocv2)
    left = p[:, 0] < 0.5
    k = np.where(left, 1.0, a.k2)
    rho = np.where(left, 1000.0, 1000.0 * a.rhocv2)
    s = Slab(p, spacing, height, k, rho, np.ones(len(p)), np.where(left, 0.0, 1.0), 1.3 * dx)
    factor = consistent_factors(s) if a.weights == "consistent" else 1.0
    errors, _, drift = evolve(s, factor, a.conductance, layers, nx)
    errors = [100 * e.max() for e in errors]
    print(f"{a.weights}, {a.conductance}: max error at t1 {errors[0]:.3f} %, at 10 t1 "
          f"{errors[1]:.3f} %, energy change {drift:.1e}")


if __name__ == "__main__":
    main()
