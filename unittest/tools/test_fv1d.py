"""tools/fv1d.py, the finite-volume reference of the validation tests, against
exact solutions (reference/analytic.md): two semi-infinite materials at early
time (case 2), a slab with held faces (case 3), and the steady composite wall
(case 6) approached from a linear start."""

import math

import numpy as np

from checks import below, finish

import fv1d

erf = np.vectorize(math.erf)

# case 2: k ratio 3, rho ratio 0.5, Tc = 0.5505
layers = [fv1d.Layer(0.0, 0.5, "constant:1", 1000.0, 1.0, 0.0),
          fv1d.Layer(0.5, 1.0, "constant:3", 500.0, 1.0, 1.0)]
x, (T,) = fv1d.solve(layers, 1.0, 400, [0.625])
e1, e2 = math.sqrt(1000.0), math.sqrt(1500.0)
tc = e2 / (e1 + e2)
exact = np.where(x < 0.5, tc * (1 - erf(-(x - 0.5) / math.sqrt(4e-3 * 0.625))),
                 tc + (1 - tc) * erf((x - 0.5) / math.sqrt(4 * 6e-3 * 0.625)))
below(np.abs(T - exact).max(), 2e-4, "two materials against the exact erf")

# case 3: slab at T0 = 1, both faces held at 0, alpha = 1
x, (T,) = fv1d.solve([fv1d.Layer(0.0, 1.0, "constant:1", 1.0, 1.0, 1.0)], 1.0, 200, [0.05], 0.0, 0.0)
series = sum(4.0 / math.pi * np.sin((2 * n + 1) * math.pi * x) / (2 * n + 1)
             * math.exp(-((2 * n + 1) * math.pi) ** 2 * 0.05) for n in range(200))
below(np.abs(T - series).max(), 1e-4, "held faces against the series")

# case 6: composite wall (L1 = 0.4, k1 = 1; L2 = 0.6, k2 = 5), faces 1 and 0, steady
layers = [fv1d.Layer(0.0, 0.4, "constant:1", 1.0, 1.0, 0.5), fv1d.Layer(0.4, 1.0, "constant:5", 1.0, 1.0, 0.5)]
x, (T,) = fv1d.solve(layers, 1.0, 50, [1.0], 1.0, 0.0)
ti = (1.0 / 0.4) / (1.0 / 0.4 + 5.0 / 0.6)
exact = np.where(x < 0.4, 1.0 + (ti - 1.0) * x / 0.4, ti * (1.0 - (x - 0.4) / 0.6))
below(np.abs(T - exact).max(), 1e-6, "composite wall against the steady solution")

finish()
