"""fix sph/wall/adami 'surface' (unittest/flow/in.adami_surface): flow
between walls started from an exact profile, on a lattice. With the
surface the walls continue a linear (Couette) or quadratic (Poiseuille)
profile exactly, so at the start every row of fluid feels the same viscous
force, none for Couette (round-off); without it (Adami's Shepard mean) the
rows next to the walls feel another, for both kernels, which shows the
check can fail. After 200 steps of Couette flow the profile has moved less
with the surface than without, and 2 and 4 ranks give the 1-rank result.
usage: test_adami_surface.py --lmp LMP --plugin PLUGIN"""

import argparse
import os
import re
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
from checks import below, finish, that
from lammps_checks import lammps_arguments, run_input


def run(args, workdir, np_=1, **variables):
    out = run_input(args.lmp, os.path.join(HERE, "in.adami_surface"),
                    {"plugin": args.plugin, **variables}, workdir, np_, args.mpirun)
    start = re.search(r"^start: largest \|f_x\| (\S+) spread (\S+)", out, re.M)
    error = float(re.search(r"^run: largest \|u - u\(y\)\| / V0 = (\S+)", out, re.M).group(1))
    return float(start.group(1)), float(start.group(2)), error


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    lammps_arguments(parser)
    args = parser.parse_args()
    workdir = tempfile.mkdtemp(prefix="adami-surface-")
    for kernel in ("wendland", "quintic"):
        force, _, error = run(args, workdir, kernel=kernel, surface="yes")
        force_shepard, _, error_shepard = run(args, workdir, kernel=kernel, surface="no")
        below(force, 1e-12, f"{kernel}, Couette, surface: no force on the exact profile (m nu V0 / dx^2)")
        that(force_shepard > 1e-4, f"{kernel}, Couette, Shepard walls: the rows next to them feel a force",
             f"{force_shepard:.3e} (m nu V0 / dx^2)")
        that(error < 0.5 * error_shepard, f"{kernel}, Couette: after 200 steps the profile moved less "
             "with the surface", f"{error:.3e} against {error_shepard:.3e} V0")
        _, spread, _ = run(args, workdir, kernel=kernel, surface="yes", profile="poiseuille", steps=0)
        _, spread_shepard, _ = run(args, workdir, kernel=kernel, surface="no", profile="poiseuille", steps=0)
        below(spread, 1e-12, f"{kernel}, Poiseuille, surface: every row feels the same viscous force "
              "(spread, m nu V0 / dx^2)")
        that(spread_shepard > 1e-3, f"{kernel}, Poiseuille, Shepard walls: the rows next to them feel another",
             f"spread {spread_shepard:.3e} (m nu V0 / dx^2)")
        if kernel == "wendland":
            for np_ in (2, 4):
                _, _, error_np = run(args, workdir, np_, kernel=kernel, surface="yes")
                below(abs(error_np - error), 1e-9 * error, f"{kernel}, Couette, surface: {np_} ranks give "
                      "the 1-rank profile")
    finish()


if __name__ == "__main__":
    main()
