"""A solid wall and a fluid-like wall of the fluid's material are the same wall to the flow.

usage: test_solid_plate.py --lmp LMP --plugin PLUGIN [--np N --mpirun CMD]

in.solid_plate: a periodic channel between plates, the fluid compressed to
1.02 rho0, jittered and driven, 400 steps, once with solid plates (no
equation of state, rho0 8000) and once with fluid-like plates (the fluid's
equation of state). Fix sph/wall/adami gives a solid the pressure, density
and viscosity of the fluid at the wall in the volume the fluid would fill
there (Adami et al. 2012), so the fluid must move the same to round-off:
positions and velocities to 1e-12 of dx and of the flow speed, densities
to 1e-12 of rho0; the solid plates keep rho = 8000 exactly.
Before the fix of 2026-11 the solid kept its own volume as the fluid was
compressed, and its density moved in the first step: the runs then differed
by 4e-2 of dx in x, 9e-3 of the speed in v and 2e-3 of rho0 in rho, the
plates' density by 5e-6, and the exchanger of examples/forced-channel broke
up within 10 s.
"""

import argparse
import os
import re
import subprocess
import sys
import tempfile

import numpy as np

from sphthermal_tools.dump import read_frames

from sphtest import finish, lammps_arguments, mpi_env, mpi_prefix

HERE = os.path.dirname(os.path.abspath(__file__))
DX, SPEED, RHO0 = 0.01, 0.2, 1000.0


def run(a, tmp, plate):
    out = os.path.join(tmp, plate + ".dump")
    cmd = mpi_prefix(a.np, a.mpirun) + [
        a.lmp, "-log", "none", "-in", os.path.join(HERE, "in.solid_plate"), "-var", "plugin",
        a.plugin, "-var", "plate", plate, "-var", "out", out]
    proc = subprocess.run(cmd, cwd=tmp, capture_output=True, text=True, env=mpi_env())
    text = proc.stdout + proc.stderr
    m = re.search(r"^PLATE_RHO (\S+) (\S+)$", text, re.M)
    if proc.returncode != 0 or not m:
        print(text)
        sys.exit(f"FAIL: the run with {plate} plates did not finish")
    return read_frames(out)[-1][1], (float(m.group(1)), float(m.group(2)))


def main():
    p = argparse.ArgumentParser(description=__doc__)
    lammps_arguments(p)
    a = p.parse_args()
    with tempfile.TemporaryDirectory() as tmp:
        solid, solid_rho = run(a, tmp, "solid")
        fluid, fluid_rho = run(a, tmp, "fluid")
    dx = max(np.max(np.abs(solid[k] - fluid[k])) for k in ("x", "y")) / DX
    dv = max(np.max(np.abs(solid[k] - fluid[k])) for k in ("vx", "vy")) / SPEED
    drho = np.max(np.abs(solid["c_rho"] - fluid["c_rho"])) / RHO0
    print(f"solid against fluid-like plates: x {dx:.1e} of dx, v {dv:.1e} of the speed, "
          f"rho {drho:.1e} of rho0; solid plates' rho {solid_rho[0]}..{solid_rho[1]}, "
          f"fluid-like plates' {fluid_rho[0]:.6f}..{fluid_rho[1]:.6f}")
    failures = []
    if not (dx < 1e-12 and dv < 1e-12 and drho < 1e-12):
        failures.append("the flow tells a solid from a fluid-like wall")
    if solid_rho != (8000.0, 8000.0):
        failures.append("the solid plates' density moved")
    finish(failures)


if __name__ == "__main__":
    main()
