"""tools/schumann.py, the reference of the heated packed bed
(examples/grains-bed/in.heatbed): its own checks (the equations' residuals,
the boundary values, the J function's reciprocity) and an independent
solution of the same equations in the reduced variables,
    d theta_f / d xi = theta_s - theta_f,   d theta_s / d tau = theta_f - theta_s,
    theta_f(0, tau) = 1, theta_s(xi, 0) = 0,
marched with the trapezoidal rule on a grid of step 0.02 (second order), at
two steps: the quadrature agrees with both, 4 times closer with the finer
(the trapezoidal rule's second order: the error is the marching's, 5e-6 at
step 0.02)."""

import numpy as np

from checks import below, finish

import schumann


def marched(extent, step):
    """theta_f and theta_s on the grid xi, tau = 0, step, ..., extent."""
    n = int(round(extent / step)) + 1
    f = np.zeros((n, n))
    s = np.zeros((n, n))
    f[0, :] = 1.0
    h = 0.5 * step
    # xi = 0: the fluid enters hot, the solid there heats as 1 - exp(-tau)
    for j in range(1, n):
        s[0, j] = (s[0, j - 1] * (1.0 - h) + 2.0 * h) / (1.0 + h)
    for i in range(1, n):
        # tau = 0: the solid still cold, the fluid decays along xi
        f[i, 0] = f[i - 1, 0] * (1.0 - h) / (1.0 + h)
        for j in range(1, n):
            # trapezoidal in xi for f, in tau for s: a 2 x 2 system
            rf = f[i - 1, j] + h * (s[i - 1, j] - f[i - 1, j])
            rs = s[i, j - 1] + h * (f[i, j - 1] - s[i, j - 1])
            # (1 + h) F - h S = rf ; -h F + (1 + h) S = rs
            det = (1.0 + h) ** 2 - h * h
            f[i, j] = ((1.0 + h) * rf + h * rs) / det
            s[i, j] = ((1.0 + h) * rs + h * rf) / det
    return f, s


for name, value in schumann.selfcheck().items():
    below(value, 1e-8, f"schumann.py's {name}")

points = [(0.52, 0.52), (2.0, 1.0), (4.0, 4.0), (1.0, 6.0), (6.0, 2.0)]
errors = []
for step in (0.04, 0.02):
    f, s = marched(6.0, step)
    worst = 0.0
    for xi, tau in points:
        i, j = int(round(xi / step)), int(round(tau / step))
        worst = max(worst, abs(f[i, j] - schumann.goldstein_j(xi, tau)),
                    abs(s[i, j] - (1.0 - schumann.goldstein_j(tau, xi))))
    errors.append(worst)
    print(f"step {step}: largest difference {worst:.3e}")
below(errors[1], 2e-4, "the J function's temperatures against the marched solution (step 0.02)")
below(errors[1] / errors[0], 0.3, "the difference falls as the step's square (ratio of step 0.02 to 0.04)")
finish()
