"""fix sph/wall/adiabatic with wall atoms beyond the kernel's reach of the
surface (unittest/robust/in.mirror_deep: the corners of three wall layers
round a strip with T = x, the walls started at T = 0). Without an exclusion
of wall-atom pairs the fix warns, naming the remedy, and the medium's
energy does drift (the corner atoms' exchange is charged to it: the
warning is needed); with 'neigh_modify exclude group wall wall' or
'exclude type 2 2' it does not warn and the energy holds to round-off.
usage: test_mirror_deep.py --lmp LMP --plugin PLUGIN"""

import argparse
import os
import re
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
INPUT = os.path.join(HERE, "in.mirror_deep")
from checks import below, finish, that
from lammps_checks import run_input
from sphtest import lammps_arguments

WARNING = "lie beyond the kernel's reach of surface medium"


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    lammps_arguments(parser, mpi=False)
    args = parser.parse_args()
    workdir = tempfile.mkdtemp(prefix="sph-mirror-deep-")
    for exclude in ("no", "group", "type"):
        text = run_input(args.lmp, INPUT, {"plugin": os.path.abspath(args.plugin), "exclude": exclude},
                         workdir)
        energy = [float(e) for e in re.findall(r"^\s*\d+\s+(\S+)\s+\S+\s*$", text, re.M)]
        drift = abs(energy[-1] - energy[0]) / abs(energy[0])
        warned = WARNING in text
        if exclude == "no":
            that(warned, "no exclusion: the warning")
            that(drift > 1e-3, "no exclusion: the energy drifts", f"{drift:.2e}")
        else:
            that(not warned, f"exclude {exclude}: no warning")
            below(drift, 1e-12, f"exclude {exclude}: the medium's energy after 200 steps")
    finish()


if __name__ == "__main__":
    main()
