"""Fine 1-D finite-volume reference for conduction in layered materials.

Solves rho cv dT/dt = d/dx (k(T) dT/dx) on [0, L] with layers of materials,
each with its own rho, cv, conductivity law and initial temperature; the
ends are adiabatic or held at a temperature. Cell-centred finite volumes,
series (harmonic) conductance between cells, explicit Euler in time with
dt = 0.4 min(rho cv dx^2 / k). Second order in space; the time step is so
small against the physical times that its error is far below the spatial
one. reference_error() states the solution's own error by comparing it
with one on half the cells.

As a module: solve(layers, length, cells, times, left=None, right=None)
returns (x, [T at each time]). As a script, see --help.
"""

import argparse
import math
import sys

import numpy as np


def conductivity_law(spec):
    """'constant:k', 'linear:k0,dkdT,T0', 'exponential:k0,a', 'table:T1,k1,T2,k2,...'."""
    name, _, values = spec.partition(":")
    c = [float(v) for v in values.split(",")] if values else []
    if name == "constant":
        return lambda T: np.full_like(T, c[0])
    if name == "linear":
        return lambda T: c[0] + c[1] * (T - c[2])
    if name == "exponential":
        return lambda T: c[0] * np.exp(c[1] * T)
    if name == "table":
        ts, ks = c[0::2], c[1::2]
        return lambda T: np.interp(T, ts, ks)
    raise ValueError(f"unknown conductivity law '{spec}'")


class Layer:
    """x0 <= x < x1: conductivity law, rho, cv and initial temperature."""

    def __init__(self, x0, x1, k, rho, cv, T0):
        self.x0, self.x1 = x0, x1
        self.k = conductivity_law(k) if isinstance(k, str) else k
        self.rho, self.cv, self.T0 = rho, cv, T0


def solve(layers, length, cells, times, left=None, right=None, left_flux=None):
    """left/right: None (adiabatic) or a temperature held at that end;
    left_flux: None, a heat flux q into the slab at x = 0, or a function
    of the cell temperatures giving it (convection)."""
    dx = length / cells
    x = (np.arange(cells) + 0.5) * dx
    owner = np.zeros(cells, dtype=int)
    for n, layer in enumerate(layers):
        owner[(x >= layer.x0) & (x < layer.x1)] = n
    capacity = np.array([layers[n].rho * layers[n].cv for n in owner])
    T = np.array([layers[n].T0 for n in owner], dtype=float)

    def conductivities(T):
        k = np.empty_like(T)
        for n, layer in enumerate(layers):
            sel = owner == n
            k[sel] = layer.k(T[sel])
        return k

    results, t = [], 0.0
    for t_out in sorted(times):
        while t < t_out - 1e-12 * max(1.0, t_out):
            k = conductivities(T)
            dt = min(0.4 * np.min(capacity * dx * dx / np.maximum(k, 1e-300)), t_out - t)
            # series conductance between neighbouring cells (flux continuity)
            g = 1.0 / (0.5 * dx / k[:-1] + 0.5 * dx / k[1:])
            flux = g * (T[:-1] - T[1:])           # from cell i to cell i+1
            dT = np.zeros_like(T)
            dT[:-1] -= flux
            dT[1:] += flux
            if left is not None:
                dT[0] += 2.0 * k[0] / dx * (left - T[0])
            if right is not None:
                dT[-1] += 2.0 * k[-1] / dx * (right - T[-1])
            if left_flux is not None:
                dT[0] += left_flux(T) if callable(left_flux) else left_flux
            T = T + dt * dT / (capacity * dx)
            t += dt
        results.append(T.copy())
    order = np.argsort(np.argsort(times))
    return x, [results[i] for i in order]


def material_from_file(path, name, x0, x1, T0):
    """A layer of material `name` of a fix sph/materials file (potentials/*.sphmat)."""
    props = {}
    with open(path) as f:
        for line in f:
            words = line.split("#", 1)[0].split()
            if len(words) >= 3 and words[0] == name:
                props[words[1]] = words[2:]
    if not {"conductivity", "rho0", "cv"} <= set(props):
        raise ValueError(f"material '{name}' of {path} lacks conductivity, rho0 or cv")
    law = props["conductivity"]
    if law[0] == "table":
        values = law[2:2 + 2 * int(law[1])]
    else:
        values = law[1:]
    k = f"{law[0]}:{','.join(values)}"
    return Layer(x0, x1, k, float(props["rho0"][0]), float(props["cv"][0]), T0)


def reference_error(layers, length, cells, times, left=None, right=None):
    """Largest difference between the solution on `cells` and on cells/2."""
    x, fine = solve(layers, length, cells, times, left, right)
    xc, coarse = solve(layers, length, cells // 2, times, left, right)
    return max(np.max(np.abs(np.interp(xc, x, f) - c)) for f, c in zip(fine, coarse))


def parse_layer(text):
    """'x0:x1 k=<law> rho=<value> cv=<value> T0=<value>'."""
    words = text.split()
    x0, x1 = (float(v) for v in words[0].split(":"))
    kv = dict(w.split("=", 1) for w in words[1:])
    return Layer(x0, x1, kv["k"], float(kv["rho"]), float(kv["cv"]), float(kv["T0"]))


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--length", type=float, required=True)
    p.add_argument("--cells", type=int, default=2000)
    p.add_argument("--layer", action="append", required=True,
                   help="'x0:x1 k=constant:1 rho=1000 cv=1 T0=0' (repeat for each layer)")
    p.add_argument("--times", required=True, help="comma-separated output times")
    p.add_argument("--left", type=float, help="temperature held at x = 0 (default adiabatic)")
    p.add_argument("--right", type=float, help="temperature held at x = L (default adiabatic)")
    p.add_argument("--out", default="-")
    a = p.parse_args()
    layers = [parse_layer(t) for t in a.layer]
    times = [float(t) for t in a.times.split(",")]
    x, Ts = solve(layers, a.length, a.cells, times, a.left, a.right)
    err = reference_error(layers, a.length, a.cells, times, a.left, a.right)
    out = sys.stdout if a.out == "-" else open(a.out, "w")
    out.write(f"# fv1d: {a.cells} cells; largest difference to {a.cells // 2} cells: {err:.2e}\n")
    out.write("# x " + " ".join(f"T(t={t:g})" for t in times) + "\n")
    for row in zip(x, *Ts):
        out.write(" ".join(f"{v:.10g}" for v in row) + "\n")
    return 0


if __name__ == "__main__":
    sys.exit(main())
