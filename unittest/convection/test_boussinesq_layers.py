"""fix sph/boussinesq T0 'layers' (unittest/convection/in.boussinesq_layers):
a fluid at rest stratified across g, T = -x.g/|g|, feels no buoyancy with T0
by layers, so its density stays at rho0 and it stays at rest (to round-off)
with g along -y. With g tilted by 45 degrees the atoms of a layer are not
centred on it, so T0 is not exactly T there: the density stays within a
small part of what T0 'mean' gives. With T0 'mean' the same fluid's density spans about
g beta dT H / (8 c0^2), which checks the measure.
usage: test_boussinesq_layers.py --lmp LMP --plugin PLUGIN"""

import argparse
import os
import re
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
from checks import below, finish, that
from lammps_checks import lammps_arguments, run_input


def stratified(args, workdir, variables):
    variables = dict(variables, plugin=args.plugin)
    out = run_input(args.lmp, os.path.join(HERE, "in.boussinesq_layers"), variables, workdir,
                    args.np, args.mpirun)
    drho, vmax, bound = (float(x) for x in re.search(r"^stratified: (\S+) (\S+) (\S+)", out, re.M).groups())
    return drho, vmax, bound


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    lammps_arguments(parser)
    args = parser.parse_args()
    workdir = tempfile.mkdtemp(prefix="boussinesq-layers-")
    drho, vmax, bound = stratified(args, workdir, {"t0": "layers"})
    below(drho, 1e-10, "T0 layers, g along -y: largest |rho/rho0 - 1|")
    below(vmax, 1e-9, "T0 layers, g along -y: largest speed")
    drho_mean, vmax_mean, _ = stratified(args, workdir, {"t0": "mean"})
    that(0.2 * bound < drho_mean < bound, "T0 mean: the stratified fluid's density spans about g beta dT H / (8 c0^2)",
         f"largest |rho/rho0 - 1| {drho_mean:.4g}, g beta dT H / (8 c0^2) = {bound:.4g}")
    drho_tilt, _, _ = stratified(args, workdir, {"t0": "layers", "gx": "0.70710678", "gy": "-0.70710678", "nx": "10"})
    drho_tilt_mean, _, _ = stratified(args, workdir, {"t0": "mean", "gx": "0.70710678", "gy": "-0.70710678", "nx": "10"})
    below(drho_tilt / drho_tilt_mean, 0.1, "g tilted: T0 layers' largest |rho/rho0 - 1| over T0 mean's")
    finish()


if __name__ == "__main__":
    main()
