"""The table of examples/grains-single (run.sh): each settling grain's slip
and velocity against the drag law's terminal slip, each held grain's
temperature against the lumped capacitance solution, from the lines the
runs printed, and the mean force and slip of a grain in a column of liquid
at rest under gravity against its weight and the drag law.
usage: results.py settle.txt heat.txt column.txt > results.md"""

import math

import re
import sys

from grain_exact import lumped_temperature, nusselt, terminal_slip

D, RHO_P, RHO_F, CP, K, T0, TF = 0.0004, 2500.0, 1000.0, 800.0, 0.5, 350.0, 300.0


def fields(line):
    return {m.group(1): float(m.group(2)) for m in re.finditer(r"([a-z]+) (-?[0-9.eE+-]+)", line)}


def main():
    print("# One grain in still fluid (run.sh): fix sph/grains against its laws' exact values")
    print()
    print("Settling under its buoyant weight, Di Felice's drag: the slip u - v through the fluid")
    print("around the grain and the grain's own velocity, against the drag law's terminal slip")
    print("at the grain's porosity.")
    print()
    print("| spacing (mm) | viscosity (Pa s) | Re | slip (m/s) | drag law (m/s) | slip error (%) | grain velocity error (%) |")
    print("|---|---|---|---|---|---|---|")
    for line in open(sys.argv[1]):
        v = fields(line)
        exact = terminal_slip("difelice", v["weight"], D, RHO_F, v["mu"], v["porosity"])
        re_p = v["porosity"] * RHO_F * D * exact / v["mu"]
        print(f"| {1e3 * v['spacing']:g} | {v['mu']:g} | {re_p:.3g} | {v['slip']:.6g} | {exact:.6g} | "
              f"{100.0 * (v['slip'] / exact - 1.0):+.3g} | {100.0 * (-v['velocity'] / exact - 1.0):+.3g} |")
    print()
    print("Held at 350 K in fluid at 300 K (Nu = 2 at rest for both laws), the grain's")
    print("temperature against the lumped capacitance solution; the error relative to the change.")
    print()
    print("| spacing (mm) | heat law | time (s) | T (K) | lumped (K) | error (% of the change) |")
    print("|---|---|---|---|---|---|")
    for line, law in zip(open(sys.argv[2]), ["ranz-marshall", "gunn"] * 2):
        v = fields(line)
        exact, tau = lumped_temperature(v["time"], T0, TF, D, RHO_P, CP, K,
                                        nusselt(law, 0.0, 1.0, v["porosity"]))
        print(f"| {1e3 * v['spacing']:g} | {law} | {v['time']:g} | {v['temperature']:.6f} | {exact:.6f} | "
              f"{100.0 * (v['temperature'] - exact) / (T0 - exact):+.3g} |")

    print()
    print("In a column of liquid at rest under gravity (in.column, spacing 1 mm), the means over")
    print("0.1 to 0.2 s: the force of the liquid on the grain (drag and buoyancy) against its")
    print("weight, its slip against the drag law's terminal slip under its buoyant weight.")
    print()
    print("| grain density (kg/m^3) | force / weight - 1 (%) | slip (m/s) | drag law (m/s) | "
          "slip error (% of the bead's drag-law slip) |")
    print("|---|---|---|---|---|")
    volume = math.pi * D ** 3 / 6.0
    lines = [fields(line) for line in open(sys.argv[3])]
    bead = terminal_slip("difelice", (RHO_P - RHO_F) * volume * 9.81, D, RHO_F, lines[0]["mu"],
                         lines[0]["porosity"])
    for v in lines:
        rho_p = v["grain"]
        exact = bead if rho_p > RHO_F else 0.0
        print(f"| {rho_p:g} | {100.0 * (v['force'] / (rho_p * volume * 9.81) - 1.0):+.3g} | {v['slip']:.4g} | "
              f"{exact:.4g} | {100.0 * (v['slip'] - exact) / bead:+.3g} |")

if __name__ == "__main__":
    main()
