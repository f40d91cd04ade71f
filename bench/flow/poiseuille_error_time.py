"""Poiseuille error against run time: examples/flow-poiseuille at 10, 20, 40
(and with --fine 80) particles across, quintic kernel (h = dx) and Wendland
C2 (h = 2 dx; at the example's dt = 0.2 h / c0, and at 0.15 h / c0 with
delta-plus shifting, C = 1), in the example's 4 m long periodic channel (n / 5 columns),
against the series solution; the error is the largest over
the four output times in % of u_max, the time the run's CPU seconds. Serial,
one run per point. Writes poiseuille_error_time.png and appends a table to
results.md here (or in --out).

  tools/sphpython bench/flow/poiseuille_error_time.py [--fine] [--lmp ...] [--plugin ...]
"""

import argparse
import importlib.util
import os
import resource
import subprocess
import tempfile

import numpy as np

here = os.path.dirname(os.path.abspath(__file__))
root = os.path.normpath(os.path.join(here, "..", ".."))
example = os.path.join(root, "examples", "flow-poiseuille")
from sphthermal_tools.dump import read_frames

spec = importlib.util.spec_from_file_location("poiseuille", os.path.join(example, "analyse.py"))
poiseuille = importlib.util.module_from_spec(spec)
spec.loader.exec_module(poiseuille)


# label, kernel, h / dx, further -var settings of in.poiseuille
SETTINGS = [
    ("quintic, h = dx", "quintic", 1.0, []),
    ("wendland, h = 2 dx", "wendland", 2.0, []),
    ("wendland, h = 2 dx, dt = 0.15 h / c0, shifted", "wendland", 2.0,
     ["-var", "dtreset", "acoustic 0.15", "-var", "shift", "1"]),
]


def run(args, workdir, n, kernel, hdx, extra):
    cmd = [args.lmp, "-in", os.path.join(example, "in.poiseuille"), "-var", "plugin", args.plugin,
           "-var", "n", str(n), "-var", "ncol", str(n // 5), "-var", "kernel", kernel,
           "-var", "hdx", str(hdx), "-var", "out", "p.dump", "-log", "none", "-screen", "none"] + extra
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    subprocess.run(cmd, cwd=workdir, check=True, env=dict(os.environ, OMP_NUM_THREADS="1"))
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = after.ru_utime - before.ru_utime
    worst = 0.0
    for t in poiseuille.TIMES:
        c = read_frames(os.path.join(workdir, f"p.dump.t{t}"))[-1][1]
        worst = max(worst, 100 * np.abs(c["vx"] - poiseuille.exact(c["y"], t)).max() / poiseuille.UMAX)
    return cpu, worst


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--lmp", default=os.path.join(root, "build", "lmp"))
    p.add_argument("--plugin", default=os.path.join(root, "build", "sphthermalplugin.so"))
    p.add_argument("--fine", action="store_true", help="also 80 across (several minutes)")
    p.add_argument("--out", default=here)
    args = p.parse_args()
    workdir = tempfile.mkdtemp(prefix="sphpoiseuille")
    sizes = [10, 20, 40] + ([80] if args.fine else [])
    rows = []
    for label, kernel, hdx, extra in SETTINGS:
        for n in sizes:
            cpu, err = run(args, workdir, n, kernel, hdx, extra)
            rows.append((label, n, cpu, err))
            print(f"{label}, {n} across: {cpu:.1f} s, max error {err:.3f} % of u_max")

    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, ax = plt.subplots(figsize=(5.6, 4.2))
    for label, _, _, _ in SETTINGS:
        pts = [(r[2], r[3], r[1]) for r in rows if r[0] == label]
        ax.loglog([q[0] for q in pts], [q[1] for q in pts], "o-", label=label)
        for cpu, err, n in pts:
            ax.annotate(str(n), (cpu, err), fontsize=7)
    ax.set_xlabel("CPU time (s)")
    ax.set_ylabel("max error over 4 times (% of u_max)")
    ax.set_title("Poiseuille Re = 65.2: error against run time", fontsize=9)
    ax.legend(fontsize=8)
    fig.tight_layout()
    png = os.path.join(args.out, "poiseuille_error_time.png")
    fig.savefig(png, dpi=120)
    with open(os.path.join(args.out, "results.md"), "a") as f:
        f.write("\n## Poiseuille: error against run time\n\n")
        f.write("`poiseuille_error_time.py`: examples/flow-poiseuille (Re = 65.2, to t = 1200 s), "
                "largest error over t = 100, 300, 600, 1200 s in % of u_max; serial CPU time.\n\n")
        f.write("| setting | particles across | CPU time (s) | max error |\n|---|---|---|---|\n")
        for label, n, cpu, err in rows:
            f.write(f"| {label} | {n} | {cpu:.1f} | {err:.3f} % |\n")
        f.write("\n![error against run time](poiseuille_error_time.png)\n")
    print("wrote", png)


if __name__ == "__main__":
    main()
