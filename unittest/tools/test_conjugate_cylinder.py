"""tools/conjugate_cylinder.py, the radial finite-volume reference of the hot
cylinder cooling in a fluid, against exact solutions and its own invariants:
(a) one material, a hot disc in an unbounded medium: the exact centre and
disc-mean temperatures, converging at second order; (b) thermal energy
conserved to round-off with the adiabatic wall, two materials; (c) the
long-time limit, uniform at the heat-capacity-weighted mean; (d) T and the
heat flux k dT/dr continuous across r = R, to discretisation accuracy;
(e) the solid's mean temperature converging at second order; (f) a cylinder
with its wall held at a temperature against the Bessel series (the held-wall
boundary)."""

import math
import time

import numpy as np

from checks import below, finish, inside

import conjugate_cylinder as cc

t_start = time.time()
R = 0.05
steel = cc.Material(7850.0, 490.0, 45.0, 353.15)
water = cc.Material(1000.0, 4180.0, 0.6, 293.15)


def refine(cells, stretch, dt_over_t, levels):
    """(n_solid, n_fluid, stretch, dt_over_t) with the cells split in two and
    the step halved at each level, as reference_error() does."""
    n1, n2 = cells
    return [(n1 * 2 ** j, n2 * 2 ** j, stretch ** (0.5 ** j), dt_over_t * 0.5 ** j) for j in range(levels)]


# (a) one material (steel): a disc at T1 = 353.15 K of radius R in an
# unbounded medium at T0 = 293.15 K. T(0, t) = T0 + (T1 - T0) (1 - exp(-R^2 /
# (4 alpha t))). With R_out = 0.5 m, (R_out - R)^2 / (4 alpha t) = 21 at
# 200 s: the wall sees exp(-21) of the disturbance (its T must not move).
# Stretched fluid cells keep the wide domain cheap. Measured centre errors
# at 1 mm / 0.5 mm cells (dt/t 0.02 / 0.01): 8.9e-3 / 2.5e-3 K at 50 s,
# 3.1e-3 / 8.8e-4 K at 100 s, 2.3e-4 / 1.7e-5 K at 200 s; ratios 3.5 - 3.6
# at 50 and 100 s (4.1 on the next halving at 400 s): second order, slightly
# pre-asymptotic at the axis.
# The disc's mean is T0 + (T1 - T0) (1 - exp(-u) (I0(u) + I1(u))), u = R^2 /
# (2 alpha t): the share of the heat still inside the disc (it tends to
# 1 - 2 sqrt(alpha t / pi) / R, the planar contact loss, at early times, and
# to R^2 / (4 alpha t), the centre value, at late times). Measured mean
# errors 4.2e-3 / 1.1e-3 K at 50 s, 2.0e-3 / 4.9e-4 K at 100 s: ratio 4.0.
def exp_bessel_i(n, u):
    """exp(-u) I_n(u), trapezoidal rule over a full period (exponentially accurate)."""
    tau = 2.0 * math.pi * np.arange(512) / 512
    return float(np.mean(np.exp(u * (np.cos(tau) - 1.0)) * np.cos(n * tau)))


hot = cc.Material(steel.rho, steel.cv, steel.k, 353.15)
cold = cc.Material(steel.rho, steel.cv, steel.k, 293.15)
times = [50.0, 100.0, 200.0]
exact = np.array([293.15 + 60.0 * (1.0 - math.exp(-R * R / (4.0 * steel.alpha * t))) for t in times])
u = [R * R / (2.0 * steel.alpha * t) for t in times]
exact_mean = np.array([293.15 + 60.0 * (1.0 - exp_bessel_i(0, x) - exp_bessel_i(1, x)) for x in u])
err, err_mean = {}, {}
for n1, n2, q, dto in refine((50, 116), 1.02, 0.02, 2):
    res = cc.solve(R, 0.5, hot, cold, times, (n1, n2), stretch=q, dt_over_t=dto)
    err[n1] = np.array([cc.temperature_at(res, [0.0], i)[0] for i in range(len(times))]) - exact
    err_mean[n1] = res["mean_solid"] - exact_mean
    print(f"one material, {n1} + {n2} cells (dr = {1e3 * R / n1:g} mm), {res['steps']} steps: "
          + ", ".join(f"T(0, {t:g} s) - exact = {e:+.2e} K" for t, e in zip(times, err[n1]))
          + "; disc mean - exact: " + ", ".join(f"{e:+.2e}" for e in err_mean[n1]) + " K")
below(np.abs(err[100]).max(), 5e-3, "one material, 0.5 mm cells: centre temperature against exact (K)")
below(np.abs(err_mean[100]).max(), 2e-3, "one material, 0.5 mm cells: disc mean temperature against exact (K)")
for i in (0, 1):
    inside(err[50][i] / err[100][i], 3.0, 5.0,
           f"one material, centre error ratio 1 mm / 0.5 mm cells at {times[i]:g} s")
    inside(err_mean[50][i] / err_mean[100][i], 3.0, 5.0,
           f"one material, disc mean error ratio 1 mm / 0.5 mm cells at {times[i]:g} s")
below(abs(res["T"][-1][-1] - 293.15), 1e-6, "one material: outer wall unreached at 200 s (K)")

# (b) thermal energy with the adiabatic wall, steel disc in water: BDF2 with
# sum(coefficients) = 0 and the flux-form increment conserve it exactly but
# for rounding. Measured against the energy that moves, sum C |T(0) - T_eq|,
# which is far smaller than the energy itself (T in K).
res = cc.solve(R, 0.25, steel, water, [10.0, 100.0, 1000.0, 1e4], 1000)
C = np.array([steel.rho * steel.cv] * res["n_solid"] + [water.rho * water.cv] * (len(res["r"]) - res["n_solid"])) \
    * res["volume"]
E = res["history"]["energy"]
T_init = np.array([steel.T0] * res["n_solid"] + [water.T0] * (len(res["r"]) - res["n_solid"]))
moved = np.sum(C * np.abs(T_init - E[0] / C.sum()))
print(f"energy over {res['steps']} steps to 1e4 s: largest |E - E0| / E0 = {np.abs(E / E[0] - 1).max():.1e}")
below(np.abs(E - E[0]).max() / moved, 1e-12, "two materials: energy change / energy moved, adiabatic wall")

# (c) long-time limit of the same (smaller) system: uniform at the heat-
# capacity-weighted mean of the initial temperatures, from the materials
# (exact areas), not from the cells
Rout = 0.1
res = cc.solve(R, Rout, steel, water, [1e6], 200)
cs, cw = steel.rho * steel.cv * R * R, water.rho * water.cv * (Rout * Rout - R * R)
T_eq = (cs * steel.T0 + cw * water.T0) / (cs + cw)
below(np.abs(res["T"][0] - T_eq).max(), 1e-9, f"two materials, t = 1e6 s: |T - T_eq| (K), T_eq = {T_eq:.6f} K")

# (d) the interface: quadratics through the three cells on each side give T
# and the heat flux -k dT/dr at r = R from each side; they must agree to the
# discretisation error, steel in water at 100 s. Measured at 100 + 400 /
# 200 + 800 cells: flux mismatch 1.0e-2 / 2.6e-3 (ratio 3.9), T jump
# 1.9e-2 / 3.4e-3 K (ratio 5.7). A wrong interface conductance (arithmetic
# mean k) gives a T jump of 1.7 / 0.9 K.
mismatch, jump = {}, {}
for n1, n2, q, dto in refine((100, 400), 1.0, 0.04, 2):
    res = cc.solve(R, 0.25, steel, water, [100.0], (n1, n2), dt_over_t=dto)
    r, T = res["r"], res["T"][0]
    left = np.polyfit(r[n1 - 3:n1] - R, T[n1 - 3:n1], 2)
    right = np.polyfit(r[n1:n1 + 3] - R, T[n1:n1 + 3], 2)
    q_left, q_right = -steel.k * left[1], -water.k * right[1]
    mismatch[n1], jump[n1] = (q_left - q_right) / q_right, left[2] - right[2]
    print(f"interface, {n1} + {n2} cells, 100 s: flux {q_right:.1f} W/m^2, relative mismatch {mismatch[n1]:+.2e}, "
          f"T jump {jump[n1]:+.2e} K")
below(abs(mismatch[200]), 5e-3, "interface, 200 + 800 cells: k dT/dr continuous at r = R (relative)")
below(abs(jump[200]), 6e-3, "interface, 200 + 800 cells: T continuous at r = R (K)")
inside(mismatch[100] / mismatch[200], 3.0, 5.0, "interface: flux mismatch ratio on halving the cells")
inside(jump[100] / jump[200], 3.0, 10.0, "interface: T jump ratio on halving the cells")

# (e) the solid's mean temperature, steel in water at 10 and 100 s, on 250,
# 500 and 1000 cells with dt/t 0.04, 0.02, 0.01: successive changes fall by
# about 4 (measured 4.35 and 4.05)
means = []
for n1, n2, q, dto in refine((50, 200), 1.0, 0.04, 3):
    means.append(cc.solve(R, 0.25, steel, water, [10.0, 100.0], (n1, n2), dt_over_t=dto)["mean_solid"])
print("mean solid T, 250 / 500 / 1000 cells: " + "; ".join(
    f"{t:g} s: {means[0][i]:.6f} / {means[1][i]:.6f} / {means[2][i]:.6f} K" for i, t in enumerate((10, 100))))
for i, t in enumerate((10, 100)):
    inside((means[0][i] - means[1][i]) / (means[1][i] - means[2][i]), 3.0, 5.0,
           f"mean solid T at {t} s: Richardson ratio of successive changes")


# (f) wall held: a cylinder of radius a at T_i with r = a held at T_w from
# t = 0: T = T_w + (T_i - T_w) sum 2 J0(b r/a) / (b J1(b)) exp(-b^2 alpha t/a^2)
# over the roots b of J0; the mean is T_w + (T_i - T_w) sum 4/b^2 exp(...).
# J_n by the trapezoidal rule over a full period (exponentially accurate).
def bessel_j(n, x):
    tau = 2.0 * math.pi * np.arange(256) / 256
    return np.mean(np.cos(n * tau - np.multiply.outer(np.asarray(x, dtype=float), np.sin(tau))), axis=-1)


roots = []
for m in range(1, 40):
    b = (m - 0.25) * math.pi
    for _ in range(20):
        b += bessel_j(0, b) / bessel_j(1, b)     # Newton: J0' = -J1
    roots.append(float(b))
# dt/t = 0.005: at Fo = 0.585 the slowest mode has decayed by exp(-3.4),
# where the relative time error grows (see conjugate_cylinder.py). Measured
# at 200 / 400 cells: mean errors 1.4e-3 / 3.4e-4 K at Fo = 0.023 and
# 5.7e-4 / 1.4e-4 K at Fo = 0.117 (ratio 4.0); largest profile errors
# 2.2e-3 / 5.5e-4 and 1.6e-3 / 4.4e-4 K.
a, T_w = 0.1, 293.15
times = [20.0, 100.0, 500.0]
err, err_mean = {}, {}
for n, dto in ((200, 0.005), (400, 0.0025)):
    res = cc.solve(R, a, hot, hot, times, n, outer=T_w, dt_over_t=dto)
    err[n], err_mean[n] = [], []
    for i, t in enumerate(times):
        fo = steel.alpha * t / a ** 2
        rr, TT = cc.nodes(res, i)
        series = T_w + 60.0 * sum(2.0 * bessel_j(0, b * rr / a) / (b * bessel_j(1, b)) * math.exp(-b * b * fo)
                                  for b in roots)
        mean = np.dot(res["volume"], res["T"][i]) / (math.pi * a * a)
        mean_exact = T_w + 60.0 * sum(4.0 / b ** 2 * math.exp(-b * b * fo) for b in roots)
        err[n].append(np.abs(TT - series).max())
        err_mean[n].append(mean - mean_exact)
    print(f"wall held, {n} cells, dt/t {dto:g}: largest |T - series| "
          + ", ".join(f"{e:.2e}" for e in err[n]) + " K; mean - series "
          + ", ".join(f"{e:+.2e}" for e in err_mean[n]) + f" K at t = {', '.join(f'{t:g}' for t in times)} s")
for i, t in enumerate(times):
    fo = steel.alpha * t / a ** 2
    below(err[200][i], 5e-3, f"wall held, 200 cells, Fo = {fo:.3f}: largest |T - series| (K)")
    below(abs(err_mean[200][i]), 2e-3, f"wall held, 200 cells, Fo = {fo:.3f}: mean T - series (K)")
for i in (0, 1):
    inside(err_mean[200][i] / err_mean[400][i], 3.0, 5.0,
           f"wall held, Fo = {steel.alpha * times[i] / a ** 2:.3f}: mean error ratio 200 / 400 cells")

print(f"run time {time.time() - t_start:.1f} s")
finish()
