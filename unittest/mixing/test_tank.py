"""Coarse versions of the heated tanks of examples/mixing-tank-2d and -3d
(Reece et al. 2024, section 3.4), with compute sph/mixing.

  tank2d   the 2-D two-component tank, 16 x 16 fluid particles, to t = 40 s
           (the fluid is at theta_H and at rest by then): no particle lost
           or outside the tank; the entropies and the VF-FTLE measure grow
           without falling back; T and the measures symmetric about the
           centre line; T near theta_H at the end
  tank3d   the 3-D cylinder, 10 across, to t = 1 s, with --components two or
           one, after the input's set-up: every particle's density within
           1 % of rho0, no particle lost, the per-particle measures in the dump for
           every fluid particle and in range, the global ones growing, T
           axisymmetric; in 3-d the flow pair keeps the plain pressure
           gradient by default (with the corrected one, the package's
           default in 2-d, T's quadrant spread was 1.5e-2 with one
           component)
"""

import argparse
import os
import shutil
import tempfile

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.join(HERE, "..", "..")
from lammps_checks import lammps_arguments, read_frames, run_input
from checks import below, finish, that
import mixing_tank


def run(args, example, variables, workdir):
    return run_input(args.lmp, os.path.join(ROOT, "examples", example),
                     {"plugin": args.plugin, **variables}, workdir, args.np, args.mpirun,
                     log="log.lammps")


def check_growth(m, names, least, what, fallback=1e-2):
    # the measures weight each particle's composition by its volume m/rho,
    # which moves with the weakly compressible density (about 1 % at the
    # tanks' Mach number): a sample may fall back by a few 1e-3 (1.3e-3 in
    # 2-D, where a round-off change of the shifts moves the chaotic flow)
    for name in names:
        series = m[name]
        that(series[-1] >= least, f"{what}: {name} grows to {series[-1]:.4f} (at least {least})")
        below(max(0.0, -np.diff(series).min()), fallback, f"{what}: {name} never falls back by more than")


def check_tank2d(args, workdir):
    n, tend = 16, 40.0
    run(args, "mixing-tank-2d/in.tank", {"n": n, "tend": tend, "every": 500, "dumpdt": tend / 2,
                                         "out": "tank.dump", "mixing": "mixing.txt"}, workdir)
    m = mixing_tank.read_mixing(os.path.join(workdir, "mixing.txt"))
    that(np.all(m["fluid_inside"] == n * n), "2-D: every fluid particle stays in the tank",
         f"{int(m['fluid_inside'].min())} of {n * n} at the least")
    check_growth(m, ["S*_A", "S*_B", "VF-FTLE"], 0.05, "2-D")
    below(303.0 - m["T_mean"][-1], 0.5, "2-D: mean T within 0.5 K of theta_H at the end (K)")
    frame = read_frames(os.path.join(workdir, "tank.dump.final"))[-1][1]
    fluid = {name: col[mixing_tank.fluid_of(frame, 2)] for name, col in frame.items()}
    that(len(fluid["id"]) == n * n, "2-D: the dump holds every fluid particle")
    t_asym, _ = mixing_tank.symmetry_2d(fluid, mixing_tank.H / n)
    below(t_asym, 0.02, "2-D: T mirror-symmetric about the centre line (of theta_H - theta_C)")


def check_tank3d(args, workdir):
    n, tend = 10, 1.0
    data = os.path.join(workdir, "tank.data")
    dx = mixing_tank.write_tank_data(n, data)
    out = run(args, "mixing-tank-3d/in.tank3d", {"data": data, "dx": dx, "components": args.components,
                                                 "tend": tend, "every": 100, "dumpdt": tend / 2,
                                                 "out": "tank.dump", "mixing": "mixing.txt",
                                                 "density": "density.txt"}, workdir)
    that("Pair style sph/harmonic/visc: correction none (the default in 3-d" in out,
         f"3-D {args.components}: the flow pair takes the plain gradient, named as 3-d's default")
    # the set-up relaxes the fluid into the gaps its lattice leaves at the
    # curved wall (without it -6 to +10 % at the start)
    rho = np.loadtxt(os.path.join(workdir, "density.txt"), comments="#", ndmin=2)
    that(rho[0, 1] == 0.0 and rho[-1, 1] >= 0.99 * tend, f"3-D {args.components}: the run after the set-up from t = 0",
         f"{rho[0, 1]:.3g} .. {rho[-1, 1]:.4g} s")
    below(np.abs(rho[:, 2:]).max(), 0.01, f"3-D {args.components}: every fluid particle's density within 1 % of "
          f"rho0 every 5 steps (largest departure)")
    m = mixing_tank.read_mixing(os.path.join(workdir, "mixing.txt"))
    frames = read_frames(os.path.join(workdir, "tank.dump")) + read_frames(os.path.join(workdir, "tank.dump.final"))
    n_fluid = int(mixing_tank.fluid_of(frames[0][1], 3).sum())
    that(np.all(m["fluid_inside"] == n_fluid), f"3-D {args.components}: every fluid particle stays in the tank",
         f"{int(m['fluid_inside'].min())} of {n_fluid} at the least")
    # in the first second the fluid's density still rings (no density diffusion)
    check_growth(m, ["S*_A", "S*_B", "VF-FTLE"], 0.005, f"3-D {args.components}")
    last = frames[-1][1]
    fluid = mixing_tank.fluid_of(last, 3)
    that(fluid.sum() == n_fluid, f"3-D {args.components}: the last dump holds every fluid particle")
    for column, lo, hi in (("c_mix[1]", 0, 1), ("c_mix[3]", 0, 1 + 1e-12), ("c_mix[4]", -1e-12, 1 + 1e-12)):
        values = last[column][fluid]
        that(np.all((values >= lo) & (values <= hi)), f"3-D {args.components}: per-particle {column} in [{lo}, {hi}]",
             f"{values.min():.4g} .. {values.max():.4g}")
    that(np.all(last["c_mix[2]"][fluid] > 0), f"3-D {args.components}: every fluid particle's FTLE > 0")
    (t_max, _), _ = mixing_tank.symmetry_3d({k: v[fluid] for k, v in last.items()}, dx)
    below(t_max, 0.01, f"3-D {args.components}: T axisymmetric (largest quadrant spread, of theta_H - theta_C)")


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("check", choices=["tank2d", "tank3d"])
    parser.add_argument("--components", choices=["two", "one"], default="two")
    lammps_arguments(parser)
    args = parser.parse_args()
    workdir = tempfile.mkdtemp(prefix="tank-")
    try:
        {"tank2d": check_tank2d, "tank3d": check_tank3d}[args.check](args, workdir)
    finally:
        shutil.rmtree(workdir, ignore_errors=True)
    finish()


if __name__ == "__main__":
    main()
