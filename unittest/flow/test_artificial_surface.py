"""Where Monaghan's artificial viscosity of pair sph/harmonic/visc acts
(unittest/flow/in.artificial_surface: water under gravity, Adami walls
below, a free surface on top or a lid, random velocities):
  * with 'artificial 0.5' against 'artificial 0', the forces of the
    particles farther than the kernel's support from the surface rows and
    from the walls are the same to round-off (the bulk is untouched), and
    those of the top row and of the row on the floor differ (the term acts
    at the free surface and at walls);
  * by default (under fix gravity) the pair takes 0.1 and counts the atoms
    at the free surface: the top rows, not the bulk;
  * in the closed tank it takes 0 by default (no free surface at the
    start), the forces those of 'artificial 0'.
usage: test_artificial_surface.py --lmp LMP --plugin PLUGIN"""

import argparse
import os
import re
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
from checks import below, finish, that  # noqa: E402
from lammps_checks import lammps_arguments, read_dump, run_input  # noqa: E402

DX, ROWS, COLUMNS = 0.001, 24, 16
SUPPORT = 4 * DX


def run(args, workdir, **variables):
    out = os.path.join(workdir, "forces.{alpha}.{closed}.dump".format(**variables))
    log = run_input(args.lmp, os.path.join(HERE, "in.artificial_surface"),
                    {"plugin": args.plugin, "out": out, **variables}, workdir)
    return read_dump(out), log


def largest_difference(a, b, ids):
    """The largest difference of a force component over the atoms at the
    indices ids (both dumps sorted by id, the same atoms)."""
    return max(max(abs(a["fx"][i] - b["fx"][i]), abs(a["fy"][i] - b["fy"][i])) for i in ids)


def main():
    parser = argparse.ArgumentParser(description=__doc__,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    lammps_arguments(parser)
    args = parser.parse_args()
    workdir = tempfile.mkdtemp(prefix="artificial-surface-")
    plain, _ = run(args, workdir, alpha=0, closed=0)
    strong, _ = run(args, workdir, alpha=0.5, closed=0)
    ids = range(len(plain["id"]))
    scale = max(max(abs(plain["fy"][i]) for i in ids), 1e-300)
    top = max(plain["y"][i] for i in ids)
    # the surface rows: within 3 spacings of the top (Shepard sum below 0.9)
    bulk = [i for i in ids
            if plain["y"][i] > SUPPORT + DX and plain["y"][i] < top - 3 * DX - SUPPORT]
    top_row = [i for i in ids if plain["y"][i] > top - 0.5 * DX]
    floor_row = [i for i in ids if plain["y"][i] < DX]
    that(len(bulk) >= 8 * COLUMNS, "the bulk band holds rows of particles", f"{len(bulk)} atoms")
    below(largest_difference(plain, strong, bulk) / scale, 1e-12,
          "artificial 0.5: the bulk's forces those of artificial 0 (relative to the largest)")
    that(largest_difference(plain, strong, top_row) / scale > 1e-3,
         "artificial 0.5: the top row's forces differ (the free surface)",
         f"{largest_difference(plain, strong, top_row) / scale:.3e}")
    that(largest_difference(plain, strong, floor_row) / scale > 1e-3,
         "artificial 0.5: the floor row's forces differ (fluid and wall particles)",
         f"{largest_difference(plain, strong, floor_row) / scale:.3e}")

    default, log = run(args, workdir, alpha=-1, closed=0)
    that("artificial 0.1 (the default under the weight of fix gravity" in log,
         "open tank: the default is 0.1 under fix gravity", "not in the log")
    count = re.search(r"artificial viscosity 0\.1 on pairs with one of (\d+) atoms now at a free "
                      r"surface", log)
    that(count is not None and COLUMNS <= int(count.group(1)) <= 4 * COLUMNS,
         "open tank: the atoms at the free surface are the top rows (1 to 4 rows of 16)",
         count.group(1) if count else "no count in the log")
    that(largest_difference(default, plain, top_row) > 0.0,
         "open tank, default: the top row's forces are not those of artificial 0", "equal")

    closed_plain, _ = run(args, workdir, alpha=0, closed=1)
    closed_default, log = run(args, workdir, alpha=-1, closed=1)
    that("artificial 0 (the default under weight when the run starts without a free surface)"
         in log, "closed tank: the default is 0", "not in the log")
    ids = range(len(closed_plain["id"]))
    below(largest_difference(closed_plain, closed_default, ids), 0.0,
          "closed tank, default: every force that of artificial 0")
    finish()


if __name__ == "__main__":
    main()
