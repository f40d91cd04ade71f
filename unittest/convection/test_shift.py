#!/usr/bin/env python3
"""Checks of fix sph/shift, run through LAMMPS.

  lattice   a periodic square lattice moving at a uniform velocity: every
            particle's kernel sum of volumes is the same, so no particle is
            shifted (positions on the lattice to 1e-12 after 100 steps)
  spread    jittered particles given a velocity but held by fix
            sph/stationary, so that only the shift moves them: the spread of
            the kernel sums of volumes falls by at least half in 200 steps
            (with the sign reversed, particles would crowd and it would
            grow), and the walls and a group left out do not move at all
  follow    with 'correct all' linear density and velocity fields follow
            the shifted particles exactly (to 1e-10)
  volume    with 'continuity yes' the group's mean density follows the
            kernel sums: in one step the group's densities change in all as
            much as their kernel sums of mass do, to first order in the
            shift (within 2 %, the difference halving with the step), where
            without it they would not change at all, and all by one factor
            (to 1e-10); with 'correct all' a linear velocity field follows
            exactly. With a linear density too, each density first follows
            its atom (exact for the linear field) and then all scale by one
            factor (to 1e-10), so that their sum changes by the first-order
            change of the kernel sums, recomputed here from the shifts (to
            1e-10 of the change)
  shared    the skillen sums made in the pair loop of sph/harmonic/visc
            (loop shared) give the positions of the fix's own pass (loop
            own) to round-off, with the corrected pressure gradient too;
            with another pressure form it makes them itself (on --np ranks)
  threads   the fix's own pass on --threads threads (package omp; default
            2) gives the positions of one thread to round-off
  linear    with 'correct yes' the temperature of a linear field follows the
            shifted particles exactly (to 1e-10), next to walls too, and the
            fix's energy equals the change of sum m cv T of the group

Every check runs with either form of the shift (--form): skillen
(Reece et al. 2024, eq 38) or delta-plus (Sun et al. 2017; Ng et al. 2020,
eqs 19-20), each with a coefficient that shifts by about as much.

Usage: test_shift.py CHECK --lmp LMP --plugin PLUGIN [--form skillen|delta-plus]
                     [--np N --mpirun MPIRUN]
"""
import argparse
import os
import re
import sys
import tempfile

import numpy as np

from lammps_checks import lammps_arguments, read_dump, run_lammps

BOX = """plugin load {plugin}
units           si
dimension       2
atom_style      sph
boundary        {boundary} p
atom_modify     map array
lattice         sq 0.1 origin 0.5 0.5 0.0
region          box block {lo} {hi} {lo} {hi} -0.5 0.5
create_box      2 box
create_atoms    1 region box
region          inner block 0 1 0 1 INF INF units box
group           fluid region inner
group           wall subtract all fluid
set             group wall type 2
fix             materials all sph/materials type * conductivity constant 1.0 cv 2.0 &
                viscosity constant 0.1 eos linear 10.0 background 10.0 rho0 1.0
sph/set         all materials spacing 0.1 temperature 0.0
pair_style      hybrid/overlay sph/harmonic/visc wendland 0.4 sph/cleary/heat wendland 0.4
pair_coeff      * * sph/harmonic/visc
pair_coeff      * * sph/cleary/heat
neigh_modify    exclude type 2 2
compute         e fluid property/atom esph
compute         esum fluid reduce sum c_e
"""


# the fluid's particles displaced by up to 0.03 (0.3 spacings), reproducibly
JITTER = """variable        jx atom 0.03*sin(37.0*x+11.0*y)
variable        jy atom 0.03*cos(23.0*x-29.0*y)
displace_atoms  fluid move v_jx v_jy 0.0 units box
"""


def wendland_pairs(x, y, radius=0.4):
    """the pair separations dx, dy, r and the Wendland C2 kernel W and
    dW/dr (2d, support radius) of every pair ij, i = j included"""
    dx = x[:, None] - x[None, :]
    dy = y[:, None] - y[None, :]
    r = np.hypot(dx, dy)
    q = r / radius
    h = radius / 2.0
    sigma = 7.0 / (4.0 * np.pi * h * h)
    w = np.where(q < 1.0, (1.0 - q) ** 4 * (1.0 + 4.0 * q), 0.0) * sigma
    dwdr = np.where(q < 1.0, -20.0 * q * (1.0 - q) ** 3, 0.0) * sigma / radius
    return dx, dy, r, w, dwdr


def kernel_sums(x, y, volume):
    """sum_j V_j W_ij of every particle i"""
    w = wendland_pairs(x, y)[3]
    return (w * volume).sum(axis=1)


# the form and its coefficients: D = 2 (5 in 'linear'), or C = 1 (2.5) with
# U the particles' speed
FORMS = {"skillen": ("skillen 2.0", "skillen 5.0"),
         "delta-plus": ("delta-plus 1.0 {speed}", "delta-plus 2.5 {speed}")}


def shift_args(a, speed, strong=False):
    return FORMS[a.form][1 if strong else 0].format(speed=speed)


def check_lattice(a, work):
    script = BOX.format(plugin=a.plugin, boundary="p p", lo=0, hi=10) + f"""
mass            2 0.01
velocity        all set 0.3 0.2 0.0 units box
fix             integrate all sph
fix             shift all sph/shift {shift_args(a, 0.36)}
timestep        1.0e-3
thermo_style    custom step f_shift[2]
run             100
write_dump      all custom lattice.dump id x y modify sort id format float %.17g
"""
    run_lammps(a.lmp, script, work)
    d = read_dump(os.path.join(work, "lattice.dump"))
    # on the lattice moved by v t (t = 0.1), wrapped into the periodic box
    gx = (d["x"] - 0.3 * 0.1 - 0.05) / 0.1
    gy = (d["y"] - 0.2 * 0.1 - 0.05) / 0.1
    off = max(np.abs(gx - np.round(gx)).max(), np.abs(gy - np.round(gy)).max()) * 0.1
    ok = off < 1e-12
    print(f"{'ok' if ok else 'FAIL'}: {a.form}: moving periodic lattice, 100 steps: largest distance from the "
          f"lattice {off:.2e} (limit 1e-12)")
    return ok


def check_spread(a, work):
    script = BOX.format(plugin=a.plugin, boundary="f f", lo=-4, hi=14) + JITTER + f"""
region          corner block 0 0.3 0 0.3 INF INF units box
group           corner region corner
group           moved subtract fluid corner
velocity        all set 1.0 0.5 0.0 units box
write_dump      all custom before.dump id x y modify sort id format float %.17g
fix             hold all sph/stationary
fix             shift moved sph/shift {shift_args(a, 1.12)}
timestep        1.0e-3
thermo_style    custom step f_shift[2] f_shift[3]
run             200
write_dump      all custom after.dump id x y modify sort id format float %.17g
"""
    run_lammps(a.lmp, script, work)
    b = read_dump(os.path.join(work, "before.dump"))
    f = read_dump(os.path.join(work, "after.dump"))
    fluid = (b["x"] > 0) & (b["x"] < 1) & (b["y"] > 0) & (b["y"] < 1)
    corner = fluid & (b["x"] < 0.3) & (b["y"] < 0.3)
    moved = fluid & ~corner
    volume = np.full(len(b["x"]), 0.01)
    c0 = kernel_sums(b["x"], b["y"], volume)
    c1 = kernel_sums(f["x"], f["y"], volume)
    spread0, spread1 = c0[moved].std(), c1[moved].std()
    step = np.hypot(f["x"] - b["x"], f["y"] - b["y"])
    still = np.abs(f["x"] - b["x"]).max(initial=0.0, where=~moved) + \
        np.abs(f["y"] - b["y"]).max(initial=0.0, where=~moved)
    ok = spread1 < 0.5 * spread0 and step[moved].max() > 0.0 and still == 0.0
    print(f"{'ok' if ok else 'FAIL'}: {a.form}: spread of the kernel sums of the shifted particles "
          f"{spread0:.4e} -> {spread1:.4e} (must halve); largest shift {step[moved].max():.3e}; "
          f"largest move of walls and the group left out {still:.1e} (must be 0)")
    return ok


SHARED_LINE = "Fix sph/shift: the sums are made in the pair loop of sph/harmonic/visc"


def check_shared(a, work):
    """The skillen sums made in the flow pair's loop (loop shared, the
    default) against the fix's own pass (loop own), on jittered particles
    that only the shift moves (rho stays put, so the pair's volumes are
    those at the end of the step): the same positions to round-off, on
    --np ranks; with another pressure form the fix makes them itself. With
    --threads the pair loops are the /omp styles' (each thread adds to its
    own copy of the sums), the own pass serial."""
    def run(name, loop, pair_options=""):
        script = BOX.format(plugin=a.plugin, boundary="f f", lo=-4, hi=14) + JITTER + f"""
velocity        all set 1.0 0.5 0.0 units box
write_dump      all custom {name}_before.dump id x y modify sort id format float %.17g
fix             hold all sph/stationary
fix             shift fluid sph/shift {shift_args(a, 1.12)} loop {loop}
timestep        1.0e-3
run             100
write_dump      all custom {name}.dump id x y modify sort id format float %.17g
"""
        if pair_options:
            script = script.replace("sph/harmonic/visc wendland 0.4 ",
                                    f"sph/harmonic/visc wendland 0.4 {pair_options} ")
        if a.threads and loop == "shared":
            script = with_threads(script, a.threads)
        out = run_lammps(a.lmp, script, work, a.np, a.mpirun)
        if a.threads and loop == "shared" and "sph/harmonic/visc/omp" not in out:
            print(f"FAIL: {name}: pair sph/harmonic/visc/omp not in the log")
            return read_dump(os.path.join(work, f"{name}.dump")), False
        d = read_dump(os.path.join(work, f"{name}.dump"))
        return d, SHARED_LINE in out
    own, own_line = run("own", "own")
    shared, shared_line = run("shared", "shared")
    other, other_line = run("other", "shared", "pressure sum")
    # the loop with the corrected pressure gradient makes them too
    corrected, corrected_line = run("corrected", "shared", "correction gradient")
    start = read_dump(os.path.join(work, "own_before.dump"))
    moved = np.hypot(own["x"] - start["x"], own["y"] - start["y"]).max()
    diff = max(np.abs(shared["x"] - own["x"]).max(), np.abs(shared["y"] - own["y"]).max())
    diff_other = max(np.abs(other["x"] - own["x"]).max(), np.abs(other["y"] - own["y"]).max())
    diff_corrected = max(np.abs(corrected["x"] - own["x"]).max(),
                         np.abs(corrected["y"] - own["y"]).max())
    ok = (moved > 1e-3 and diff < 1e-13 and diff_other < 1e-13 and diff_corrected < 1e-13
          and shared_line and not own_line and not other_line and corrected_line)
    threads = f", {a.threads} threads" if a.threads else ""
    print(f"{'ok' if ok else 'FAIL'}: {a.form} on {a.np} rank(s){threads}: largest shift {moved:.2e} in 100 steps; "
          f"positions after them, "
          f"sums from the pair loop against the fix's own pass: {diff:.2e}, with correction "
          f"gradient {diff_corrected:.2e}, with pressure sum "
          f"(own pass taken) {diff_other:.2e} (limit 1e-13); log line: shared {shared_line}, own "
          f"{own_line}, correction gradient {corrected_line}, pressure sum {other_line}")
    return ok


def with_threads(script, threads):
    """the script with package omp and suffix omp before its styles"""
    return script.replace("units           si\n",
                          f"package omp {threads}\nsuffix omp\nunits           si\n", 1)


def check_threads(a, work):
    """The fix's own pass (loop own) on --threads threads (default 2), each
    adding to its own copy of the sums, against one thread: the same
    positions to round-off, with 'correct all' (every sum) on jittered
    particles that only the shift moves."""
    threads = a.threads or 2

    def run(name, script):
        run_lammps(a.lmp, script, work, a.np, a.mpirun)
        return read_dump(os.path.join(work, f"{name}.dump"))

    script = BOX.format(plugin=a.plugin, boundary="f f", lo=-4, hi=14) + JITTER + f"""
velocity        all set 1.0 0.5 0.0 units box
write_dump      all custom {{name}}_before.dump id x y modify sort id format float %.17g
fix             hold all sph/stationary
fix             shift fluid sph/shift {shift_args(a, 1.12)} loop own correct all
timestep        1.0e-3
run             100
write_dump      all custom {{name}}.dump id x y modify sort id format float %.17g
"""
    one = run("one", script.replace("{name}", "one"))
    many = run("many", with_threads(script.replace("{name}", "many"), threads))
    start = read_dump(os.path.join(work, "one_before.dump"))
    moved = np.hypot(one["x"] - start["x"], one["y"] - start["y"]).max()
    diff = max(np.abs(many["x"] - one["x"]).max(), np.abs(many["y"] - one["y"]).max())
    ok = diff < 1e-13 and moved > 1e-3
    print(f"{'ok' if ok else 'FAIL'}: {a.form}, the own pass on {threads} threads against one: "
          f"largest shift {moved:.2e} in 100 steps, positions after them within {diff:.2e} "
          f"(limit 1e-13)")
    return ok


def check_linear(a, work):
    script = BOX.format(plugin=a.plugin, boundary="f f", lo=-4, hi=14) + JITTER + f"""
variable        Tlin atom 0.2+0.7*x-0.4*y
sph/set         all temperature v_Tlin
pair_style      sph/harmonic/visc wendland 0.4
pair_coeff      * *
velocity        all set 1.0 0.5 0.0 units box
# no integrator: only the shift moves particles and changes T
fix             shift fluid sph/shift {shift_args(a, 1.12, True)} correct yes
timestep        2.0e-3
variable        energy equal c_esum*mass[1]
thermo_style    custom step v_energy f_shift
thermo_modify   format float %.17g
run             0
run             50
compute         T fluid sph/t/atom
compute         Tmax fluid reduce max c_T
thermo_style    custom step c_Tmax v_energy f_shift
thermo_modify   format float %.17g
run             0 post no
write_dump      fluid custom linear.dump id x y c_T modify sort id format float %.17g
"""
    out = run_lammps(a.lmp, script, work)
    rows = [line.split() for line in out.splitlines() if re.match(r"^\s+\d+(\s+\S+){2,3}\s*$", line)]
    e_first, e_last = float(rows[0][1]), float(rows[-1][-2])
    tally = float(rows[-1][-1])
    d = read_dump(os.path.join(work, "linear.dump"))
    err = np.abs(d["c_T"] - (0.2 + 0.7 * d["x"] - 0.4 * d["y"])).max()
    energy_err = abs((e_last - e_first) - tally)
    ok = err < 1e-10 and energy_err < 1e-12 * max(1.0, abs(e_first)) and abs(tally) > 1e-9
    print(f"{'ok' if ok else 'FAIL'}: {a.form}: linear T follows the shifted particles: largest error "
          f"{err:.2e} (limit 1e-10); energy change {e_last - e_first:.6e}, tallied {tally:.6e} "
          f"(difference {energy_err:.1e})")
    return ok


def check_follow(a, work):
    script = BOX.format(plugin=a.plugin, boundary="f f", lo=-4, hi=14) + JITTER + f"""
variable        rholin atom 1.0+0.05*x-0.03*y
variable        vxlin atom 1.0+0.2*x-0.1*y
variable        vylin atom 0.5-0.15*x+0.1*y
set             group all sph/rho v_rholin
velocity        all set v_vxlin v_vylin 0.0 units box
# walls at rest with a solid's density: the fluid's gradients must not see them
set             group wall sph/rho 8000.0
velocity        wall set 0.0 0.0 0.0 units box
pair_style      sph/harmonic/visc wendland 0.4
pair_coeff      * *
# no integrator: only the shift moves particles and changes rho and v
fix             shift fluid sph/shift {shift_args(a, 1.12, True)} correct all
timestep        2.0e-3
write_dump      fluid custom start.dump id x y modify sort id format float %.17g
run             50
write_dump      fluid custom follow.dump id x y vx vy modify sort id format float %.17g
compute         rho fluid property/atom rho
compute         rhomax fluid reduce max c_rho
thermo_style    custom step c_rhomax
run             0 post no
write_dump      fluid custom follow_rho.dump id c_rho modify sort id format float %.17g
"""
    run_lammps(a.lmp, script, work, np_=a.np, mpirun=a.mpirun)
    d = read_dump(os.path.join(work, "follow.dump"))
    r = read_dump(os.path.join(work, "follow_rho.dump"))
    x, y = d["x"], d["y"]
    err = max(np.abs(r["c_rho"] - (1.0 + 0.05 * x - 0.03 * y)).max(),
              np.abs(d["vx"] - (1.0 + 0.2 * x - 0.1 * y)).max(),
              np.abs(d["vy"] - (0.5 - 0.15 * x + 0.1 * y)).max())
    b = read_dump(os.path.join(work, "start.dump"))
    moved = np.hypot(x - b["x"], y - b["y"]).max()
    # uncorrected, rho and v would be off by their gradients (0.03 to 0.2) times the shift
    ok = err < 1e-10 and moved > 1e-3
    print(f"{'ok' if ok else 'FAIL'}: {a.form}, {a.np} rank(s): with 'correct all' linear rho and v "
          f"follow the shifted particles: largest error {err:.2e} (limit 1e-10); largest shift {moved:.2e} "
          f"(must be > 1e-3)")
    return ok


def kernel_gradient_sums(x, y, shares):
    """sum_j shares_j grad_i W_ij of every particle i"""
    dx, dy, r, _, dwdr = wendland_pairs(x, y)
    f = np.divide(dwdr, r, out=np.zeros_like(r), where=r > 0.0) * shares[None, :]
    return (f * dx).sum(axis=1), (f * dy).sum(axis=1)


def volume_change(a, work, dt, linear_rho=False):
    """the change in all of the group's densities and of their kernel sums
    of mass in one step; the largest error of linear v; the densities
    before and after (linear_rho: a linear density field in the group)"""
    rho_field = """
variable        rholin atom 1.0+0.05*x-0.03*y
set             group fluid sph/rho v_rholin
""" if linear_rho else ""
    script = BOX.format(plugin=a.plugin, boundary="f f", lo=-4, hi=14) + JITTER + rho_field + f"""
variable        vxlin atom 1.0+0.2*x-0.1*y
variable        vylin atom 0.5-0.15*x+0.1*y
velocity        all set v_vxlin v_vylin 0.0 units box
pair_style      sph/harmonic/visc wendland 0.4
pair_coeff      * *
# no integrator: only the shift moves particles and changes rho and v
fix             shift fluid sph/shift {shift_args(a, 1.12)} correct all continuity yes
timestep        {dt}
compute         rho all property/atom rho
# thermo invokes the compute at each run's end, so that the dumps may use it
compute         rhomax all reduce max c_rho
thermo_style    custom step c_rhomax
run             0 post no
write_dump      all custom start.dump id x y c_rho modify sort id format float %.17g
run             1
write_dump      all custom volume.dump id x y vx vy c_rho modify sort id format float %.17g
"""
    run_lammps(a.lmp, script, work)
    b = read_dump(os.path.join(work, "start.dump"))
    d = read_dump(os.path.join(work, "volume.dump"))
    fluid = (b["x"] > 0) & (b["x"] < 1) & (b["y"] > 0) & (b["y"] < 1)
    # every particle's mass is 0.01 (rho 1, spacing 0.1): the kernel sum of
    # mass is the density the particles' arrangement gives them
    mass = np.full(len(b["x"]), 0.01)
    change_sum = (kernel_sums(d["x"], d["y"], mass) - kernel_sums(b["x"], b["y"], mass))[fluid].sum()
    change_rho = (d["c_rho"] - b["c_rho"])[fluid].sum()
    v_err = max(np.abs(d["vx"] - (1.0 + 0.2 * d["x"] - 0.1 * d["y"]))[fluid].max(),
                np.abs(d["vy"] - (0.5 - 0.15 * d["x"] + 0.1 * d["y"]))[fluid].max())
    return change_sum, change_rho, v_err, b, d, fluid


def check_linear_density(a, work):
    """with a linear density field: it follows the atoms, then one factor"""
    _, change_rho, v_err, b, d, fluid = volume_change(a, work, 1.0e-3, linear_rho=True)
    linear = lambda x, y: 1.0 + 0.05 * x - 0.03 * y
    ratio = (d["c_rho"] / linear(d["x"], d["y"]))[fluid]
    spread = ratio.max() - ratio.min()
    # the first-order change of the kernel sums, as the fix's documentation
    # writes it: sum_i rho_i dr_i . sum_j s_j V_j grad_i W_ij, s_j = 2 in the
    # group, 1 for the walls (which do not move)
    volume = 0.01 / b["c_rho"]
    shares = np.where(fluid, 2.0, 1.0) * volume
    gx, gy = kernel_gradient_sums(b["x"], b["y"], shares)
    drx, dry = d["x"] - b["x"], d["y"] - b["y"]
    want = (b["c_rho"] * (drx * gx + dry * gy))[fluid].sum()
    sum_err = abs(change_rho - want) / abs(want)
    ok = spread < 1e-10 and abs(ratio.mean() - 1.0) > 1e-9 and sum_err < 1e-10 and v_err < 1e-10
    print(f"{'ok' if ok else 'FAIL'}: {a.form}: linear rho: the densities follow their atoms and scale by "
          f"one factor {ratio.mean():.12f} (spread {spread:.2e}, limit 1e-10; uncorrected the spread would be "
          f"the gradient times the shift); their sum changes by {change_rho:.6e}, the kernel sums' first-order "
          f"change {want:.6e} (relative difference {sum_err:.2e}, limit 1e-10)")
    return ok


def check_volume(a, work):
    # the form is first order in the shift: its error in all must halve with dt
    results = []
    for dt in (1.0e-3, 5.0e-4):
        total, rho, v_err, b, d, fluid = volume_change(a, work, dt)
        # the densities scale together: one factor for the whole group
        ratio = (d["c_rho"] / b["c_rho"])[fluid]
        results.append((total, rho, max(v_err, ratio.max() - ratio.min())))
    errors = [abs(rho / total - 1.0) for total, rho, _ in results]
    v_err = max(r[2] for r in results)
    ok = (errors[0] < 0.02 and errors[1] < 0.6 * errors[0] and abs(results[1][0]) > 1e-3
          and v_err < 1e-10)
    for dt, (total, rho, _), e in zip((1.0e-3, 5.0e-4), results, errors):
        print(f"{a.form}: dt {dt:.1e}: the shifted particles' kernel sums of mass change by {total:.4e} in "
              f"all, their densities by {rho:.4e} (relative difference {e:.2e})")
    print(f"{'ok' if ok else 'FAIL'}: {a.form}: the mean density follows the kernel sums to first order "
          f"(difference below 0.02 and halving with dt); one factor for all densities and linear v "
          f"followed to {v_err:.2e} (limit 1e-10)")
    return check_linear_density(a, work) and ok


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawTextHelpFormatter)
    p.add_argument("check", choices=["lattice", "spread", "linear", "follow", "volume", "shared",
                                     "threads"])
    p.add_argument("--form", choices=sorted(FORMS), default="skillen")
    p.add_argument("--threads", type=int, default=0,
                   help="'shared': the /omp pair styles on this many threads")
    lammps_arguments(p)  # --np: MPI ranks ('follow' only)
    a = p.parse_args()
    a.lmp, a.plugin = os.path.abspath(a.lmp), os.path.abspath(a.plugin)
    with tempfile.TemporaryDirectory() as work:
        ok = {"lattice": check_lattice, "spread": check_spread, "linear": check_linear,
              "follow": check_follow, "volume": check_volume, "shared": check_shared,
              "threads": check_threads}[a.check](
            a, work)
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
