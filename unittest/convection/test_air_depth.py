#!/usr/bin/env python3
"""examples/convection-cavity/in.air in 3-D (-var nz, the quasi-2-D cavity
of Reece et al. 2024, section 3.3) against the same input in 2-D: a coarse
air cavity (12 across; 10 spacings of periodic depth) from rest to
t = 1 s. Both mean Nusselt numbers of the hot wall, from its heat and from
the temperature gradient on it, must agree with the 2-D run's within 2 %
(measured: -0.87 % and -0.32 %); the 3-D run's walls' area is L times the
depth (10/12 L here), and with compute sph/nusselt's default area in 3-D,
L^2, the heat's number would be 17 % low. The 3-D dump must hold nz times the 2-D one's particles.

Usage: test_air_depth.py --lmp LMP --plugin PLUGIN
"""
import os
import sys
import tempfile

from lammps_checks import final_nusselt, read_dump, run_input, serial_check

HERE = os.path.dirname(os.path.abspath(__file__))
IN_AIR = os.path.join(HERE, "..", "..", "examples", "convection-cavity", "in.air")
N, NZ = 12, 10


def run(a, cwd, nz):
    out = run_input(a.lmp, IN_AIR, {"plugin": os.path.abspath(a.plugin), "n": N, "nz": nz,
                                    "seconds": 1.0, "every": 100000, "out": f"air{nz}.dump"},
                    cwd)
    final = final_nusselt(out)
    count = len(read_dump(os.path.join(cwd, f"air{nz}.dump"))["id"])
    return final["heat"][0], final["gradient"][0], count


def main():
    a, check = serial_check(__doc__)

    with tempfile.TemporaryDirectory() as tmp:
        heat_2d, gradient_2d, count_2d = run(a, tmp, 0)
        heat_3d, gradient_3d, count_3d = run(a, tmp, NZ)
    check(count_3d == NZ * count_2d, f"{count_3d} particles in 3-D, {NZ} x {count_2d}")
    for name, two, three in (("heat", heat_2d, heat_3d), ("gradient", gradient_2d, gradient_3d)):
        off = (three - two) / two
        check(abs(off) < 0.02, f"Nu from the {name}: 3-D {three:.6f}, 2-D {two:.6f} "
              f"({100 * off:+.3f} %, within 2 %)")
    if check.failures:
        sys.exit(1)
    print("PASS")


if __name__ == "__main__":
    main()
