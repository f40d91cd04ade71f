"""The dam break's front against Martin and Moyce's experiment: a table
(results.md) and a plot (PNG) from the logs of in.dam_break.
usage: results.py LOG... [--plain LOG] --md FILE --png FILE"""

import argparse

import dam_break_reference as reference

LENGTH = 8.0    # the tank, in a (in.dam_break's default)


def main():
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("logs", nargs="+")
    parser.add_argument("--plain", help="a log of the run without the artificial viscosity")
    parser.add_argument("--md", required=True)
    parser.add_argument("--png", required=True)
    args = parser.parse_args()
    runs = []
    for path in args.logs:
        with open(path) as f:
            rows = reference.front_series(f.read())
        n = round((rows[0][2] / 2) ** 0.5)
        runs.append((f"n = {n}", rows))
    if args.plain:
        with open(args.plain) as f:
            rows = reference.front_series(f.read())
        runs.append((f"n = {round((rows[0][2] / 2) ** 0.5)}, no artificial viscosity", rows))
    points = [(t, z) for t, z in reference.MARTIN_MOYCE if z < LENGTH - 1]
    lines = ["# Dam break: the front against Martin and Moyce (1952)", "",
             "Written by results.py (run.sh). Z = x / a of the front, T = t sqrt(2 g / a);",
             "the package's defaults (under fix gravity Monaghan's artificial viscosity, 0.1, at",
             "the free surface and at walls) unless said otherwise.", "",
             "| T | experiment | " + " | ".join(name for name, _ in runs) + " |",
             "|---|---|" + "---|" * len(runs)]
    worst = {name: 0.0 for name, _ in runs}
    for t, z in points:
        cells = []
        for name, rows in runs:
            got = reference.front_at(rows, t) if rows[-1][0] >= t else float("nan")
            if got == got:
                worst[name] = max(worst[name], abs(got / z - 1.0))
            cells.append(f"{got:.3f} ({100 * (got / z - 1):+.1f} %)" if got == got else "-")
        lines.append(f"| {t:.3f} | {z:.3f} | " + " | ".join(cells) + " |")
    lines += ["", "Largest difference from the experiment before the far wall:", ""]
    for name, rows in runs:
        lost = rows[0][2] - min(r[2] for r in rows)
        reach = max(r[1] for r in rows)
        lines.append(f"- {name}: {100 * worst[name]:.1f} %; to T = {rows[-1][0]:.2f}, "
                     f"{lost:.0f} particles lost, the front's farthest reach {reach:.4f} a "
                     f"(the wall's surface at {LENGTH:g} a)")
    with open(args.md, "w") as f:
        f.write("\n".join(lines) + "\n")
    print("\n".join(lines))

    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(figsize=(6, 4.5))
    ax.plot([t for t, _ in reference.MARTIN_MOYCE], [z for _, z in reference.MARTIN_MOYCE], "ko",
            label="Martin and Moyce (1952)")
    for name, rows in runs:
        ax.plot([r[0] for r in rows], [r[1] for r in rows], "--" if "no artificial" in name else "-",
                label=name)
    ax.axhline(LENGTH, color="grey", lw=0.8)
    ax.set_xlim(0, 7)
    ax.set_ylim(1, LENGTH + 0.5)
    ax.set_xlabel("T = t sqrt(2 g / a)")
    ax.set_ylabel("Z = x / a (front)")
    ax.legend(loc="upper left", fontsize=8)
    fig.tight_layout()
    fig.savefig(args.png, dpi=100)


if __name__ == "__main__":
    main()
