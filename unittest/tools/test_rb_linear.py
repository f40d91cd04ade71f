"""tools/rb_linear.py, the linear-stability reference for Rayleigh-Benard
convection between rigid plates, against Chandrasekhar (1961): the free onset
Ra_c = 1707.762 at a_c = 3.117, the onsets of the periodic boxes W = 2H and
W = 1.5H that the SPH convection runs use, and the growth rate changing sign
at the onset so that measured growth rates can be compared with it."""

import math

from checks import finish, near, that

import rb_linear

ra, a = rb_linear.onset()
near(ra, 1707.76, 0.05, "free onset Ra_c")
near(a, 3.117, 0.005, "free onset a_c")

ra2, a2 = rb_linear.onset(2.0)
near(ra2, 1707.9223, 0.1, "W = 2H onset Ra_c against the computed 1707.9223")
near(ra2, 1707.9, 0.005 * 1707.9, "W = 2H onset Ra_c within 0.5 %")
near(a2, math.pi, 1e-9, "W = 2H onset wavenumber (mode 1)")

ra15, a15 = rb_linear.onset(1.5)
near(ra15, 1955.8, 0.005 * 1955.8, "W = 1.5H onset Ra_c within 0.5 %")
near(a15, 4.0 * math.pi / 3.0, 1e-9, "W = 1.5H onset wavenumber (mode 1)")

# the growth rate at a = pi: slowest thermal decay -2 pi^2 at Ra = 0, zero at
# the marginal Ra and changing sign across it
near(rb_linear.growth_rate(0.0, math.pi, 1.0), -2.0 * math.pi ** 2, 1e-6, "growth rate at Ra = 0")
near(rb_linear.growth_rate(ra2, math.pi, 1.0), 0.0, 1e-6, "growth rate at the marginal Ra")
for pr in (0.7, 7.0):
    below = rb_linear.growth_rate(0.95 * ra2, math.pi, pr)
    above = rb_linear.growth_rate(1.05 * ra2, math.pi, pr)
    that(below < 0.0 < above, f"growth rate sign at Pr = {pr:g}",
         f"{below:.4g} at 0.95 Ra_c, {above:.4g} at 1.05 Ra_c (expected negative, positive)")

finish()
