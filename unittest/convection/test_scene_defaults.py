"""The defaults that depend on the scene (unittest/convection/in.scene_defaults):
with fix sph/boussinesq and no 'correction' in the commands, pair
sph/harmonic/visc takes 'correction gradient' and sph/cleary/heat
'correction consistent', say so and apply them (the setup's counts of
corrected atoms); without buoyancy both take none; with buoyancy and the
'sum' pressure form the flow pair takes none and says why; a correction
given in the command is kept and not called a default; after a restart
without fix sph/boussinesq the defaults are taken again.
usage: test_scene_defaults.py --lmp LMP --plugin PLUGIN"""

import argparse
import os
import re
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
from checks import finish, that
from lammps_checks import lammps_arguments, run_input

FLOW_DEFAULT = r"Pair style sph/harmonic/visc: correction (\w+) \(the default ([^)]*)\)"
HEAT_DEFAULT = r"Pair style sph/cleary/heat: correction (\w+) \(the default ([^)]*)\)"
FLOW_APPLIED = r"Pair style sph/harmonic/visc: correction gradient on \d+ fluid atoms"
HEAT_APPLIED = r"Pair style sph/cleary/heat: correction consistent on \d+ of"


def run(args, workdir, **variables):
    return run_input(args.lmp, os.path.join(HERE, "in.scene_defaults"),
                     dict(plugin=args.plugin, **variables), workdir, args.np, args.mpirun)


def taken(pattern, out):
    return [m.group(1) for m in re.finditer(pattern, out)]


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    lammps_arguments(parser)
    args = parser.parse_args()
    workdir = tempfile.mkdtemp(prefix="scene-defaults-")

    out = run(args, workdir, buoyant="yes")
    that(taken(FLOW_DEFAULT, out) == ["gradient"] and re.search(FLOW_APPLIED, out) is not None,
         "with buoyancy the flow pair takes and applies correction gradient", str(taken(FLOW_DEFAULT, out)))
    that(taken(HEAT_DEFAULT, out) == ["consistent"] and re.search(HEAT_APPLIED, out) is not None,
         "with buoyancy the heat pair takes and applies correction consistent", str(taken(HEAT_DEFAULT, out)))

    out = run(args, workdir, buoyant="no")
    that(taken(FLOW_DEFAULT, out) == ["none"] and re.search(FLOW_APPLIED, out) is None,
         "without buoyancy the flow pair takes correction none", str(taken(FLOW_DEFAULT, out)))
    that(taken(HEAT_DEFAULT, out) == ["none"] and re.search(HEAT_APPLIED, out) is None,
         "without buoyancy the heat pair takes correction none", str(taken(HEAT_DEFAULT, out)))

    out = run(args, workdir, buoyant="yes", pressure="sum")
    why = re.search(FLOW_DEFAULT, out)
    that(why is not None and why.group(1) == "none" and "pressure form" in why.group(2),
         "with buoyancy and pressure sum the flow pair takes none and names the pressure form",
         why.group(0) if why else "no line")

    out = run(args, workdir, buoyant="yes", flow="correction none", heat="correction none")
    that(not taken(FLOW_DEFAULT, out) and not taken(HEAT_DEFAULT, out)
         and re.search(FLOW_APPLIED, out) is None and re.search(HEAT_APPLIED, out) is None,
         "a correction given in the command is kept and not called a default")

    out = run(args, workdir, restart="yes")
    after = out.split("resumed without fix sph/boussinesq", 1)
    that(len(after) == 2 and taken(FLOW_DEFAULT, after[0]) == ["gradient"]
         and taken(FLOW_DEFAULT, after[1]) == ["none"] and taken(HEAT_DEFAULT, after[1]) == ["none"],
         "the restart keeps 'default', taken again without buoyancy",
         f"{taken(FLOW_DEFAULT, after[-1])} {taken(HEAT_DEFAULT, after[-1])}")
    finish()


if __name__ == "__main__":
    main()
