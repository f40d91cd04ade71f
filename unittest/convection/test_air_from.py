#!/usr/bin/env python3
"""examples/convection-cavity/in.air started from a dump of itself
(-var from, as bench/convection/air_developed.sh does): a coarse air cavity
(12 across) runs to t = 3 s and writes its dump; a second run starts from
it and stops after 10 steps (0.014 s). Its particles must be where the
first run left them (0.07 spacings apart on average, measured; below 0.15
asked: the densities restart at rho0, which jolts the particles next to
the walls) and have its temperatures (0.045 K apart on average; below
0.2 K asked), where the first run took them 0.35 spacings from the lattice
on average (above 0.25 asked) and 3.5 K from 293 K (above 2 K asked):
without the dump's state the second run would start on the lattice at
293 K.

Usage: test_air_from.py --lmp LMP --plugin PLUGIN
"""
import os
import sys
import tempfile

import numpy as np

from lammps_checks import read_dump, run_input, serial_check

HERE = os.path.dirname(os.path.abspath(__file__))
IN_AIR = os.path.join(HERE, "..", "..", "examples", "convection-cavity", "in.air")
N = 12
DX = 0.0386 / N


def run(a, cwd, variables):
    run_input(a.lmp, IN_AIR, {"plugin": os.path.abspath(a.plugin), "n": N, **variables}, cwd)


def main():
    a, check = serial_check(__doc__)

    with tempfile.TemporaryDirectory() as tmp:
        run(a, tmp, {"seconds": 3.0, "every": 10000, "out": "first.dump"})
        with open(os.path.join(tmp, "first.dump")) as f:
            lines = f.read().split("\n")
        step = int(lines[1])
        ids_T = [ln.split()[0] + " " + ln.split()[5] for ln in lines[9:] if ln.strip()]
        with open(os.path.join(tmp, "T.atomfile"), "w") as f:
            f.write(f"{len(ids_T)}\n" + "\n".join(ids_T) + "\n")
        run(a, tmp, {"seconds": 0.01, "every": 10000, "out": "second.dump",
                     "from": "first.dump", "fromstep": step, "fromT": "T.atomfile"})
        first = read_dump(os.path.join(tmp, "first.dump"))
        second = read_dump(os.path.join(tmp, "second.dump"))
    ids = sorted(first["id"])
    order_1 = np.argsort(first["id"])
    order_2 = np.argsort(second["id"])
    check(np.array_equal(np.sort(second["id"]), np.array(ids)), "the same fluid particles")
    xy1 = np.column_stack([first["x"][order_1], first["y"][order_1]])
    xy2 = np.column_stack([second["x"][order_2], second["y"][order_2]])
    T1, T2 = first["c_T"][order_1], second["c_T"][order_2]
    lattice = xy1 / DX - 0.5
    off_lattice = np.linalg.norm(lattice - np.round(lattice), axis=1).mean()
    check(off_lattice > 0.25, f"the first run took particles off the lattice ({off_lattice:.3f} dx "
          "on average)")
    warm = np.abs(T1 - 293.0).mean()
    check(warm > 2.0, f"the first run's temperatures are {warm:.2f} K from 293 K on average")
    moved = np.linalg.norm(xy2 - xy1, axis=1).mean() / DX
    check(moved < 0.15, f"the second run starts where the first ended ({moved:.4f} dx apart on "
          "average)")
    dT = np.abs(T2 - T1).mean()
    check(dT < 0.2, f"... with its temperatures ({dT:.4f} K apart on average)")
    return 1 if check.failures else 0


if __name__ == "__main__":
    sys.exit(main())
