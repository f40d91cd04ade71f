#!/usr/bin/env python3
"""The 3-D cylindrical tank with the plain and the corrected pressure gradient.

Runs examples/mixing-tank-3d/in.tank3d (Reece et al. 2024, section 3.4)
on the particles of tools/mixing_tank.py at n across to t = tend, with
the package's default (in 3-d the plain gradient) and with 'correction
gradient' given (-var flow), for one and two components, on the
default particles and on those whose wall rings hold a multiple of 4
particles (tools/mixing_tank.py ring_multiple 4: the tank the same after a
quarter turn about its axis, as the exact flow), one MPI rank each, and
writes for each run the largest spread of the temperature
between the quadrants about the axis at the end, as a fraction of
theta_H - theta_C (tools/mixing_tank.py, symmetry_3d: the axisymmetry that
the exact flow has), the largest speed, the fluid particles inside, the
steps and the loop time. The defaults are those of the CI test
mixing.validation.tank3d_*.

  tools/sphpython bench/convection/tank3d_pressure_correction.py     # 10 across to 1 s (about 2 min on one core)

Options: --n N, --tend T, --out FILE (the table, default
bench/convection/tank3d_pressure_correction.md), --dir (the runs'
directories), --lmp, --plugin.
"""

import os
import subprocess

import mixing_tank
from sphthermal_tools.dump import read_frames
from sphthermal_tools.log import thermo_tables
from tank_pressure_correction import ROOT, arguments, loop_totals, write_table

SETTINGS = (("plain (default)", ""), ("corrected", "correction gradient"))


def run(args, rings, components, flow):
    work = os.path.join(args.dir, f"n{args.n}.rings{rings}.{components}."
                        + (flow.replace(" ", "_") or "default"))
    os.makedirs(work, exist_ok=True)
    data = os.path.join(work, "tank.data")
    dx = mixing_tank.write_tank_data(args.n, data, ring_multiple=rings)
    cmd = [args.lmp, "-in", os.path.join(ROOT, "examples", "mixing-tank-3d", "in.tank3d"),
           "-var", "plugin", args.plugin, "-var", "data", data, "-var", "dx", str(dx),
           "-var", "components", components, "-var", "tend", str(args.tend), "-var", "every", "100",
           "-var", "dumpdt", str(args.tend), "-var", "out", "tank.dump", "-var", "mixing", "mixing.txt",
           "-var", "flow", flow, "-log", "log.lammps"]
    proc = subprocess.run(cmd, cwd=work, capture_output=True, text=True)
    if proc.returncode != 0:
        raise SystemExit(f"{' '.join(cmd)} failed in {work}:\n{proc.stdout[-2000:]}")
    log = open(os.path.join(work, "log.lammps")).read()
    steps, loop = loop_totals(log)
    last = read_frames(os.path.join(work, "tank.dump.final"))[-1][1]
    fluid = mixing_tank.fluid_of(last, 3)
    (spread, _), _ = mixing_tank.symmetry_3d({k: v[fluid] for k, v in last.items()}, dx)
    m = mixing_tank.read_mixing(os.path.join(work, "mixing.txt"))
    tables = [t for t in thermo_tables(log) if "c_vmax" in t]
    return {"spread": spread, "vmax": max(t["c_vmax"].max() for t in tables),
            "inside": f"{int(m['fluid_inside'].min())} of {int(fluid.sum())}",
            "steps": steps, "loop": loop}


def main():
    p = arguments(__doc__, "tank3d_pressure_correction.md", "tank3d_pressure_correction_runs")
    p.add_argument("--n", type=int, default=10)
    p.add_argument("--tend", type=float, default=1.0)
    args = p.parse_args()
    args.dir = os.path.abspath(args.dir)

    lines = ["# The 3-D cylindrical tank: plain against corrected pressure gradient", "",
             "Written by `bench/convection/tank3d_pressure_correction.py` (do not edit); made with", "",
             f"    bench/convection/tank3d_pressure_correction.py --n {args.n} --tend {args.tend:g}", "",
             f"T spread: the largest difference of the temperature between the quadrants about the "
             f"axis at t = {args.tend:g} s, of theta_H - theta_C. One MPI rank per run.", "",
             "| ring counts | components | pressure gradient | T spread | largest speed (m/s) | inside "
             "| steps | loop (s) |",
             "|---|---|---|---|---|---|---|---|"]
    for rings in (1, 4):
        for components in ("one", "two"):
            for name, flow in SETTINGS:
                r = run(args, rings, components, flow)
                counts = 'round(2 pi r / dx)' if rings == 1 else 'a multiple of 4'
                lines.append(f"| {counts} | {components} | {name} | "
                             f"{r['spread']:.2e} | {r['vmax']:.4f} | {r['inside']} | {r['steps']} | "
                             f"{r['loop']:.0f} |")
                print(lines[-1], flush=True)
    write_table(args.out, lines)


if __name__ == "__main__":
    main()
