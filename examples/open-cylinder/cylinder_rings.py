#!/usr/bin/env python3
"""The cylinder's rings for in.cylinder (tools/sph_boundary.py --body: the
surface halfway between the wall's particles and the fluid's, three wall
and three fluid rings), D = 0.1 m centred at (0.2, 0.2), n particles per
diameter, written to a data file. One place for run.sh and the stress
suite (bench/stress/stress.py).

  cylinder_rings.py N PATH
"""
import sys

import sph_boundary


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    n, path = int(sys.argv[1]), sys.argv[2]
    sph_boundary.main(["disc", "--body", "--radius", "0.05", "--center", "0.2,0.2",
                       "--dx", repr(0.1 / n), "--layers", "3", "--fluid-layers", "3",
                       "--section", "none", "-o", path])


if __name__ == "__main__":
    main()
