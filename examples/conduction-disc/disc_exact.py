"""Exact conduction in a disc, numpy only: the infinite cylinder with its surface
held at a constant temperature (Carslaw & Jaeger 1959, Conduction of Heat in Solids).

Disc of radius R at T0, rim held at Tw from t = 0, Fo = alpha t / R^2, j_n the
zeros of J0:
  theta = (T - Tw)/(T0 - Tw) = sum_n 2 / (j_n J1(j_n)) J0(j_n r/R) exp(-j_n^2 Fo)
  Q' / (k (T0 - Tw)) = 4 pi sum_n exp(-j_n^2 Fo)     (heat flow out per unit depth)
  mean theta = sum_n 4 / j_n^2 exp(-j_n^2 Fo)
J0, J1 by Bessel's integral J_m(x) = 1/(2 pi) int_0^{2 pi} cos(m t - x sin t) dt
with the trapezoid rule on a full period (exponentially convergent: M >= |x| + 64
points give round-off accuracy); zeros by McMahon's expansion and Newton steps.
"""

import math

import numpy as np

def bessel_j(m, x, chunk=256):
    """J_m(x) for integer m and real x (array): trapezoid rule with M >= |x| + 64 points."""
    x = np.asarray(x, dtype=float)
    flat = x.ravel()
    big = float(np.abs(flat).max()) if flat.size else 0.0
    M = 64
    while M < big + 64:
        M *= 2
    tau = 2.0 * math.pi * np.arange(M) / M
    out = np.empty_like(flat)
    for s in range(0, len(flat), chunk):
        out[s:s + chunk] = np.mean(np.cos(m * tau[None, :] - flat[s:s + chunk, None] * np.sin(tau)[None, :]), axis=1)
    return out.reshape(x.shape)


def j0_zeros(n):
    """The first n positive zeros of J0."""
    k = np.arange(1, n + 1)
    b = (k - 0.25) * math.pi
    z = b + 1.0 / (8 * b) - 124.0 / (3 * (8 * b) ** 3) + 120928.0 / (15 * (8 * b) ** 5)
    for _ in range(3):
        z = z + bessel_j(0, z) / bessel_j(1, z)     # J0' = -J1
    return z


_ZEROS = j0_zeros(600)
_COEF = 2.0 / (_ZEROS * bessel_j(1, _ZEROS))


def theta(r_over_R, fo, tol=1e-14):
    """(T - Tw)/(T0 - Tw) at r/R (array) and Fourier number fo > 0."""
    r = np.asarray(r_over_R, dtype=float)
    decay = np.exp(-_ZEROS ** 2 * fo)
    n = max(1, int(np.searchsorted(-decay, -tol)))
    z, c, d = _ZEROS[:n], _COEF[:n], decay[:n]
    return np.sum(c[:, None] * bessel_j(0, np.outer(z, r.ravel())) * d[:, None], axis=0).reshape(r.shape)


def heat_flow(fo):
    """Q' / (k (T0 - Tw)), the heat flow out through the rim per unit depth;
    the short-time expansion 2 pi (1/sqrt(pi Fo) - 1/2 - sqrt(Fo)/(4 sqrt(pi)))
    where the 600-term series would not have converged."""
    fo = np.asarray(fo, dtype=float)
    series = 4.0 * math.pi * np.sum(np.exp(-np.outer(np.atleast_1d(fo), _ZEROS ** 2)), axis=1)
    f = np.maximum(np.atleast_1d(fo), 1e-300)
    short = 2.0 * math.pi * (1.0 / np.sqrt(math.pi * f) - 0.5 - np.sqrt(f) / (4 * math.sqrt(math.pi)))
    out = np.where(np.atleast_1d(fo) * _ZEROS[-1] ** 2 > 40.0, series, short)
    return out.reshape(fo.shape)


def mean_theta(fo):
    return float(np.sum(4.0 / _ZEROS ** 2 * np.exp(-_ZEROS ** 2 * fo)))


def fo_centre_half():
    """Fourier number at which the centre has dropped to theta = 1/2 (bisection)."""
    lo, hi = 0.05, 0.5
    for _ in range(60):
        mid = 0.5 * (lo + hi)
        lo, hi = (mid, hi) if theta(np.array([0.0]), mid)[0] > 0.5 else (lo, mid)
    return 0.5 * (lo + hi)


def check():
    """Check values at Fo = 0.1 (centre, r = R/2, mean, Q'/k); returns the largest relative deviation."""
    got = [theta(np.array([0.0]), 0.1)[0], theta(np.array([0.5]), 0.1)[0], mean_theta(0.1), float(heat_flow(0.1))]
    want = [0.848355, 0.610247, 0.394176, 7.65161]
    return max(abs(g / w - 1.0) for g, w in zip(got, want)), got


if __name__ == "__main__":
    dev, got = check()
    print("theta(0), theta(R/2), mean, Q'/k at Fo = 0.1:", got, "max rel deviation", dev)
    print("zeros:", _ZEROS[:6], "J0 at zeros max", abs(bessel_j(0, _ZEROS)).max())
    print("Fo(centre = 1/2) =", fo_centre_half())
    for fo in (1e-4, 1e-3, 0.005, 0.01):
        s = 4.0 * math.pi * np.sum(np.exp(-_ZEROS ** 2 * fo))
        f = fo
        sh = 2.0 * math.pi * (1.0 / math.sqrt(math.pi * f) - 0.5 - math.sqrt(f) / (4 * math.sqrt(math.pi)))
        print(fo, s, sh, heat_flow(fo))
    print("theta at r=1:", theta(np.array([1.0]), 0.01), "theta(0.5, 0.002):", theta(np.array([0.5]), 0.002))
