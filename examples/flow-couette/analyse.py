"""Errors of the Couette start-up example against the exact series; writes couette.png.

u(y, t) = V0 y / W + sum_{n>=1} 2 V0 (-1)^n / (n pi) sin(n pi y / W) exp(-n^2 pi^2 nu t / W^2)
(the series solution of Morris, Fox & Zhu 1997). Errors are in % of the
plate velocity V0, over all fluid particles; |vy| (0 exactly) in the same unit.
"""

import sys

import numpy as np

import channel_flow

W, RHO, MU = 20.0, 1.0, 0.248
NU = MU / RHO
V0 = 65.2 * MU / (RHO * W)          # Re = rho V0 W / mu = 65.2
TIMES = [20, 100, 300, 600, 1200]


def exact(y, t, terms=2000):
    n = np.arange(1, terms + 1)[:, None]
    series = 2 * V0 * (-1.0) ** n / (n * np.pi) * np.sin(n * np.pi * y / W) \
        * np.exp(-n ** 2 * np.pi ** 2 * NU * t / W ** 2)
    return V0 * y / W + series.sum(axis=0)


if __name__ == "__main__":
    sys.exit(channel_flow.run(__doc__, exact, TIMES, V0, "V0", "Couette start-up Re = 65.2", "couette", W))
