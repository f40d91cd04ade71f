#!/usr/bin/env python3
"""Mirror walls around an obstacle: a surface region 'side out'.

The medium (jittered particles holding a linear temperature field) fills a
box around a square obstacle of wall particles, whose surface is the
boundary of 'region obstacle block ... side out'. fix sph/wall/adiabatic
mirrors each wall particle within the kernel's reach across the nearest face
of the obstacle, out into the medium, and takes the temperature there: for a
linear field T_wall = T(ghost) to 1e-10 (where two faces are equally near,
either ghost). The wall particles beyond the kernel's reach keep their own
temperature. Before, such a region was refused with a false message (its
wall atoms said to lie inside it).

Usage: test_mirror_side.py --lmp LMP --plugin PLUGIN [--np N]
"""
import os
import tempfile

import numpy as np

from lammps_checks import read_dump, run_lammps

from sphtest import Checks, finish, lammps_arguments

LO, HI = 0.8, 1.6    # the obstacle, in x and y
CUT = 0.3            # the kernel's support

SCRIPT = """plugin load {plugin}
units           si
dimension       2
atom_style      sph
boundary        f f p
atom_modify     map array
lattice         sq 0.1 origin 0.5 0.5 0.0
region          box block 0 24 0 24 -0.5 0.5
create_box      2 box
create_atoms    1 region box
region          obstacle block {lo} {hi} {lo} {hi} INF INF side out units box
group           medium region obstacle
group           wall subtract all medium
set             group wall type 2
variable        jx atom 0.025*sin(37.0*x+11.0*y)
variable        jy atom 0.025*cos(23.0*x-29.0*y)
displace_atoms  medium move v_jx v_jy 0.0 units box
fix             materials all sph/materials type * conductivity constant 1.0 cv 1.0 rho0 1.0
sph/set         all materials spacing 0.1 temperature 5.0
variable        Tlin atom 0.2+0.7*x-0.4*y
sph/set         medium temperature v_Tlin
pair_style      sph/cleary/heat quintic {cut}
pair_coeff      * *
neigh_modify    exclude type 2 2
fix             adiabatic wall sph/wall/adiabatic surface obstacle
compute         T all sph/t/atom
# LAMMPS 29Sep2021 dumps a per-atom compute only on a step that used it
compute         Tmax all reduce max c_T
thermo_style    custom step c_Tmax
run             0
write_dump      wall custom walls.dump id x y c_T modify sort id format float %.17g
"""


def main():
    parser = lammps_arguments(__import__("argparse").ArgumentParser(description=__doc__))
    a = parser.parse_args()
    check = Checks()
    with tempfile.TemporaryDirectory() as work:
        run_lammps(os.path.abspath(a.lmp),
                   SCRIPT.format(plugin=os.path.abspath(a.plugin), lo=LO, hi=HI, cut=CUT), work,
                   a.np, a.mpirun)
        d = read_dump(os.path.join(work, "walls.dump"))
    x, y, t = d["x"], d["y"], d["c_T"]
    depth = np.stack([x - LO, HI - x, y - LO, HI - y])    # to the four faces, from inside
    nearest = depth.min(axis=0)
    reach = nearest < CUT
    # the ghost across each face, and the linear field there
    ghosts = [(2 * LO - x, y), (2 * HI - x, y), (x, 2 * LO - y), (x, 2 * HI - y)]
    want = np.stack([0.2 + 0.7 * gx - 0.4 * gy for gx, gy in ghosts])
    tied = np.abs(depth - nearest) < 1e-12
    err = np.where(tied, np.abs(t - want), np.inf).min(axis=0)
    check(reach.sum() > 0 and err[reach].max() < 1e-10,
          f"{reach.sum()} wall particles within reach of the obstacle's faces: largest "
          f"|T_wall - T(ghost)| {err[reach].max():.2e} (limit 1e-10)")
    check(np.all(t[~reach] == 5.0),
          f"{(~reach).sum()} wall particles beyond reach keep T = 5 (found {np.unique(t[~reach])})")
    finish(check.failures)


if __name__ == "__main__":
    main()
