"""fix sph/hold/volume. In the Rayleigh-Benard layer of
examples/convection-rayleigh-benard (settings convection, with the shift's
'continuity no', 10 per H, Ra 2e4, to t = 0.15) the fluid's volume sum
m / rho stays at its start, 2 (W = 2H, H = 1), to round-off when held (fix
sph/boussinesq 'hold yes', its own fix sph/hold/volume), and drifts by more
than 1e-4 with 'hold no'. (The shift's 'continuity yes' changes the
densities at the step's end after the hold, by up to 1e-5 of the volume
here, undone at the next step.)
Across a restart (unittest/convection/in.hold_volume_restart) the fix holds
the volume of the restart file: one step scales a doubled density back to 1;
on another group it warns and holds that group's volume at the new start.
usage: test_hold_volume.py --lmp LMP --plugin PLUGIN"""

import argparse
import os
import re
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.abspath(os.path.join(HERE, "..", ".."))
from checks import below, finish, that
from lammps_checks import lammps_arguments, run_input


def layer_volume(args, workdir, hold):
    out = run_input(args.lmp, os.path.join(ROOT, "examples", "convection-rayleigh-benard", "in.rb"),
                    {"plugin": args.plugin, "settings": "convection", "n": "10", "ra": "2e4",
                     "tend": "0.15", "hold": hold, "eps": "0.1", "continuity": "no"}, workdir, args.np, args.mpirun)
    return float(re.search(r"^final: .* volume = (\S+)", out, re.M).group(1))


def restarted(args, workdir, group):
    out = run_input(args.lmp, os.path.join(HERE, "in.hold_volume_restart"),
                    {"plugin": args.plugin, "group": group}, workdir, args.np, args.mpirun)
    rho = float(re.search(r"^rho after restart: (\S+)", out, re.M).group(1))
    return rho, out


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    lammps_arguments(parser)
    args = parser.parse_args()
    workdir = tempfile.mkdtemp(prefix="hold-volume-")
    held = layer_volume(args, workdir, "yes")
    below(abs(held / 2.0 - 1.0), 1e-12, "held: the layer's volume against its start")
    free = layer_volume(args, workdir, "no")
    that(abs(free / 2.0 - 1.0) > 1e-4, "without the fix the layer's volume drifts",
         f"volume {free:.10g} against 2")
    rho, _ = restarted(args, workdir, "fluid")
    below(abs(rho - 1.0), 1e-12, "restart: the density scaled back to 1 (the file's volume)")
    rho, out = restarted(args, workdir, "other")
    below(abs(rho - 2.0), 1e-12, "restart on another group: the density stays 2 (the new start's volume)")
    that("the restart file's volume" in out, "restart on another group: the warning",
         "no warning in the output")
    finish()


if __name__ == "__main__":
    main()
