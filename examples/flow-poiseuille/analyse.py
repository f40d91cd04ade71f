"""Errors of the transient Poiseuille example against the exact series; writes poiseuille.png.

u(y, t) = F/(2 nu) y (W - y)
          - sum_{n>=0} 4 F W^2 / (nu pi^3 (2n+1)^3) sin((2n+1) pi y / W) exp(-(2n+1)^2 pi^2 nu t / W^2)
(the series solution of Morris, Fox & Zhu 1997), with F = 8 u_max nu / W^2.
Errors are in % of the steady centre-line velocity u_max, over all fluid particles;
|vy| (which is 0 exactly) is reported in the same unit.
"""

import sys

import channel_flow

W, RHO, MU = 20.0, 1.0, 0.248
NU = MU / RHO
UMAX = 65.2 * MU / (RHO * W)          # Re = rho u_max W / mu = 65.2
TIMES = [100, 300, 600, 1200]


def exact(y, t):
    return channel_flow.poiseuille_from_rest(y, t, UMAX, NU, W)


if __name__ == "__main__":
    sys.exit(channel_flow.run(__doc__, exact, TIMES, UMAX, "u_max", "Poiseuille Re = 65.2", "poiseuille", W))
