#!/usr/bin/env python3
"""The 2-D mixing tank with the corrected and the plain pressure gradient.

Runs examples/mixing-tank-2d/in.tank (Reece et al. 2024, section 3.4.3)
at n x n fluid particles to t = tend, once with the package's defaults
(which correct the flow pair's pressure gradient in a buoyancy-driven flow
of shifted particles) and once with the plain gradient (-var flow
'correction none'), one MPI rank each, and writes for each run the
fluid's mean temperature rise as a fraction of theta_H - theta_C at a few
times (the heat the hot walls gave, the tank's counterpart of the cavity's
Nusselt number), the mixing measure S*_A (compute sph/mixing) at the same
times, the fluid's density range about rho0, the fluid particles left
inside, the steps and the loop time. There is no reference: what the table
shows is whether the two settings approach each other as n grows.

  tools/sphpython bench/convection/tank_pressure_correction.py     # 16, 24, 32 across to 20 s (about 12 min on one core)

Options: --n N ..., --tend T, --times T ..., --out FILE (the table,
default bench/convection/tank_pressure_correction.md), --dir (the runs'
directories), --lmp, --plugin.
"""

import argparse
import os
import re
import subprocess

import numpy as np

import mixing_tank
from sphthermal_tools.log import thermo_tables

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.abspath(os.path.join(HERE, "..", ".."))
THETA_C, THETA_H = 283.0, 303.0
SETTINGS = (("corrected (default)", ""), ("plain", "correction none"))


def arguments(doc, out, runs):
    """The parser of both tank comparisons with the options they share."""
    p = argparse.ArgumentParser(description=doc, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--out", default=os.path.join(HERE, out))
    p.add_argument("--dir", default=runs)
    p.add_argument("--lmp", default=os.path.join(ROOT, "build", "lmp"))
    p.add_argument("--plugin", default=os.path.join(ROOT, "build", "sphthermalplugin.so"))
    return p


def loop_totals(log):
    """The steps and the loop time (s) of every run of a LAMMPS log."""
    loops = re.findall(r"Loop time of (\S+) on \d+ procs for (\d+) steps", log)
    return sum(int(s) for _, s in loops), sum(float(t) for t, _ in loops)


def write_table(path, lines):
    with open(path, "w") as f:
        f.write("\n".join(lines) + "\n")
    print(f"wrote {path}")


def run(args, n, flow):
    work = os.path.join(args.dir, f"n{n}." + (flow.replace(" ", "_") or "default"))
    os.makedirs(work, exist_ok=True)
    cmd = [args.lmp, "-in", os.path.join(ROOT, "examples", "mixing-tank-2d", "in.tank"),
           "-var", "plugin", args.plugin, "-var", "n", str(n), "-var", "tend", str(args.tend),
           "-var", "every", "200", "-var", "dumpdt", str(args.tend), "-var", "out", "tank.dump",
           "-var", "mixing", "mixing.txt", "-var", "flow", flow, "-log", "log.lammps"]
    proc = subprocess.run(cmd, cwd=work, capture_output=True, text=True)
    if proc.returncode != 0:
        raise SystemExit(f"{' '.join(cmd)} failed in {work}:\n{proc.stdout[-2000:]}")
    log = open(os.path.join(work, "log.lammps")).read()
    tables = [t for t in thermo_tables(log) if "v_drho_min" in t]
    m = mixing_tank.read_mixing(os.path.join(work, "mixing.txt"))
    steps, loop = loop_totals(log)
    row = {"steps": steps, "loop": loop,
           "drho": (min(t["v_drho_min"].min() for t in tables),
                    max(t["v_drho_max"].max() for t in tables)),
           "inside": int(m["fluid_inside"].min())}
    for t in args.times:
        k = int(np.argmin(np.abs(m["time"] - t)))
        row[t] = ((m["T_mean"][k] - THETA_C) / (THETA_H - THETA_C), m["S*_A"][k])
    return row


def main():
    p = arguments(__doc__, "tank_pressure_correction.md", "tank_pressure_correction_runs")
    p.add_argument("--n", type=int, nargs="+", default=[16, 24, 32])
    p.add_argument("--tend", type=float, default=20.0)
    p.add_argument("--times", type=float, nargs="+", default=[2.0, 5.0, 10.0, 20.0])
    args = p.parse_args()
    args.dir = os.path.abspath(args.dir)

    times = " | ".join(f"t = {t:g} s" for t in args.times)
    lines = ["# The 2-D mixing tank: corrected against plain pressure gradient", "",
             "Written by `bench/convection/tank_pressure_correction.py` (do not edit); made with", "",
             f"    bench/convection/tank_pressure_correction.py --n {' '.join(map(str, args.n))} "
             f"--tend {args.tend:g}", "",
             "Each cell: the fluid's mean temperature rise, (T_mean - theta_C) / (theta_H - theta_C), "
             "and S*_A of compute sph/mixing at that time. One MPI rank per run, two runs sharing "
             "a 2-core machine.", "",
             f"| n | pressure gradient | {times} | density - rho0 (% of rho0) | inside | steps | loop (s) |",
             "|---" * (6 + len(args.times)) + "|"]
    for n in args.n:
        for name, flow in SETTINGS:
            r = run(args, n, flow)
            cells = " | ".join(f"{r[t][0]:.4f}, {r[t][1]:.3f}" for t in args.times)
            lines.append(f"| {n} | {name} | {cells} | {100 * r['drho'][0]:+.2f} to "
                         f"{100 * r['drho'][1]:+.2f} | {r['inside']} of {n * n} | {r['steps']} | "
                         f"{r['loop']:.0f} |")
            print(lines[-1], flush=True)
    write_table(args.out, lines)


if __name__ == "__main__":
    main()
