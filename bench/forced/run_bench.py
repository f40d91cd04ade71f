#!/usr/bin/env python3
"""Forced convection: the cost of particle shifting and of the periodic inlet
per particle-step, against LAMMPS's own thermal-flow pair step in the same
set of runs.

Runs bench/flow/in.bench (n x n jittered particles in a periodic box, shear
flow and temperature field, fix sph) with our thermal-flow pairs
(sph/harmonic/visc + sph/cleary/heat, Lucy kernel, cutoff 2.6 dx) alone and
with fix sph/shift (delta-plus, skillen) or fix sph/inlet/temperature, and
with LAMMPS's sph/taitwater/morris + sph/heatconduction on the same
particles. The cost of an extra is the difference of the runs' CPU time per
particle-step (the fastest of --repeat runs each).

  tools/sphpython bench/forced/run_bench.py            # 120 x 120, 1000 steps, 3 repeats
  tools/sphpython bench/forced/run_bench.py --quick    # 60 x 60, 300 steps, 1 repeat
"""

import argparse
import os
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.normpath(os.path.join(HERE, "..", ".."))
from sphthermal_tools.bench import cost


def per_particle_step(a, workdir, **lmp_vars):
    return cost(os.path.join(ROOT, "bench", "flow", "in.bench"), a, workdir, lmp_vars, whole_run=True)


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawTextHelpFormatter)
    p.add_argument("--lmp", default=os.path.join(ROOT, "build", "lmp"))
    p.add_argument("--plugin", default=os.path.join(ROOT, "build", "sphthermalplugin.so"))
    p.add_argument("--repeat", type=int)
    p.add_argument("--quick", action="store_true")
    p.add_argument("--out", default=HERE)
    a = p.parse_args()
    a.repeat = a.repeat or (1 if a.quick else 3)
    n, steps = (60, 300) if a.quick else (120, 1000)
    workdir = tempfile.mkdtemp(prefix="sphforcedbench")
    base = dict(n=n, steps=steps, kernel="lucy", hdx=2.6)
    lammps = per_particle_step(a, workdir, pair="lammps", **base)
    ours = per_particle_step(a, workdir, pair="ours", extra="none", **base)
    rows = [("LAMMPS: sph/taitwater/morris + sph/heatconduction", lammps, None),
            ("ours: sph/harmonic/visc + sph/cleary/heat", ours, None)]
    for extra, label in [("deltaplus", "ours + fix sph/shift delta-plus"),
                         ("skillen", "ours + fix sph/shift skillen"),
                         ("inlet", "ours + fix sph/inlet/temperature")]:
        c = per_particle_step(a, workdir, pair="ours", extra=extra, **base)
        rows.append((label, c, c - ours))
    for label, c, extra in rows:
        print(f"{label}: {1e6 * c:.3f} us per particle-step ({c / lammps:.2f} x LAMMPS)"
              + (f", the extra {1e6 * extra:.3f} us ({extra / lammps:.2f} x LAMMPS)" if extra is not None else ""))
    with open(os.path.join(a.out, "results.md"), "w") as f:
        f.write("# Forced convection benchmark results\n\n")
        f.write(f"CPU time per particle-step (microseconds, whole run), serial, the fastest of "
                f"{a.repeat} runs of {steps} steps; {n} x {n} jittered particles in a periodic "
                "box (2-D), shear flow and temperature field, fix sph, Lucy kernel, cutoff 2.6 dx "
                "(bench/flow/in.bench). Written by `bench/forced/run_bench.py`.\n\n")
        f.write("| run | per particle-step | / LAMMPS | the extra | extra / LAMMPS |\n|---|---|---|---|---|\n")
        for label, c, extra in rows:
            e = f"{1e6 * extra:.3f} | {extra / lammps:.2f}" if extra is not None else "- | -"
            f.write(f"| {label} | {1e6 * c:.3f} | {c / lammps:.2f} | {e} |\n")
    print("wrote", os.path.join(a.out, "results.md"))


if __name__ == "__main__":
    main()
