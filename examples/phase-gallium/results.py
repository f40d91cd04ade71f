"""The gallium melting runs of run.sh against the experiment of Gau and
Viskanta (1986), the computation of Blais and Ilinca (2018) and, while the
melt is thin, pure conduction (tools/gallium_reference.py): writes the
results table (Markdown, to stdout) and gallium.png (the melted volume and
the fronts against time, the liquid fraction and temperature at 15 min).

  python3 results.py OUT N...    # OUT: run.sh's output directory; N: the
                                 # resolutions run (particles across H)
"""

import os
import sys

import numpy as np

import gallium_reference as ref
import phase_fv
from sphthermal_tools.dump import read_frames

HERE = os.path.dirname(os.path.abspath(__file__))
ROWS = ("top", "middle", "bottom")
EXPERIMENT_FRONTS = {"top": ref.FRONT_TOP, "middle": ref.FRONT_MIDDLE, "bottom": ref.FRONT_BOTTOM}


def snapshots(out, n):
    """{time (s): frame} of the run at n particles across H."""
    frames = {}
    directory = os.path.join(out, f"n{n}")
    for name in os.listdir(directory):
        parts = name.split(".")
        if len(parts) == 3 and parts[0] == "gallium" and parts[2] == "dump":
            frames[float(parts[1])] = read_frames(os.path.join(directory, name))[-1][1]
    return dict(sorted(frames.items()))


def main():
    out, resolutions = sys.argv[1], [int(n) for n in sys.argv[2:]]
    runs = {n: snapshots(out, n) for n in resolutions}
    finest = resolutions[-1]
    fv, fv2, grid, grid2 = phase_fv.reference_series("gallium")
    fv_row = {"top": f"top_{finest}", "middle": f"mid_row_{finest}", "bottom": f"bottom_{finest}"}
    print("# Melting of gallium heated from one side (fix sph/phase)\n")
    print(f"Experiment's abscissae against the times taken: within "
          f"{100 * ref.abscissa_ratio_spread():.1f} %.\n")

    print("## While the melt conducts: melted volume against the two-phase Neumann solution\n")
    print("| n | t (s) | melted fraction | conduction (Neumann) | difference |")
    print("|---|---|---|---|---|")
    for n in resolutions:
        for t in (60.0, 120.0):
            if t in runs[n]:
                sim, exact = ref.melted_fraction(runs[n][t]), ref.conduction_melt_fraction(t)
                print(f"| {n} | {t:g} | {sim:.4f} | {exact:.4f} | {100 * (sim / exact - 1):+.1f} % |")

    print("\n## Melted volume fraction against the experiment, Blais and Ilinca (2018) and the finite volume\n")
    print(f"Finite volume: the same model (Brent et al.'s) by tools/phase_fv.py on {grid} cells (in "
          f"brackets: its change from {grid2}, the measure of its own error).\n")
    head = " | ".join(f"n = {n}" for n in resolutions)
    print(f"| t (min) | experiment | Blais and Ilinca | finite volume | {head} |")
    print("|---" * (4 + len(resolutions)) + "|")
    worst = {n: 0.0 for n in resolutions}
    for t, measured in zip(ref.MELT_TIMES, ref.MELT_FRACTION):
        blais = np.interp(t, ref.BLAIS_TIMES, ref.BLAIS_FRACTION)
        cells = []
        for n in resolutions:
            if t in runs[n]:
                sim = ref.melted_fraction(runs[n][t])
                worst[n] = max(worst[n], abs(sim - measured))
                cells.append(f"{sim:.3f} ({sim - measured:+.3f})")
            else:
                cells.append("")
        volume = fv[t]["liquid_fraction"]
        fv_cell = f"{volume:.3f} ({volume - fv2[t]['liquid_fraction']:+.3f})"
        print(f"| {t / 60:g} | {measured:.3f} | {blais:.3f} | {fv_cell} | {' | '.join(cells)} |")
    print("\n(SPH: in brackets minus the experiment)\n")
    for n in resolutions:
        print(f"- n = {n}: largest difference from the experiment {worst[n]:.3f}")
    for n in resolutions:
        gap = max(abs(ref.melted_fraction(runs[n][t]) - fv[t]["liquid_fraction"]) for t in ref.MELT_TIMES
                  if t in runs[n])
        print(f"- n = {n}: largest difference from the finite volume {gap:.3f}")

    print("\n## Melt front (fraction of W) against the experiment and the finite volume\n")
    print(f"Finite volume: in the rows of n = {finest}, on {grid} cells (in brackets: its change from {grid2}).\n")
    print("| t (min) | row | experiment | finite volume | " + " | ".join(f"n = {n}" for n in resolutions) + " |")
    print("|---" * (4 + len(resolutions)) + "|")
    for i, t in enumerate(ref.FRONT_TIMES):
        for row in ROWS:
            cells = []
            for n in resolutions:
                if t in runs[n]:
                    front = ref.front_positions(runs[n][t], ref.HEIGHT / n)[row]
                    cells.append(f"{front:.3f} ({front - EXPERIMENT_FRONTS[row][i]:+.3f})")
                else:
                    cells.append("")
            front = fv[t]["fronts"][fv_row[row]]
            fv_cell = f"{front:.3f} ({front - fv2[t]['fronts'][fv_row[row]]:+.3f})"
            print(f"| {t / 60:g} | {row} | {EXPERIMENT_FRONTS[row][i]:.3f} | {fv_cell} | {' | '.join(cells)} |")

    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, axes = plt.subplots(2, 2, figsize=(11, 8))
    volume, fronts, liquid, temperature = axes.ravel()
    volume.plot(ref.MELT_TIMES / 60, ref.MELT_FRACTION, "ks", label="experiment (Gau and Viskanta 1986)")
    volume.plot(ref.BLAIS_TIMES / 60, ref.BLAIS_FRACTION, "k--", lw=0.8, label="Blais and Ilinca 2018")
    fv_times = np.array(sorted(fv))
    volume.plot(fv_times / 60, [fv[tt]["liquid_fraction"] for tt in fv_times], "k-", lw=0.8,
                label=f"finite volume, {grid} (tools/phase_fv.py)")
    t = np.linspace(1.0, 300.0, 50)
    volume.plot(t / 60, [ref.conduction_melt_fraction(tt) for tt in t], "k:", lw=0.8,
                label="conduction only (Neumann)")
    for n in resolutions:
        times = np.array(list(runs[n]))
        volume.plot(times / 60, [ref.melted_fraction(runs[n][tt]) for tt in times], "o-", ms=3,
                    label=f"fix sph/phase, n = {n}")
    volume.set_xlabel("t (min)")
    volume.set_ylabel("melted volume fraction")
    volume.legend(fontsize=7)
    for row, colour in zip(ROWS, ("C3", "C2", "C0")):
        fronts.plot(ref.FRONT_TIMES / 60, EXPERIMENT_FRONTS[row], "s", color=colour, label=f"experiment, {row}")
        fronts.plot(fv_times / 60, [fv[tt]["fronts"][fv_row[row]] for tt in fv_times], ":", color=colour,
                    label=f"finite volume, {row}")
        times = np.array(list(runs[finest]))
        fronts.plot(times / 60, [ref.front_positions(runs[finest][tt], ref.HEIGHT / finest)[row] for tt in times],
                    "-", color=colour, label=f"n = {finest}, {row}")
    fronts.set_xlabel("t (min)")
    fronts.set_ylabel("melt front x / W")
    fronts.legend(fontsize=7, ncol=2)
    # the snapshot at the experiment's last front (or the run's end before it)
    last = max(t for t in runs[finest] if t <= ref.FRONT_TIMES[-1])
    frame = runs[finest][last]
    for axis, column, label, cmap in ((liquid, "f_phase", "liquid fraction", "coolwarm"),
                                      (temperature, "c_T", "T (K)", "inferno")):
        scatter = axis.scatter(1e3 * frame["x"], 1e3 * frame["y"], c=frame[column], s=4, cmap=cmap)
        axis.set_aspect("equal")
        axis.set_xlabel("x (mm)")
        axis.set_ylabel("y (mm)")
        axis.set_title(f"{label}, t = {last / 60:g} min, n = {finest}")
        fig.colorbar(scatter, ax=axis, shrink=0.8)
    for i, row in enumerate(ROWS):
        i_time = np.argmin(np.abs(ref.FRONT_TIMES - last))
        level = {"top": ref.HEIGHT, "middle": 0.5 * ref.HEIGHT, "bottom": 0.0}[row]
        liquid.plot(1e3 * EXPERIMENT_FRONTS[row][i_time] * ref.WIDTH, 1e3 * level, "ks", ms=5)
    liquid.set_title(f"liquid fraction, t = {last / 60:g} min, n = {finest}\n"
                     f"(squares: the experiment's front at {ref.FRONT_TIMES[i_time] / 60:g} min)", fontsize=10)
    fig.tight_layout()
    fig.savefig(os.path.join(HERE, "gallium.png"), dpi=100)


if __name__ == "__main__":
    main()
