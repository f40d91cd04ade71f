"""Errors of the two-materials example; writes <prefix>.png.

References: the exact solution for two semi-infinite materials in contact
(Carslaw & Jaeger 1959, Conduction of Heat in Solids; valid while the diffusion lengths are small
against the slab) and a fine 1-D finite-volume solution of the finite slab
(tools/fv1d.py, its own error printed). Errors are in % of the temperature
jump T2 - T1, at t1 (when 2 sqrt(alpha t) of the less diffusive material is
4 particle spacings) and at 10 t1; the energy sum(m esph) drift is printed.
"""

import argparse
import math
import os
import sys

import numpy as np

root = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..")
import fv1d
from sphthermal_tools.dump import read_frames


def layers_for(case):
    if case == "ratio":
        return [fv1d.Layer(0.0, 0.5, "constant:1", 1000.0, 1.0, 0.0),
                fv1d.Layer(0.5, 1.0, "constant:3", 500.0, 1.0, 1.0)]
    materials = os.path.join(root, "potentials", "thermal_300K.sphmat")
    return [fv1d.material_from_file(materials, "air", 0.0, 0.5, 300.0),
            fv1d.material_from_file(materials, "water", 0.5, 1.0, 310.0)]


def exact(x, t, layers):
    """Two semi-infinite materials meeting at x = 0.5 (conductivities at the initial T)."""
    a, b = layers
    ka, kb = float(a.k(np.array(a.T0))), float(b.k(np.array(b.T0)))
    ea, eb = math.sqrt(ka * a.rho * a.cv), math.sqrt(kb * b.rho * b.cv)
    tc = (ea * a.T0 + eb * b.T0) / (ea + eb)
    erf = np.vectorize(math.erf)
    xa = (x - 0.5) / np.sqrt(4.0 * ka / (a.rho * a.cv) * t)
    xb = (x - 0.5) / np.sqrt(4.0 * kb / (b.rho * b.cv) * t)
    return np.where(x < 0.5, tc + (a.T0 - tc) * erf(-xa), tc + (b.T0 - tc) * erf(xb))


def main():
    p = argparse.ArgumentParser(description=__doc__)
    p.add_argument("prefix", nargs="?", default="two-materials")
    p.add_argument("--case", default="ratio", choices=["ratio", "airwater"])
    p.add_argument("--nx", type=int, default=80)
    p.add_argument("--dt", type=float, required=True)
    p.add_argument("--cells", type=int, default=500, help="finite-volume cells")
    p.add_argument("--label", default="pair sph/cleary/heat")
    p.add_argument("--max-error", type=float, help="fail (exit 1) above this max error at t1 and 10 t1, %%")
    p.add_argument("--max-drift", type=float, help="fail (exit 1) above this relative energy drift")
    a = p.parse_args()

    layers = layers_for(a.case)
    jump = layers[1].T0 - layers[0].T0
    dx = 1.0 / a.nx
    alpha_min = min(float(L.k(np.array(L.T0))) / (L.rho * L.cv) for L in layers)
    t1 = 4.0 * dx * dx / alpha_min

    frames = [(step * a.dt, c) for step, c in read_frames(a.prefix + ".dump") if step > 0]
    times = [t for t, _ in frames]
    x_fv, T_fv = fv1d.solve(layers, 1.0, a.cells, times)
    fv_error = fv1d.reference_error(layers, 1.0, a.cells, times)
    print(f"finite-volume reference: {a.cells} cells, largest difference to {a.cells // 2} cells "
          f"{100 * fv_error / abs(jump):.4f} % of the jump")

    print(f"{'t (s)':>10} {'max err % (FV)':>15} {'mean err % (FV)':>16} {'max err % (erf)':>16}")
    errors = []
    for (t, c), T_ref in zip(frames, T_fv):
        e_fv = 100.0 * np.abs(c["c_T"] - np.interp(c["x"], x_fv, T_ref)) / abs(jump)
        e_erf = 100.0 * np.abs(c["c_T"] - exact(c["x"], t, layers)) / abs(jump)
        errors.append((t, e_fv.max(), e_fv.mean(), e_erf.max()))
        print(f"{t:10.4g} {e_fv.max():15.4f} {e_fv.mean():16.4f} {e_erf.max():16.4f}")

    def at(t):
        return min(errors, key=lambda e: abs(e[0] - t))

    e1, e10 = at(t1), at(10.0 * t1)
    energy = np.loadtxt(a.prefix + ".energy", ndmin=2)
    drift = np.abs(energy[:, 1] / energy[0, 1] - 1.0)
    print(f"{a.label}: max error at t1 = {e1[0]:g} s: {e1[1]:.3f} % (against the exact erf: {e1[3]:.3f} %)")
    print(f"{a.label}: max error at 10 t1 = {e10[0]:g} s: {e10[1]:.3f} % (the semi-infinite erf "
          f"is {e10[3]:.2f} % off there)")
    print(f"{a.label}: relative change of sum(m esph) by t = {energy[-1, 0]:g} s: "
          f"{energy[-1, 1] / energy[0, 1] - 1.0:+.3e} (largest {drift.max():.2e})")

    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, ax = plt.subplots(figsize=(6.4, 4.2))
    for t, colour in [(e1[0], "C0"), (e10[0], "C1")]:
        k = times.index(t)
        c = frames[k][1]
        ax.plot(x_fv, T_fv[k], "-", color=colour, lw=1, label=f"finite volume, t = {t:g} s")
        ax.plot(c["x"], c["c_T"], ".", color=colour, ms=3, label=f"SPH, t = {t:g} s")
    ax.set_xlabel("x (m)")
    ax.set_ylabel("T")
    ax.set_title(f"{a.case}, {a.label}: max error {max(e1[1], e10[1]):.2f} % of the jump", fontsize=9)
    ax.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(a.prefix + ".png", dpi=120)
    print("plot:", os.path.abspath(a.prefix + ".png"))

    failed = a.max_error is not None and max(e1[1], e10[1]) > a.max_error
    failed = failed or (a.max_drift is not None and drift.max() > a.max_drift)
    if failed:
        print(f"FAIL: error above {a.max_error} % or energy drift above {a.max_drift}")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
