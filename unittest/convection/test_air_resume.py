#!/usr/bin/env python3
"""examples/convection-cavity/in.air goes on from its own restart file
(-var restart, -var resume), so that a long run can be made in pieces.

A coarse air cavity (12 across) runs to t = 1 s once, and once to 0.5 s
with a restart file, then from that file to 1 s. Resumed, it must not set
its start state again (the lattice at rest at 293 K): the last dumps agree
to 1e-6 m in position (3e-4 spacings), 1e-5 m/s in velocity (the flow
reaches 0.066 m/s) and 1e-3 K in temperature, and the wall-mean Nusselt
numbers to 1e-5. Measured: 6e-8 m, 5e-7 m/s, 9e-6 K and 1e-6, the
difference LAMMPS's fix sph makes between one run and two. With the start
state set again on resuming, the dumps were 3 K and 2.5 spacings apart.

Usage: test_air_resume.py --lmp LMP --plugin PLUGIN
"""
import os
import sys
import tempfile

import numpy as np

from lammps_checks import final_nusselt, read_dump, run_input, serial_check

HERE = os.path.dirname(os.path.abspath(__file__))
IN_AIR = os.path.join(HERE, "..", "..", "examples", "convection-cavity", "in.air")
N = 12


def run(a, cwd, name, variables):
    out = run_input(a.lmp, IN_AIR, {"plugin": os.path.abspath(a.plugin), "n": N, "every": 10000,
                                    "out": name, **variables}, cwd)
    final = final_nusselt(out)
    dump = read_dump(os.path.join(cwd, name))
    order = np.argsort(dump["id"])
    return {key: np.asarray(dump[key])[order] for key in dump}, [*final["heat"], final["time"]]


def main():
    a, check = serial_check(__doc__)

    with tempfile.TemporaryDirectory() as tmp:
        whole, nu_whole = run(a, tmp, "whole", {"seconds": 1.0})
        first, _ = run(a, tmp, "first", {"seconds": 0.5, "restart": 0.5})
        check(os.path.exists(os.path.join(tmp, "first.restart.end")),
              "the first piece wrote first.restart.end")
        resumed, nu_resumed = run(a, tmp, "resumed", {"seconds": 1.0,
                                                      "resume": "first.restart.end"})
    check(np.array_equal(whole["id"], resumed["id"]), "the same fluid particles")
    check(abs(nu_whole[2] - nu_resumed[2]) < 1e-9,
          f"both end at t = {nu_whole[2]:g} s")
    moved = np.abs(whole["x"] - first["x"]).max()
    check(moved > 1e-3, f"the flow moved particles between the pieces ({moved:.2e} m)")
    for key, limit, unit in (("x", 1e-6, "m"), ("y", 1e-6, "m"), ("vx", 1e-5, "m/s"),
                             ("vy", 1e-5, "m/s"), ("c_T", 1e-3, "K")):
        diff = np.abs(resumed[key] - whole[key]).max()
        check(diff < limit, f"{key}: resumed against one run, largest difference {diff:.2e} "
              f"{unit} (limit {limit:g})")
    for wall, index in (("hot", 0), ("cold", 1)):
        diff = abs(nu_resumed[index] - nu_whole[index])
        check(diff < 1e-5, f"Nu of the {wall} wall {nu_resumed[index]:.6f} against "
              f"{nu_whole[index]:.6f} in one run")
    return 1 if check.failures else 0


if __name__ == "__main__":
    sys.exit(main())
