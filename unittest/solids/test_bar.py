"""Xu's bar, a MACHDYN solid (examples/solid-machdyn-bar/in.bar, 4 across,
to t = 0.02, in a closed box: pair smd/tlsph of LAMMPS 29Sep2021 can hang
in a periodic one): with the flux, the energy the medium gained (compute
sph/thermal's books) and the heat fix sph/surface/flux tallied are q A t to
round-off. The flux enters both the MACHDYN bar, whose integrator applies a
step's rate once, and the SPH particles around it, whose fix sph/stationary
applies it in two halves, and the two kinds exchange heat across the bar's
side faces (the box's outer faces are free, so the field is not 1-D);
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
                                       "tend": TEND, "out": out, "periodic": "no"}, workdir, np_, args.mpirun)
    rows = {step: re.findall(rf"^\s*{step}\s+(\S+)\s+(\S+)\s+(\S+)\s+(\S+)\s+(\S+)\s*$", text, re.M)
            for step in (0, 320)}
    if not rows[0] or not rows[320]:
        sys.exit(f"FAIL: {case}, {np_} rank(s): no thermo line of step 0 or 320")
    # time, the medium's energy gain, the bar's, the heating rate, the heat of fix
    # hot (at the run's end: the 'run 0' after it evaluates the rates again at the
    # end-of-step energies, which moves the half step still to be applied)
    start, end = ([float(v) for v in rows[step][0]] for step in (0, 320))
    values = [end[0], end[1] - start[1], end[2] - start[2], end[3], end[4]]
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
