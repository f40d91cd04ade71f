"""fix sph/boussinesq 'hold' and its default (unittest/convection/in.hold_default,
a small cavity, 200 steps): with the buoyancy from the 'gravity' keyword and
no fix gravity the fix says it holds the fluid's volume and does, to
round-off, also beside a fix gravity of magnitude 0; with 'hold no', with fix gravity (weight: a free surface may
exist), on a group with a type that has no equation of state or with the
walls of fix sph/wall/adami, it says
why not (for 'hold no' it says nothing) and the volume drifts; with the
user's own fix sph/hold/volume on the fluid it stands down and that one
holds it; across a restart the volume held is that of the file (the
densities doubled before writing are scaled back, the volume returns to 1).
usage: test_hold_default.py --lmp LMP --plugin PLUGIN"""

import argparse
import os
import re
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
from checks import below, finish, that
from lammps_checks import lammps_arguments, run_input

HOLD_LOG = r"^Fix sph/boussinesq buoyancy: hold (yes|no)[^(]*\((.*)\)$"
HELD = 1e-12      # round-off of a sum of 64 volumes
DRIFTS = 1e-9     # 200 steps of flow against walls move the volume by more


def run(args, workdir, **variables):
    out = run_input(args.lmp, os.path.join(HERE, "in.hold_default"),
                    dict(plugin=args.plugin, **variables), workdir, args.np, args.mpirun)
    start = float(re.search(r"^VOLUME START (\S+)", out, re.M).group(1))
    end = float(re.search(r"^VOLUME END (\S+)", out, re.M).group(1))
    said = [m.groups() for m in re.finditer(HOLD_LOG, out, re.M)]
    return abs(end / start - 1.0), said


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    lammps_arguments(parser)
    args = parser.parse_args()
    workdir = tempfile.mkdtemp(prefix="hold-default-")

    drift, said = run(args, workdir, scene="closed")
    closed = ("yes", "the default in a closed domain: buoyancy without weight (no fix gravity, or one of "
              "magnitude 0), so no free surface")
    that(said == [closed], "closed cavity: the fix says it holds the volume by default", str(said))
    below(drift, HELD, "closed cavity: the volume held")

    # a fix gravity of magnitude 0 weighs nothing: the scene's defaults are
    # those without it
    drift, said = run(args, workdir, scene="zero_weight")
    that(said == [closed], "fix gravity of magnitude 0: the volume held by default", str(said))
    below(drift, HELD, "fix gravity of magnitude 0: the volume held")

    drift, said = run(args, workdir, scene="off")
    that(said == [], "hold no: nothing said", str(said))
    that(drift > DRIFTS, "hold no: the volume drifts", f"{drift:.3g}")

    # scenes the default leaves unheld: the scene, what it is, the reason the log gives
    for scene, what, reason in (("weight", "fix gravity", "fix weight (style gravity)"),
                                ("solid", "a solid type in the group",
                                 "atom type 2, which has no equation of state"),
                                ("walls", "walls in the group",
                                 "wall atoms of fix sph/wall/adami flow_walls")):
        drift, said = run(args, workdir, scene=scene)
        that(len(said) == 1 and said[0][0] == "no" and reason in said[0][1],
             f"{what}: not held, and why", str(said))
        that(drift > DRIFTS, f"{what}: the volume drifts", f"{drift:.3g}")

    drift, said = run(args, workdir, scene="own")
    that(said == [("no", "fix sph/hold/volume hold holds it already")],
         "the user's fix sph/hold/volume: the fix stands down", str(said))
    below(drift, HELD, "the user's fix sph/hold/volume holds the volume")

    drift, said = run(args, workdir, restart="yes")
    that(len(said) == 2 and all(s[0] == "yes" for s in said), "restart: held before and after", str(said))
    below(drift, HELD, "restart: the volume of the file held (the doubled densities scaled back)")
    finish()


if __name__ == "__main__":
    main()
