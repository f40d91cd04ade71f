#!/usr/bin/env python3
"""Checks of fix sph/inlet/temperature, run through LAMMPS (conduction only:
a lattice of particles, periodic along x, at rest or moving at a uniform
velocity, so that the exact outcome is known).

  reservoir  at rest: the inlet fix with 'ghosts held' (Ng et al. 2020) on
             the periodic box gives every particle
             the same temperature history (to 1e-12) as the box cut open at
             the periodic plane with, upstream of the inlet, three columns of
             particles held at T_inlet and, downstream of the outlet, nothing
             (adiabatic); on 1 rank and on --np ranks split along x
  reenter    moving at u (conduction switched off by a negligible
             conductivity): exactly the particles that have passed the
             outlet (image flag 1) have T_inlet, every other keeps its initial
             T, and the fix's reset energy is their sum of m cv (T_inlet - T)
  balance    moving at u with conduction: the change of sum m esph equals the
             fix's energy (resets and plane) to round-off; the heat rate
             through the plane is negative (the inlet is colder)
  walls      the dummies of fix sph/wall/dirichlet next to the inlet take
             their temperature from the inlet side only: hotter fluid at the
             outlet end leaves them unchanged (to 1e-14), while without the
             inlet fix it changes them
  mirror     at rest, T linear along x and T_inlet on the plane: with the
             neighbours across the plane mirrored (the default), the columns
             at the inlet keep their temperature to round-off (the plane
             is where the inlet holds T_inlet); with them held at T_inlet
             they warm (the plane lies upstream); on 1 rank and on --np
             ranks split along x
  restart    the balance scene run in two halves through write_restart and
             read_restart gives the same temperatures and the same energy as
             the two halves run one after the other

Usage: test_inlet.py CHECK --lmp LMP --plugin PLUGIN [--np N --mpirun MPIRUN]
"""
import argparse
import os
import sys
import tempfile

import numpy as np

from lammps_checks import read_dump, run_lammps, thermo_tables

from sphtest import lammps_arguments

SPACING = 0.1
T_INLET = 0.25
# the box: 20 columns along x (x = 0 .. 2), 6 rows along y, periodic in y
BOX = """plugin load {plugin}
units           si
dimension       2
atom_style      sph
boundary        {xboundary} p p
atom_modify     map array
processors      * 1 1
lattice         sq 0.1 origin 0.5 0.5 0.0
region          box block {xlo} 20 0 6 -0.5 0.5
create_box      1 box
create_atoms    1 box
{settings}sph/set         all materials spacing 0.1
variable        Tinit atom 1.0+0.3*sin(2.0*PI*y/0.6)+0.2*x
sph/set         all temperature v_Tinit
timestep        1.0e-3
"""
# what a restarted run defines again: materials, pair, the computes read
SETTINGS = """fix             materials all sph/materials type * conductivity constant {k} cv 2.0 &
                eos linear 10.0 rho0 1.0
pair_style      sph/cleary/heat wendland 0.3
pair_coeff      * *
compute         T all sph/t/atom
compute         Tsum all reduce sum c_T
compute         e all property/atom esph
variable        me atom mass*c_e
compute         energy all reduce sum v_me
"""


def box(a, xboundary, xlo, k):
    return BOX.format(plugin=a.plugin, xboundary=xboundary, xlo=xlo,
                      settings=SETTINGS.format(k=k))


def dump_now(name):
    """Input lines that write T now (LAMMPS 29Sep2021 wants the compute
    current: a run 0 whose thermo invokes it)."""
    return f"""
thermo_style    custom step c_Tsum
run             0 post no
write_dump      all custom {name} id type x y ix c_T modify sort id format float %.17g
"""


def last_table(out, column):
    """The last thermo table of out that has the column."""
    return [t for t in thermo_tables(out) if column in t][-1]


def run_dump(a, work, script, name, np_=1):
    out = run_lammps(a.lmp, script + dump_now(name), work, np_=np_, mpirun=a.mpirun)
    return read_dump(os.path.join(work, name)), out


def by_position(d, keep):
    order = np.lexsort((np.round(d["y"][keep], 9), np.round(d["x"][keep], 9)))
    return d["c_T"][keep][order], d["x"][keep][order]


def check_reservoir(a, work):
    steps = 200
    inlet = box(a, "p", 0, 1.0) + f"""
fix             integrate all sph
fix             inlet all sph/inlet/temperature {T_INLET} ghosts held
run             {steps}
"""
    cut = box(a, "f", -3, 1.0) + f"""
region          upstream block INF 0 INF INF INF INF units box
group           reservoir region upstream
group           channel subtract all reservoir
sph/set         reservoir temperature {T_INLET}
fix             integrate channel sph
run             {steps}
"""
    ref, _ = run_dump(a, work, cut, "cut.dump")
    ref_t, ref_x = by_position(ref, ref["x"] > 0.0)
    ok = True
    for np_ in sorted({1, a.np}):
        got, _ = run_dump(a, work, inlet, f"inlet{np_}.dump", np_)
        got_t, got_x = by_position(got, got["x"] > -1.0)
        same_places = len(got_x) == len(ref_x) and np.abs(got_x - ref_x).max() < 1e-12
        dev = np.abs(got_t - ref_t).max() if same_places else np.inf
        # the first column started at 1.01 on average
        cooled = 1.01 - ref_t[ref_x < SPACING].mean()
        good = same_places and dev < 1e-12 and cooled > 0.1
        ok &= good
        print(f"{'ok' if good else 'FAIL'}: at rest, {steps} steps, {np_} rank(s): inlet against a "
              f"reservoir at T_inlet upstream and nothing downstream: largest difference "
              f"{dev:.1e} (limit 1e-12); the inlet cooled the first column by {cooled:.3f} on average")
    return ok


def check_mirror(a, work):
    # T_inlet on the plane x = 0, rising along x; 2 steps: the adiabatic
    # outlet end (x > 1.7) reaches no further than x = 1.1 (one cutoff a step)
    scene = box(a, "p", 0, 1.0) + f"""
variable        Tlinear atom {T_INLET}+0.2*x
sph/set         all temperature v_Tlinear
fix             integrate all sph
"""
    ok = True
    for ghosts, np_ in [("mirror", 1), ("mirror", a.np), ("held", 1)]:
        script = scene + f"fix inlet all sph/inlet/temperature {T_INLET} ghosts {ghosts}\nrun 2\n"
        d, _ = run_dump(a, work, script, f"{ghosts}{np_}.dump", np_)
        inlet = d["x"] < 0.3
        change = np.abs(d["c_T"][inlet] - (T_INLET + 0.2 * d["x"][inlet])).max()
        good = change < 1e-13 if ghosts == "mirror" else change > 1e-4
        ok &= good
        print(f"{'ok' if good else 'FAIL'}: T linear along x, ghosts {ghosts}, {np_} rank(s): the "
              f"first three columns changed by {change:.1e} in 2 steps (must be "
              f"{'< 1e-13' if ghosts == 'mirror' else '> 1e-4'})")
    return ok


WALLED = """plugin load {plugin}
units           si
dimension       2
atom_style      sph
boundary        p p p
atom_modify     map array
lattice         sq 0.1 origin 0.5 0.5 0.0
region          box block 0 20 -3 9 -0.5 0.5
create_box      2 box
create_atoms    1 box
region          channel block INF INF 0 0.6 INF INF units box
group           fluid region channel
group           wall subtract all fluid
set             group wall type 2
fix             materials all sph/materials type * conductivity constant 1.0 cv 2.0 &
                eos linear 10.0 rho0 1.0
sph/set         all materials spacing 0.1 temperature 1.0
region          outlet_end block 1.7 INF INF INF INF INF units box
group           outlet_end region outlet_end
group           hot_end intersect fluid outlet_end
sph/set         hot_end temperature {t_outlet}
pair_style      sph/cleary/heat wendland 0.3
pair_coeff      * *
neigh_modify    exclude type 2 2
fix             walls wall sph/wall/dirichlet 2.0 surface channel
fix             integrate fluid sph
{inlet}
compute         T all sph/t/atom
compute         Tsum all reduce sum c_T
"""


def check_walls(a, work):
    def dummies(t_outlet, inlet):
        script = WALLED.format(plugin=a.plugin, t_outlet=t_outlet,
                               inlet=f"fix inlet fluid sph/inlet/temperature {T_INLET}" if inlet else "")
        d, _ = run_dump(a, work, script, "walls.dump")
        near = (d["type"] == 2) & (d["x"] < 0.3)
        return d["c_T"][near]

    same = np.abs(dummies(1.0, True) - dummies(5.0, True)).max()
    without = np.abs(dummies(1.0, False) - dummies(5.0, False)).max()
    ok = same < 1e-14 and without > 1e-3
    print(f"{'ok' if ok else 'FAIL'}: dummies within 0.3 of the inlet, fluid at the outlet end at 1 "
          f"or at 5: largest change {same:.1e} with the inlet fix (limit 1e-14), {without:.3f} "
          f"without it (must be > 1e-3)")
    return ok


def check_reenter(a, work):
    # 0.5 m/s for 1.01 s: the last five columns pass the outlet
    script = box(a, "p", 0, 1e-30) + f"""
velocity        all set 0.5 0.0 0.0 units box
fix             integrate all sph
fix             inlet all sph/inlet/temperature {T_INLET}
""" + dump_now("before.dump") + """
thermo_style    custom step f_inlet[2]
thermo_modify   format float %.17g
run             1010
"""
    d, out = run_dump(a, work, script, "after.dump")
    b = read_dump(os.path.join(work, "before.dump"))
    passed = d["ix"] >= 1
    mass, cv = 1.0 * SPACING**2, 2.0
    expected = (mass * cv * (T_INLET - b["c_T"][passed])).sum()
    energy = last_table(out, "f_inlet[2]")["f_inlet[2]"][-1]
    wrong_in = np.abs(d["c_T"][passed] - T_INLET).max()
    wrong_kept = np.abs(d["c_T"][~passed] - b["c_T"][~passed]).max()
    ok = passed.sum() == 5 * 6 and wrong_in == 0.0 and wrong_kept == 0.0 and \
        abs(energy - expected) < 1e-12 * abs(expected)
    print(f"{'ok' if ok else 'FAIL'}: {passed.sum()} particles passed the outlet (expected 30): "
          f"largest |T - T_inlet| {wrong_in:.1e}, largest change of the others {wrong_kept:.1e} "
          f"(both must be 0); reset energy {energy:.12e}, expected {expected:.12e}")
    return ok


BALANCE = """
velocity        all set 0.5 0.0 0.0 units box
fix             integrate all sph
fix             inlet all sph/inlet/temperature {t_inlet}
thermo_style    custom step c_energy f_inlet f_inlet[2] f_inlet[3] f_inlet[4]
thermo_modify   format float %.17g
thermo          50
"""


def check_balance(a, work):
    script = box(a, "p", 0, 1.0) + \
        BALANCE.format(t_inlet=T_INLET) + "run 600\n"
    _, out = run_dump(a, work, script, "balance.dump", a.np)
    t = last_table(out, "f_inlet")
    change = t["c_energy"] - t["c_energy"][0]
    dev = np.abs(change - t["f_inlet"]).max()
    scale = np.abs(t["c_energy"]).max()
    ok = dev < 1e-12 * scale and t["f_inlet[2]"][-1] < 0 and t["f_inlet[3]"][-1] < 0 and \
        (t["f_inlet[4]"][1:] < 0).all()
    print(f"{'ok' if ok else 'FAIL'}: moving lattice, conduction, {a.np} rank(s): energy change "
          f"{change[-1]:.12e}, fix energy {t['f_inlet'][-1]:.12e} (resets "
          f"{t['f_inlet[2]'][-1]:.4e}, plane {t['f_inlet[3]'][-1]:.4e}); largest difference over "
          f"{len(change)} rows {dev:.1e} (limit 1e-12 of {scale:.3e}); heat rate through the plane "
          f"at the end {t['f_inlet[4]'][-1]:.4e} (must be < 0)")
    return ok


def check_restart(a, work):
    scene = box(a, "p", 0, 1.0)
    # fix sph evaluates the rates at a run's setup from the full-step energy,
    # within a run from the half-step one: a run split in two differs from
    # one run by O(dt^2), so the restart is held against the same split
    whole, out1 = run_dump(a, work, scene + BALANCE.format(t_inlet=T_INLET) + "run 300\nrun 300\n",
                           "whole.dump")
    first = scene + BALANCE.format(t_inlet=T_INLET) + "run 300\nwrite_restart half.restart\n"
    run_lammps(a.lmp, first, work)
    second = f"""plugin load {a.plugin}
read_restart    half.restart
{SETTINGS.format(k=1.0)}fix             integrate all sph
fix             inlet all sph/inlet/temperature {T_INLET}
thermo_style    custom step c_energy f_inlet
thermo_modify   format float %.17g
run             300
"""
    halves, out2 = run_dump(a, work, second, "halves.dump")
    dev = np.abs(whole["c_T"] - halves["c_T"]).max()
    e1 = last_table(out1, "f_inlet")["f_inlet"][-1]
    e2 = last_table(out2, "f_inlet")["f_inlet"][-1]
    ok = dev < 1e-13 and abs(e1 - e2) < 1e-12 * abs(e1) and e1 != 0.0
    print(f"{'ok' if ok else 'FAIL'}: 300 + 300 steps against 300 + restart + 300: largest T difference "
          f"{dev:.1e} (limit 1e-13); fix energy {e1:.12e} and {e2:.12e}")
    return ok


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawTextHelpFormatter)
    p.add_argument("check", choices=["reservoir", "reenter", "balance", "walls", "restart", "mirror"])
    lammps_arguments(p)
    a = p.parse_args()
    a.lmp, a.plugin = os.path.abspath(a.lmp), os.path.abspath(a.plugin)
    with tempfile.TemporaryDirectory() as work:
        ok = {"reservoir": check_reservoir, "reenter": check_reenter, "balance": check_balance,
              "walls": check_walls, "restart": check_restart, "mirror": check_mirror}[a.check](a, work)
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
