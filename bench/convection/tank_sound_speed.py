#!/usr/bin/env python3
"""The 2-D mixing tank against its speed of sound.

Runs examples/mixing-tank-2d/in.tank (Reece et al. 2024, section 3.4.3)
at n x n fluid particles to t = tend with each c0 given, one MPI rank
each, and writes, for each run: c0 and c0 over the tank's largest speed
(0.0184 m/s, measured at 39 across, examples/mixing-tank-2d/README.md),
the fluid particles left inside the tank (the least over the run), the
fluid's density range about rho0 over the run (the thermo columns
v_drho_min and v_drho_max), the mixing measures S*_A and S*_B at the end
and the most either fell back between outputs (compute sph/mixing, Reece
et al. 2024, Table 4), the steps and the loop time. The example takes the
package's c0 (auto: the speed at which the buoyancy's pressure compresses
the fluid by 0.05 while the hot walls are 20 K above the fluid's mean),
about 38 times the largest speed: what sets it is that compression, not
the speed.

  tools/sphpython bench/convection/tank_sound_speed.py              # 16 across to 40 s: c0 auto, 0.6, 0.3, 0.18 (about 4 min)
  tools/sphpython bench/convection/tank_sound_speed.py --c0 0.6 0.45

Options: --n N, --tend T, --c0 C ..., --out FILE (the table, default
bench/convection/tank_sound_speed.md), --dir (the runs' directories),
--lmp, --plugin.
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
LARGEST_SPEED = 0.0184    # m/s, at 39 across (examples/mixing-tank-2d/README.md)


def density_range(tables):
    """The least v_drho_min and the largest v_drho_max over every thermo table."""
    tables = [t for t in tables if "v_drho_min" in t]
    return (min(t["v_drho_min"].min() for t in tables), max(t["v_drho_max"].max() for t in tables))


def run(args, c0):
    work = os.path.join(args.dir, f"n{args.n}.c{c0}")
    os.makedirs(work, exist_ok=True)
    cmd = [args.lmp, "-in", os.path.join(ROOT, "examples", "mixing-tank-2d", "in.tank"),
           "-var", "plugin", args.plugin, "-var", "n", str(args.n), "-var", "tend", str(args.tend),
           "-var", "every", "500", "-var", "dumpdt", str(args.tend), "-var", "out", "tank.dump",
           "-var", "mixing", "mixing.txt", "-var", "c0", c0, "-log", "log.lammps"]
    proc = subprocess.run(cmd, cwd=work, capture_output=True, text=True)
    log = open(os.path.join(work, "log.lammps")).read()
    loops = re.findall(r"Loop time of (\S+) on \d+ procs for (\d+) steps", log)
    auto = c0 == "auto"
    if auto:    # the value the package took, from the log
        c0 = re.search(r"speed of sound of atom type 1 is (\S+)", log).group(1)
    row = {"c0": float(c0), "auto": auto, "steps": sum(int(s) for _, s in loops),
           "loop": sum(float(t) for t, _ in loops)}
    lost = re.search(r"ERROR: Lost atoms: original (\d+) current (\d+)", proc.stdout + log)
    tables = thermo_tables(log)
    if proc.returncode != 0:
        row["failed"] = (f"lost {int(lost.group(1)) - int(lost.group(2))} atoms" if lost
                         else "LAMMPS error") + f" after t = {tables[-1]['Time'][-1]:.1f} s"
    row["drho"] = density_range(tables)
    if "failed" not in row:
        m = mixing_tank.read_mixing(os.path.join(work, "mixing.txt"))
        row["inside"] = int(m["fluid_inside"].min())
        for name in ("S*_A", "S*_B"):
            row[name] = m[name][-1]
            row[name + " back"] = max(0.0, -np.diff(m[name]).min())
    return row


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--n", type=int, default=16)
    p.add_argument("--tend", type=float, default=40.0)
    p.add_argument("--c0", nargs="+", default=["auto", "0.6", "0.3", "0.18"])
    p.add_argument("--lmp", default=os.path.join(ROOT, "build", "lmp"))
    p.add_argument("--plugin", default=os.path.join(ROOT, "build", "sphthermalplugin.so"))
    p.add_argument("--dir", default=os.path.join(HERE, "out", "tank_sound_speed"))
    p.add_argument("--out", default=os.path.join(HERE, "tank_sound_speed.md"))
    args = p.parse_args()
    lines = ["# The 2-D mixing tank against its speed of sound", "",
             "Written by `tools/sphpython bench/convection/tank_sound_speed.py` (one MPI rank per run): "
             f"examples/mixing-tank-2d/in.tank at {args.n} x {args.n} fluid particles to t = {args.tend:g} s, "
             "every other setting the example's (the package's defaults; auto: the c0 the package takes). c0 / v: over the largest speed, 0.0184 m/s "
             "(39 across). Density: the fluid's range about rho0 over the run. S*_A, S*_B: compute "
             "sph/mixing at the end (Reece et al. 2024, Table 4), and the most either fell back between "
             "outputs (every 500 steps).", "",
             "| c0 (m/s) | c0 / v | result | fluid inside (least) | density (% of rho0) | S*_A | S*_B | "
             "fell back | steps | loop (s) |",
             "|---|---|---|---|---|---|---|---|---|---|"]
    for c0 in args.c0:
        r = run(args, c0)
        drho = f"{100 * r['drho'][0]:+.2f} to {100 * r['drho'][1]:+.2f}"
        if "failed" in r:
            cells = [r["failed"], "-", drho, "-", "-", "-"]
        else:
            cells = ["stable", f"{r['inside']} of {args.n * args.n}", drho, f"{r['S*_A']:.3f}",
                     f"{r['S*_B']:.3f}", f"{max(r['S*_A back'], r['S*_B back']):.1e}"]
        cost = ["-", "-"] if "failed" in r else [str(r["steps"]), f"{r['loop']:.0f}"]
        c0_cell = f"auto ({r['c0']:.3g})" if r["auto"] else f"{r['c0']:g}"
        line = f"| {c0_cell} | {r['c0'] / LARGEST_SPEED:.1f} | " + " | ".join(cells + cost) + " |"
        print(line, flush=True)
        lines.append(line)
    with open(args.out, "w") as f:
        f.write("\n".join(lines) + "\n")
    print("wrote", args.out)


if __name__ == "__main__":
    main()
