"""A MACHDYN solid in a flowing fluid (unittest/solids/in.flow): the block is a
moving wall of fix sph/wall/adami for the flow of pair sph/harmonic/visc.
 - heavy and stiff, moving at U: the fluid flows as around the same block
   moved as a rigid wall by fix move (velocities within 1e-5 U; they would
   differ by far more if the wall's no-slip velocity overwrote the velocity
   pair smd/tlsph reads, or if the flow read the solid's own velocity);
 - light (twice the fluid's density): the fluid slows it down, and the
   momentum and thermal energy of block plus fluid are conserved to
   round-off (the energy relative to the total, the block's m cv T), on
   --np ranks.
usage: test_flow.py --lmp LMP --plugin PLUGIN --np N --mpirun MPIRUN"""

import argparse
import os
import re
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
INPUT = os.path.join(HERE, "in.flow")
from checks import below, finish, that
from lammps_checks import read_dump, run_input
from sphtest import lammps_arguments

U = 0.5


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    lammps_arguments(parser)
    args = parser.parse_args()
    workdir = tempfile.mkdtemp(prefix="sph-solid-flow-")
    plugin = os.path.abspath(args.plugin)

    def run(name, np_=1, **values):
        out = os.path.join(workdir, name + ".dump")
        text = run_input(args.lmp, INPUT, dict({"plugin": plugin, "out": out, "U": U}, **values), workdir, np_,
                         args.mpirun)
        momentum = re.findall(r"^momentum: change of sum\(m v\) (\S+) of the block's; the fluid's (\S+); "
                              r"block vx (\S+)", text, re.M)
        thermal = re.findall(r"^thermal: heat given off by the block (\S+); relative change of the total (\S+)",
                             text, re.M)
        return ([float(v) for v in momentum[-1]] if momentum else None,
                [float(v) for v in thermal[-1]] if thermal else None, out)

    heavy, _, heavy_dump = run("machdyn", args.np)
    _, _, moved_dump = run("moved", 1, solid="moved")
    that(heavy is not None, "the heavy block's run printed its books", str(heavy))
    machdyn, moved = read_dump(heavy_dump), read_dump(moved_dump)
    fluid = moved["type"] == 1
    that(fluid.any() and (machdyn["id"] == moved["id"]).all(), "the same particles in both dumps",
         f"{len(machdyn['id'])} and {len(moved['id'])}")
    if heavy and fluid.any() and (machdyn["id"] == moved["id"]).all():
        speeds = [moved[k][fluid] for k in ("vx", "vy", "vz")]
        largest = max(abs(s).max() for s in speeds)
        that(largest > 0.05 * U, "the moved wall set the fluid moving", f"largest fluid speed {largest / U:.3e} U")
        worst = max(abs(machdyn[k][fluid] - moved[k][fluid]).max() for k in ("vx", "vy", "vz"))
        below(worst / U, 1e-5, f"fluid velocities around the heavy MACHDYN block against the moved wall "
              f"on {args.np} rank(s), in units of U")
        below(abs(heavy[2] - U) / U, 1e-5, f"the heavy block keeps its speed: vx {heavy[2]}")

    light, thermal, _ = run("light", args.np, rhos=2000, E=2e6)
    that(light is not None and thermal is not None, "the light block's run printed its books", f"{light} {thermal}")
    if light and thermal:
        dp, fluid_share, vx = light
        that(fluid_share > 0.01, "the fluid took momentum from the block",
             f"fluid's momentum {fluid_share:.3e} of the block's, block vx {vx / U:.6f} U")
        below(dp, 1e-12, f"momentum of block plus fluid on {args.np} rank(s), relative to the block's")
        heat, drift = thermal
        total = 2000 * 48 * 0.1**3 * 1000 * 1.0  # the block's m cv T at the start (in.flow)
        that(heat > 1e-3 * total, "the hot block gave heat to the fluid", f"{heat / total:.3e} of its energy")
        below(drift, 1e-14, f"thermal energy of block plus fluid, relative to the total, on {args.np} rank(s)")
    finish()


if __name__ == "__main__":
    main()
