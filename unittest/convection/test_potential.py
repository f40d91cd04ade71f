"""The buoyancy's potential of fix sph/boussinesq ('potential N'),
unittest/convection/in.potential.

series   At rest with T = 1 - x in the unit square, T0 = 0.5, g = (0, -1, 0)
         and beta = 1, the buoyancy f = (0, 1/2 - x) has div f = 0 inside and
         f . n = +-(1/2 - x) on the floor and the lid: the potential solves
         lap phi = 0 with d phi / dn = f . n, exactly
           phi = sum over odd k of 4 / (k pi)^2 cos(k pi x)
                 sinh(k pi (y - 1/2)) / (k pi cosh(k pi / 2))
         (mean 0). The set-up's converged phi is within --tolerance of
         max|phi| of it (measured 2.2 % at 20 across in the Python model of
         the discretisation, 0.82 % at 40); at 2 n it is closer.
restart  A flow warmer to the right: 20 steps, a restart file and 20 more
         equal two runs of 20 steps to round-off: phi goes in the restart file
         and the restarted run goes on from it (it does not solve it again).
         (One run of 40 steps differs from two by about 1e-5 with or without
         the potential: LAMMPS's fix sph starts each run anew.)
ranks    The same 40 steps on --np ranks equal one rank's to round-off.
cavity   examples/convection-cavity/in.cavity-options at Ra = 1e4, 12 across,
         to t = 0.1, c0 = 10 times the benchmark's largest speed (squeeze
         10), with and without 'potential 1': with it the fluid's density
         spreads over less than 0.6 of the range (measured 0.9920-1.0144
         against 0.9868-1.0328, 0.49; 0.45 at 20 across, where the start's
         pressure waves at the walls are most of what is left; at 40 across
         to the steady state 0.9957-1.0056 with the package's c0 for the
         potential against 0.9860-1.0261 at ten times the speed without it,
         bench/convection/sound_speed.md), and
         the wall-mean Nu moves by less than 1 % (0.15 %).
usage: test_potential.py series|restart|ranks|cavity --lmp LMP --plugin PLUGIN [--np N --mpirun M]"""

import argparse
import math
import os
import sys
import tempfile

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
from checks import finish, that
from lammps_checks import lammps_arguments, read_dump, run_input

sys.path.insert(0, os.path.join(HERE, "..", "..", "tools"))
from sphthermal_tools.log import final_nusselt, longest_thermo_table  # noqa: E402


def run(args, workdir, np_=1, **variables):
    return run_input(args.lmp, os.path.join(HERE, "in.potential"),
                     dict(plugin=args.plugin, **variables), workdir, np_, args.mpirun)


def exact(x, y, terms=400):
    phi = np.zeros_like(x)
    for k in range(1, 2 * terms, 2):
        kp = k * math.pi
        # sinh(kp (y - 1/2)) / cosh(kp / 2) without overflow
        ratio = (np.exp(kp * (y - 1.0)) - np.exp(-kp * y)) / (1.0 + math.exp(-kp))
        phi += 4.0 / kp ** 2 * np.cos(kp * x) * ratio / kp
    return phi


def series(args, workdir):
    errors = {}
    for n in (args.n, 2 * args.n):
        out = run(args, workdir, n=n, mode="series", out=f"series{n}.dump")
        that("converged in" in out and "go on converging" not in out,
             f"{n} across: the set-up's sweeps converge")
        d = read_dump(os.path.join(workdir, f"series{n}.dump"))
        ref = exact(d["x"], d["y"])
        ref -= ref.mean()
        errors[n] = np.abs(d["f_buoyancy"] - ref).max() / np.abs(ref).max()
        that(abs(d["f_buoyancy"].mean()) < 1e-12 * np.abs(ref).max(), f"{n} across: mean phi 0")
    that(errors[args.n] < args.tolerance,
         f"phi within {errors[args.n]:.4f} of max|phi| of the exact series at {args.n} across "
         f"(limit {args.tolerance})")
    that(errors[2 * args.n] < 0.6 * errors[args.n],
         f"closer at {2 * args.n} across: {errors[2 * args.n]:.4f}")


def flow_dump(args, workdir, name, np_=1, **variables):
    run(args, workdir, np_, n=12, mode="flow", steps=40, out=name, **variables)
    return read_dump(os.path.join(workdir, name))


def by_site(d, n=12):
    """The atoms in the order of their lattice sites (create_atoms numbers
    them by rank, so the ids of 1 and 2 ranks differ; in 40 steps none moves
    by half a spacing)."""
    ix = np.rint(d["x"] * n - 0.5).astype(int)
    iy = np.rint(d["y"] * n - 0.5).astype(int)
    order = np.lexsort((ix, iy))
    return {k: v[order] for k, v in d.items()}, (iy * n + ix)[order]


def compare(a, b, what):
    (a, sites_a), (b, sites_b) = by_site(a), by_site(b)
    same_sites = np.array_equal(sites_a, sites_b) and len(np.unique(sites_a)) == len(sites_a)
    worst = max(np.abs(a[k] - b[k]).max() / np.abs(b[k]).max()
                for k in ("x", "y", "vx", "vy", "c_T", "f_buoyancy"))
    moving = np.abs(b["vy"]).max() > 1e-3 and np.abs(b["f_buoyancy"]).max() > 0.0
    that(same_sites and worst <= 1e-10 and moving,
         f"{what}: largest difference {worst:.2e} of the largest value (limit 1e-10); the fluid "
         f"moves and has a potential: {moving}")


def cavity(args, workdir):
    options = os.path.join(HERE, "..", "..", "examples", "convection-cavity", "in.cavity-options")
    spread, nu = {}, {}
    for sweeps in (0, 1):
        log = os.path.join(workdir, f"cavity{sweeps}.log")
        run_input(args.lmp, options, dict(plugin=args.plugin, ra="1e4", n=12, tend=0.1, squeeze=10,
                                          potential=sweeps, every=50, out=f"cavity{sweeps}.dump"),
                  workdir, log=log)
        text = open(log).read()
        table = longest_thermo_table(text)
        low, high = min(table["c_rho_min"]), max(table["c_rho_max"])
        spread[sweeps] = high - low
        nu[sweeps] = sum(final_nusselt(text)["heat"]) / 2.0
        print(f"potential {sweeps}: density {low:.4f}-{high:.4f}, Nu {nu[sweeps]:.5f}")
    that(spread[1] < 0.6 * spread[0],
         f"the potential keeps the density within {spread[1]:.4f} (without it {spread[0]:.4f})")
    that(abs(nu[1] / nu[0] - 1.0) < 0.01, f"Nu {nu[1]:.5f} with it, {nu[0]:.5f} without")


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("check", choices=("series", "restart", "ranks", "cavity"))
    parser.add_argument("--n", type=int, default=20)
    parser.add_argument("--tolerance", type=float, default=0.03)
    lammps_arguments(parser)
    args = parser.parse_args()
    workdir = tempfile.mkdtemp(prefix="potential-")
    if args.check == "series":
        series(args, workdir)
    elif args.check == "restart":
        compare(flow_dump(args, workdir, "halves.dump", restart="yes"),
                flow_dump(args, workdir, "two.dump", restart="two"),
                "20 + 20 steps through a restart file against two runs")
    elif args.check == "cavity":
        cavity(args, workdir)
    else:
        compare(flow_dump(args, workdir, "many.dump", np_=args.np),
                flow_dump(args, workdir, "one.dump"), f"{args.np} ranks against 1")
    finish()


if __name__ == "__main__":
    main()
