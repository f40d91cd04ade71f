"""The tables of examples/grains-bed (run.sh): the superficial velocity
through a fixed packed bed at each pressure gradient against the drag law's
exact value for the bed and against Ergun's equation, from the lines the
runs printed (in.bed); the heated bed's temperatures against Schumann's
solution (in.heatbed, tools/heatbed_compare.py) and their plot
(heatbed.png, written where it runs).
usage: results.py bed.txt heatbed.txt OUT > results.md"""

import re
import sys

import os

from grain_exact import bed_superficial, ergun_superficial
from heatbed_compare import compare

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
    heated(sys.argv[2], sys.argv[3])


def heated(path, out):
    """The heated bed's table and plot."""
    print()
    print("## Heated by a hot inflow: against Schumann's solution")
    print()
    print("The bed (porosity 0.5, Gidaspow's drag, Gunn's heat law) fed at T_in = 350 K through the")
    print("periodic inlet (fix sph/inlet/temperature), bed and liquid at 300 K at the start. Largest")
    print("deviation over the whole bed at the end, in % of T_in - T0; L_f = eps rho_f c_f u / (h a),")
    print("the exchange length, against the kernel's support of 3 mm.")
    print()
    print("| k (W/m/K) | Re | L_f (mm) | time (s) | grains (%) | fluid (%) | fluid's lowest theta |")
    print("|---|---|---|---|---|---|---|")
    results = []
    for n, line in enumerate(open(path)):
        label = line.split(":", 1)[0].split()[1]
        r = compare(line, os.path.join(out, f"{label}.grains.dump"), os.path.join(out, f"{label}.fluid.dump"))
        results.append(r)
        print(f"| {r['k']:g} | {r['re']:.3g} | {1e3 * r['exchange_length']:.3g} | {r['time']:g} | "
              f"{100.0 * r['grains']:.2f} | {100.0 * r['fluid']:.2f} | {r['fluid_min']:.3g} |")
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        return
    fig, ax = plt.subplots(figsize=(6.4, 4.0))
    for r, style in zip(results, ["o", "s"]):
        ax.plot(1e3 * r["x"][::5], r["grain_theta"][::5], style, ms=3, mfc="none",
                label=f"grains, SPH (L_f = {1e3 * r['exchange_length']:.0f} mm, t = {r['time']:g} s)")
        ax.plot(1e3 * r["x"], r["schumann_s"], "-", lw=1, label=f"Schumann, t = {r['time']:g} s")
    ax.set_xlabel("x (mm)")
    ax.set_ylabel("(T - T0) / (T_in - T0)")
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig("heatbed.png", dpi=120)


if __name__ == "__main__":
    main()
