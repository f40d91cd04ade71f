"""A dam break (examples/flow-dam-break, in.dam_break) at 20 particles
across the column, with the package's defaults (under fix gravity they
include Monaghan's artificial viscosity, 0.1, at the free surface and at
walls):
  * the front within 10 % of Martin and Moyce's experiment at every point of
    theirs before it reaches the far wall (measured: within 8.3 %; without the
    artificial viscosity 15 % ahead);
  * after the far wall's impact and splash (to t = 0.4 s) no particle lost
    and none past a wall's surface (the front at most 8 a);
  * without the artificial viscosity the front runs ahead of it by the
    experiment's T = 2 (the term acts);
  * on 2 ranks the same front to round-off until the impact.
usage: test_dam_break.py --lmp LMP --plugin PLUGIN [--np 2 --mpirun M]"""

import argparse
import os
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "tools"))
sys.path.insert(0, os.path.join(HERE, "..", "..", "tools"))
import dam_break_reference as reference  # noqa: E402
from checks import finish, that  # noqa: E402
from lammps_checks import lammps_arguments, run_input  # noqa: E402

INPUT = os.path.join(HERE, "..", "..", "examples", "flow-dam-break", "in.dam_break")
N, LENGTH = 20, 8


def run(args, workdir, np_=1, **variables):
    values = {"plugin": args.plugin, "n": N, "length": LENGTH, "every": 50}
    values.update(variables)
    log = os.path.join(workdir, f"log.{np_}.{values.get('alpha', 'default')}.{values['tend']}")
    run_input(args.lmp, INPUT, values, workdir, np_, args.mpirun, log=log)
    with open(log) as f:
        return reference.front_series(f.read())


def main():
    parser = argparse.ArgumentParser(description=__doc__)
    lammps_arguments(parser)
    args = parser.parse_args()
    workdir = tempfile.mkdtemp(prefix="dam-break-")
    rows = run(args, workdir, tend=0.4)
    water = rows[0][2]
    that(water == N * 2 * N, "the column has n x 2n particles", f"{water:.0f}")
    for t, z in reference.MARTIN_MOYCE:
        if z > LENGTH - 1:
            break
        got = reference.front_at(rows, t)
        that(abs(got / z - 1.0) < 0.10, f"front at T = {t}: within 10 % of the experiment's {z}",
             f"{got:.3f}")
    that(rows[-1][0] > 7.0, "the run goes on after the impact on the far wall (T = 5.5-6)",
         f"to T = {rows[-1][0]:.3f}")
    that(all(r[2] == water for r in rows), "no particle lost",
         f"{min(r[2] for r in rows):.0f} left")
    reach = max(r[1] for r in rows)
    that(reach <= LENGTH + 0.5 / N, f"no particle past the far wall's surface ({LENGTH} a)",
         f"{reach:.4f} a")
    plain = run(args, workdir, tend=0.12, alpha=0)
    ahead = reference.front_at(plain, 2.0) - reference.front_at(rows, 2.0)
    that(ahead > 0.05, "without the artificial viscosity the front is ahead at T = 2",
         f"{ahead:.3f} a")
    if args.np > 1:
        two = run(args, workdir, np_=2, tend=0.2)
        # (the last row of the shorter run is its end, off the sampling)
        worst = max(abs(a[1] - b[1]) for a, b in zip(rows, two[:-1]))
        that(len(two) > 50 and worst < 1e-9,
             "2 ranks: the same front to round-off until the impact", f"{worst:.2e}")
    finish()


if __name__ == "__main__":
    main()
