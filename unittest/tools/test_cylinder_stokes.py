"""tools/cylinder_stokes.py, the Taylor-Hood (P2-P1) Stokes reference for the
drag per unit length on a cylinder translating in a closed channel or a
concentric container, against exact and published results and its own
invariants: (a) inside a concentric cylinder, b/a = 4 and 2, against the
exact drag 4 pi mu U / (ln(b/a) - (b^2 - a^2) / (b^2 + a^2)), the error
falling by at least 3 on halving the mesh; (b) midway in a channel,
l/a = 4 with the ends 8 a from the centre, against Faxen's series for the
infinite channel, converging to it; (c) a centred cylinder feels no lateral
force, reversing the velocity reverses the drag, and the drag is linear in
mu; (d) the drag is the dissipated power over the speed, to round-off;
(e) a closed end 4 a below the centre raises the drag by 1 to 2 % over an end
8 a below (the settling example's end effect)."""

import math
import time

import numpy as np

from checks import below, finish, inside

import cylinder_stokes as cs

t_start = time.time()
a = 1.0
DOWN = (0.0, -1.0)

# (a) concentric container, the default grading (hmax = 4 h0). Measured
# relative errors, b/a = 4: +1.424e-3 at h0 = 0.2 a, +1.731e-4 at 0.1 a
# (ratio 8.2; the far-field and polygon errors have opposite signs). b/a = 2
# (a gap of one radius, pre-asymptotic at h0 >= 0.1 a): +2.630e-3 at
# h0 = 0.05 a, +6.290e-4 at 0.025 a (ratio 4.2). Limits: about 3 times the
# measured errors at the finer mesh, and a ratio of at least 3.
for b, h0s, limit in ((4.0, (0.2, 0.1), 5e-4), (2.0, (0.05, 0.025), 2e-3)):
    exact = cs.annulus_drag(a, b)
    err = []
    for h0 in h0s:
        res = cs.solve(a, cs.Annulus(b), DOWN, 1.0, h0, 4.0 * h0)
        err.append(res["drag"][1] / exact - 1.0)
        print(f"annulus b/a = {b:g}, h0 = {h0:g} a, {res['elements']} elements: drag {res['drag'][1]:.8f}, "
              f"exact {exact:.8f}, relative error {err[-1]:+.3e}")
    below(abs(err[1]), limit, f"annulus b/a = {b:g}, h0 = {h0s[1]:g} a: |drag / exact - 1|")
    inside(err[0] / err[1], 3.0, 16.0, f"annulus b/a = {b:g}: error ratio h0 = {h0s[0]:g} a / {h0s[1]:g} a")

# (b) channel of half-width l = 4 a, closed 8 a below and above the centre,
# against Faxen's series for the infinite channel (the ends change the drag
# by 3e-4 at 6 a and less at 8 a). Measured relative errors -4.255e-3 at
# h0 = 0.2 a, hmax = 0.5 a and -1.121e-3 at h0 = 0.1 a, hmax = 0.25 a (ratio
# 3.8); the Richardson extrapolation of three meshes is 2.8e-5 from Faxen.
# Limit 2e-3 (1.8 times the measured) and a ratio of at least 3.
faxen = cs.faxen_drag(a, 4.0)
channel = cs.Channel(4.0, 8.0, 8.0)
err = []
for h0, hmax in ((0.2, 0.5), (0.1, 0.25)):
    res = cs.solve(a, channel, DOWN, 1.0, h0, hmax)
    err.append(res["drag"][1] / faxen - 1.0)
    print(f"channel l/a = 4, ends at -+8 a, h0 = {h0:g} a, hmax = {hmax:g} a, {res['elements']} elements: "
          f"drag {res['drag'][1]:.8f}, Faxen {faxen:.8f}, relative difference {err[-1]:+.3e}")
below(abs(err[1]), 2e-3, "channel l/a = 4, ends at -+8 a, h0 = 0.1 a: |drag / Faxen - 1|")
inside(err[0] / err[1], 3.0, 16.0, "channel l/a = 4: difference ratio h0 = 0.2 a / 0.1 a")
drag8 = res

# (c) symmetry and linearity on the same mesh. Measured |F_x| / F_y =
# 1.4e-7 (the mesh is not exactly mirror-symmetric: the square lattice's
# diagonals); reversed velocity and mu = 2.5 agree to round-off (0 and 4e-15).
below(abs(drag8["drag"][0]) / drag8["drag"][1], 1e-6, "channel, centred cylinder: |F_x| / F_y")
up = cs.solve(a, channel, (0.0, 1.0), 1.0, 0.1, 0.25)
below(np.abs(up["drag"] + drag8["drag"]).max() / drag8["drag"][1], 1e-10,
      "channel: |F(U) + F(-U)| / F, velocity reversed")
viscous = cs.solve(a, channel, DOWN, 2.5, 0.1, 0.25)
below(abs(viscous["drag"][1] / (2.5 * drag8["drag"][1]) - 1.0), 1e-10, "channel: drag(mu = 2.5) / (2.5 drag(mu = 1)) - 1")

# (d) the reaction is the dissipation: with the velocity discretely
# divergence-free, U . F = u^T A u = 2 mu int D:D dA. Measured 7e-15
# relative; |B u| 3e-14.
K, nodes, _ = cs.assemble(drag8["vertices"], drag8["triangles"], 1.0)
nn = len(nodes)
u = np.concatenate([drag8["velocity"][:, 0], drag8["velocity"][:, 1]])
power = float(u @ (K[:2 * nn, :2 * nn] @ u))
print(f"channel, h0 = 0.1 a: 2 mu int D:D dA = {power:.12g}, U . F = {drag8['drag'][1]:.12g}")
below(abs(power / drag8["drag"][1] - 1.0), 1e-10, "channel: U . F / dissipated power - 1")
below(np.abs(K[2 * nn:, :2 * nn] @ u).max(), 1e-10, "channel: discrete divergence |B u|")

# (e) a closed end nearer the cylinder raises the drag: the bottom 4 a below
# the centre instead of 8 a (top at 8 a). Measured +1.49 % at h0 = 0.1 a,
# hmax = 0.25 a (and +8.4 % at 3 a, +0.23 % at 5 a).
near_end = cs.solve(a, cs.Channel(4.0, 4.0, 8.0), DOWN, 1.0, 0.1, 0.25)
inside(near_end["drag"][1] / drag8["drag"][1] - 1.0, 0.01, 0.02,
       "channel l/a = 4: drag with the bottom at 4 a / at 8 a - 1")

print(f"run time {time.time() - t_start:.1f} s")
finish()
