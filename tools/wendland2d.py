"""Wendland C2 in 2-d, as src/USER-SPHTHERMAL/sph_kernels.h defines it, for
the analysis scripts of the examples (numpy arrays of r).

    W(r, h) = 7 / (4 pi h^2) (1 - q/2)^4 (2 q + 1),  q = r / h < 2
    dW/dr   = 7 / (4 pi h^3) (-5 q) (1 - q/2)^3

Checked by unittest/tools/test_wendland2d.py (normalisation, derivative,
support).
"""

import numpy as np

SIGMA = 7.0 / (4.0 * np.pi)


def w(r, h):
    q = np.asarray(r, dtype=float) / h
    u = np.clip(1.0 - 0.5 * q, 0.0, None)
    return SIGMA / (h * h) * u ** 4 * (2.0 * q + 1.0)


def dwdr(r, h):
    q = np.asarray(r, dtype=float) / h
    u = np.clip(1.0 - 0.5 * q, 0.0, None)
    return SIGMA / (h * h * h) * (-5.0 * q) * u ** 3
