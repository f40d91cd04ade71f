"""Two fluids of different rest densities (unittest/flow/in.two_fluid_layers):
at rest, each at its own rest density, the default density diffusion gives
no density rate (it does not act across the interface); in layered Couette
flow at density ratio 2, 10 and 1000 with diffusion on and the default
fix sph/dt/reset the flow stays bounded (|v| <= 1.5 V0, |v_y| <= 0.1 V0) to
the end time; with the heavier fluid's background pressure at ratio 1000 the
pair warns.
usage: test_two_fluids.py --lmp LMP --plugin PLUGIN [--tend T]"""

import argparse
import os
import re
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
from checks import below, finish, that
from lammps_checks import lammps_arguments, run_input


def run(args, workdir, **variables):
    return run_input(args.lmp, os.path.join(HERE, "in.two_fluid_layers"),
                     {"plugin": args.plugin, **variables}, workdir, args.np, args.mpirun)


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--tend", type=float, default=100.0)
    lammps_arguments(parser)
    args = parser.parse_args()
    workdir = tempfile.mkdtemp(prefix="two-fluids-")
    for ratio in (2, 10, 1000):
        out = run(args, workdir, ratio=ratio, tend=args.tend)
        rest = float(re.search(r"^rest: largest \|drho\| (\S+)", out, re.M).group(1))
        below(rest, 1e-12, f"ratio {ratio}: no density rate at rest across the interface")
        m = re.search(r"^layers: t (\S+) largest speed (\S+) largest \|vy\| (\S+) V0 (\S+)", out, re.M)
        t, vmax, vymax, v0 = (float(x) for x in m.groups())
        that(t >= args.tend and vmax <= 1.5 * v0 and vymax <= 0.1 * v0,
             f"ratio {ratio}: bounded to t = {args.tend:g} s with the default timestep",
             f"t {t:.4g}, |v| {vmax / v0:.3g} V0, |v_y| {vymax / v0:.3g} V0")
    out = run(args, workdir, ratio=1000, tend=0.0, bgfluid="lower")
    that("the background pressure 0.65363991" in out and "is 10 rho0 c0^2" in out,
         "ratio 1000 with the heavier fluid's background: the pair warns")
    finish()


if __name__ == "__main__":
    main()
