"""fix sph/surface/flux against the 1-D finite-volume solution (tools/fv1d.py):
runs unittest/conduction/in.surface (a flux or a convective condition on the
left face of a slab) and compares T at t = 50 s; fails above --max-error, in %
of the largest temperature rise.
  check_surface_flux.py --lmp L --plugin P --mode flux|convection --max-error E"""

import argparse
import os
import subprocess
import sys
import tempfile

import numpy as np

here = os.path.dirname(os.path.abspath(__file__))
import fv1d
from sphthermal_tools.dump import read_frames

from sphtest import lammps_arguments

p = argparse.ArgumentParser(description=__doc__)
lammps_arguments(p, mpi=False)
p.add_argument("--mode", choices=["flux", "convection"], default="flux")
p.add_argument("--max-error", type=float, required=True)
a = p.parse_args()

with tempfile.TemporaryDirectory() as work:
    dump = os.path.join(work, "surface.dump")
    proc = subprocess.run([os.path.abspath(a.lmp), "-in", "in.surface", "-var", "plugin", a.plugin, "-var", "mode", a.mode,
                           "-var", "out", dump, "-log", "none"], cwd=os.path.join(here, "..", "conduction"),
                          capture_output=True, text=True, env=dict(os.environ, OMP_NUM_THREADS="1"))
    print("\n".join(line for line in proc.stdout.splitlines() if "heat added" in line or "ERROR" in line))
    if proc.returncode != 0:
        sys.exit(f"FAIL: LAMMPS exited with {proc.returncode}")
    step, c = read_frames(dump)[-1]

# the SPH surface particle, whose temperature the convective flux uses, sits
# half a spacing (0.0125 m) inside the face
cells = 400
x_fv = (np.arange(cells) + 0.5) / cells
flux = 10.0 if a.mode == "flux" else (lambda T: 5.0 * (1.0 - np.interp(0.0125, x_fv, T)))
x, (T,) = fv1d.solve([fv1d.Layer(0.0, 1.0, "constant:1", 1000.0, 1.0, 0.0)], 1.0, cells, [50.0],
                     left_flux=flux)
rise = T.max() - T.min()
err = 100.0 * np.abs(c["c_T"] - np.interp(c["x"], x, T)).max() / rise
print(f"{a.mode}: largest deviation from the finite-volume solution at t = 50 s: {err:.3f} % of the "
      f"temperature rise {rise:.4g}")
sys.exit(0 if err <= a.max_error else 1)
