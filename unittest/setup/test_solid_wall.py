"""A no-slip steel wall conducts with steel's own density and heat capacity.

usage: test_solid_wall.py --lmp LMP --plugin PLUGIN --potentials DIR [--np N --mpirun CMD]

in.solid_wall: water (a fluid, fix sph) | steel (the wall of fix
sph/wall/adami, a solid: its type has no equation of state), 1-D conduction
from 350 K steel into 300 K water for 20 s. Checked:
- T(x), averaged over y, against tools/fv1d.py (400 cells; its own error
  is printed, 0.03 %): largest error below 2 % of the 50 K jump (measured
  1.55 % with 20 particles per material, 0.87 % with 40: first order, at the
  water's side of the interface). Were the steel's density that of the
  water (the wall density of a fluid-like Adami wall), the steel would hold
  8 times less heat: the reference then differs by 41 % of the jump;
- the steel keeps its own density (7900) exactly; the water stays at rest;
- the books: water's gain = heat flow of fix sph/heatflow = steel's loss,
  to 1e-12 relative.
"""

import argparse
import os
import re
import subprocess
import sys
import tempfile

import numpy as np

import fv1d
from sphthermal_tools.dump import read_frames

from sphtest import finish, lammps_arguments, mpi_env, mpi_prefix

HERE = os.path.dirname(os.path.abspath(__file__))


def main():
    p = argparse.ArgumentParser(description=__doc__)
    lammps_arguments(p)
    p.add_argument("--potentials", required=True)
    a = p.parse_args()
    length, steps, dt = 0.04, 2000, 0.01
    with tempfile.TemporaryDirectory() as tmp:
        out = os.path.join(tmp, "solid.dump")
        cmd = [a.lmp, "-log", "none", "-in", os.path.join(HERE, "in.solid_wall"), "-var", "plugin",
               a.plugin, "-var", "potentials", a.potentials, "-var", "out", out]
        cmd = mpi_prefix(a.np, a.mpirun) + cmd
        proc = subprocess.run(cmd, cwd=tmp, capture_output=True, text=True, env=mpi_env())
        text = proc.stdout + proc.stderr
        m = re.search(r"^BOOKS (\S+) (\S+) (\S+)$", text, re.M)
        if proc.returncode != 0 or not m:
            print(text)
            sys.exit("FAIL: the run did not finish")
        step, last = read_frames(out)[-1]
    gain, flow, loss = (float(v) for v in m.groups())
    books = max(abs(gain - flow), abs(loss - flow)) / abs(flow)
    print(f"books: water gain {gain:.12e}, flow {flow:.12e}, steel loss {loss:.12e} J/m: {books:.1e}")

    water = fv1d.material_from_file(os.path.join(a.potentials, "thermal_300K.sphmat"), "water",
                                    0.0, length / 2, 300.0)
    steel = fv1d.material_from_file(os.path.join(a.potentials, "thermal_300K.sphmat"), "steel",
                                    length / 2, length, 350.0)
    t = step * dt
    x_ref, (T_ref,) = fv1d.solve([water, steel], length, 400, [t])
    ref_error = fv1d.reference_error([water, steel], length, 400, [t])
    xs = np.unique(np.round(last["x"], 12))
    T_sph = np.array([np.mean(last["c_T"][np.isclose(last["x"], x)]) for x in xs])
    err = np.max(np.abs(T_sph - np.interp(xs, x_ref, T_ref))) / 50.0 * 100.0
    steel_rho = last["c_rho"][last["type"] == 2]
    speed = np.max(np.hypot(last["vx"], last["vy"]))
    print(f"t = {t:g} s: largest error of T {err:.3f} % of the jump (reference's own error "
          f"{ref_error / 50.0 * 100.0:.4f} %); steel density {steel_rho.min()}..{steel_rho.max()}; "
          f"largest water speed {speed:.2e} m/s")
    failures = []
    if books > 1e-12:
        failures.append("books")
    if err > 2.0:
        failures.append("temperature")
    if not np.all(steel_rho == 7900.0):
        failures.append("steel density")
    if speed > 1e-9:
        failures.append("water at rest")
    finish(failures)


if __name__ == "__main__":
    main()
