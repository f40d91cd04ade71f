"""sph/faces puts every atom where its position says, on any number of ranks.

usage: test_faces.py --lmp LMP --plugin PLUGIN --dim 2|3 [--np N --mpirun CMD]

in.faces: a lattice around a block (2-d) or a cylinder (3-d); sph/faces with
inside, outside, faces and others. Each atom's groups (grmask) must equal
those computed here from its position:
- inside: in the region (the block, or within the cylinder's radius and
  height); outside: the rest;
- an atom outside goes to the first face listed that it lies beyond (the
  faces of the region's bounding box; in 2-d 'ylo bottom xlo hot' puts the
  bottom corners into bottom, not hot), else to 'others' (in 3-d the atoms
  outside the cylinder but within its bounding box);
- a group that existed keeps its atoms (hot held atom 1, a bottom corner);
- the log gives each group's count.
"""

import argparse
import os
import re
import tempfile

import numpy as np

from sphtest import Checks, finish, lammps_arguments
from lammps_checks import read_dump, run_input

HERE = os.path.dirname(os.path.abspath(__file__))


def expected(d, dim):
    x, y, z = d["x"], d["y"], d["z"]
    eps = 1e-9
    if dim == 2:
        inside = (x >= -eps) & (x <= 1 + eps) & (y >= -eps) & (y <= 1 + eps)
        faces = [("bottom", y < -eps), ("hot", x < -eps), ("cold", x > 1 + eps)]
    else:
        inside = ((x - 0.5) ** 2 + (y - 0.5) ** 2 <= 0.35 ** 2 + eps) & (z >= -eps) & (z <= 1 + eps)
        faces = [("bottom", z < -eps), ("east", x > 0.85 + eps)]
    groups = {"fluid": inside, "wall": ~inside}
    free = ~inside
    for name, beyond in faces:
        groups[name] = free & beyond
        free = free & ~beyond
    groups["rest"] = free
    if dim == 2:
        groups["hot"] = groups["hot"] | (d["id"] == 1)
    return groups


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawTextHelpFormatter)
    lammps_arguments(p)
    p.add_argument("--dim", type=int, choices=[2, 3], required=True)
    a = p.parse_args()
    check = Checks()
    with tempfile.TemporaryDirectory() as work:
        out = run_input(a.lmp, os.path.join(HERE, "in.faces"),
                        {"plugin": a.plugin, "dim": a.dim, "out": "faces.dump"}, work, a.np, a.mpirun)
        d = read_dump(os.path.join(work, "faces.dump"))
    want = expected(d, a.dim)
    for name, mask in want.items():
        got = d[f"v_{name}"] > 0.5
        wrong = int(np.sum(got != mask))
        check(wrong == 0 and mask.sum() > 0,
              f"group {name}: {int(got.sum())} atoms, {int(mask.sum())} expected from the "
              f"positions, {wrong} misplaced ({a.np} ranks)")
    for name in want:
        if name == "hot":
            continue  # the log counts the atoms added (atom 1 was there before)
        logged = re.search(rf"^sph/faces: (\d+) atoms of group all .* added to group {name}$", out, re.M)
        check(logged is not None and int(logged.group(1)) == int(want[name].sum()),
              f"the log gives group {name}'s count: {logged.group(1) if logged else 'no line'}")
    if a.dim == 2:
        corner = (d["x"] < 0) & (d["y"] < 0)
        check(bool(np.all(d["v_bottom"][corner] > 0.5)) and corner.sum() == 9,
              f"the {int(corner.sum())} bottom-left corner atoms are in bottom (listed before hot)")
    finish(check.failures)


if __name__ == "__main__":
    main()
