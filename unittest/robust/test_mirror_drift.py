#!/usr/bin/env python3
"""Mirror walls and a medium atom past the wall's surface
(robust.mirror.drift, called by ctest).

At each run's start the mirror walls check that the medium next to the wall
lies inside the surface region. As set up (step 0) strictly: an atom
outside means a region that is not the wall's. At a later run's start
(after a restart, or a run before) a fluid particle may have drifted past
the surface by a fraction of a spacing, which is the flow's doing (an
impact pushes it there): up to the depth of the nearest wall atom (the
wall's first row, 0.05 beyond the surface here) it is taken, farther it is
not. Checked: fluid atom 45, next to the bottom wall (surface y = 0),
moved to y = -0.04 stops the run at step 0 and passes at step 5; moved to
y = -0.06 (past the first wall row) it stops the run at step 5 too.
"""
import argparse
import re

from sphtest import Checks, finish, lammps_arguments, run_script

SCRIPT = """plugin load {plugin}
units           si
dimension       2
atom_style      sph
atom_modify     map array
boundary        f f p
comm_modify     vel yes
lattice         sq 0.1 origin 0.5 0.5 0.0
region          box block -3 9 -3 9 -0.5 0.5
create_box      2 box
create_atoms    1 box
region          cavity block 0 6 0 6 INF INF
group           fluid region cavity
group           wall subtract all fluid
set             group wall type 2
fix             materials all sph/materials type * conductivity constant 1.0 cv 1.0 rho0 1.0
sph/set         all materials spacing 0.1 temperature 0.5
pair_style      sph/cleary/heat quintic 0.3
pair_coeff      * *
neigh_modify    exclude type 2 2
set             atom 45 y {y}
reset_timestep  {step}
fix             a wall sph/wall/adiabatic surface cavity
run             0
"""

REFUSED = re.compile(r"ERROR: Fix a sph/wall/adiabatic: medium atom 45 \(type 1\) at "
                     r"\(0\.55 -0\.0\d+ 0\), within the kernel's reach")


def main():
    parser = lammps_arguments(argparse.ArgumentParser(description=__doc__), mpi=False)
    args = parser.parse_args()
    check = Checks()
    for y, step, refused in ((-0.04, 0, True), (-0.04, 5, False), (-0.06, 5, True)):
        code, output = run_script(args.lmp, SCRIPT.format(plugin=args.plugin, y=y, step=step))
        errors = [line for line in output.splitlines() if line.startswith("ERROR")]
        if refused:
            check(code != 0 and bool(REFUSED.search(output)),
                  f"atom 45 at y = {y}, step {step}: refused ({errors[:1]})")
        else:
            check(code == 0 and not errors, f"atom 45 at y = {y}, step {step}: taken ({errors[:1]})")
    finish(check.failures)


if __name__ == "__main__":
    main()
