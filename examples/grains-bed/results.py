"""The table of examples/grains-bed (run.sh): the superficial velocity
through a fixed packed bed at each pressure gradient against the drag law's
exact value for the bed and against Ergun's equation, from the lines the
runs printed (in.bed).
usage: results.py bed.txt > results.md"""

import re
import sys

from grain_exact import bed_superficial, ergun_superficial

RHO_F = 1000.0
NAMES = ["U", "drag", "drive", "gradient", "porosity", "fluid porosity", "grain porosity", "d", "mu",
         "spacing"]


def fields(line):
    """The named numbers of one printed line, and its drag law."""
    values = {name: float(re.search(rf"(?:^|, ){name} (-?[0-9.eE+-]+)", line.split(":", 1)[1].strip()).group(1))
              for name in NAMES}
    return values, re.search(r"drag law (\w+)", line).group(1)


def rows(path):
    """Per run: law, porosity, gradient, Re, U, the law's U, Ergun's U,
    the steady force balance and the porosity the kernel gives the grains."""
    for line in open(path):
        v, law = fields(line)
        eps, d = v["porosity"], v["d"]
        exact = bed_superficial(law, v["gradient"], d, eps, RHO_F, v["mu"])
        ergun = ergun_superficial(v["gradient"], d, eps, RHO_F, v["mu"])
        yield {"law": law, "eps": eps, "gradient": v["gradient"], "re": RHO_F * exact * d / v["mu"],
               "U": v["U"], "exact": exact, "ergun": ergun, "balance": v["drag"] / v["drive"] - 1.0,
               "grain_eps": v["grain porosity"], "fluid_eps": v["fluid porosity"]}


def main():
    table = list(rows(sys.argv[1]))
    print("# A fixed packed bed (run.sh): fix sph/grains against the drag law and Ergun's equation")
    print()
    print("Superficial velocity U through a periodic bed of 512 grains on a simple cubic lattice")
    print("(spacing 1 mm, Wendland support 3 mm) driven by a pressure gradient G, the mean over the")
    print("last fifth of 15 relaxation times. 'law' is the drag law's exact U for the bed")
    print("(tools/grain_exact.py), 'Ergun' Ergun's (1952). Re = rho U d / mu.")
    print()
    print("| drag law | porosity | G (Pa/m) | Re | U (m/s) | law (m/s) | error (%) | Ergun (m/s) | "
          "law vs Ergun (%) | drag / drive - 1 | porosity at the grains |")
    print("|---|---|---|---|---|---|---|---|---|---|---|")
    for r in table:
        print(f"| {r['law']} | {r['eps']:g} | {r['gradient']:g} | {r['re']:.3g} | {r['U']:.6g} | "
              f"{r['exact']:.6g} | {100.0 * (r['U'] / r['exact'] - 1.0):+.3g} | {r['ergun']:.6g} | "
              f"{100.0 * (r['exact'] / r['ergun'] - 1.0):+.3g} | {r['balance']:+.2g} | "
              f"{r['grain_eps']:.5f} |")
    worst = max(abs(r["U"] / r["exact"] - 1.0) for r in table)
    worst_ergun = max(abs(r["U"] / r["ergun"] - 1.0) for r in table if r["law"] == "gidaspow")
    print()
    print(f"Largest error against the drag law's exact U: {100.0 * worst:.2f} %; with Gidaspow's "
          f"drag against Ergun's U: {100.0 * worst_ergun:.2f} %.")


if __name__ == "__main__":
    main()
