#!/usr/bin/env python3
"""Linear-stability reference for Rayleigh-Benard convection between rigid plates.

A fluid layer of height H between two no-slip, isothermal plates, heated from
below (Chandrasekhar 1961, chapter II). With z in units of H (plates at
z = +-1/2), a horizontal wavenumber a (in units of 1/H) and time in units of
the thermal diffusion time H^2/kappa, the linear perturbations obey

    (1/Pr) d/dt (D^2 - a^2) w = (D^2 - a^2)^2 w - Ra a^2 theta
           d/dt theta         = (D^2 - a^2) theta + w

with w = Dw = theta = 0 at z = +-1/2. Exchange of stabilities holds, so the
marginal state is stationary: (D^2 - a^2)^2 w = Ra a^2 theta,
(D^2 - a^2) theta = -w, a real eigenproblem for Ra in which Pr does not enter.

Chebyshev collocation on n + 1 Gauss-Lobatto points. w is represented as
(1 - x^2) q(x), which holds w = Dw = 0 exactly (Trefethen 2000, Spectral
Methods in MATLAB, program 38); theta keeps its interior values. The marginal
Ra is the inverse of the largest eigenvalue of -a^2 L4^-1 L2^-1, a form built
from solves rather than from the product L2 L4, whose round-off grows as n^8.
growth_rate() solves the full generalised problem sigma B v = A v.

Results (n = 40): free a: Ra_c = 1707.7618, a_c = 3.1163 (Chandrasekhar:
1707.762, 3.117); box width W = 2H (a = pi, mode 1): Ra_c = 1707.9223;
W = 1.5H (a = 4.18879, mode 1): Ra_c = 1955.8084.
Own error: the collocation has converged by n = 16 (n = 8 is off by 6e-3,
n = 12 by 1e-7). Between n = 20, 30, 40 and 60 the marginal Ra differs by
less than 2e-8 (relative 1e-11) at a = pi and 4.18879, the free Ra_c by
less than 1e-7 and a_c by less than 5e-6 (round-off, magnified by the
flatness of Ra(a) at its minimum). growth_rate gives sigma = -2 pi^2 (the
slowest thermal mode) at Ra = 0 and |sigma| < 2e-11 at the marginal Ra, and
its values differ by less than 1e-10 between n = 20 and 60.

As a module: rayleigh_at(a, n=40), onset(width_over_height=None, n=40)
returning (Ra_c, a), growth_rate(ra, a, pr, n=40). As a script, see --help.
"""

import argparse
import functools
import math
import sys

import numpy as np
from scipy.optimize import minimize_scalar


def cheb(n):
    """Chebyshev differentiation matrix on x_j = cos(pi j / n), j = 0..n."""
    x = np.cos(np.pi * np.arange(n + 1) / n)
    c = np.hstack([2.0, np.ones(n - 1), 2.0]) * (-1.0) ** np.arange(n + 1)
    dx = x[:, None] - x[None, :]
    d = np.outer(c, 1.0 / c) / (dx + np.eye(n + 1))
    d -= np.diag(d.sum(axis=1))       # rows sum to zero: better round-off
    return d, x


@functools.lru_cache(maxsize=8)
def _base(n):
    """D^2 for theta (theta = 0 at the ends), D^2 and D^4 for clamped w, on
    the interior points, in z = x / 2 (plates at z = +-1/2)."""
    if n < 4:
        raise ValueError("n must be at least 4")
    d, x = cheb(n)
    d2, d3, d4 = d @ d, d @ d @ d, d @ d @ d @ d
    i = slice(1, n)
    xi = x[i]
    s = np.diag(1.0 / (1.0 - xi ** 2))
    # w = (1 - x^2) q:  w'' = (1-x^2) q'' - 4x q' - 2q,  w'''' = (1-x^2) q'''' - 8x q''' - 12 q''
    w2 = (np.diag(1.0 - xi ** 2) @ d2[i, i] - 4.0 * np.diag(xi) @ d[i, i] - 2.0 * np.eye(n - 1)) @ s
    w4 = (np.diag(1.0 - xi ** 2) @ d4[i, i] - 8.0 * np.diag(xi) @ d3[i, i] - 12.0 * d2[i, i]) @ s
    return 4.0 * d2[i, i], 4.0 * w2, 16.0 * w4


def _operators(a, n):
    """(D^2 - a^2) on theta, (D^2 - a^2) and (D^2 - a^2)^2 on w."""
    t2, w2, w4 = _base(n)
    eye = np.eye(n - 1)
    a2 = a * a
    return t2 - a2 * eye, w2 - a2 * eye, w4 - 2.0 * a2 * w2 + a2 * a2 * eye


def rayleigh_at(a, n=40):
    """Marginal (stationary) Rayleigh number of horizontal wavenumber a (units 1/H)."""
    if a <= 0:
        raise ValueError("wavenumber must be positive")
    l2t, _, l4w = _operators(a, n)
    # L4 w = Ra a^2 theta, L2 theta = -w  =>  -a^2 L4^-1 L2^-1 w = w / Ra
    k = -a * a * np.linalg.solve(l4w, np.linalg.solve(l2t, np.eye(n - 1)))
    mu = np.linalg.eigvals(k).real.max()
    return 1.0 / mu


def onset(width_over_height=None, n=40):
    """(Ra_c, a): the free minimum over a, or with a periodic width W = ratio H
    the smallest Ra over the allowed a = 2 pi m H / W, m = 1, 2, ..."""
    best = minimize_scalar(lambda a: rayleigh_at(a, n), bounds=(2.0, 4.5),
                           method="bounded", options={"xatol": 1e-6})
    ra_c, a_c = float(best.fun), float(best.x)
    if width_over_height is None:
        return ra_c, a_c
    if width_over_height <= 0:
        raise ValueError("width must be positive")
    # Ra(a) has a single minimum, so the onset is one of the two modes around a_c
    step = 2.0 * math.pi / width_over_height
    m = max(1, int(a_c / step))
    return min((rayleigh_at(k * step, n), k * step) for k in (m, m + 1))


def growth_rate(ra, a, pr, n=40):
    """Largest real part of the growth rate sigma (units kappa/H^2) of the
    wavenumber-a perturbations at Rayleigh number ra and Prandtl number pr."""
    if a <= 0 or pr <= 0:
        raise ValueError("wavenumber and Prandtl number must be positive")
    l2t, l2w, l4w = _operators(a, n)
    eye, zero = np.eye(n - 1), np.zeros((n - 1, n - 1))
    lhs = np.block([[l2w / pr, zero], [zero, eye]])             # sigma B v
    rhs = np.block([[l4w, -ra * a * a * eye], [eye, l2t]])      # = A v
    return float(np.linalg.eigvals(np.linalg.solve(lhs, rhs)).real.max())


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--width-over-height", type=float,
                   help="periodic box width W / H (default: free wavenumber)")
    p.add_argument("--n", type=int, default=40, help="Chebyshev polynomial degree (default 40)")
    p.add_argument("--ra", type=float, help="also print the growth rate at this Ra at the onset wavenumber")
    p.add_argument("--pr", type=float, default=1.0, help="Prandtl number for --ra (default 1)")
    args = p.parse_args()
    ra_c, a = onset(args.width_over_height, args.n)
    check, _ = onset(args.width_over_height, args.n // 2)
    if args.width_over_height is None:
        print(f"free wavenumber: Ra_c = {ra_c:.4f} at a = {a:.4f}")
    else:
        m = round(a * args.width_over_height / (2.0 * math.pi))
        print(f"W/H = {args.width_over_height:g}: Ra_c = {ra_c:.4f} at a = {a:.5f} "
              f"(horizontal mode {m}: wavelength W/{m})")
    print(f"# n = {args.n}; difference to n = {args.n // 2}: {abs(ra_c - check):.1e}")
    if args.ra is not None:
        sigma = growth_rate(args.ra, a, args.pr, args.n)
        print(f"growth rate at Ra = {args.ra:g}, Pr = {args.pr:g}, a = {a:.5f}: "
              f"sigma = {sigma:.6g} kappa/H^2")
    return 0


if __name__ == "__main__":
    sys.exit(main())
