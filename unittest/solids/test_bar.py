"""Xu's bar, a MACHDYN solid (examples/solid-machdyn-bar/in.bar, 4 across,
to t = 0.02): with the flux, the energy the medium gained and the heat fix
sph/surface/flux tallied are q A t to round-off (the flux enters both the
MACHDYN bar, whose integrator applies a step's rate once, and the SPH
particles around it, whose fix sph/stationary applies it in two halves);
with --np N > 1, the held and the flux case give the same temperatures as
on one rank (to 1e-12 of the largest).
usage: test_bar.py --lmp LMP --plugin PLUGIN --np N --mpirun MPIRUN"""

import argparse
import os
import re
import sys
import tempfile

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
INPUT = os.path.join(HERE, "..", "..", "examples", "solid-machdyn-bar", "in.bar")
from checks import below, finish
from lammps_checks import read_dump, run_input
from sphtest import lammps_arguments

TEND, Q, AREA = 0.02, 1.0, 0.2 * 0.2


def run(args, workdir, case, np_):
    out = f"{case}-np{np_}.dump"
    text = run_input(args.lmp, INPUT, {"plugin": os.path.abspath(args.plugin), "case": case, "n": 4,
                                       "tend": TEND, "out": out}, workdir, np_, args.mpirun)
    rows = re.findall(r"^\s*320\s+(\S+)\s+(\S+)\s+(\S+)\s+(\S+)\s+(\S+)\s*$", text, re.M)
    if not rows:
        sys.exit(f"FAIL: {case}, {np_} rank(s): no thermo line of step 320")
    # time, the medium's energy, the bar's, the heating rate, the heat of fix hot
    values = [float(v) for v in rows[-1]]
    return values, read_dump(os.path.join(workdir, out))


def by_position(dump):
    """The temperatures ordered by the particles' lattice positions."""
    key = np.lexsort((np.round(dump["z"], 9), np.round(dump["y"], 9), np.round(dump["x"], 9)))
    return dump["c_th"][key]


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    lammps_arguments(parser)
    args = parser.parse_args()
    workdir = tempfile.mkdtemp(prefix="sph-bar-")
    heat = Q * AREA * TEND
    flux, flux_dump = run(args, workdir, "flux", 1)
    below(abs(flux[1] - heat) / heat, 1e-12, "flux: the medium's energy gain against q A t")
    below(abs(flux[4] - heat) / heat, 1e-12, "flux: the heat fix sph/surface/flux tallied against q A t")
    if args.np > 1:
        held, held_dump = run(args, workdir, "held", 1)
        for case, dump in (("held", held_dump), ("flux", flux_dump)):
            _, many = run(args, workdir, case, args.np)
            # (create_atoms numbers the atoms by rank: compare by position)
            ref, other = by_position(dump), by_position(many)
            scale = max(abs(ref).max(), 1e-300)
            below(abs(other - ref).max() / scale, 1e-12,
                  f"{case}: T on {args.np} ranks against 1 rank")
    finish()


if __name__ == "__main__":
    main()
