"""Tests of fix sph/dt/reset (called by ctest, see dt_reset.cmake).

  conduction  pure conduction: the thermal limit C_t / max_i lambda_i, with
              lambda_i = sum_j m_j K_ij |r dW/dr| / (rho_i rho_j (r^2 + eta^2) cv_i)
              (K_ij the pair's conductance: the diagonal of the explicit
              conduction update) recomputed here from the dumped positions,
              rho, T and the data's cv: two materials of k ratio 27 (case
              uniform), and k(T) of every kind of law (case varying, dt changing
              every step; after step 0 the pair's T is half a step older than
              the dump's, so there the tolerance is 1e-2)
  flow        channel flow (in.dt_reset): the four limits, the active one and
              dt at every dumped step, recomputed here from the dumped v, f,
              mass, rho; and time = sum of the dt's
  restart     run, write_restart, read_restart in a new process, run: time
              continues from where it was and stays the sum of the dt's; dt
              and time match one session that runs twice; a fixed-dt run's
              restart file written during the run ('restart' command, which
              holds the run's start time) resumed with the fix: the time
              goes on from step * dt
  mpi         the dt sequence and the active limits on 1 and --np ranks
  until       'until T': the run stops at the step whose end is T (to
              round-off), every earlier step but the last two takes the
              chosen dt, with N = 1 and N = 5; a run after it (the fix given
              again with a later T) goes on to that T; a run that starts at
              T stops before its first step with a warning, one that starts
              1e-8 before T takes two equal steps; with thermo every 7
              steps the stop step has its thermo row
  time        'time t0' after a set-up run and reset_timestep 0: the next
              run starts at t0 (0 and 1.5) on either release (29Sep2021's
              reset_timestep keeps the time) and its time is the sum of dt

The limits are written out here independently of the C++ code:
  acoustic C_a h / (c_i + |v_i|), force C_f sqrt(h m_i / |f_i|),
  viscous C_v h^2 rho_i / mu, thermal C_t / lambda_i (above),
with h = cutoff / q_max (cubic 2, quintic 3).
"""

import argparse
import math
import os
import re
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
from sphtest import lammps_arguments, mpi_env

BIG = 1.0e299              # the fix reports a limit that applies to no atom as 1e300
DEFAULTS = {"acoustic": 0.1, "force": 0.25, "viscous": 0.125, "thermal": 0.5}
LIMITS = ["acoustic", "force", "viscous", "thermal"]
failures = []


def check(ok, message):
    print(("ok   " if ok else "FAIL ") + message)
    if not ok:
        failures.append(message)


def run_lammps(a, input_file, lmp_vars, np_=1, cwd=None):
    cmd = []
    if np_ > 1:
        cmd = [a.mpirun, "--oversubscribe", "-np", str(np_)]
        if hasattr(os, "geteuid") and os.geteuid() == 0:
            cmd.append("--allow-run-as-root")
    cmd += [a.lmp, "-log", "none", "-in", os.path.join(HERE, input_file), "-var", "plugin", a.plugin]
    for name, value in lmp_vars.items():
        cmd += ["-var", name, str(value)]
    proc = subprocess.run(cmd, cwd=cwd, env=mpi_env(), capture_output=True, text=True)
    output = proc.stdout + proc.stderr
    if proc.returncode != 0 or re.search(r"^ERROR", output, re.M):
        sys.stderr.write(output)
        sys.exit(f"FAIL: {' '.join(cmd)} exited with {proc.returncode}")
    return output


def thermo_runs(output):
    """Every run's thermo rows: dicts of step, time, dt, scalar, v1..v6."""
    runs, rows = [], None
    for line in output.splitlines():
        words = line.split()
        if words[:4] == ["Step", "Time", "Dt", "f_dt"]:
            rows = []
            runs.append(rows)
        elif rows is not None and words and words[0] == "Loop":
            rows = None
        elif rows is not None and len(words) == 10:
            values = [float(w) for w in words]
            row = {"step": int(values[0]), "time": values[1], "dt": values[2], "scalar": values[3]}
            row.update({f"v{k}": values[3 + k] for k in range(1, 7)})
            rows.append(row)
    if not runs or not all(runs):
        sys.exit("FAIL: no thermo output of fix sph/dt/reset found")
    return runs


def read_dump(path):
    """{step: [dict per atom]} of a LAMMPS text dump."""
    snapshots = {}
    with open(path) as f:
        lines = f.read().splitlines()
    i = 0
    while i < len(lines):
        step = int(lines[i + 1])
        natoms = int(lines[i + 3])
        columns = lines[i + 8].split()[2:]
        atoms = [dict(zip(columns, map(float, lines[j].split()))) for j in range(i + 9, i + 9 + natoms)]
        snapshots[step] = atoms
        i += 9 + natoms
    return snapshots


def coefficients(dtargs):
    words = dtargs.split()
    coeff, bounds = dict(DEFAULTS), {"min": 0.0, "max": math.inf, "h": None}
    for key, value in zip(words[::2], words[1::2]):
        if key in coeff:
            coeff[key] = float(value)
        else:
            bounds[key] = float(value)
    return coeff, bounds


def choose(limits, bounds):
    """dt and active limit (1-4, 5 = bound) from the four unclamped limits."""
    dt, active = math.inf, 0
    for k, value in enumerate(limits):
        if value < dt:
            dt, active = value, k + 1
    if dt < bounds["min"]:
        dt, active = bounds["min"], 5
    elif dt > bounds["max"]:
        dt, active = bounds["max"], 5
    return dt, active


def close(a, b, rtol):
    if a >= BIG or b >= BIG:
        return a >= BIG and b >= BIG
    return abs(a - b) <= rtol * abs(b)


def compare_row(row, limits, bounds, rtol, label):
    dt, active = choose(limits, bounds)
    for k, name in enumerate(LIMITS):
        got = row[f"v{k + 3}"]
        want = limits[k]
        dev = 0.0 if (got >= BIG and want >= BIG) else abs(got - want) / abs(want)
        check(close(got, want, rtol),
              f"{label}: {name:8} limit {got:.17g}, recomputed {want:.17g} (rel. dev. {dev:.1e})")
    check(int(row["v2"]) == active, f"{label}: active limit {int(row['v2'])}, recomputed {active}")
    check(close(row["dt"], dt, rtol) and row["dt"] == row["v1"] == row["scalar"],
          f"{label}: dt {row['dt']:.17g} (f_dt {row['scalar']:.17g}, f_dt[1] {row['v1']:.17g}),"
          f" recomputed {dt:.17g}")
    return active


def check_time(rows, label, start=None, rtol=1e-14):
    """time of each row = time of the previous + the dt set at the previous."""
    worst = 0.0
    if start is not None:
        worst = abs(rows[0]["time"] - start) / max(abs(start), 1e-300)
    for prev, row in zip(rows, rows[1:]):
        worst = max(worst, abs(row["time"] - (prev["time"] + prev["dt"])) / row["time"])
    check(worst <= rtol, f"{label}: time = sum of dt over {len(rows)} rows"
          f"{'' if start is None else f' from {start:.17g}'} (largest rel. deviation {worst:.1e})")


# ---------------------------------------------------------------- conduction

def table(points, T):
    if T <= points[0][0]:
        return points[0][1]
    if T >= points[-1][0]:
        return points[-1][1]
    for (t0, p0), (t1, p1) in zip(points, points[1:]):
        if t0 <= T < t1:
            return p0 + (p1 - p0) * (T - t0) / (t1 - t0)
    return points[-1][1]


# conductivity laws of in.dt_conduction, case varying
K_VARYING = {1: lambda T: 1.0 * math.exp(0.2 * T), 2: lambda T: 3.0 + 0.5 * (T - 2.0),
             3: lambda T: table([(0.0, 0.4), (2.0, 0.6), (5.0, 0.9)], T)}


def read_cv(data_file):
    cv, in_atoms = {}, False
    with open(data_file) as f:
        for line in f:
            words = line.split()
            if line.startswith("Atoms"):
                in_atoms = True
            elif in_atoms and len(words) >= 8:
                cv[int(words[0])] = float(words[4])   # id type rho esph cv x y z
            elif in_atoms and words and not words[0][0].isdigit():
                break
    return cv


def relaxation_rates(atoms, box, mass, cv, k, kernel="cubic", cut=0.026, eta=0.1):
    """lambda_i of every atom (harmonic mean), by a direct sum over all pairs."""
    from sphtest import KERNEL_2D
    q_max, sigma, dfdq = KERNEL_2D[kernel]
    h = cut / q_max
    eta2 = (eta * h) ** 2
    rates = []
    for i, ai in enumerate(atoms):
        rate = 0.0
        for j, aj in enumerate(atoms):
            if i == j:
                continue
            d = [ai["x"] - aj["x"], ai["y"] - aj["y"]]
            d = [c - L * round(c / L) for c, L in zip(d, box)]
            r = math.hypot(*d)
            if r >= cut:
                continue
            dwdr = sigma / h ** 3 * dfdq(r / h)
            kij = 4 * k[i] * k[j] / (k[i] + k[j])
            rate -= mass(aj) * kij / (ai["c_rho"] * aj["c_rho"]) * r * dwdr / (r * r + eta2)
        rates.append(rate / cv(ai))
    return rates


def cmd_conduction(a):
    with tempfile.TemporaryDirectory() as tmp:
        dump = os.path.join(tmp, "dump")
        data = os.path.join(HERE, "..", "conduction", "rates.data")
        # with N = 5 the relaxation rates come from the force computations of
        # the steps that choose dt only (the others skip them)
        lmp_vars = {"case": a.case, "out": dump, "data": data, "steps": 10 * a.every, "dump": 5,
                    "every": a.every}
        if a.h:
            lmp_vars["dtargs"] = f"h {a.h}"    # h does not enter the thermal limit
        rows = thermo_runs(run_lammps(a, "in.dt_conduction", lmp_vars, cwd=tmp))[0]
        snapshots = read_dump(dump)
    if a.case == "uniform":
        # the input's numbers: 10 x 6 lattice of spacing 0.01, m = 0.1,
        # cv = 4180, k = 0.6 (type 1) and 16 (type 2)
        box, rtol = (0.10, 0.06), 1e-12
        mass = lambda at: 0.1
        cv = lambda at: 4180.0
        conductivity = lambda at: {1: 0.6, 2: 16.0}[int(at["type"])]
    else:
        cvs = read_cv(data)
        box, rtol = (0.12, 0.10), 1e-12
        mass = lambda at: {1: 0.10, 2: 0.05, 3: 0.30}[int(at["type"])]
        cv = lambda at: cvs[int(at["id"])]
        conductivity = lambda at: K_VARYING[int(at["type"])](at["c_T"])
    bounds = {"min": 0.0, "max": math.inf}
    steps = {row["step"]: row for row in rows}
    for step, atoms in sorted(snapshots.items()):
        rates = relaxation_rates(atoms, box, mass, cv, [conductivity(at) for at in atoms])
        thermal = 0.5 / max(rates)
        compare_row(steps[step], [math.inf, math.inf, math.inf, thermal], bounds,
                    rtol if step == 0 else 1e-2, f"step {step}")
    for row in rows:
        check(int(row["v2"]) == 4 and all(row[f"v{k}"] >= BIG for k in (3, 4, 5)),
              f"step {row['step']}: active limit {int(row['v2'])} (4 = thermal); no eos, no "
              f"viscosity, no force: the other limits do not apply")
    if a.case == "varying":
        dts = [row["dt"] for row in rows if row["step"] % a.every == 0]
        check(len(set(dts)) > 3, f"dt changes during the run ({len(set(dts))} different values)")
        held = all(row["dt"] == prev["dt"] for prev, row in zip(rows, rows[1:]) if row["step"] % a.every)
        check(held, f"dt is chosen every {a.every} steps only")
    check_time(rows, "conduction")
    return report()


# ---------------------------------------------------------------- flow

CASES = {
    # name: (variables of in.dt_reset, expected active limit at step 0)
    "acoustic": ({}, 1),
    "force": ({"drive": 50000, "dtargs": "acoustic 0.25"}, 2),
    "viscous": ({"mu": 20.0}, 3),
    "tait": ({"eos": "tait", "dtargs": "acoustic 0.3 force 0.2"}, 1),
    "peratom_mass": ({"mass": "peratom", "drive": 50000, "dtargs": "acoustic 0.25 force 0.3"}, 2),
    "max": ({"dtargs": "max 0.01"}, 5),
    "min": ({"dtargs": "min 0.1 viscous 0.2"}, 5),
    "every5": ({"every": 5, "dump": 5, "dtargs": "h 1.5"}, 1),
}


def flow_limits(atoms, coeff, h, mu, eos):
    c0, rho0, gamma = 10.0 * 0.80848, 1.0, 7.0
    limits = [math.inf] * 4
    for at in atoms:
        speed = math.sqrt(at["vx"] ** 2 + at["vy"] ** 2 + at["vz"] ** 2)
        force = math.sqrt(at["fx"] ** 2 + at["fy"] ** 2 + at["fz"] ** 2)
        rho = at["c_rho"]
        c = c0 if eos == "linear" else c0 * (rho / rho0) ** (0.5 * (gamma - 1.0))
        candidates = [coeff["acoustic"] * h / (c + speed),
                      coeff["force"] * math.sqrt(h * at["mass"] / force) if force > 0 else math.inf,
                      coeff["viscous"] * h * h * rho / mu,
                      math.inf]     # no conductivity in the flow input
        for k in range(3):
            if coeff[LIMITS[k]] > 0:
                limits[k] = min(limits[k], candidates[k])
    return limits


def flow_h(n, bounds):
    if bounds.get("h"):
        return bounds["h"]
    # dx = W / n and cut = 3 dx are equal-style variables: LAMMPS passes their
    # values on as text with 15 digits
    dx = float("%.15g" % (20.0 / n))
    return float("%.15g" % (3.0 * dx)) / 3.0


def cmd_flow(a):
    lmp_vars, active0 = CASES[a.case]
    lmp_vars = dict({"n": 12, "steps": 20, "dump": 10, "mu": 0.248, "eos": "linear",
                     "dtargs": "min 0", "every": 1}, **lmp_vars)
    coeff, bounds = coefficients(lmp_vars["dtargs"])
    h = flow_h(lmp_vars["n"], bounds)
    with tempfile.TemporaryDirectory() as tmp:
        dump = os.path.join(tmp, "dump")
        rows = thermo_runs(run_lammps(a, "in.dt_reset", dict(lmp_vars, out=dump), cwd=tmp))[-1]
        snapshots = read_dump(dump)
    steps = {row["step"]: row for row in rows}
    for step, atoms in sorted(snapshots.items()):
        limits = flow_limits(atoms, coeff, h, float(lmp_vars["mu"]), lmp_vars["eos"])
        active = compare_row(steps[step], limits, bounds, a.rtol, f"{a.case} step {step}")
        if step == 0:
            check(active == active0, f"{a.case}: active limit at step 0 is {active}, the case "
                  f"is built for {active0}")
    every = int(lmp_vars["every"])
    if every > 1:
        # dt is recomputed at multiples of N only
        same = all(row["dt"] == prev["dt"] for prev, row in zip(rows, rows[1:]) if row["step"] % every)
        changes = sum(row["dt"] != prev["dt"] for prev, row in zip(rows, rows[1:]) if row["step"] % every == 0)
        check(same and changes > 0, f"{a.case}: dt changes only every {every} steps ({changes} changes)")
    dts = [row["dt"] for row in rows]
    if active0 != 5:
        check(len(set(dts)) > 2, f"{a.case}: dt changes during the run ({len(set(dts))} values)")
    check_time(rows, a.case)
    return report()


# ---------------------------------------------------------------- restart

def cmd_restart(a):
    common = {"n": 12, "steps": 15, "dump": 0}
    with tempfile.TemporaryDirectory() as tmp:
        restart = os.path.join(tmp, "restart")
        first = thermo_runs(run_lammps(a, "in.dt_reset", dict(common, split="write", restart=restart),
                                       cwd=tmp))[0]
        second = thermo_runs(run_lammps(a, "in.dt_reset", dict(common, split="read", restart=restart),
                                        cwd=tmp))[0]
        twice = thermo_runs(run_lammps(a, "in.dt_reset", dict(common, split="twice"), cwd=tmp))
    check(second[0]["step"] == first[-1]["step"] and second[0]["step"] > 0,
          f"the restarted run starts at step {second[0]['step']}")
    check_time(first, "before write_restart")
    # LAMMPS 29Sep2021 does not store the elapsed time (without the fix it restarts
    # at 0); 4Feb2025 does: on both the time must go on
    check_time(second, "after read_restart", start=first[-1]["time"])
    dts = [row["dt"] for row in first + second]
    check(len(set(dts)) > 5, f"dt changes over the runs ({len(set(dts))} values)")
    # one session with two runs: the same steps, times and dt's
    worst = max(max(abs(r["time"] - s["time"]) / max(s["time"], 1e-300), abs(r["dt"] - s["dt"]) / s["dt"])
                for r, s in zip(first + second, twice[0] + twice[1]))
    check(len(first + second) == len(twice[0] + twice[1]) and worst <= 1e-12,
          f"restart against one session running twice: largest rel. deviation of time and dt "
          f"{worst:.1e}")
    # a restart file of a fixed-dt run written during it holds the time of the
    # run's start: the fix takes the time up from there (step * 0.001 here)
    with tempfile.TemporaryDirectory() as tmp:
        restart = os.path.join(tmp, "restart")
        run_lammps(a, "in.dt_reset", dict(common, split="fixedwrite", restart=restart), cwd=tmp)
        resumed = thermo_runs(run_lammps(a, "in.dt_reset", dict(common, split="read", restart=restart),
                                         cwd=tmp))[0]
    start = common["steps"] * 0.001
    check(resumed[0]["step"] == common["steps"] and abs(resumed[0]["time"] - start) <= 1e-14,
          f"resumed from a fixed-dt run's restart file: step {resumed[0]['step']} at time "
          f"{resumed[0]['time']!r}, expected {start!r}")
    check_time(resumed, "after a fixed-dt run's restart file", start=start)
    return report()


# ---------------------------------------------------------------- until

def check_until(rows, output, until, label, steps):
    last = rows[-1]
    check(len(rows) - 1 < steps and abs(last["time"] - until) <= 1e-13 * until,
          f"{label}: the run stops after {len(rows) - 1} of {steps} steps at time {last['time']:.17g}, "
          f"until {until:.17g}")
    check(f"reached until {until:g} at step {last['step']}: the run stopped" in output,
          f"{label}: the log names the step the run stops at ({last['step']})")
    # the chosen dt is the smallest limit (thermo prints the limits of the
    # last choice); only the last two steps are shortened
    chosen = [min(row[f"v{k}"] for k in range(3, 7)) for row in rows]
    shortened = [k for k, row in enumerate(rows[:-1]) if row["dt"] < chosen[k] * (1 - 1e-14)]
    check(0 < len(shortened) <= 2 and shortened[-1] == len(rows) - 2,
          f"{label}: steps shortened to land on until: {len(shortened)}, the last ones "
          f"(rows {shortened} of {len(rows)})")
    check_time(rows, label)


def cmd_until(a):
    until, steps = 0.2345, 100
    with tempfile.TemporaryDirectory() as tmp:
        for every in (1, 5):
            output = run_lammps(a, "in.dt_reset", {"n": 12, "dump": 0, "steps": steps, "every": every,
                                                   "dtargs": f"min 0 until {until}"}, cwd=tmp)
            rows = thermo_runs(output)[-1]
            check_until(rows, output, until, f"N = {every}", steps)
            if every == 5:
                fixed = [row["dt"] for row in rows[:-3] if row["step"] % 5 != 0]
                check(len(set(fixed)) < len(rows) // 2, "N = 5: dt chosen every 5 steps")
        # the timer of the stopped run must not stop the next one
        output = run_lammps(a, "in.dt_reset", {"n": 12, "dump": 0, "steps": steps, "split": "again",
                                               "dtargs": f"min 0 until {until}",
                                               "dtargs2": f"min 0 until {2 * until}"}, cwd=tmp)
        first, second = thermo_runs(output)
        check_until(first, output, until, "first run", steps)
        check_until(second, output, 2 * until, "the fix given again with until 2T: the next run", steps)
        check(second[0]["time"] == first[-1]["time"], "the next run starts where the first stopped")
        # thermo every 7 steps: the step the run stops at has its row
        output = run_lammps(a, "in.dt_reset", {"n": 12, "dump": 0, "steps": steps, "thermo": 7,
                                               "dtargs": f"min 0 until {until}"}, cwd=tmp)
        rows = thermo_runs(output)[-1]
        check(abs(rows[-1]["time"] - until) <= 1e-13 * until and rows[-1]["step"] % 7 != 0
              and f"at step {rows[-1]['step']}: the run stopped" in output,
              f"thermo every 7 steps: the last row is the stop's, step {rows[-1]['step']} at time "
              f"{rows[-1]['time']:.17g}")
        # a run that starts less than a step before until: two steps share what is left
        later = until + 1e-8
        output = run_lammps(a, "in.dt_reset", {"n": 12, "dump": 0, "steps": steps, "split": "again",
                                               "dtargs": f"min 0 until {until}",
                                               "dtargs2": f"min 0 until {later!r}"}, cwd=tmp)
        second = thermo_runs(output)[1]
        steps_taken = [b["time"] - a_["time"] for a_, b in zip(second, second[1:])]
        check(len(steps_taken) == 2 and abs(second[-1]["time"] - later) <= 1e-13 * later
              and abs(steps_taken[0] - steps_taken[1]) <= 1e-3 * steps_taken[0],
              f"a run that starts 1e-8 before until: {len(steps_taken)} steps of "
              f"{steps_taken}, ends at {second[-1]['time']:.17g}")
        # a run that starts at until: not one step, and a warning
        output = run_lammps(a, "in.dt_reset", {"n": 12, "dump": 0, "steps": steps, "split": "twice",
                                               "dtargs": f"min 0 until {until}"}, cwd=tmp)
        first, second = thermo_runs(output)
        check(len(second) == 1 and second[0]["step"] == first[-1]["step"]
              and "is already at until 0.2345: the run of 100 steps stops before its first step" in output,
              f"a run that starts at until: {len(second) - 1} steps, and the warning")
    return report()


# ---------------------------------------------------------------- time

def cmd_time(a):
    with tempfile.TemporaryDirectory() as tmp:
        for start in (0.0, 1.5):
            output = run_lammps(a, "in.dt_reset", {"n": 12, "dump": 0, "steps": 20, "split": "reset",
                                                   "dtargs2": f"min 0 time {start}"}, cwd=tmp)
            first, second = thermo_runs(output)
            check(first[-1]["time"] > 0.0 and second[0]["step"] == 0,
                  f"time {start}: the set-up run reached {first[-1]['time']:.6g}, the next starts at step "
                  f"{second[0]['step']}")
            check_time(second, f"time {start}: the run after the set-up", start=start)
    return report()


# ---------------------------------------------------------------- mpi

MPI_CONFIGS = {
    "acoustic": ("in.dt_reset", dict({"n": 12, "ncol": 8, "steps": 30, "dump": 0}, **CASES["acoustic"][0])),
    "viscous": ("in.dt_reset", dict({"n": 12, "ncol": 8, "steps": 30, "dump": 0}, **CASES["viscous"][0])),
    "thermal": ("in.dt_conduction", {"case": "varying", "steps": 30, "dump": 0,
                                     "data": os.path.join(HERE, "..", "conduction", "rates.data")}),
}


def cmd_mpi(a):
    for name, (input_file, lmp_vars) in MPI_CONFIGS.items():
        runs = {}
        for np_ in (1, a.np):
            with tempfile.TemporaryDirectory() as tmp:
                runs[np_] = thermo_runs(run_lammps(a, input_file, lmp_vars, np_, cwd=tmp))[-1]
        one, many = runs[1], runs[a.np]
        worst = max(abs(r["dt"] - s["dt"]) / s["dt"] for r, s in zip(many, one))
        worst_t = max(abs(r["time"] - s["time"]) / max(s["time"], 1e-300) for r, s in zip(many, one))
        same_active = [int(r["v2"]) for r in many] == [int(s["v2"]) for s in one]
        check(len(one) == len(many) and worst <= a.rtol and worst_t <= a.rtol and same_active,
              f"{name}: {a.np} ranks against 1, {len(one)} steps: largest rel. deviation of dt "
              f"{worst:.1e}, of time {worst_t:.1e} (tolerance {a.rtol:.0e}), active limits "
              f"{'identical' if same_active else 'DIFFERENT'}")
        check(len(set(r["dt"] for r in one)) > 5, f"{name}: dt changes during the run")
    return report()


def report():
    if failures:
        print(f"{len(failures)} check(s) failed")
        return 1
    return 0


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    lammps_arguments(p, ranks=False)  # --np is the mpi subcommand's
    sub = p.add_subparsers(dest="cmd", required=True)
    s = sub.add_parser("conduction")
    s.add_argument("--case", choices=["uniform", "varying"], required=True)
    s.add_argument("--h", type=float, help="give the fix an explicit h")
    s.add_argument("--every", type=int, default=1, help="N of the fix")
    s = sub.add_parser("flow")
    s.add_argument("--case", choices=sorted(CASES), required=True)
    s.add_argument("--rtol", type=float, default=1e-12)
    sub.add_parser("restart")
    sub.add_parser("until")
    sub.add_parser("time")
    s = sub.add_parser("mpi")
    s.add_argument("--np", type=int, required=True)
    s.add_argument("--rtol", type=float, default=1e-12)
    a = p.parse_args()
    a.lmp = os.path.abspath(a.lmp)
    a.plugin = os.path.abspath(a.plugin)
    return {"conduction": cmd_conduction, "flow": cmd_flow, "restart": cmd_restart, "until": cmd_until, "time": cmd_time,
            "mpi": cmd_mpi}[a.cmd](a)


if __name__ == "__main__":
    sys.exit(main())
