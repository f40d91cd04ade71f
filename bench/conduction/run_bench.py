"""Conduction benchmark: error against run time, and cost per particle-step,
for pair sph/cleary/heat (every kernel) and LAMMPS's pair sph/heatconduction
on the same particles, measured in the same run of this script.

Cases: the erf slab (examples/conduction-erf, max error in % of the jump over
the output times) at 40 x 10, 80 x 20 and 160 x 40 particles, and the
sinusoid with isothermal sides (examples/conduction-sinusoid, flux error by
the energy method; sph/cleary/heat only, as sph/heatconduction has no
isothermal wall) at 20 x 20, 40 x 40 and 80 x 80. The time step scales
with dx^2. Serial runs, one at a time, each point the fastest of --repeat
runs (timings on a shared machine are noisy). Writes results.md and
error_vs_time.png here (or in --out).

  tools/sphpython bench/conduction/run_bench.py [--quick] [--lmp ...] [--plugin ...]
"""

import argparse
import importlib.util
import math
import os
import re
import subprocess
import sys
import tempfile

import numpy as np

here = os.path.dirname(os.path.abspath(__file__))
root = os.path.normpath(os.path.join(here, "..", ".."))
from sphthermal_tools.dump import read_frames

spec = importlib.util.spec_from_file_location("erf", os.path.join(root, "examples", "conduction-erf", "analyse.py"))
erf_analysis = importlib.util.module_from_spec(spec)
spec.loader.exec_module(erf_analysis)

QMAX = {"lucy": 1, "cubic": 2, "quintic": 3, "wendland": 2}


def lammps(args, inp, lmp_vars, workdir):
    """Run time and pair cost per particle-step: the fastest of --repeat runs."""
    best = None
    for _ in range(args.repeat):
        result = lammps_once(args, inp, lmp_vars, workdir)
        best = result if best is None or result[0] < best[0] else best
    return best


def lammps_once(args, inp, lmp_vars, workdir):
    cmd = [args.lmp, "-in", inp, "-var", "plugin", args.plugin, "-log", "log.lammps"]
    for k, v in lmp_vars.items():
        cmd += ["-var", k, str(v)]
    env = dict(os.environ, OMP_NUM_THREADS="1")
    subprocess.run(cmd, cwd=workdir, check=True, capture_output=True, env=env)
    log = open(os.path.join(workdir, "log.lammps")).read()
    loop = float(re.findall(r"Loop time of ([0-9.eE+-]+) on \d+ procs for (\d+) steps with (\d+) atoms", log)[-1][0])
    steps, natoms = (int(v) for v in re.findall(r"Loop time of [0-9.eE+-]+ on \d+ procs for (\d+) steps with (\d+) atoms", log)[-1])
    pair = float(re.findall(r"^Pair\s+\|\s+([0-9.eE+-]+)", log, re.M)[-1])
    return loop, pair / (steps * natoms)


def erf_case(args, workdir, nx, kernel, hdx, eta, pair):
    dt = 0.005 * (80.0 / nx) ** 2
    v = {"nx": nx, "ny": nx // 4, "kernel": kernel, "hdx": hdx, "eta": eta, "dt": dt, "pair": pair,
         "out": "erf.dump"}
    loop, cost = lammps(args, os.path.join(root, "examples", "conduction-erf", "in.erf"), v, workdir)
    worst = 0.0
    for step, c in read_frames(os.path.join(workdir, "erf.dump")):
        if step > 0:
            t = step * dt
            worst = max(worst, 100 * np.abs(c["c_T"] - erf_analysis.exact(c["x"], t, 1e-3, 0.5)).max())
    return loop, cost, worst


def sinusoid_case(args, workdir, n, kernel, hdx):
    dt = 0.0005 * (40.0 / n) ** 2
    v = {"n": n, "kernel": kernel, "hdx": hdx, "dt": dt, "out": "s"}
    loop, cost = lammps(args, os.path.join(root, "examples", "conduction-sinusoid", "in.sinusoid"), v, workdir)
    d = np.loadtxt(os.path.join(workdir, "s.flux"), ndmin=2)
    l = (n - 1) / n
    exact = (math.pi / l) * np.exp(-(math.pi / l) ** 2 * 0.1 * d[:, 0])
    return loop, cost, 100 * np.abs((d[:, 1] - exact) / exact).max()


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--lmp", default=os.path.join(root, "build", "lmp"))
    p.add_argument("--plugin", default=os.path.join(root, "build", "sphthermalplugin.so"))
    p.add_argument("--out", default=here)
    p.add_argument("--quick", action="store_true", help="two resolutions only")
    p.add_argument("--repeat", type=int, default=3, help="runs per point; the fastest counts")
    a = p.parse_args()

    erf_sizes = [40, 80] if a.quick else [40, 80, 160]
    sin_sizes = [20, 40] if a.quick else [20, 40, 80]
    # (label, kernel, h/dx, eta, pair): equal cutoff 2.6 dx for the Lucy comparison
    erf_setups = [("sph/cleary/heat cubic h=1.3dx", "cubic", 1.3, 0.1, "cleary"),
                  ("sph/cleary/heat cubic h=1.3dx eta=0.01h", "cubic", 1.3, 0.01, "cleary"),
                  ("sph/cleary/heat wendland h=1.3dx", "wendland", 1.3, 0.1, "cleary"),
                  ("sph/cleary/heat quintic h=1.0dx", "quintic", 1.0, 0.1, "cleary"),
                  ("sph/cleary/heat lucy cutoff 2.6dx eta=0.01h", "lucy", 2.6, 0.01, "cleary"),
                  ("sph/heatconduction (LAMMPS) lucy cutoff 2.6dx", "cubic", 1.3, 0.1, "heatconduction")]
    sin_setups = [("sph/cleary/heat cubic h=1.0dx", "cubic", 1.0),
                  ("sph/cleary/heat cubic h=1.3dx", "cubic", 1.3),
                  ("sph/cleary/heat wendland h=1.0dx", "wendland", 1.0)]

    rows = []
    with tempfile.TemporaryDirectory() as work:
        for label, kernel, hdx, eta, pair in erf_setups:
            for nx in erf_sizes:
                loop, cost, err = erf_case(a, work, nx, kernel, hdx, eta, pair)
                rows.append(("erf", label, f"{nx} x {nx // 4}", loop, cost, err))
                print(f"erf {label:48s} {nx:4d}: {loop:8.3f} s, {1e9 * cost:7.1f} ns/particle-step, "
                      f"max error {err:.4f} %", flush=True)
        for label, kernel, hdx in sin_setups:
            for n in sin_sizes:
                loop, cost, err = sinusoid_case(a, work, n, kernel, hdx)
                rows.append(("sinusoid", label, f"{n} x {n}", loop, cost, err))
                print(f"sinusoid {label:43s} {n:4d}: {loop:8.3f} s, {1e9 * cost:7.1f} ns/particle-step, "
                      f"flux error {err:.4f} %", flush=True)

    ref = {(r[2]): r[4] for r in rows if r[1].startswith("sph/heatconduction")}
    with open(os.path.join(a.out, "results.md"), "w") as f:
        f.write("| case | style and kernel | particles | run time (s) | pair cost (ns per particle-step) "
                "| pair cost / sph/heatconduction's | error (%) |\n|---|---|---|---|---|---|---|\n")
        for case, label, size, loop, cost, err in rows:
            ratio = f"{cost / ref[size]:.2f}" if case == "erf" and size in ref else ""
            f.write(f"| {case} | {label} | {size} | {loop:.3f} | {1e9 * cost:.1f} | {ratio} | {err:.4f} |\n")

    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, axes = plt.subplots(1, 2, figsize=(11, 4.2))
    for ax, case, what in [(axes[0], "erf", "max error, % of the jump"),
                           (axes[1], "sinusoid", "wall flux error, %")]:
        for label in dict.fromkeys(r[1] for r in rows if r[0] == case):
            pts = [(r[3], r[5]) for r in rows if r[0] == case and r[1] == label]
            ax.loglog(*zip(*pts), "o-" if "cleary" in label else "s--", label=label)
        ax.set_xlabel("run time (s, serial)")
        ax.set_ylabel(what)
        ax.set_title(case)
        ax.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(os.path.join(a.out, "error_vs_time.png"), dpi=120)
    print("wrote", os.path.join(a.out, "results.md"), "and error_vs_time.png")
    return 0


if __name__ == "__main__":
    sys.exit(main())
