#!/usr/bin/env python3
"""Checks of the mirror walls and the heated cavity, run through LAMMPS.

  linear     a linear temperature field in jittered fluid particles is
             reproduced exactly at the ghost points of fix sph/wall/adiabatic
             (straight walls and corners): T_wall = T(ghost) to 1e-10
  conserve   a closed box with adiabatic walls on every side keeps the
             fluid's energy to round-off (conserve yes); without giving the
             wall's intake back (conserve no) it drifts, so the check can fail
  nusselt    compute sph/nusselt on Dirichlet mirror walls left (T = 1) and
             right (T = 0) of jittered fluid holding T = 1 - x: the gradient
             estimate is 1 to 1e-10 on each first-layer atom of both walls
             and 0 on every other wall atom; the heat estimate is within 5 %
             of 1, positive on both walls (dT = 1 hot, -1 cold), and its
             per-atom values times the spacing add up to the wall mean
  cavity     the flagship cavity (in.cavity) at --ra, --n x --n particles, to
             --tend: the mean Nu of both walls (from their heat, averaged
             over the last third of the run) within --tolerance (relative)
             of de Vahl Davis (1983), and the flow upward at the hot wall
  ranks      the cavity with buoyancy and shifting, 12 x 12, to t = 0.03, on
             1 and --np ranks: the Nusselt numbers of compute sph/nusselt
             (heat and gradient, both walls) and the shift's energy agree
             to 1e-10
  conduction the cavity of examples/convection-cavity without buoyancy (3-D
             with a periodic depth of --nz layers when given): the
             mean Nusselt number of both walls is 1 within --tolerance, and
             the zero-order walls (Shepard dummies, k = 0 top and bottom) are
             further off than that
  defaults   the flagship in.cavity (the package's defaults) against
             in.cavity-options (every setting given), 12 x 12, to t = 0.01:
             the final dumps agree to 1e-9 and the log names the default;
             in.cavity has at most 40 lines besides comments and blanks

Usage: test_walls.py CHECK --lmp LMP --plugin PLUGIN [--tolerance T]
"""
import argparse
import os
import re
import sys
import tempfile

import numpy as np

from cavity_scenes import BOX, NUSSELT_WALLS
from lammps_checks import (DE_VAHL_DAVIS, final_nusselt, lammps_arguments, late_rows,
                           longest_thermo_table, read_dump, run_input, run_lammps)

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))


def check_linear(a, work):
    script = BOX.format(plugin=a.plugin) + """
variable        Tlin atom 0.2+0.7*x-0.4*y
sph/set         fluid temperature v_Tlin
fix             adiabatic wall sph/wall/adiabatic surface cavity
compute         T all sph/t/atom
# LAMMPS 29Sep2021 dumps a per-atom compute only on a step that used it
compute         Tmax all reduce max c_T
thermo_style    custom step c_Tmax
run             0
write_dump      wall custom walls.dump id x y c_T modify sort id format float %.17g
"""
    run_lammps(a.lmp, script, work)
    d = read_dump(os.path.join(work, "walls.dump"))
    x, y, t = d["x"], d["y"], d["c_T"]
    # mirror through the nearest point of the unit square (the vertex at corners)
    gx = 2.0 * np.clip(x, 0.0, 1.0) - x
    gy = 2.0 * np.clip(y, 0.0, 1.0) - y
    reach = np.hypot(x - np.clip(x, 0, 1), y - np.clip(y, 0, 1)) < 0.3
    want = 0.2 + 0.7 * gx - 0.4 * gy
    corner = reach & (np.abs(gx - x) > 0) & (np.abs(gy - y) > 0)
    err_straight = np.abs(t - want)[reach & ~corner].max()
    err_corner = np.abs(t - want)[corner].max()
    ok = err_straight < 1e-10 and err_corner < 1e-10 and corner.sum() > 0
    print(f"{'ok' if ok else 'FAIL'}: {reach.sum()} wall particles within reach ({corner.sum()} at "
          f"corners): largest |T_wall - T(ghost)| {err_straight:.2e} (straight), "
          f"{err_corner:.2e} (corners), tolerance 1e-10")
    return ok


def check_nusselt(a, work):
    script = BOX.format(plugin=a.plugin) + NUSSELT_WALLS + """# LAMMPS 29Sep2021 dumps a per-atom compute only on a step that used it
compute         hot_local hot reduce sum c_nu_hot[1]
compute         cold_local cold reduce sum c_nu_cold[1]
thermo_style    custom step c_nu_hot[*] c_nu_cold[*]
thermo_modify   format float %.17g
run             0
thermo_style    custom step c_hot_local c_cold_local
run             0 post no
write_dump      held custom held.dump id x y c_nu_hot[1] c_nu_hot[2] c_nu_cold[1] c_nu_cold[2] &
                modify sort id format float %.17g
"""
    out = run_lammps(a.lmp, script, work)
    row = [line.split() for line in out.splitlines()
           if re.match(r"^\s+0\s+\S+\s+\S+\s+\S+\s+\S+\s*$", line)][0]
    hot_heat, hot_grad, cold_heat, cold_grad = (float(w) for w in row[1:])
    d = read_dump(os.path.join(work, "held.dump"))
    ok = True
    for side, heat, grad, is_side in (("hot", hot_heat, hot_grad, d["x"] < 0),
                                      ("cold", cold_heat, cold_grad, d["x"] > 1)):
        local_heat, local_grad = d[f"c_nu_{side}[1]"][is_side], d[f"c_nu_{side}[2]"][is_side]
        first = np.abs(np.abs(d["x"][is_side] - 0.5) - 0.55) < 1e-9
        first &= (d["y"][is_side] > 0) & (d["y"][is_side] < 1)
        grad_err = max(abs(grad - 1.0), np.abs(local_grad[first] - 1.0).max())
        others = np.abs(local_grad[~first]).max()
        summed = local_heat.sum() * 0.1
        good = (first.sum() == 10 and grad_err < 1e-10 and others == 0.0 and
                abs(heat - 1.0) < 0.05 and abs(summed - heat) < 1e-12 * abs(heat))
        ok &= good
        print(f"{'ok' if good else 'FAIL'}: {side} wall: Nu from the gradient {grad:.15f} (largest "
              f"first-layer error {grad_err:.1e} over {first.sum()} atoms, largest elsewhere "
              f"{others:.1e}); from the heat {heat:.6f}, per-atom sum {summed:.6f}")
    return ok


def fluid_energy_drift(a, work, conserve):
    script = BOX.format(plugin=a.plugin) + f"""
variable        Tinit atom 1.0+x*y*y+0.5*sin(4.0*x)
sph/set         fluid temperature v_Tinit
fix             adiabatic wall sph/wall/adiabatic surface cavity conserve {conserve}
fix             integrate fluid sph/stationary
compute         e fluid property/atom esph
compute         esum fluid reduce sum c_e
variable        energy equal c_esum*mass[1]
timestep        2.0e-4
thermo_style    custom step v_energy f_adiabatic[1]
thermo_modify   format float %.17g
thermo          100
run             500
"""
    out = run_lammps(a.lmp, script, work)
    rows = [line.split() for line in out.splitlines() if re.match(r"^\s+\d+\s+\S+\s+\S+\s*$", line)]
    energy = np.array([float(r[1]) for r in rows])
    return np.abs(energy - energy[0]).max() / abs(energy[0]), energy


def check_conserve(a, work):
    drift_yes, e_yes = fluid_energy_drift(a, work, "yes")
    drift_no, e_no = fluid_energy_drift(a, work, "no")
    ok = drift_yes < 1e-13 and drift_no > 1e-9
    print(f"{'ok' if ok else 'FAIL'}: fluid energy over 500 steps: relative drift {drift_yes:.2e} "
          f"with conserve yes (limit 1e-13), {drift_no:.2e} with conserve no (must exceed 1e-9)")
    return ok


def run_cavity(a, work, np_=1, lean=False, **variables):
    """examples/convection-cavity/in.cavity-options (the scene with every
    setting a variable), or with lean the flagship in.cavity (the package's
    defaults), with these -var values on np_ ranks; its screen output (the
    check stops if the run fails)."""
    name = "in.cavity" if lean else "in.cavity-options"
    return run_input(a.lmp, os.path.join(ROOT, "examples/convection-cavity", name),
                     dict(plugin=a.plugin, **variables), work, np_, a.mpirun)


def cavity_nu(a, work, thermal, n):
    out = run_cavity(a, work, ra=0, n=n, tend=a.tend if a.nz else 0.6, thermal=thermal, nz=a.nz,
                     out="cavity.dump")
    return final_nusselt(out, gradient=(thermal == "mirror"))["heat"]


def check_cavity(a, work):
    table = longest_thermo_table(run_cavity(a, work, lean=True, ra=a.ra, n=a.n, tend=a.tend,
                                            out="cavity.dump"))
    late = late_rows(table)
    hot, cold = table["c_nu_hot[1]"][late].mean(), table["c_nu_cold[1]"][late].mean()
    ref = DE_VAHL_DAVIS[a.ra][0]
    err = 0.5 * (hot + cold) / ref - 1.0
    d = read_dump(os.path.join(work, "cavity.dump"))
    rising = d["vy"][d["x"] < 0.15].mean()
    ok = abs(err) < a.tolerance and rising > 0.0
    print(f"{'ok' if ok else 'FAIL'}: Ra {a.ra:g}, {a.n} x {a.n}: mean Nu hot {hot:.4f}, cold "
          f"{cold:.4f} over {late.sum()} rows from t = {2.0 / 3.0 * a.tend:g}; de Vahl Davis {ref}: "
          f"error {100 * err:+.2f} % (limit {100 * a.tolerance:g} %); mean vy near the hot wall "
          f"{rising:.3f} (must be > 0)")
    return ok


def cavity_rows(a, work, np_):
    out = run_cavity(a, work, np_, ra="1e4", n=12, tend=0.03, every=100, shift=2, correct="yes",
                     digits=16, out=f"cavity{np_}.dump")
    table = longest_thermo_table(out)
    return {k: v[:4] for k, v in table.items() if k.startswith("c_nu_")}


def check_ranks(a, work):
    one, more = cavity_rows(a, work, 1), cavity_rows(a, work, a.np)
    ok = True
    for name in sorted(one):
        dev = np.abs(one[name] - more[name]).max() / np.abs(one[name]).max()
        good = dev < 1e-10 and len(one[name]) >= 2
        ok &= good
        print(f"{'ok' if good else 'FAIL'}: {name} over {len(one[name])} thermo rows, 1 and "
              f"{a.np} ranks: largest relative difference {dev:.1e} (limit 1e-10)")
    return ok and len(one) == 4


def check_conduction(a, work):
    hot, cold = cavity_nu(a, work, "mirror", a.n)
    ok = abs(hot - 1.0) < a.tolerance and abs(cold - 1.0) < a.tolerance
    shape = f"{a.n} x {a.n}" + (f" x {a.nz} (3-D, periodic depth)" if a.nz else "")
    print(f"{'ok' if ok else 'FAIL'}: conduction, {shape}, mirror walls: Nu hot {hot:.6f}, "
          f"cold {cold:.6f} (|Nu - 1| < {a.tolerance})")
    hot0, cold0 = cavity_nu(a, work, "zero", a.n)
    worse = abs(hot0 - 1.0) > a.tolerance
    print(f"{'ok' if worse else 'FAIL'}: the zero-order walls are further off: Nu hot {hot0:.6f}, "
          f"cold {cold0:.6f}")
    return ok and worse


def check_defaults(a, work):
    """The flagship in.cavity (the package's defaults for a buoyancy-driven
    flow where it names no setting) and in.cavity-options (every setting
    given, at its validated value) are the same run: their final dumps
    agree to round-off, and the log names the conduction's default."""
    lean_out = run_cavity(a, work, lean=True, ra="1e4", n=12, tend=0.01)
    lean = read_dump(os.path.join(work, "cavity.dump"))
    run_cavity(a, work, ra="1e4", n=12, tend=0.01, out="options.dump")
    given = read_dump(os.path.join(work, "options.dump"))
    named = "correction consistent (the default with shifting" in lean_out
    same_atoms = np.array_equal(lean["id"], given["id"])
    worst = max(np.abs(lean[k] - given[k]).max() / np.abs(given[k]).max()
                for k in ("x", "y", "vx", "vy", "c_T")) if same_atoms else np.inf
    moving = np.abs(given["vy"]).max() > 1.0
    # the flagship sets only its physics: at most 40 lines besides comments and blank lines
    with open(os.path.join(ROOT, "examples/convection-cavity/in.cavity")) as f:
        lines = [line for line in f if line.strip() and not line.lstrip().startswith("#")]
    print(f"{'ok' if len(lines) <= 40 else 'FAIL'}: in.cavity has {len(lines)} lines besides "
          "comments and blank lines (at most 40)")
    ok = named and same_atoms and worst < 1e-9 and moving and len(lines) <= 40
    print(f"{'ok' if ok else 'FAIL'}: in.cavity (defaults) against in.cavity-options (settings given): "
          f"largest difference {worst:.2e} of the largest value (limit 1e-9), largest vy "
          f"{np.abs(given['vy']).max():.3f} (must exceed 1); the log names the conduction's default: {named}")
    return ok


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawTextHelpFormatter)
    p.add_argument("check", choices=["linear", "conserve", "nusselt", "conduction", "cavity", "ranks",
                                      "defaults"])
    lammps_arguments(p)
    p.set_defaults(np=2)  # 'ranks' compares 1 rank against --np, 2 unless given
    p.add_argument("--n", type=int, default=20)
    p.add_argument("--tolerance", type=float, default=0.002)
    p.add_argument("--ra", type=float, default=1e4)
    p.add_argument("--tend", type=float, default=0.3)
    p.add_argument("--nz", type=int, default=0, help="3-D with this many layers of periodic depth")
    a = p.parse_args()
    a.lmp, a.plugin = os.path.abspath(a.lmp), os.path.abspath(a.plugin)
    with tempfile.TemporaryDirectory() as work:
        ok = {"linear": check_linear, "conserve": check_conserve, "nusselt": check_nusselt,
              "cavity": check_cavity, "ranks": check_ranks, "defaults": check_defaults,
              "conduction": check_conduction}[a.check](a, work)
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
