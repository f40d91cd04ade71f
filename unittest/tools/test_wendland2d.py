"""tools/wendland2d.py: W integrates to 1 over the plane, dW/dr is the
derivative of W, and both vanish from r = 2 h on."""

import sys

import numpy as np

import wendland2d

failures = []
h = 0.7
r = np.linspace(0.0, 2.0 * h, 200001)
integral = np.trapz(2.0 * np.pi * r * wendland2d.w(r, h), r)
if abs(integral - 1.0) > 1e-8:
    failures.append(f"integral of W {integral}")
rr = np.linspace(0.01, 1.99, 199) * h
step = 1e-6 * h
numeric = (wendland2d.w(rr + step, h) - wendland2d.w(rr - step, h)) / (2.0 * step)
if np.max(np.abs(numeric - wendland2d.dwdr(rr, h))) > 1e-6 * np.max(np.abs(numeric)):
    failures.append("dW/dr is not the derivative of W")
outside = np.array([2.0, 2.5, 10.0]) * h
if np.any(wendland2d.w(outside, h) != 0.0) or np.any(wendland2d.dwdr(outside, h) != 0.0):
    failures.append("W or dW/dr nonzero outside the support")
if failures:
    sys.exit("FAIL: " + ", ".join(failures))
print("ok")
