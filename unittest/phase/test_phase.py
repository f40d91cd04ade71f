"""Melting and solidification with fix sph/phase on Neumann's Stefan problem
(examples/phase-stefan/in.stefan; the exact solution: tools/stefan.py). Every
property 1, the face x = 0 held at 1, melting at 0, the liquid's Stefan
number 1; n particles on [0, 4] (dx = 4 / n), to t = 1 (exact depth
2 lam = 1.2401 one-phase, 0.9397 with the solid at -0.5).

  one_phase   the solid at the melting point, n = 80: the melt's depth
              (liquid volume per height) within 0.5 % of Neumann's at t = 1
              (measured +0.026 %) and within 1 % from t = 0.25 on; T of
              every particle within 1 % of Tw - Ti of the exact profile; the
              heat through the wall equal to the particles' energy gain to
              1e-12 of it
  two_phase   the same with the solid at -0.5 (St_s = 0.5): depth within
              0.5 % at t = 1 (measured -0.28 %) and 1.5 % from t = 0.5 on
              (measured 1.04 %: the front at one melting temperature crosses
              the particles a row at a time), T,
              energy
  conductivity_jump
              the two-phase problem (solid at -0.5) with the solid's
              conductivity 2 and 0.5 (k steps at the melting point; nu =
              sqrt(alpha_l / alpha_s)), dx = 0.025 (n = 240 on [0, 6] for
              k = 2, 160 on [0, 4] for 0.5): Neumann's solution meets the
              Stefan condition (to the differences' 1e-4), the depth within
              1 % of it at t = 1 (measured +0.29 % and -0.58 %), T within
              1 and 1.5 % of Tw - Ti (measured 0.13 and 1.02 %), the energy
              balance
  heat_capacity_jump
              the two-phase problem with the liquid's specific heat 2 and
              0.5 (the solid's 1: fix sph/phase's cv_liquid; St_l = cl,
              alpha_l = 1 / cl), n = 160: Neumann's solution meets the
              Stefan condition, the depth within 1 % of it at t = 1
              (measured -0.27 % and -0.21 %), T within 1 % of Tw - Ti
              (measured 0.39 and 0.51 %), the energy balance; the timestep
              halved by the liquid's cv of 0.5 (the smaller of the phases'
              bounds the conduction's)
  converging  the depth's error at n = 20 at least twice that at n = 80, one-
              and two-phase (measured 0.44 -> 0.026 % and 1.87 -> 0.28 %)
  mushy       a mushy zone 0.1 wide about the melting point, the solid at its
              solidus: the energy balance, and the liquid volume within 2 %
              of the pure substance's melt (measured +0.8 %)
  freezing    the liquid at 1 cooled from the face held at -1: the energy
              balance, a frozen layer growing (liquid fraction falling),
              every particle's T within the bounds
  mpi         one_phase's depth and heat on --np ranks equal to 1 rank's to
              1e-12
  damping     keyword mushy on a uniform box (in.mushy; solidus 0, liquidus
              1): a mushy atom's velocity falls by 1 / (1 + dt A) per step,
              A = C (1 - f)^2 / ((f^3 + 1e-3) rho), to 1e-12 (at A dt = 2e5
              to 1e-9, the pair's round-off), never below 0; under a steady push g its velocity goes
              to g / A; a solid atom does not move, pushed or not; a liquid
              one is not damped (v = v0 + g t)
"""

import argparse
import math
import os
import sys
import tempfile

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "tools"))
sys.path.insert(0, os.path.join(HERE, "..", "..", "tools"))
from checks import below, finish, that  # noqa: E402
from lammps_checks import lammps_arguments, read_dump, run_input, thermo_tables  # noqa: E402
import stefan  # noqa: E402

INPUT = os.path.join(HERE, "..", "..", "examples", "phase-stefan", "in.stefan")
MUSHY = os.path.join(HERE, "in.mushy")
LX, TW, TM = 4.0, 1.0, 0.0


def run(args, variables, np_=1):
    with tempfile.TemporaryDirectory() as tmp:
        out = run_input(args.lmp, INPUT, {"plugin": args.plugin, "out": "stefan.dump", **variables}, tmp,
                        np_, args.mpirun)
        dump = read_dump(os.path.join(tmp, "stefan.dump"))
    table = thermo_tables(out)[-2]    # the run's (the last is the run 0 of the dump)
    return table, dump


def exact_depth(t, ti, ks=1.0, cl=1.0):
    # rho = 1, L = 1, the melt's k = 1: alpha_l = 1 / cl, alpha_s = ks,
    # St_l = cl (Tw - Tm), St_s = Tm - Ti
    lam = stefan.neumann_lambda(cl, TM - ti, math.sqrt(1.0 / (cl * ks)))
    return stefan.front(t, lam, 1.0 / cl), lam


def check_energy(table, what):
    heat = table["f_heat"][-1]
    below(np.abs(table["v_balance"]).max() / heat, 1e-12,
          f"{what}: heat through the wall = the particles' energy gain (largest |difference| / heat)")


def check_stefan(args, ti, limit, what, n=80, ks=1.0, lx=LX, t_limit=0.01, cl=1.0):
    table, dump = run(args, {"n": n, "ti": ti, "every": 20, "ks": ks, "lx": lx, "cl": cl})
    t, depth = table["Time"], table["v_depth"]
    exact_end, lam = exact_depth(t[-1], ti, ks, cl)
    that(abs(t[-1] - 1.0) < 1e-12, f"{what}: the run ends at t = 1", f"{t[-1]:.15g}")
    error_end = depth[-1] / exact_end - 1.0
    below(abs(error_end), limit, f"{what}: melt depth {depth[-1]:.6f} at t = 1 against Neumann's "
          f"{exact_end:.6f} (relative error)", ".2e")
    # (a front at one melting temperature crosses the particles a row at a
    # time: the error swings by about 1 % while the melt is < 12 rows deep)
    late = t >= 0.5
    worst = max(abs(d / exact_depth(tt, ti, ks, cl)[0] - 1.0) for tt, d in zip(t[late], depth[late]))
    below(worst, 0.015, f"{what}: melt depth from t = 0.5 on against Neumann's (largest error)")
    exact_t = np.array([stefan.temperature(x, t[-1], lam, TW, TM, ti, 1.0 / cl, ks) for x in dump["x"]])
    below(np.abs(dump["c_T"] - exact_t).max() / (TW - ti), t_limit,
          f"{what}: T of every particle against the exact profile (largest error / (Tw - Ti))")
    f = dump["f_phase"]
    that(np.all((f >= 0.0) & (f <= 1.0)), f"{what}: every liquid fraction in [0, 1]",
         f"{f.min():.3g} .. {f.max():.3g}")
    check_energy(table, what)
    return table


def check_conductivity_jump(args):
    # the exact solution first: its front and temperatures meet the Stefan
    # condition L ds/dt = -k_l dT/dx (melt side) + k_s dT/dx (solid side)
    for ks in (2.0, 0.5):
        s, lam = exact_depth(1.0, -0.5, ks)
        h = 1e-5
        temp = [stefan.temperature(x, 1.0, lam, TW, TM, -0.5, 1.0, ks) for x in (s - 2 * h, s - h, s + h, s + 2 * h)]
        flux_balance = -(temp[1] - temp[0]) / h + ks * (temp[3] - temp[2]) / h
        below(abs(lam - flux_balance), 1e-4, f"ks = {ks}: Neumann's solution meets the Stefan condition "
              "(|L ds/dt - heat into the front|, one-sided differences)")
    # dx = 0.025: the melt 35 to 39 particles deep (measured +0.29 % and
    # -0.58 %); the solid conducting more takes the heat farther: on [0, 6]
    check_stefan(args, -0.5, 1e-2, "solid conducting 2x the melt", n=240, ks=2.0, lx=6.0)
    # (T: the particle next to the front 1.02 % off at this spacing, 0.40 %
    # at half and 0.20 % at twice the resolution)
    check_stefan(args, -0.5, 1e-2, "solid conducting 0.5x the melt", n=160, ks=0.5, t_limit=0.015)


def check_heat_capacity_jump(args):
    # the exact solution first: the Stefan condition L ds/dt = -dT/dx (melt
    # side) + dT/dx (solid side), k = 1 in both, at t = 1
    for cl in (2.0, 0.5):
        s, lam = exact_depth(1.0, -0.5, 1.0, cl)
        h = 1e-5
        temp = [stefan.temperature(x, 1.0, lam, TW, TM, -0.5, 1.0 / cl, 1.0)
                for x in (s - 2 * h, s - h, s + h, s + 2 * h)]
        flux_balance = -(temp[1] - temp[0]) / h + (temp[3] - temp[2]) / h
        below(abs(lam * math.sqrt(1.0 / cl) - flux_balance), 1e-4, f"cl = {cl}: Neumann's solution meets the "
              "Stefan condition (|L ds/dt - heat into the front|, one-sided differences)")
    # dx = 0.025, the melt 35 and 39 particles deep (measured -0.27 % and
    # -0.21 %)
    richer = check_stefan(args, -0.5, 1e-2, "liquid's cv 2x the solid's", n=160, cl=2.0)
    poorer = check_stefan(args, -0.5, 1e-2, "liquid's cv 0.5x the solid's", n=160, cl=0.5)
    # the conduction's timestep is bounded by the smaller cv of the two
    # phases: the solid's (1) for cl = 2, the liquid's (0.5) for cl = 0.5
    ratio = poorer["Dt"][0] / richer["Dt"][0]
    below(abs(ratio - 0.5), 1e-12, f"the timestep at cl = 0.5 over that at cl = 2 ({ratio:.15g}) against 0.5")


def check_converging(args):
    for ti, what in ((0.0, "one-phase"), (-0.5, "two-phase")):
        errors = {}
        for n in (20, 80):
            table, _ = run(args, {"n": n, "ti": ti, "every": 100000})
            errors[n] = abs(table["v_depth"][-1] / exact_depth(table["Time"][-1], ti)[0] - 1.0)
        that(errors[80] <= 0.5 * errors[20], f"{what}: the depth's error falls with resolution",
             f"{errors[20]:.2e} at n = 20, {errors[80]:.2e} at n = 80")


def check_mushy(args):
    # the solid at the solidus, as the pure substance's at its melting point
    table, dump = run(args, {"n": 80, "mushy": 0.1, "ti": -0.05, "every": 20})
    check_energy(table, "mushy zone 0.1")
    exact_end, _ = exact_depth(table["Time"][-1], 0.0)
    below(abs(table["v_depth"][-1] / exact_end - 1.0), 0.02,
          "mushy zone 0.1: the liquid volume per height against the pure substance's front")
    f = dump["f_phase"]
    that(np.any((f > 0.0) & (f < 1.0)), "mushy zone 0.1: some particles mushy at the end",
         f"{int(((f > 0.0) & (f < 1.0)).sum())}")


def check_freezing(args):
    # the liquid at 1 (e = cv T + L), the face held at -1: it freezes
    table, dump = run(args, {"n": 80, "ti": 1.0, "tw": -1.0, "every": 20})
    check_energy(table, "freezing")
    fraction = table["f_phase[1]"]
    that(fraction[0] == 1.0 and np.all(np.diff(fraction) <= 1e-15) and fraction[-1] < 0.9,
         "freezing: the liquid fraction starts at 1 and falls", f"{fraction[0]:.4f} -> {fraction[-1]:.4f}")
    below(max(dump["c_T"].max() - 1.0, -1.0 - dump["c_T"].min()), 1e-12,
          "freezing: every T within [Tw, Ti] (largest excursion)")


def check_mpi(args):
    one, _ = run(args, {"n": 80, "every": 20})
    many, _ = run(args, {"n": 80, "every": 20}, args.np)
    for column in ("v_depth", "f_heat"):
        deviation = np.abs(many[column] - one[column]).max() / np.abs(one[column]).max()
        below(deviation, 1e-12, f"{args.np} ranks against 1: {column} (largest relative deviation)")


def run_mushy(args, variables):
    with tempfile.TemporaryDirectory() as tmp:
        out = run_input(args.lmp, MUSHY, {"plugin": args.plugin, **variables}, tmp, 1, args.mpirun)
    return thermo_tables(out)[-1]


def check_damping(args):
    dt, vx0 = 1.0e-4, 1.0e-3

    def rate(c, f=0.5, rho=1.0):
        return c * (1.0 - f) ** 2 / ((f ** 3 + 1.0e-3) * rho)

    # (at A dt = 2e5 the velocity falls to 1e-9 of vx0 in one step, where the
    # pair's round-off accelerations, about 1e-11, weigh 1e-11 of it)
    for c, limit in ((1000.0, 1e-12), (1.0e9, 1e-9)):
        table = run_mushy(args, {"T": 0.5, "C": c})
        v = table["c_vx"]
        ratios = v[2:] / v[1:-1]
        want = 1.0 / (1.0 + dt * rate(c))
        below(np.abs(ratios[v[2:] > 1e-9 * vx0] / want - 1.0).max(), limit,
              f"C = {c:g} (A dt = {dt * rate(c):.3g}): the velocity falls by 1 / (1 + dt A) per step")
        that(np.all(v >= 0.0) and np.all(np.diff(v) <= 0.0), f"C = {c:g}: the velocity falls monotonically to 0",
             f"last {v[-1]:.3g}")
    g = 0.01
    table = run_mushy(args, {"T": 0.5, "g": g, "steps": 300})
    below(abs(table["c_vx"][-1] / (g / rate(1000.0)) - 1.0), 1e-9,
          "pushed by g: the mushy atoms' velocity reaches g / A (relative difference)")
    table = run_mushy(args, {"T": -0.5, "g": g})
    that(np.all(table["c_vx"] == 0.0) and np.all(table["c_x"] == table["c_x"][0]),
         "solid atoms pushed by g do not move", f"largest |vx| {np.abs(table['c_vx']).max():.3g}")
    table = run_mushy(args, {"T": 2.0, "g": g})
    below(np.abs(table["c_vx"] - (vx0 + g * table["Time"])).max() / vx0, 1e-12,
          "liquid atoms are not damped: vx = vx0 + g t (largest difference / vx0)")


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--check", required=True,
                        choices=["one_phase", "two_phase", "conductivity_jump", "heat_capacity_jump", "converging",
                                 "mushy", "freezing", "mpi", "damping"])
    lammps_arguments(parser)
    args = parser.parse_args()
    if args.check == "one_phase":
        check_stefan(args, 0.0, 5e-3, "one-phase")
    elif args.check == "two_phase":
        check_stefan(args, -0.5, 5e-3, "two-phase")
    elif args.check == "conductivity_jump":
        check_conductivity_jump(args)
    elif args.check == "heat_capacity_jump":
        check_heat_capacity_jump(args)
    elif args.check == "converging":
        check_converging(args)
    elif args.check == "mushy":
        check_mushy(args)
    elif args.check == "freezing":
        check_freezing(args)
    elif args.check == "damping":
        check_damping(args)
    else:
        check_mpi(args)
    finish()


if __name__ == "__main__":
    main()
