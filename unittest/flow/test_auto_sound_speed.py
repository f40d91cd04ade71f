"""'eos linear auto' without buoyancy (unittest/flow/in.auto_sound_speed):
the speed of sound is 10 times the scene's speed (the eos's 'speed', the
atoms' largest at the start, sqrt(|g| H) along a non-periodic g), the
densest fluid's rho0 c0^2 for a lighter one, the eos's speed raises fix
sph/boussinesq's estimate, and the background pressure a flow without
weight or buoyancy takes by default is 0.01 rho0 c0^2 between walls (0
under weight or with a side open).
With --np 2 each case runs on 2 ranks as well.
usage: test_auto_sound_speed.py --lmp LMP --plugin PLUGIN [--np 2 --mpirun M]"""

import argparse
import math
import os
import re
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
from checks import finish, near, that
from lammps_checks import lammps_arguments, run_input


def main():
    parser = argparse.ArgumentParser(description=__doc__)
    lammps_arguments(parser)
    args = parser.parse_args()
    workdir = tempfile.mkdtemp(prefix="auto-c0-")
    # case: (c0 of types 1, 2 and the last, background logged)
    expected = {
        "speed": ((5.0, 5.0, 5.0), "0.01 rho0 c0^2"),
        # no walls above the fluid: a free surface takes no background
        "open": ((5.0, 5.0, 5.0), "0 "),
        "moving": ((3.0, 3.0, 3.0), "0.01 rho0 c0^2"),
        # H: the 10 rows of 0.1 (each atom's cell), g along -y
        "weight": ((10 * math.sqrt(9.81),) * 3, "0 "),
        # g along the periodic x: no head, the eos's speed
        "periodic": ((2.0, 2.0, 2.0), "0 "),
        # type 3 has rho0 / 4: twice the speed, the same rho0 c0^2
        "light": ((10.0, 10.0, 20.0), "0.01 rho0 c0^2"),
        # the eos's speed 100 above the buoyancy's estimate (2.67)
        "buoyant": ((1000.0, 1000.0, 1000.0), "0 "),
    }
    for case, (c0, background) in expected.items():
        # the extents and speeds are reduced over ranks: 2 ranks find the same
        for np_ in (1, 2) if args.np > 1 else (1,):
            out = run_input(args.lmp, os.path.join(HERE, "in.auto_sound_speed"),
                            {"plugin": args.plugin, "case": case}, workdir, np_, args.mpirun)
            found = [float(x) for x in re.search(r"^c0: (\S+) (\S+) (\S+)", out, re.M).groups()]
            for t, (got, want) in enumerate(zip(found, c0)):
                near(got, want, 1e-9,
                     f"{case}, {np_} rank(s): c0 of type {'1, 2, last'.split(', ')[t]}")
            that(f"Fix sph/materials: background {background}" in out,
                 f"{case}, {np_} rank(s): the default background {background.strip()} is logged")
    finish()


if __name__ == "__main__":
    main()
