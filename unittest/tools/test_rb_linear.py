"""tools/rb_linear.py, the linear-stability reference for Rayleigh-Benard
convection between rigid plates, against Chandrasekhar (1961): the free onset
Ra_c = 1707.762 at a_c = 3.117, the onsets of the periodic boxes W = 2H and
W = 1.5H that the SPH convection runs use, and the growth rate changing sign
at the onset so that measured growth rates can be compared with it."""

import math
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "tools"))
import rb_linear  # noqa: E402

failures = 0


def expect(value, target, tolerance, what):
    global failures
    ok = abs(value - target) <= tolerance
    failures += not ok
    print(f"{'ok' if ok else 'FAIL'} {what}: {value:.8g} (expected {target:.8g} +- {tolerance:.2g})")


ra, a = rb_linear.onset()
expect(ra, 1707.76, 0.05, "free onset Ra_c")
expect(a, 3.117, 0.005, "free onset a_c")

ra2, a2 = rb_linear.onset(2.0)
expect(ra2, 1707.9223, 0.1, "W = 2H onset Ra_c against the computed 1707.9223")
expect(ra2, 1707.9, 0.005 * 1707.9, "W = 2H onset Ra_c within 0.5 %")
expect(a2, math.pi, 1e-9, "W = 2H onset wavenumber (mode 1)")

ra15, a15 = rb_linear.onset(1.5)
expect(ra15, 1955.8, 0.005 * 1955.8, "W = 1.5H onset Ra_c within 0.5 %")
expect(a15, 4.0 * math.pi / 3.0, 1e-9, "W = 1.5H onset wavenumber (mode 1)")

# the growth rate at a = pi: slowest thermal decay -2 pi^2 at Ra = 0, zero at
# the marginal Ra and changing sign across it
expect(rb_linear.growth_rate(0.0, math.pi, 1.0), -2.0 * math.pi ** 2, 1e-6, "growth rate at Ra = 0")
expect(rb_linear.growth_rate(ra2, math.pi, 1.0), 0.0, 1e-6, "growth rate at the marginal Ra")
for pr in (0.7, 7.0):
    below = rb_linear.growth_rate(0.95 * ra2, math.pi, pr)
    above = rb_linear.growth_rate(1.05 * ra2, math.pi, pr)
    ok = below < 0.0 < above
    failures += not ok
    print(f"{'ok' if ok else 'FAIL'} growth rate sign at Pr = {pr:g}: {below:.4g} at 0.95 Ra_c, "
          f"{above:.4g} at 1.05 Ra_c (expected negative, positive)")

sys.exit(1 if failures else 0)
