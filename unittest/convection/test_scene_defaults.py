"""The defaults that depend on the scene (unittest/convection/in.scene_defaults):
with fix sph/shift and no 'correction' in its command, pair
sph/cleary/heat takes 'correction consistent', says so and applies it (the
setup's count of corrected atoms), with or without fix sph/boussinesq;
without shifting it takes none; a correction given in the command is kept
and not called a default; after a restart without fix sph/boussinesq and
fix sph/shift the default is taken again (none). The flow pair's
'correction': gradient with buoyancy and shifting, said and applied (the
kinetic energy after the steps equals that of 'correction gradient' given
and differs from 'correction none'), none otherwise. The same for 'eta': 0.01 with buoyancy
and shifting, 0.1 otherwise, and applied: the fluid's energy after the step
equals that of a run with 'eta 0.01' given, and differs from 'eta 0.1'.
The background pressure of an equation of state that gives none: 0.1 rho0
c0^2 with buoyancy and shifting (the kinetic energy equals that of the
background given as 1000 = 0.1 rho0 c0^2, and differs from 0), 0 otherwise.
fix sph/shift without a form (alone, or with a keyword next) is skillen 2:
says so, and moves the particles as 'skillen 2' does, not as 'skillen 1'.
usage: test_scene_defaults.py --lmp LMP --plugin PLUGIN"""

import argparse
import os
import re
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
from checks import finish, that
from lammps_checks import lammps_arguments, run_input

HEAT_DEFAULT = r"Pair style sph/cleary/heat: correction (\w+) \(the default ([^)]*)\)"
FLOW_DEFAULT = r"Pair style sph/harmonic/visc: correction (\w+) \(the default ([^)]*)\)"
FLOW_APPLIED = r"Pair style sph/harmonic/visc: correction gradient on \d+ fluid atoms"
HEAT_APPLIED = r"Pair style sph/cleary/heat: correction consistent on \d+ of"
ETA_DEFAULT = r"Pair style sph/cleary/heat: eta (\S+) \(the default ([^)]*)\)"
BACKGROUND_DEFAULT = r"Fix sph/materials: background (\S+)(?: rho0 c0\^2)? \(the default ([^)]*)\)"
SHIFT_DEFAULT = r"Fix sph/shift shift: skillen (\S+) \(the default form"


def energy(out):
    return float(re.search(r"^FLUID ENERGY (\S+)", out, re.M).group(1))


def kinetic(out):
    return float(re.search(r"^FLUID KE (\S+)", out, re.M).group(1))


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
    that(taken(HEAT_DEFAULT, out) == ["consistent"] and re.search(HEAT_APPLIED, out) is not None,
         "with buoyancy and shifting the heat pair takes and applies correction consistent",
         str(taken(HEAT_DEFAULT, out)))
    ke_default = kinetic(out)
    ke_given = kinetic(run(args, workdir, buoyant="yes", flow="correction gradient"))
    plain = run(args, workdir, buoyant="yes", flow="correction none")
    that(taken(FLOW_DEFAULT, out) == ["gradient"] and re.search(FLOW_APPLIED, out) is not None
         and ke_default == ke_given and ke_default != kinetic(plain),
         "with buoyancy and shifting the flow pair takes and applies correction gradient",
         f"{taken(FLOW_DEFAULT, out)}: kinetic energy {ke_default!r}, given {ke_given!r}, "
         f"none {kinetic(plain)!r}")
    that(not taken(FLOW_DEFAULT, plain) and re.search(FLOW_APPLIED, plain) is None,
         "the flow pair's correction given in the command is kept and not called a default")
    e_default = energy(out)
    e_small = energy(run(args, workdir, buoyant="yes", heat="eta 0.01"))
    e_cleary = energy(run(args, workdir, buoyant="yes", heat="eta 0.1"))
    that(taken(ETA_DEFAULT, out) == ["0.01"] and e_default == e_small and e_default != e_cleary,
         "with buoyancy and shifting the heat pair takes and applies eta 0.01",
         f"{taken(ETA_DEFAULT, out)}: energy {e_default!r}, with eta 0.01 {e_small!r}, "
         f"with eta 0.1 {e_cleary!r}")

    out = run(args, workdir, buoyant="yes", shift="no")
    that(taken(HEAT_DEFAULT, out) == ["none"] and re.search(HEAT_APPLIED, out) is None,
         "with buoyancy but no shifting the heat pair takes none", str(taken(HEAT_DEFAULT, out)))
    that(taken(ETA_DEFAULT, out) == ["0.1"], "with buoyancy but no shifting eta 0.1",
         str(taken(ETA_DEFAULT, out)))
    that(taken(FLOW_DEFAULT, out) == ["none"] and re.search(FLOW_APPLIED, out) is None,
         "with buoyancy but no shifting the flow pair takes the plain gradient",
         str(taken(FLOW_DEFAULT, out)))

    out = run(args, workdir, buoyant="no", shift="no")
    that(taken(HEAT_DEFAULT, out) == ["none"] and re.search(HEAT_APPLIED, out) is None,
         "without buoyancy or shifting the heat pair takes none", str(taken(HEAT_DEFAULT, out)))

    out = run(args, workdir, buoyant="no")
    that(taken(HEAT_DEFAULT, out) == ["consistent"] and re.search(HEAT_APPLIED, out) is not None
         and "the default with shifting, fix sph/shift shift" in out,
         "with shifting and no buoyancy (a driven flow) the heat pair takes and applies "
         "correction consistent", str(taken(HEAT_DEFAULT, out)))
    that(taken(FLOW_DEFAULT, out) == ["none"] and re.search(FLOW_APPLIED, out) is None,
         "with shifting and no buoyancy the flow pair takes the plain gradient",
         str(taken(FLOW_DEFAULT, out)))
    e_default = energy(out)
    e_cleary = energy(run(args, workdir, buoyant="no", heat="eta 0.1"))
    that(taken(ETA_DEFAULT, out) == ["0.1"] and e_default == e_cleary,
         "without buoyancy the heat pair takes and applies eta 0.1",
         f"{taken(ETA_DEFAULT, out)}: energy {e_default!r}, with eta 0.1 {e_cleary!r}")

    out = run(args, workdir, buoyant="yes", heat="correction none")
    that(not taken(HEAT_DEFAULT, out) and re.search(HEAT_APPLIED, out) is None,
         "a correction given in the command is kept and not called a default")

    # the background pressure: given (1000 = 0.1 rho0 c0^2 of the input), or the scene's
    given = run(args, workdir)    # the background and the shift's form given
    out = run(args, workdir, eos_bg="")
    ke_default, ke_given = kinetic(out), kinetic(given)
    ke_none = kinetic(run(args, workdir, eos_bg="background 0.0"))
    that(taken(BACKGROUND_DEFAULT, out) == ["0.1"] and ke_default == ke_given
         and ke_default != ke_none,
         "with buoyancy and shifting the eos takes and applies background 0.1 rho0 c0^2",
         f"{taken(BACKGROUND_DEFAULT, out)}: kinetic energy {ke_default!r}, given {ke_given!r}, "
         f"none {ke_none!r}")
    out = run(args, workdir, eos_bg="", shift="no")
    ke_default = kinetic(out)
    ke_none = kinetic(run(args, workdir, eos_bg="background 0.0", shift="no"))
    that(taken(BACKGROUND_DEFAULT, out) == ["0"] and ke_default == ke_none,
         "with buoyancy but no shifting the eos takes and applies background 0",
         f"{taken(BACKGROUND_DEFAULT, out)}: kinetic energy {ke_default!r}, none {ke_none!r}")
    that(not taken(BACKGROUND_DEFAULT, given), "a background given in the eos is not called a default")

    # fix sph/shift without a form: skillen 2, alone or with a keyword next
    that(not re.search(SHIFT_DEFAULT, given), "a form given is not called a default")
    ke_two, ke_one = kinetic(given), kinetic(run(args, workdir, shift_args="skillen 1"))
    for words in ("", "continuity no"):
        out = run(args, workdir, shift_args=words)
        that(taken(SHIFT_DEFAULT, out) == ["2"] and kinetic(out) == ke_two and ke_two != ke_one,
             f"fix sph/shift '{words}' takes and applies skillen 2",
             f"{taken(SHIFT_DEFAULT, out)}: kinetic energy {kinetic(out)!r}, skillen 2 {ke_two!r}, "
             f"skillen 1 {ke_one!r}")

    out = run(args, workdir, restart="yes")
    after = out.split("resumed without fix sph/boussinesq", 1)
    that(len(after) == 2 and taken(HEAT_DEFAULT, after[0]) == ["consistent"]
         and taken(HEAT_DEFAULT, after[1]) == ["none"],
         "the restart keeps 'default', taken again without buoyancy", str(taken(HEAT_DEFAULT, after[-1])))
    that(len(after) == 2 and taken(ETA_DEFAULT, after[0]) == ["0.01"]
         and taken(ETA_DEFAULT, after[1]) == ["0.1"],
         "the restart keeps eta's 'default', taken again without buoyancy (0.1)",
         str(taken(ETA_DEFAULT, after[-1])))
    that(len(after) == 2 and taken(FLOW_DEFAULT, after[0]) == ["gradient"]
         and taken(FLOW_DEFAULT, after[1]) == ["none"]
         and re.search(FLOW_APPLIED, after[1]) is None,
         "the restart keeps the flow pair's 'default', taken again without buoyancy (none)",
         str(taken(FLOW_DEFAULT, after[-1])))
    finish()


if __name__ == "__main__":
    main()
