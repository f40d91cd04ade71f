"""The table of examples/grains-single (run.sh): each settling grain's slip
and velocity against the drag law's terminal slip, each held grain's
temperature against the lumped capacitance solution, from the lines the
runs printed. usage: results.py settle.txt heat.txt > results.md"""

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


if __name__ == "__main__":
    main()
