"""Neumann's exact solution of the Stefan problem of melting a half-space
x > 0 (H. S. Carslaw and J. C. Jaeger, Conduction of Heat in Solids, 2nd
ed., Oxford 1959; V. Alexiades and A. D. Solomon, Mathematical Modeling of
Melting and Freezing Processes, Hemisphere 1993): the solid, at T_i <= T_m, is held at T_w > T_m on x = 0 from
t = 0; the melt front is at s(t) = 2 lam sqrt(alpha_l t), lam the root of

  St_l / (exp(lam^2) erf(lam)) - St_s / (nu exp(nu^2 lam^2) erfc(nu lam))
      = lam sqrt(pi),

St_l = c_l (T_w - T_m) / L, St_s = c_s (T_m - T_i) / L, nu = sqrt(alpha_l
/ alpha_s) (one-phase problem: T_i = T_m, St_s = 0). The temperature:

  liquid, x < s: T_w - (T_w - T_m) erf(x / (2 sqrt(alpha_l t))) / erf(lam)
  solid,  x > s: T_i + (T_m - T_i) erfc(x / (2 sqrt(alpha_s t))) / erfc(nu lam)

lam is found by bisection to 1e-15 relative (the left side falls
monotonically in lam), so its own error is round-off; the functions below
are exact to double precision.

  python3 tools/stefan.py --stl 1 --sts 0.5 --nu 1     # prints lam
"""

import argparse
import math


def neumann_lambda(st_l, st_s=0.0, nu=1.0):
    """The root lam of Neumann's transcendental equation (above)."""
    if not st_l > 0.0:
        raise ValueError("the liquid's Stefan number must be > 0")

    def residual(lam):
        solid = 0.0
        if st_s > 0.0:
            # exp(x^2) erfc(x) without overflow for large x
            x = nu * lam
            scaled = math.exp(x * x) * math.erfc(x) if x < 25.0 else 1.0 / (x * math.sqrt(math.pi))
            solid = st_s / (nu * scaled)
        return st_l / (math.exp(lam * lam) * math.erf(lam)) - solid - lam * math.sqrt(math.pi)

    lo, hi = 1e-12, 1.0
    while residual(hi) > 0.0:
        hi *= 2.0
    while hi - lo > 1e-15 * hi:
        mid = 0.5 * (lo + hi)
        if residual(mid) > 0.0:
            lo = mid
        else:
            hi = mid
    return 0.5 * (lo + hi)


def front(t, lam, alpha_l):
    """The melt front's position at time t."""
    return 2.0 * lam * math.sqrt(alpha_l * t)


def temperature(x, t, lam, t_w, t_m, t_i, alpha_l, alpha_s):
    """T(x, t) of Neumann's solution."""
    s = front(t, lam, alpha_l)
    if x <= s:
        return t_w - (t_w - t_m) * math.erf(x / (2.0 * math.sqrt(alpha_l * t))) / math.erf(lam)
    nu = math.sqrt(alpha_l / alpha_s)
    return t_i + (t_m - t_i) * math.erfc(x / (2.0 * math.sqrt(alpha_s * t))) / math.erfc(nu * lam)


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--stl", type=float, required=True, help="the liquid's Stefan number")
    p.add_argument("--sts", type=float, default=0.0, help="the solid's Stefan number (0: one-phase)")
    p.add_argument("--nu", type=float, default=1.0, help="sqrt(alpha_l / alpha_s)")
    a = p.parse_args()
    print(f"{neumann_lambda(a.stl, a.sts, a.nu):.15g}")


if __name__ == "__main__":
    main()
