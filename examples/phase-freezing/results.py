"""The freezing runs of run.sh against the package's finite-volume
enthalpy-porosity solver (tools/phase_fv.py, its results in
tools/phase_fv_results.json) and, without gravity, against pure
conduction: writes the results table (Markdown, to stdout) and
freezing.png (the solid fraction and the fronts against time, the liquid
fraction and temperature at the end).

  python3 results.py OUT N...    # OUT: run.sh's output directory; N: the
                                 # resolutions run (particles across H)
"""

import math
import os
import sys

import numpy as np

import phase_fv
import stefan
from sphthermal_tools import phase
from sphthermal_tools.dump import read_frames
from sphthermal_tools.log import thermo_tables

HERE = os.path.dirname(os.path.abspath(__file__))
ROWS = ("top", "middle", "bottom")
FV_ROW = {"top": "top_{}", "middle": "mid_row_{}", "bottom": "bottom_{}"}
TM = 300.0


def snapshots(directory):
    """{time: frame} of the snapshots in directory."""
    frames = {}
    for name in os.listdir(directory):
        parts = name.split(".")
        if len(parts) == 3 and parts[0] == "freezing" and parts[2] == "dump":
            frames[float(parts[1])] = read_frames(os.path.join(directory, name))[-1][1]
    return dict(sorted(frames.items()))


def nusselt(directory):
    """{time: (Nu cold, Nu hot)} at the ends of the runs of the log."""
    out = {}
    with open(os.path.join(directory, "log.freezing")) as f:
        for table in thermo_tables(f.read()):
            if "c_nu_cold[1]" in table and len(table["Time"]):
                out[round(float(table["Time"][-1]), 6)] = (table["c_nu_cold[1]"][-1], table["c_nu_hot[1]"][-1])
    return out


def solid(frame):
    return 1.0 - phase.liquid_fraction(frame)


def fronts(frame, n):
    return phase.front_positions(frame, 1.0 / n, 1.0, 1.0, "solid")


def main():
    out, resolutions = sys.argv[1], [int(n) for n in sys.argv[2:]]
    runs = {n: snapshots(os.path.join(out, f"n{n}")) for n in resolutions}
    nus = {n: nusselt(os.path.join(out, f"n{n}")) for n in resolutions}
    finest = resolutions[-1]
    fv, fv2, grid, grid2 = phase_fv.reference_series("freezing", "convection")
    print("# Freezing in a square cavity cooled from one side (fix sph/phase)\n")
    print(f"Reference: tools/phase_fv.py on {grid} x {grid} cells (in brackets: its change from "
          f"{grid2} x {grid2}, the measure of its own error).\n")

    print("## Solid fraction of the cavity\n")
    print("| t | finite volume | " + " | ".join(f"n = {n}" for n in resolutions) + " |")
    print("|---" * (2 + len(resolutions)) + "|")
    worst = {n: 0.0 for n in resolutions}
    for t in sorted(fv):
        if not any(t in runs[n] for n in resolutions):
            continue
        ref = 1.0 - fv[t]["liquid_fraction"]
        cells = []
        for n in resolutions:
            if t in runs[n]:
                sim = solid(runs[n][t])
                worst[n] = max(worst[n], abs(sim - ref))
                cells.append(f"{sim:.4f} ({sim - ref:+.4f})")
            else:
                cells.append("")
        own = ref - (1.0 - fv2[t]["liquid_fraction"])
        print(f"| {t:g} | {ref:.4f} ({own:+.4f}) | {' | '.join(cells)} |")
    print("\n(SPH: in brackets minus the finite volume)\n")
    for n in resolutions:
        print(f"- n = {n}: largest difference from the finite volume {worst[n]:.4f}")

    print("\n## Front (fraction of H from the cold wall) in the top, middle and bottom rows\n")
    print("| t | row | " + " | ".join(f"finite volume, n = {n} rows | n = {n}" for n in resolutions) + " |")
    print("|---" * (2 + 2 * len(resolutions)) + "|")
    worst_front = {n: 0.0 for n in resolutions}
    for t in sorted(fv):
        if t < 40.0 or not all(t in runs[n] for n in resolutions):
            continue
        for row in ROWS:
            cells = []
            for n in resolutions:
                ref = fv[t]["fronts"][FV_ROW[row].format(n)]
                sim = fronts(runs[n][t], n)[row]
                worst_front[n] = max(worst_front[n], abs(sim - ref))
                cells.append(f"{ref:.3f} | {sim:.3f} ({sim - ref:+.3f})")
            print(f"| {t:g} | {row} | {' | '.join(cells)} |")
    print(f"\n(the finite volume's fronts move by a cell, 1/{grid} = {1 / int(grid):.3f}, at a time)\n")
    for n in resolutions:
        print(f"- n = {n}: largest front difference from the finite volume {worst_front[n]:.3f}")

    print("\n## Nusselt number of the cold and the hot wall\n")
    print("| t | finite volume, cold / hot | " + " | ".join(f"n = {n}" for n in resolutions) + " |")
    print("|---" * (2 + len(resolutions)) + "|")
    for t in sorted(fv):
        if t < 40.0:
            continue
        cells = [f"{nus[n][t][0]:.3f} / {nus[n][t][1]:.3f}" if t in nus[n] else "" for n in resolutions]
        print(f"| {t:g} | {fv[t]['Nu_left']:.3f} / {fv[t]['Nu_right']:.3f} | {' | '.join(cells)} |")

    conduction_dir = os.path.join(out, "conduction")
    if os.path.isdir(conduction_dir):
        cond = snapshots(conduction_dir)
        cfv, cfv2, cgrid, cgrid2 = phase_fv.reference_series("freezing", "conduction")
        n_cond = int(round(math.sqrt(len(next(iter(cond.values()))["x"]))))
        # Neumann: the solid's and the liquid's Stefan numbers 1, the same
        # diffusivity; exact while the heat has not reached the hot wall
        lam = stefan.neumann_lambda(1.0, 1.0, 1.0)
        alpha = math.sqrt(2.0e-5)
        print(f"\n## Without gravity: pure conduction (n = {n_cond})\n")
        print(f"| t | Neumann (semi-infinite) | finite volume, {cgrid} cells | fix sph/phase |")
        print("|---|---|---|---|")
        for t, frame in cond.items():
            neumann = stefan.front(t, lam, alpha) if t <= 20.0 else float("nan")
            ref = 1.0 - cfv[t]["liquid_fraction"] if t in cfv else float("nan")
            sim = solid(frame)
            cell = "" if math.isnan(neumann) else f"{neumann:.4f}"
            print(f"| {t:g} | {cell} | {ref:.4f} | {sim:.4f} ({sim - ref:+.4f}) |")
        last = cond[max(cond)]
        x, T = last["x"], last["c_T"]
        print(f"\nAt t = {max(cond):g}: the exact steady solid is 0.5 thick with T = Tm - 1 + 2 x linear; "
              f"the largest |T - exact| {np.abs(T - (TM - 1.0 + 2.0 * x)).max():.2e} over the particles.")

    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, axes = plt.subplots(2, 2, figsize=(11, 8))
    fraction, front_axis, liquid, temperature = axes.ravel()
    ts = sorted(fv)
    fraction.plot(ts, [1.0 - fv[t]["liquid_fraction"] for t in ts], "k-", label=f"finite volume {grid}^2")
    for n in resolutions:
        times = list(runs[n])
        fraction.plot(times, [solid(runs[n][t]) for t in times], "o", ms=4, label=f"fix sph/phase, n = {n}")
    fraction.set_xscale("log")
    fraction.set_xlabel("t")
    fraction.set_ylabel("solid fraction")
    fraction.legend(fontsize=8)
    for row, colour in zip(ROWS, ("C3", "C2", "C0")):
        front_axis.plot(ts, [fv[t]["fronts"][FV_ROW[row].format(finest)] for t in ts], "-", color=colour,
                        label=f"finite volume, {row}")
        times = list(runs[finest])
        front_axis.plot(times, [fronts(runs[finest][t], finest)[row] for t in times], "o", color=colour,
                        ms=4, label=f"n = {finest}, {row}")
    front_axis.set_xscale("log")
    front_axis.set_xlabel("t")
    front_axis.set_ylabel("front x / H")
    front_axis.legend(fontsize=7, ncol=2)
    end = max(runs[finest])
    frame = runs[finest][end]
    for axis, column, label, cmap in ((liquid, "f_phase", "liquid fraction", "coolwarm"),
                                      (temperature, "c_T", "T - Tm", "coolwarm")):
        values = frame[column] - (TM if column == "c_T" else 0.0)
        scatter = axis.scatter(frame["x"], frame["y"], c=values, s=6, cmap=cmap)
        axis.set_aspect("equal")
        axis.set_xlabel("x / H")
        axis.set_ylabel("y / H")
        axis.set_title(f"{label}, t = {end:g}, n = {finest}", fontsize=10)
        fig.colorbar(scatter, ax=axis, shrink=0.8)
    if end in fv:
        centres = (np.arange(finest) + 0.5) / finest
        heights = {"top": centres[-1], "middle": centres[np.argmin(np.abs(centres - 0.5))], "bottom": centres[0]}
        for row in ROWS:
            liquid.plot(fv[end]["fronts"][FV_ROW[row].format(finest)], heights[row], "ks", ms=5)
        liquid.set_title(f"liquid fraction, t = {end:g}, n = {finest}\n(squares: the finite volume's front)",
                         fontsize=10)
    fig.tight_layout()
    fig.savefig(os.path.join(HERE, "freezing.png"), dpi=100)


if __name__ == "__main__":
    main()
