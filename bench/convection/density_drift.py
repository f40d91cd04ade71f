#!/usr/bin/env python3
"""The flagship cavity's mean density over many diffusion times.

Runs examples/convection-cavity/in.cavity as it is (the package's defaults
for a buoyancy-driven flow of shifted particles) with two lines added for
output only: the fluid's mean density (compute sph/rho/atom, reduce ave) in
the thermo output, every 2000 steps. A closed cell keeps its fluid's
volume, so the mean density should stay at rho0 = 1; the discrete
continuity equation and the shifting do not keep it by construction.
Writes the range of the mean density and its value at the end, with the
mean Nu over the run's second half, to bench/convection/density_drift.md.

  tools/sphpython bench/convection/density_drift.py                # Ra 1e4, 20 x 20, to t = 10 (about 40 min)
  tools/sphpython bench/convection/density_drift.py --log LOG      # the table from an existing run's log

Options: --ra, --n, --tend, --lmp, --plugin, --out DIR.
"""

import argparse
import os
import subprocess
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.abspath(os.path.join(HERE, "..", ".."))
sys.path.insert(0, os.path.join(ROOT, "tools"))
from sphthermal_tools.log import longest_thermo_table  # noqa: E402

EXAMPLE = os.path.join(ROOT, "examples", "convection-cavity", "in.cavity")


def drift_input():
    """in.cavity with the fluid's mean density in the thermo output."""
    text = open(EXAMPLE).read()
    anchor = "compute         T fluid sph/t/atom\n"
    thermo = "thermo          100\n"
    if anchor not in text or thermo not in text or "thermo_style    custom" not in text:
        sys.exit("density_drift: in.cavity no longer has the lines this script extends")
    text = text.replace(anchor, anchor + "compute rho fluid sph/rho/atom\n"
                        "compute rhomean fluid reduce ave c_rho\n")
    lines = []
    for line in text.splitlines():
        if line.startswith("thermo_style    custom"):
            line += " c_rhomean\nthermo_modify format float %.8g"
        lines.append(line)
    return "\n".join(lines).replace(thermo.strip(), "thermo          2000") + "\n"


def summarise(log, ra, n):
    table = longest_thermo_table(open(log).read())
    t, rho = table["Time"], table["c_rhomean"]
    half = t >= 0.5 * t[-1]
    nu = 0.5 * (table["c_nu_hot[1]"][half].mean() + table["c_nu_cold[1]"][half].mean())
    worst = np.abs(rho - 1.0).max()
    return (f"| {ra:g} | {n} x {n} | {t[-1]:.4g} | {len(t) - 1} | {rho.min():.5f} | {rho.max():.5f} | "
            f"{rho[-1]:.5f} | {100 * worst:.2g} % | {nu:.4f} |")


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawTextHelpFormatter)
    p.add_argument("--ra", type=float, default=1e4)
    p.add_argument("--n", type=int, default=20)
    p.add_argument("--tend", type=float, default=10.0)
    p.add_argument("--lmp", default=os.path.join(ROOT, "build", "lmp"))
    p.add_argument("--plugin", default=os.path.join(ROOT, "build", "sphthermalplugin.so"))
    p.add_argument("--out", default=os.path.join(HERE, "out", "drift"))
    p.add_argument("--log", help="summarise this log instead of running")
    a = p.parse_args()
    log = a.log
    if not log:
        os.makedirs(a.out, exist_ok=True)
        path = os.path.join(a.out, "in.drift")
        with open(path, "w") as f:
            f.write(drift_input())
        log = os.path.join(a.out, f"log.ra{a.ra:g}.n{a.n}")
        subprocess.run([a.lmp, "-in", path, "-var", "plugin", a.plugin, "-var", "ra", f"{a.ra:g}",
                        "-var", "n", str(a.n), "-var", "tend", f"{a.tend:g}", "-log", log,
                        "-screen", "none"], cwd=a.out, check=True)
    row = summarise(log, a.ra, a.n)
    text = ("# The flagship cavity's mean density over many diffusion times\n\n"
            "Written by `bench/convection/density_drift.py`: examples/convection-cavity/in.cavity "
            "with its defaults, the fluid's mean density (rho0 = 1) every 2000 steps; time in "
            "diffusion times L^2 / alpha; mean Nu from the walls' heat over the run's second half.\n\n"
            "| Ra | particles | to t = | rows | lowest | highest | at the end | largest departure | "
            "mean Nu |\n|---|---|---|---|---|---|---|---|---|\n" + row + "\n")
    with open(os.path.join(HERE, "density_drift.md"), "w") as f:
        f.write(text)
    print(text)


if __name__ == "__main__":
    main()
