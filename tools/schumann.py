"""Schumann's solution for a packed bed heated by a hot inflow (T. E. W.
Schumann, Heat transfer: a liquid flowing through a porous prism, Journal
of the Franklin Institute 208 (1929) 405-416): a bed of grains and fluid at
T0, fluid entering at x = 0 at T_in from t = 0 on, no conduction along the
bed, the exchange h a (T_f - T_s) per volume:
    eps rho_f c_f (dT_f/dt + u dT_f/dx) = h a (T_s - T_f)
    (1 - eps) rho_s c_s dT_s/dt          = h a (T_f - T_s)
with u the fluid's own (pore) velocity. In the reduced variables
    xi  = h a x / (eps rho_f c_f u),
    tau = h a (t - x / u) / ((1 - eps) rho_s c_s)   (nothing moves for tau < 0)
theta = (T - T0) / (T_in - T0) is, with Anzelius's and Goldstein's J
function J(x, y) = 1 - int_0^x exp(-y - s) I0(2 sqrt(y s)) ds,
    theta_f = J(xi, tau),   theta_s = 1 - J(tau, xi).
The integral is evaluated by composite Gauss-Legendre quadrature with the
scaled Bessel function (exp(-y - s) I0(2 sqrt(ys)) = i0e(z) exp(-(sqrt(s) -
sqrt(y))^2), z = 2 sqrt(ys), I0 numpy's); selfcheck() measures the solution's own
error: its boundary values, the reciprocity J(x, y) + J(y, x) = 1 + exp(-x
- y) I0(2 sqrt(xy)), and the residuals of both equations by central
differences.
usage: schumann.py            (prints the self-check)"""

import numpy as np

# nodes and weights of a 16-point Gauss-Legendre rule on [0, 1]
_NODES, _WEIGHTS = np.polynomial.legendre.leggauss(16)
_NODES = 0.5 * (_NODES + 1.0)
_WEIGHTS = 0.5 * _WEIGHTS


def _i0e(z):
    """exp(-z) I0(z), for the z of a bed (numpy's I0 is finite to z ~ 700)"""
    return np.i0(z) * np.exp(-z)


def _kernel(s, y):
    return _i0e(2.0 * np.sqrt(y * s)) * np.exp(-(np.sqrt(s) - np.sqrt(y)) ** 2)


def goldstein_j(x, y, panels=400):
    """J(x, y) for x, y >= 0 (scalars)."""
    if x <= 0.0:
        return 1.0
    edges = np.linspace(0.0, x, panels + 1)
    width = edges[1] - edges[0]
    s = (edges[:-1, None] + width * _NODES[None, :]).ravel()
    w = np.tile(width * _WEIGHTS, panels)
    return 1.0 - float(np.sum(w * _kernel(s, y)))


def reduced(x, t, u, ha, fluid_capacity, solid_capacity):
    """xi and tau of a point x at time t; fluid_capacity = eps rho_f c_f,
    solid_capacity = (1 - eps) rho_s c_s (per volume of the bed)."""
    return ha * x / (fluid_capacity * u), ha * (t - x / u) / solid_capacity


def temperatures(x, t, u, ha, fluid_capacity, solid_capacity):
    """theta_f and theta_s at x (an array) and time t."""
    theta_f, theta_s = [], []
    for xi, tau in (reduced(xx, t, u, ha, fluid_capacity, solid_capacity) for xx in np.atleast_1d(x)):
        if tau <= 0.0:
            theta_f.append(0.0)
            theta_s.append(0.0)
            continue
        theta_f.append(goldstein_j(xi, tau))
        theta_s.append(1.0 - goldstein_j(tau, xi))
    return np.array(theta_f), np.array(theta_s)


def selfcheck():
    """The largest deviation of each check, over a grid of (xi, tau)."""
    points = [(xi, tau) for xi in (0.3, 1.0, 3.0, 8.0, 20.0) for tau in (0.2, 1.0, 4.0, 10.0, 25.0)]
    recip = max(abs(goldstein_j(x, y) + goldstein_j(y, x) - 1.0
                    - _i0e(2.0 * np.sqrt(x * y)) * np.exp(-(np.sqrt(x) - np.sqrt(y)) ** 2))
                for x, y in points)
    step = 1e-4
    fluid_residual = solid_residual = 0.0
    for xi, tau in points:
        f = lambda a, b: goldstein_j(a, b)
        s = lambda a, b: 1.0 - goldstein_j(b, a)
        dfdxi = (f(xi + step, tau) - f(xi - step, tau)) / (2.0 * step)
        dsdtau = (s(xi, tau + step) - s(xi, tau - step)) / (2.0 * step)
        fluid_residual = max(fluid_residual, abs(dfdxi - (s(xi, tau) - f(xi, tau))))
        solid_residual = max(solid_residual, abs(dsdtau - (f(xi, tau) - s(xi, tau))))
    boundary = max(max(abs(goldstein_j(0.0, tau) - 1.0) for tau in (0.5, 5.0)),
                   max(abs(goldstein_j(xi, 0.0) - np.exp(-xi)) for xi in (0.5, 5.0)),
                   max(abs(1.0 - goldstein_j(tau, 0.0) - (1.0 - np.exp(-tau))) for tau in (0.5, 5.0)))
    return {"reciprocity": recip, "fluid equation": fluid_residual, "solid equation": solid_residual,
            "boundary values": boundary}


if __name__ == "__main__":
    for name, value in selfcheck().items():
        print(f"{name}: {value:.2e}")
