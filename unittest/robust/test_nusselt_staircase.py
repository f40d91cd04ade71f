#!/usr/bin/env python3
"""compute sph/nusselt on a staircase wall warns; on flat walls it does not.

annulus: steady conduction between two concentric cylinders held at 1 and 0
by mirrored dummies cut from the square lattice (in.nusselt_annulus, 10
spacings across the gap, from the exact profile). The estimate from the heat
is the exact Nu = 1/ln(ro/ri) within 0.3 %; the gradient's is far off
(1.8 times), and the compute says so in one WARNING that names compute
sph/nusselt, its group and the estimate to use.

flat: the square cavity between a hot and a cold wall of layered dummies
(fix sph/wall/dirichlet surface on a block, corners included) with a
linear field, as in test_walls.py nusselt: no warning of compute
sph/nusselt, and the gradient estimate is 1.

Usage: test_nusselt_staircase.py --lmp LMP --plugin PLUGIN [--np N]
"""
import math
import os
import re
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
from lammps_checks import run_input, run_lammps
from cavity_scenes import CONDUCTION, LATTICE, NUSSELT_WALLS

from sphtest import Checks, finish, lammps_arguments

# the flat-walled cavity of convection.nusselt.linear, not jittered
FLAT = LATTICE + CONDUCTION + NUSSELT_WALLS + """compute         hot_local hot reduce sum c_nu_hot[1]
thermo_style    custom step c_nu_hot[*] c_nu_cold[*] c_hot_local
thermo_modify   format float %.15g
run             0
print           "FLAT gradient $(c_nu_hot[2]:%.15g) $(c_nu_cold[2]:%.15g)"
"""


def value(out, key):
    m = re.search(key + r"\s+(\S+)\s+(\S+)", out)
    return (float(m.group(1)), float(m.group(2))) if m else (math.nan, math.nan)


def main():
    parser = lammps_arguments(__import__("argparse").ArgumentParser(description=__doc__))
    a = parser.parse_args()
    check = Checks()
    lmp, plugin = os.path.abspath(a.lmp), os.path.abspath(a.plugin)
    with tempfile.TemporaryDirectory() as work:
        out = run_input(lmp, os.path.join(HERE, "in.nusselt_annulus"),
                        {"plugin": plugin, "n": 10, "steps": 1500}, work, a.np, a.mpirun)
        m = re.search(r"ANNULUS n \S+ heat (\S+) gradient (\S+) exact (\S+)", out)
        heat, grad, exact = (float(v) for v in m.groups()) if m else (math.nan,) * 3
        warnings = [line for line in out.splitlines()
                    if line.startswith("WARNING") and "sph/nusselt" in line]
        check(abs(heat / exact - 1) < 3e-3,
              f"annulus: Nu from the heat {heat:.6f} against the exact {exact:.6f} "
              f"({100 * (heat / exact - 1):+.3f} %, limit 0.3 %); from the gradient {grad:.4f}")
        check(len(warnings) == 1 and re.search(
                  r"compute sph/nusselt nu: the wall atoms of group hot do not lie in layers "
                  r"parallel to the surface of fix hotw .*use the mean from the heat",
                  warnings[0]) is not None,
              f"annulus: one WARNING of compute sph/nusselt naming the group and the heat "
              f"(found {len(warnings)}: {warnings[:1]})")
        out = run_lammps(lmp, FLAT.format(plugin=plugin), work, a.np, a.mpirun)
        warnings = [line for line in out.splitlines()
                    if line.startswith("WARNING") and "sph/nusselt" in line]
        hot, cold = value(out, "FLAT gradient")
        check(not warnings and abs(hot - 1) < 1e-10 and abs(cold - 1) < 1e-10,
              f"flat walls with corners: no WARNING of compute sph/nusselt (found {warnings}); "
              f"Nu from the gradient {hot:.12f} {cold:.12f} (1 within 1e-10)")
    finish(check.failures)


if __name__ == "__main__":
    main()
