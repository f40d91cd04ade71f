"""Stability maps of USER-SPHTHERMAL's explicit time integration: the largest
stable timestep, found by bisection, as a multiple of each theoretical limit,
and whether the defaults of fix sph/dt/reset are stable.

Conduction (pair sph/cleary/heat, fix sph/stationary, cubic spline, h = 1.3 dx,
2-D periodic square of two materials side by side, a 100 K temperature jump
plus +-1 K of seeded noise): for k2/k1, (rho cv)2/(rho cv)1, lattice disorder
and the mean of the conductivities, the largest multiple M of the fix's
thermal limit 1/lambda_max (fix sph/dt/reset ... thermal M) for which over
2000 steps
  * monotone: T stays within its initial range (to 1e-6 of the range), and
  * bounded:  T stays within the initial range widened by the range on each
              side, and no LAMMPS error (non-finite values stop the run),
the same dt as a multiple of Cleary's h^2 rho cv / k (minimum over the
particles), and direct runs with the fix's default (thermal 0.5) and with
Cleary's dt = 0.1 h^2 rho cv / k.

Flow (pair sph/harmonic/visc, fix sph, quintic spline, h = dx, walls of fix
sph/wall/adami; largest stable fixed dt as a multiple of the acoustic limit
h / c0, and a run with the default fix sph/dt/reset 1):
  * Poiseuille channel (examples/flow-poiseuille, 20 across, 4 m long,
    c0 = 10 u_max, background 0.01 rho0 c0^2) at four Reynolds numbers (the
    viscosity varies), and the example's Re = 65.2 at 40 across, to
    t = 300 s; unstable if |v| > 1.5 u_max or |v_y| > 0.1 u_max, or on a
    LAMMPS error;
  * a water column at rest in a tank (examples/flow-hydrostatic, 10 x 20,
    c0 = 10 sqrt(g H), Fourtakas's density diffusion), to t = 1.5 s;
  * two fluids layered in a column periodic in x (heavy below, density ratio
    1, 10, 1000, same kinematic viscosity; the same c0, or the light fluid's
    c0 giving it the heavy fluid's rho0 c0^2, *matched*), to t = 1.5 s; and
    with the default fix at light fluids of several stiffnesses (*stiffness*);
    columns: unstable if the largest fluid speed exceeds 10 % of sqrt(g H),
    or on a LAMMPS error;
  * two fluids in layered Couette flow (examples/flow-two-fluid-couette,
    no gravity, heavy below, density ratio 1, 10, 1000, with the default
    density diffusion delta 0.1 and without), to t = 300 s; unstable as the
    Poiseuille channel (with the wall speed for u_max).

Bisection is geometric, to a bracket [stable, unstable] of ratio 1.05 (1.25
with --quick). Every LAMMPS run is serial, one at a time; a run that fails
counts as unstable. Inputs and the screen output of the last run of each
case are kept in bench/stability/out/ (git-ignored), with results.json (all
results; --from-json writes the tables and the plot again without runs).
Writes results.md and stability_map.png next to this script (or in --out).
About 5 minutes on one core (--quick: about 1 minute).

  tools/sphpython bench/stability/run_stability.py [--quick] [--only conduction|poiseuille|column|couette|stiffness]
"""

import argparse
import datetime
import itertools
import json
import math
import os
import platform
import re
import subprocess
import sys
import time

import numpy as np

here = os.path.dirname(os.path.abspath(__file__))
root = os.path.normpath(os.path.join(here, "..", ".."))

# ---------------------------------------------------------------- settings

# conduction: n x n particles, spacing dx (m), cubic spline with h = hdx dx,
# material 1: rho, cv1, k1 at T1; material 2 (right half): k1 * k_ratio,
# rho cv1 * rhocv_ratio (through cv; with m = rho dx^2 the update depends
# on rho cv only), at T1 + jump; noise: +- noise K, uniform, seeded
CONDUCTION = dict(n=24, dx=0.01, hdx=1.3, rho=1000.0, cv1=1.0, k1=1.0, T1=300.0, jump=100.0,
                  noise=1.0, steps=2000, seed_jitter=4321, seed_noise=8765)
K_RATIOS = [1.0, 1.0e2, 1.0e4]
RHOCV_RATIOS = [1.0, 1.0e3]
JITTERS = [0.0, 0.1, 0.3]          # random displacement, fraction of dx (uniform in +-)
MEANS = ["harmonic", "arithmetic"]

# Poiseuille: examples/flow-poiseuille (W = 20 m, rho0 = 1, u_max = 0.80848 m/s,
# c0 = 10 u_max, background 0.01 rho0 c0^2, delta 0.1, eta 0.01 h, periodic
# length 4 m)
POISEUILLE = dict(W=20.0, length=4.0, rho0=1.0, umax=0.80848, cfac=10.0, pb=0.01, delta=0.1,
                  eta=0.01, t_end=300.0, vmax_factor=1.5, vy_factor=0.1)
# (Reynolds number u_max W rho / mu, particles across); the example has Re =
# 65.2 (mu = 0.248) at 40 across
POISEUILLE_CASES = [(0.652, 20), (6.52, 20), (65.2, 20), (652.0, 20), (65.2, 40)]

# columns under gravity: H = 1 m, g = 9.81, heavy fluid rho0 = 1000,
# mu = 1e-3; c0 = 10 sqrt(g H) for the heavy fluid, and for the light one
# unless matched; Fourtakas's diffusion
COLUMN = dict(H=1.0, g=9.81, rho_heavy=1000.0, mu_heavy=1.0e-3, cfac=10.0, delta=0.1, eta=0.01,
              t_end=1.5, speed_limit=0.10)
# name: (columns nx, rows ny, side walls?, rho_heavy / rho_light, delta[, light c0]);
# light c0: True for sqrt(ratio) times the heavy fluid's c0, the same rho0
# c0^2 (what pair sph/harmonic/visc asks for under a body force), or the factor
# itself
COLUMN_CASES = {
    "tank, one fluid": (10, 20, True, 1.0, 0.1),
    "layers, ratio 1": (10, 20, False, 1.0, 0.1),
    "layers, ratio 2": (10, 20, False, 2.0, 0.1),
    "layers, ratio 10": (10, 20, False, 10.0, 0.1),
    "layers, ratio 1000": (10, 20, False, 1000.0, 0.1),
    "layers, ratio 10, delta 0": (10, 20, False, 10.0, 0.0),
    "layers, ratio 2, matched": (10, 20, False, 2.0, 0.1, True),
    "layers, ratio 10, matched": (10, 20, False, 10.0, 0.1, True),
    "layers, ratio 1000, matched": (10, 20, False, 1000.0, 0.1, True),
}

# two fluids in layered Couette flow (examples/flow-two-fluid-couette, no
# gravity): lower fluid rho0 = 1, mu = 0.248, upper fluid rho0 = 1 / ratio
# with the same kinematic viscosity, the upper wall at V0 = 0.80848 m/s;
# c0 = 10 V0 and background 0.01 rho0 c0^2 of the upper (lighter) fluid in
# both fluids (the lower fluid's 0.01 rho0 c0^2 is 10 times the upper's
# rho0 c0^2 at ratio 1000, which pair sph/harmonic/visc warns of: case
# "ratio 1000, heavy background")
COUETTE = dict(n=20, ncol=4, W=20.0, rho0=1.0, mu=0.248, V0=0.80848, cfac=10.0, pb=0.01, eta=0.01,
               t_end=300.0, vmax_factor=1.5, vy_factor=0.1)
# name: (rho_lower / rho_upper, delta[, background from the lower fluid])
COUETTE_CASES = {
    "Couette, ratio 1": (1.0, 0.1),
    "Couette, ratio 2": (2.0, 0.1),
    "Couette, ratio 10": (10.0, 0.1),
    "Couette, ratio 1000": (1000.0, 0.1),
    "Couette, ratio 1, delta 0": (1.0, 0.0),
    "Couette, ratio 10, delta 0": (10.0, 0.0),
    "Couette, ratio 1000, delta 0": (1000.0, 0.0),
    "Couette, ratio 1000, heavy background": (1000.0, 0.1, True),
}

DEFAULTS = dict(acoustic=0.1, force=0.25, viscous=0.125, thermal=0.5)


def conduction_cases(quick):
    """The CASES table of the conduction map: every combination."""
    ks = [1.0, 1.0e4] if quick else K_RATIOS
    jits = [0.0, 0.3] if quick else JITTERS
    cases = []
    for mean, kr, cr, jit in itertools.product(MEANS, ks, RHOCV_RATIOS, jits):
        cases.append(dict(name=f"{mean}_k{kr:g}_rhocv{cr:g}_jitter{jit:g}", mean=mean, k_ratio=kr,
                          rhocv_ratio=cr, jitter=jit))
    return cases


# ---------------------------------------------------------------- running LAMMPS

def case_dir(args, kind, case):
    """Where the runs of a flow case work (its input, data and screen.last)."""
    return os.path.join(args.work, kind, re.sub(r"[^A-Za-z0-9]+", "_", case).strip("_"))


class Runner:
    """Writes an input, runs LAMMPS serially, returns (ok, screen output)."""

    def __init__(self, args):
        self.args = args
        self.nruns = 0
        self.seconds = 0.0

    def run(self, case_dir, text, files=None):
        os.makedirs(case_dir, exist_ok=True)
        for name, content in (files or {}).items():
            with open(os.path.join(case_dir, name), "w") as f:
                f.write(content)
        path = os.path.join(case_dir, "in.run")
        with open(path, "w") as f:
            f.write(text)
        env = dict(os.environ, OMP_NUM_THREADS="1")
        start = time.time()
        try:
            proc = subprocess.run([self.args.lmp, "-in", "in.run", "-log", "none", "-echo", "none"],
                                  cwd=case_dir, capture_output=True, text=True, env=env,
                                  timeout=self.args.timeout)
            out, rc = proc.stdout + proc.stderr, proc.returncode
        except subprocess.TimeoutExpired as e:
            out = (e.stdout or b"").decode(errors="replace") if isinstance(e.stdout, bytes) else (e.stdout or "")
            out, rc = out + "\nTIMEOUT\n", -1
        self.seconds += time.time() - start
        self.nruns += 1
        with open(os.path.join(case_dir, "screen.last"), "w") as f:
            f.write(out)
        ok = rc == 0 and not re.search(r"^ERROR", out, re.M) and "TIMEOUT" not in out
        return ok, out


def thermo_rows(out):
    """Rows of every thermo block (thermo_modify format float %.17g) as dicts of floats."""
    rows, header = [], None
    for line in out.splitlines():
        words = line.split()
        if words and words[0] == "Step":
            header = words
            continue
        if header is None:
            continue
        if line.startswith("Loop time") or len(words) != len(header):
            header = None if line.startswith("Loop time") else header
            continue
        try:
            values = [float(w) for w in words]
        except ValueError:
            continue
        rows.append(dict(zip(header, values)))
    return rows


def halted(out, fix_id):
    return re.search(rf"Fix halt condition for fix-id {fix_id} met", out) is not None


def bisect(stable, start, lo_min, hi_max, tol):
    """Largest stable multiple: (lo, hi), stable(lo), not stable(hi), hi / lo <= 1 + tol.
    lo is None when even lo_min is unstable, hi is None when hi_max is stable."""
    lo = hi = None
    m = start
    if stable(m):
        lo = m
        while hi is None:
            m = 2.0 * lo
            if m > hi_max:
                return lo, None
            if stable(m):
                lo = m
            else:
                hi = m
    else:
        hi = m
        while lo is None:
            m = 0.5 * hi
            if m < lo_min:
                return None, hi
            if stable(m):
                lo = m
            else:
                hi = m
    while hi / lo > 1.0 + tol:
        m = math.sqrt(lo * hi)
        if stable(m):
            lo = m
        else:
            hi = m
    return lo, hi


class Cached:
    """stable(M) with the runs remembered (one LAMMPS run per M)."""

    def __init__(self, evaluate):
        self.evaluate = evaluate
        self.results = {}

    def __call__(self, m):
        key = float(f"{m:.12g}")
        if key not in self.results:
            self.results[key] = self.evaluate(key)
        return self.results[key]


# ---------------------------------------------------------------- conduction

CONDUCTION_INPUT = """# conduction stability case {name}, thermal {thermal}
plugin load {plugin}
units           si
dimension       2
atom_style      sph
atom_modify     map array
boundary        p p p
lattice         sq {dx} origin 0.5 0.5 0.0
region          box block 0 {n} 0 {n} -0.5 0.5
create_box      2 box
create_atoms    1 box
region          right block {half} INF INF INF INF INF
group           right region right
set             group right type 2
{displace}
mass            1 {m1}
mass            2 {m2}
set             group all sph/rho {rho}
set             group all sph/cv {cv1}
set             type 2 sph/cv {cv2}
variable        T0 atom {T1}+{jump}*(type-1)+{noise}*random(-1.0,1.0,{seed_noise})
variable        e0 atom ({cv1}+{dcv}*(type-1))*v_T0
set             group all sph/e v_e0
fix             materials all sph/materials type 1 conductivity constant {k1} type 2 conductivity constant {k2}
pair_style      sph/cleary/heat cubic {cut} mean {mean}
pair_coeff      * *
neighbor        {skin} bin
fix             integrate all sph/stationary
fix             dt all sph/dt/reset 1{dtargs}
compute         T all sph/t/atom
compute         Tmin all reduce min c_T
compute         Tmax all reduce max c_T
thermo_style    custom step dt f_dt[2] f_dt[6] c_Tmin c_Tmax
thermo_modify   format float %.17g
thermo          1
run             {steps}
"""


def conduction_input(args, case, thermal, steps):
    c = CONDUCTION
    cv2 = c["cv1"] * case["rhocv_ratio"]
    jit = case["jitter"] * c["dx"]
    displace = (f"displace_atoms  all random {jit:.17g} {jit:.17g} 0.0 {c['seed_jitter']} units box"
                if jit > 0 else "# no disorder")
    return CONDUCTION_INPUT.format(
        name=case["name"], thermal=thermal if thermal is not None else "default (0.5)", plugin=args.plugin,
        dx=c["dx"], n=c["n"], half=c["n"] // 2, displace=displace, m1=c["rho"] * c["dx"] ** 2,
        m2=c["rho"] * c["dx"] ** 2, rho=c["rho"], cv1=c["cv1"], cv2=cv2, dcv=cv2 - c["cv1"],
        T1=c["T1"], jump=c["jump"], noise=c["noise"], seed_noise=c["seed_noise"], k1=c["k1"],
        k2=c["k1"] * case["k_ratio"], cut=2.0 * c["hdx"] * c["dx"], mean=case["mean"],
        skin=0.1 * c["dx"], dtargs="" if thermal is None else f" thermal {thermal:.12g}", steps=steps)


def cleary_limit(case):
    """min over the particles of h^2 rho cv / k (Cleary 1998, eq 7 without 0.1)."""
    c = CONDUCTION
    h = c["hdx"] * c["dx"]
    rc1 = c["rho"] * c["cv1"]
    return min(h * h * rc1 / c["k1"], h * h * rc1 * case["rhocv_ratio"] / (c["k1"] * case["k_ratio"]))


def conduction_run(args, runner, case, thermal, steps):
    """One run: dict(dt, limit (1/lambda_max), monotone, bounded, Tmin, Tmax)."""
    ok, out = runner.run(os.path.join(args.work, "conduction", case["name"]),
                         conduction_input(args, case, thermal, steps))
    rows = thermo_rows(out)
    res = dict(dt=float("nan"), limit=float("nan"), monotone=False, bounded=False, error="")
    if rows:
        coeff = DEFAULTS["thermal"] if thermal is None else thermal
        res["dt"] = rows[0]["Dt"]
        res["limit"] = rows[0]["f_dt[6]"] / coeff
    if not ok or len(rows) < steps + 1:
        err = re.search(r"^ERROR.*$", out, re.M)
        res["error"] = err.group(0)[:120] if err else "run failed"
        return res
    lo, hi = rows[0]["c_Tmin"], rows[0]["c_Tmax"]
    span = hi - lo
    tmin = np.array([r["c_Tmin"] for r in rows])
    tmax = np.array([r["c_Tmax"] for r in rows])
    finite = np.all(np.isfinite(tmin)) and np.all(np.isfinite(tmax))
    res["monotone"] = bool(finite and tmin.min() >= lo - 1e-6 * span and tmax.max() <= hi + 1e-6 * span)
    res["bounded"] = bool(finite and tmin.min() >= lo - span and tmax.max() <= hi + span)
    res["overshoot"] = float(max(lo - tmin.min(), tmax.max() - hi) / span) if finite else float("inf")
    return res


def conduction_map(args, runner):
    cases = conduction_cases(args.quick)
    steps = 500 if args.quick else CONDUCTION["steps"]
    results = []
    for i, case in enumerate(cases):
        runs = Cached(lambda m: conduction_run(args, runner, case, m, steps))
        monotone = Cached(lambda m: runs(m)["monotone"])
        bounded = Cached(lambda m: runs(m)["bounded"])
        mono = bisect(monotone, 1.0, 1.0 / 64, 64.0, args.tol)
        # bounded is implied by monotone: start from the largest monotone multiple
        bnd = bisect(bounded, mono[0] or 1.0 / 64, 1.0 / 64, 64.0, args.tol)
        limit = runs(1.0)["limit"]
        lc = cleary_limit(case)
        default = conduction_run(args, runner, case, None, steps)
        cleary01 = runs(0.1 * lc / limit)
        r = dict(case, limit=limit, cleary=lc, mono=mono, bnd=bnd, default=default, cleary01=cleary01,
                 nruns=len(runs.results) + 1)
        results.append(r)
        print(f"[conduction {i + 1}/{len(cases)}] {case['name']}: 1/lambda_max = {limit:.4g} s = "
              f"{limit / lc:.4g} h^2 rho cv/k; monotone up to {fmt_bracket(mono)}, bounded up to "
              f"{fmt_bracket(bnd)} x 1/lambda_max; default {cleary_verdict(default)}, "
              f"Cleary's 0.1 {cleary_verdict(cleary01)} "
              f"({r['nruns']} runs, {runner.seconds:.0f} s so far)", flush=True)
    return results


# ---------------------------------------------------------------- flow: Poiseuille

# the end of the channel inputs: halt on a velocity beyond its bounds (NaN
# compares false) or at the end time, thermo for the parser
CHANNEL_MONITOR = """variable        speed2 atom vx*vx+vy*vy
compute         v2max fluid reduce max v_speed2
variable        vmax equal sqrt(c_v2max)
variable        vysq atom vy*vy
compute         vy2max fluid reduce max v_vysq
variable        vymax equal sqrt(c_vy2max)
# NaN compares false: halt unless both are within bounds
variable        ok equal (v_vmax<={vlim})&&(v_vymax<={vylim})
fix             blowup all halt 10 v_ok == 0 error continue
variable        done equal time>={t_end}
fix             tend all halt 10 v_done == 1 error continue
thermo_style    custom step time dt v_vmax v_vymax {dtcols}
thermo_modify   format float %.17g
thermo          500
run             {steps}
"""

POISEUILLE_INPUT = """# Poiseuille stability case Re = {Re}, {what}
plugin load {plugin}
units           si
dimension       2
atom_style      sph
boundary        p p p
comm_modify     vel yes
lattice         sq {dx} origin 0.5 0.5 0.0
region          box block 0 {ncol} -3 {top} -0.5 0.5
create_box      2 box
create_atoms    1 region box
region          fluid block INF INF 0 {n} INF INF
group           fluid region fluid
group           wall subtract all fluid
set             group wall type 2
mass            * {mass}
set             group all sph/rho {rho0}
set             group all sph/cv 1.0
fix             materials all sph/materials type * viscosity constant {mu} &
                eos linear {c0} background {pback} rho0 {rho0}
pair_style      sph/harmonic/visc quintic {cut} delta {delta} eta {eta}
pair_coeff      * *
neighbor        {skin} bin
neigh_modify    delay 0 every 1 check yes
neigh_modify    exclude type 2 2
fix             walls wall sph/wall/adami
fix             integrate fluid sph
fix             drive fluid addforce {fdrive} 0.0 0.0
timestep        {dt}
{dtfix}
""" + CHANNEL_MONITOR


def poiseuille_params(Re, n):
    p = dict(POISEUILLE, Re=Re, n=n)
    p["dx"] = p["W"] / n
    p["ncol"] = int(round(p["length"] / p["dx"]))
    p["h"] = p["dx"]
    p["mu"] = p["umax"] * p["W"] * p["rho0"] / Re
    p["c0"] = p["cfac"] * p["umax"]
    p["acoustic"] = p["h"] / p["c0"]
    p["viscous"] = p["h"] ** 2 * p["rho0"] / p["mu"]
    return p


def poiseuille_run(args, runner, Re, n, mult):
    """mult: dt / (h / c0), or None for the default fix sph/dt/reset 1."""
    p = poiseuille_params(Re, n)
    t_end = 100.0 if args.quick else p["t_end"]
    fx = 8 * p["umax"] * p["mu"] / (p["rho0"] * p["W"] ** 2)
    dt, steps, dtfix, dtcols, what = fixed_or_default(mult, p["acoustic"], t_end)
    text = POISEUILLE_INPUT.format(
        Re=Re, what=what, plugin=args.plugin, dx=p["dx"], ncol=p["ncol"], top=p["n"] + 3, n=p["n"],
        mass=p["rho0"] * p["dx"] ** 2, rho0=p["rho0"], mu=f"{p['mu']:.17g}", c0=p["c0"],
        pback=p["pb"] * p["rho0"] * p["c0"] ** 2, cut=3 * p["dx"], delta=p["delta"], eta=p["eta"],
        skin=0.2 * p["dx"], fdrive=f"{fx * p['rho0'] * p['dx'] ** 2:.17g}", dt=f"{dt:.17g}", dtfix=dtfix,
        vlim=p["vmax_factor"] * p["umax"], vylim=p["vy_factor"] * p["umax"], t_end=t_end,
        dtcols=dtcols, steps=steps)
    ok, out = runner.run(os.path.join(args.work, "poiseuille", f"Re{Re:g}_n{n}"), text)
    return flow_result(ok, out, mult, p["acoustic"])


def fixed_or_default(mult, acoustic, t_end):
    """A fixed dt = mult h/c0 for t_end, or (mult None) the default fix
    sph/dt/reset 1 on the fluid, run until time >= t_end (fix halt tend)."""
    if mult is None:
        return (0.1 * acoustic, 50000000, "fix             dt fluid sph/dt/reset 1", "f_dt[2]",
                "default fix sph/dt/reset 1")
    dt = mult * acoustic
    return dt, int(math.ceil(t_end / dt)), "", "", f"dt = {mult:.6g} h/c0"


def describe_default(d):
    return (f"default fix: dt = {d.get('dt_min', float('nan')):.4g} h/c0 "
            f"({'/'.join(LIMIT_NAMES[k] for k in d.get('active', []))}), "
            f"{'stable' if d['stable'] else 'UNSTABLE'}")


def flow_result(ok, out, mult, acoustic):
    rows = thermo_rows(out)
    stable = ok and halted(out, "tend") and not halted(out, "blowup") if mult is None else \
        ok and not halted(out, "blowup") and bool(rows)
    res = dict(stable=bool(stable), error="")
    if not ok:
        err = re.search(r"^ERROR.*$", out, re.M)
        res["error"] = err.group(0)[:120] if err else "run failed"
    if rows:
        res["vmax"] = max(r["v_vmax"] for r in rows) if all(math.isfinite(r["v_vmax"]) for r in rows) \
            else float("inf")
        res["time"] = rows[-1]["Time"]
        res["steps"] = int(rows[-1]["Step"])
        if mult is None:
            res["dt_first"] = rows[0]["Dt"] / acoustic
            res["dt_min"] = min(r["Dt"] for r in rows) / acoustic
            res["active"] = sorted({int(r["f_dt[2]"]) for r in rows})
    return res


LIMIT_NAMES = {0: "none", 1: "acoustic", 2: "force", 3: "viscous", 4: "thermal", 5: "bound"}


def poiseuille_map(args, runner):
    cases = [(65.2, 20)] if args.quick else POISEUILLE_CASES
    results = []
    for i, (Re, n) in enumerate(cases):
        p = poiseuille_params(Re, n)
        runs = Cached(lambda m: poiseuille_run(args, runner, Re, n, m))
        lohi = bisect(lambda m: runs(m)["stable"], 0.2, 0.012, 3.2, args.tol)
        default = poiseuille_run(args, runner, Re, n, None)
        r = dict(Re=Re, n=n, ncol=p["ncol"], mu=p["mu"], viscous=p["viscous"] / p["acoustic"], lohi=lohi,
                 default=default, nruns=len(runs.results) + 1)
        results.append(r)
        print(f"[poiseuille {i + 1}/{len(cases)}] Re = {Re:g} (mu = {p['mu']:.4g}), {n} across: stable up to "
              f"{fmt_bracket(lohi)} h/c0 (viscous limit h^2 rho/mu = {r['viscous']:.4g} h/c0); "
              f"{describe_default(default)} ({r['nruns']} runs, {runner.seconds:.0f} s so far)",
              flush=True)
    return results


# ---------------------------------------------------------------- flow: columns under gravity

COLUMN_INPUT = """# column stability case {name}, {what}
plugin load {plugin}
units           si
dimension       2
atom_style      sph
boundary        {xb} f p
comm_modify     vel yes
read_data       column.data
group           fluid type 1 2
group           wall type 3
fix             materials all sph/materials &
                type 1 viscosity constant {mu_h} eos linear {c0} rho0 {rho_h} &
                type 2 viscosity constant {mu_l} eos linear {c_l} rho0 {rho_l} &
                type 3 viscosity constant {mu_h} eos linear {c0} rho0 {rho_h}
pair_style      sph/harmonic/visc quintic {cut} delta {delta} eta {eta} fourtakas 0.0 -{g} 0.0
pair_coeff      * *
neighbor        {skin} bin
neigh_modify    delay 0 every 1 check yes
neigh_modify    exclude type 3 3
fix             walls wall sph/wall/adami body 0.0 -{g} 0.0
fix             integrate fluid sph
fix             gravity fluid gravity {g} vector 0.0 -1.0 0.0
timestep        {dt}
{dtfix}
variable        speed2 atom vx*vx+vy*vy
compute         v2max fluid reduce max v_speed2
variable        vmax equal sqrt(c_v2max)
variable        ok equal v_vmax<={vlim}
fix             blowup all halt 10 v_ok == 0 error continue
variable        done equal time>={t_end}
fix             tend all halt 10 v_done == 1 error continue
thermo_style    custom step time dt v_vmax {dtcols}
thermo_modify   format float %.17g
thermo          500
run             {steps}
"""


def column_params(case):
    nx, ny, side, ratio, delta = COLUMN_CASES[case][:5]
    light = COLUMN_CASES[case][5] if len(COLUMN_CASES[case]) > 5 else 1.0
    p = dict(COLUMN, nx=nx, ny=ny, side=side, ratio=ratio, delta=delta)
    p["dx"] = p["H"] / ny
    p["h"] = p["dx"]
    p["rho_light"] = p["rho_heavy"] / ratio
    p["mu_light"] = p["mu_heavy"] / ratio         # the same kinematic viscosity
    p["c0"] = p["cfac"] * math.sqrt(p["g"] * p["H"])
    p["c_light"] = p["c0"] * (math.sqrt(ratio) if light is True else light)
    p["acoustic"] = p["h"] / p["c_light"]    # of the fastest sound
    p["force"] = math.sqrt(p["h"] / p["g"])
    return p


def column_data(p):
    """Data file: the column in hydrostatic balance of the linear EOS, heavy
    fluid (type 1) below H/2, light (type 2) above, walls (type 3) three rows
    below and, in a tank, three columns on each side; every row moved so that
    each particle's volume m / rho is its share of the compressed column (as
    examples/flow-hydrostatic does for one fluid)."""
    dx, H, g = p["dx"], p["H"], p["g"]
    Hi = 0.5 * H
    rh, rl = p["rho_heavy"], p["rho_light"]
    ch2, cl2 = p["c0"] ** 2, p["c_light"] ** 2

    def load(y0):            # mass above a lattice height, per unit area
        return rl * (H - y0) if y0 >= Hi else rl * (H - Hi) + rh * (Hi - y0)

    def rho_at(y0, rho0, c2):    # hydrostatic density of the linear EOS (no background)
        return rho0 + g * load(y0) / c2

    def height(y0):          # compressed height of lattice height y0 (0 stays at 0)
        if y0 <= Hi:
            return ch2 / g * math.log(rho_at(0.0, rh, ch2) / rho_at(y0, rh, ch2))
        return height(Hi) + cl2 / g * math.log(rho_at(Hi, rl, cl2) / rho_at(y0, rl, cl2))

    layers = 3
    nx, ny = p["nx"], p["ny"]
    atoms = []
    cols = range(-layers, nx + layers) if p["side"] else range(nx)
    for i in cols:
        rows = range(-layers, ny + layers) if (p["side"] and (i < 0 or i >= nx)) else range(-layers, ny)
        for j in rows:
            x0, y0 = (i + 0.5) * dx, (j + 0.5) * dx
            wall = j < 0 or i < 0 or i >= nx
            t = 3 if wall else (1 if y0 < Hi else 2)
            rho0, c2 = (rl, cl2) if t == 2 else (rh, ch2)
            atoms.append((t, rho_at(y0, rho0, c2), x0, height(y0)))
    if p["side"]:
        xlo, xhi = -layers * dx, (nx + layers) * dx
    else:
        xlo, xhi = 0.0, nx * dx
    ylo, yhi = -(layers + 1) * dx, (ny + 2 * layers) * dx
    lines = ["LAMMPS data file: column under gravity (bench/stability/run_stability.py)", "",
             f"{len(atoms)} atoms", "3 atom types", "",
             f"{xlo:.17g} {xhi:.17g} xlo xhi", f"{ylo:.17g} {yhi:.17g} ylo yhi",
             f"{-0.5 * dx:.17g} {0.5 * dx:.17g} zlo zhi", "", "Masses", "",
             f"1 {rh * dx * dx:.17g}", f"2 {rl * dx * dx:.17g}", f"3 {rh * dx * dx:.17g}", "",
             "Atoms # sph", ""]
    for k, (t, rho, x, y) in enumerate(atoms):
        lines.append(f"{k + 1} {t} {rho:.17g} 1.0 1.0 {x:.17g} {y:.17g} 0.0")
    return "\n".join(lines) + "\n"


def column_run(args, runner, case, mult):
    p = column_params(case)
    t_end = 0.5 if args.quick else p["t_end"]
    dt, steps, dtfix, dtcols, what = fixed_or_default(mult, p["acoustic"], t_end)
    text = COLUMN_INPUT.format(
        name=case, what=what, plugin=args.plugin, xb="f" if p["side"] else "p", mu_h=p["mu_heavy"],
        mu_l=f"{p['mu_light']:.17g}", c0=f"{p['c0']:.17g}", c_l=f"{p['c_light']:.17g}", rho_h=p["rho_heavy"], rho_l=f"{p['rho_light']:.17g}",
        cut=f"{3 * p['dx']:.17g}", delta=p["delta"], eta=p["eta"], g=p["g"], skin=f"{0.2 * p['dx']:.17g}",
        dt=f"{dt:.17g}", dtfix=dtfix, vlim=f"{p['speed_limit'] * math.sqrt(p['g'] * p['H']):.17g}",
        t_end=t_end, dtcols=dtcols, steps=steps)
    ok, out = runner.run(case_dir(args, "column", case), text, {"column.data": column_data(p)})
    return flow_result(ok, out, mult, p["acoustic"])


def column_map(args, runner):
    cases = ["tank, one fluid", "layers, ratio 1000"] if args.quick else list(COLUMN_CASES)
    results = []
    for i, case in enumerate(cases):
        p = column_params(case)
        runs = Cached(lambda m: column_run(args, runner, case, m))
        lohi = bisect(lambda m: runs(m)["stable"], 0.1, 0.012, 1.6, args.tol)
        default = column_run(args, runner, case, None)
        r = dict(case=case, ratio=p["ratio"], delta=p["delta"], side=p["side"], nx=p["nx"], ny=p["ny"], lohi=lohi,
                 force=0.25 * p["force"] / p["acoustic"], default=default, nruns=len(runs.results) + 1)
        results.append(r)
        print(f"[column {i + 1}/{len(cases)}] {case}: stable up to {fmt_bracket(lohi)} h/c0; "
              f"{describe_default(default)}"
              + (f", largest speed {100 * default['vmax'] / math.sqrt(p['g'] * p['H']):.3g} % of sqrt(g H)"
                 if default["stable"] else "") + f" ({r['nruns']} runs, {runner.seconds:.0f} s so far)", flush=True)
    return results


# the layered column with the default fix at light fluids of several
# stiffnesses: the light fluid's c0 as a factor of the heavy's, per ratio
# (the bulk modulus ratio, light over heavy, is factor^2 / ratio)
STIFFNESS_FACTORS = {10.0: [1.0, 1.414, 2.0, 2.8, 3.6, 4.5], 100.0: [2.0, 3.16, 5.0, 8.0, 12.0, 15.0],
                     1000.0: [3.16, 5.6, 7.0, 10.0, 15.0, 22.4, 31.6]}


def stiffness_map(args, runner):
    results = []
    for ratio, factors in STIFFNESS_FACTORS.items():
        for factor in factors[:2] if args.quick else factors:
            case = f"layers, ratio {ratio:g}, light c0 x {factor:g}"
            COLUMN_CASES[case] = (10, 20, False, ratio, 0.1, factor)
            default = column_run(args, runner, case, None)
            results.append(dict(case=case, ratio=ratio, factor=factor, modulus=factor * factor / ratio,
                                default=default))
            p = column_params(case)
            speed = 100 * default.get("vmax", math.inf) / math.sqrt(p["g"] * p["H"])
            print(f"[stiffness] {case} (rho0 c0^2 {factor * factor / ratio:.3g} of the heavy's): "
                  f"{describe_default(default)}, largest speed {speed:.3g} % of sqrt(g H) "
                  f"({runner.seconds:.0f} s so far)", flush=True)
    return results


# ---------------------------------------------------------------- flow: two-fluid Couette

COUETTE_INPUT = """# two-fluid Couette stability case {name}, {what}
plugin load {plugin}
units           si
dimension       2
atom_style      sph
boundary        p p p
comm_modify     vel yes
lattice         sq {dx} origin 0.5 0.5 0.0
region          box block 0 {ncol} -3 {top} -0.5 0.5
# types: 1 lower (heavy) fluid, 2 upper (light) fluid, 3 lower (fixed) wall, 4 upper (moving) wall
create_box      4 box
create_atoms    1 region box
region          upper block INF INF {half} {n} INF INF
region          bottom block INF INF INF 0 INF INF
region          lid block INF INF {n} INF INF INF
set             region upper type 2
set             region bottom type 3
set             region lid type 4
group           fluid type 1 2
group           wall type 3 4
group           lid type 4
mass            1 {m1}
mass            3 {m1}
mass            2 {m2}
mass            4 {m2}
set             type 1 sph/rho {rho1}
set             type 3 sph/rho {rho1}
set             type 2 sph/rho {rho2}
set             type 4 sph/rho {rho2}
set             group all sph/cv 1.0
fix             materials all sph/materials &
                type 1 viscosity constant {mu1} eos linear {c0} background {pback} rho0 {rho1} &
                type 2 viscosity constant {mu2} eos linear {c0} background {pback} rho0 {rho2} &
                type 3 viscosity constant {mu1} eos linear {c0} background {pback} rho0 {rho1} &
                type 4 viscosity constant {mu2} eos linear {c0} background {pback} rho0 {rho2}
pair_style      sph/harmonic/visc quintic {cut} delta {delta} eta {eta}
pair_coeff      * *
neighbor        {skin} bin
neigh_modify    delay 0 every 1 check yes
neigh_modify    exclude type 3 3 exclude type 4 4 exclude type 3 4
fix             walls wall sph/wall/adami
fix             integrate fluid sph
velocity        lid set {V0} 0.0 0.0 units box
timestep        {dt}
{dtfix}
""" + CHANNEL_MONITOR


def couette_params(case):
    ratio, delta, *heavy = COUETTE_CASES[case]
    p = dict(COUETTE, ratio=ratio, delta=delta)
    # the background pressure: 0.01 rho0 c0^2 of the lighter fluid, or of the heavier
    p["rho_background"] = p["rho0"] if heavy else p["rho0"] / ratio
    p["dx"] = p["W"] / p["n"]
    p["h"] = p["dx"]
    p["c0"] = p["cfac"] * p["V0"]
    p["acoustic"] = p["h"] / p["c0"]
    p["viscous"] = p["h"] ** 2 * p["rho0"] / p["mu"]
    return p


def couette_run(args, runner, case, mult):
    p = couette_params(case)
    t_end = 100.0 if args.quick else p["t_end"]
    dt, steps, dtfix, dtcols, what = fixed_or_default(mult, p["acoustic"], t_end)
    rho2 = p["rho0"] / p["ratio"]
    text = COUETTE_INPUT.format(
        name=case, what=what, plugin=args.plugin, dx=p["dx"], ncol=p["ncol"], top=p["n"] + 3,
        half=p["n"] // 2, n=p["n"], m1=p["rho0"] * p["dx"] ** 2, m2=f"{rho2 * p['dx'] ** 2:.17g}",
        rho1=p["rho0"], rho2=f"{rho2:.17g}", mu1=p["mu"], mu2=f"{p['mu'] / p['ratio']:.17g}",
        c0=f"{p['c0']:.17g}", pback=f"{p['pb'] * p['rho_background'] * p['c0'] ** 2:.17g}", cut=3 * p["dx"],
        delta=p["delta"], eta=p["eta"], skin=0.2 * p["dx"], V0=p["V0"], dt=f"{dt:.17g}", dtfix=dtfix,
        vlim=p["vmax_factor"] * p["V0"], vylim=p["vy_factor"] * p["V0"], t_end=t_end, dtcols=dtcols,
        steps=steps)
    ok, out = runner.run(case_dir(args, "couette", case), text)
    return flow_result(ok, out, mult, p["acoustic"])


def couette_map(args, runner):
    cases = ["Couette, ratio 10", "Couette, ratio 1000"] if args.quick else list(COUETTE_CASES)
    results = []
    for i, case in enumerate(cases):
        p = couette_params(case)
        runs = Cached(lambda m: couette_run(args, runner, case, m))
        lohi = bisect(lambda m: runs(m)["stable"], 0.2, 0.012, 3.2, args.tol)
        default = couette_run(args, runner, case, None)
        r = dict(case=case, ratio=p["ratio"], delta=p["delta"], lohi=lohi, default=default,
                 nruns=len(runs.results) + 1)
        results.append(r)
        print(f"[couette {i + 1}/{len(cases)}] {case}: stable up to {fmt_bracket(lohi)} h/c0; "
              f"{describe_default(default)} ({r['nruns']} runs, {runner.seconds:.0f} s so far)", flush=True)
    return results


# ---------------------------------------------------------------- output

def fmt_bracket(lohi, digits=3):
    lo, hi = lohi
    if lo is None:
        return f"< {hi:.{digits}g}"
    if hi is None:
        return f">= {lo:.{digits}g}"
    return f"{lo:.{digits}g} (fails at {hi:.{digits}g})"


def cleary_verdict(res):
    """A conduction run: monotone, overshoots (bounded only) or UNSTABLE."""
    return "monotone" if res["monotone"] else ("overshoots" if res["bounded"] else "UNSTABLE")


def default_cells(d, vref=None):
    """dt (h/c0), active limit(s) and result of a default-fix run, as table cells."""
    cells = [f"{d.get('dt_min', float('nan')):.3g}",
             "/".join(LIMIT_NAMES[k] for k in d.get("active", [])) or "-",
             "stable" if d["stable"] else "**UNSTABLE**" + (f" ({d['error']})" if d["error"] else "")]
    if vref is not None:
        cells.append(f"{100 * d['vmax'] / vref:.3g}" if d["stable"] and "vmax" in d else "-")
    return cells


def write_results(args, maps, elapsed, runner):
    cond, pois, cols, cous = maps["conduction"], maps["poiseuille"], maps["column"], maps["couette"]
    stiff = maps.get("stiffness", [])
    lines = ["# Stability maps: largest stable timestep", "",
             f"Written by `/usr/bin/python3 bench/stability/run_stability.py{' --quick' if args.quick else ''}` "
             f"on {datetime.date.today().isoformat()}: {runner.nruns} LAMMPS runs, {elapsed:.0f} s of run "
             f"time in all. Machine: {platform.machine()}, {platform.system()} {platform.release()}; every run "
             "serial (one MPI rank, one OpenMP thread), one at a time. Bisection is geometric, to a "
             f"bracket [stable, unstable] of ratio {1 + args.tol:.2f}; the tables give the largest stable "
             "multiple found and, in parentheses, the smallest one that failed (`< x`: failed down to x, "
             "the smallest tried). Inputs of the last run of every case: bench/stability/out/ "
             "(git-ignored).", ""]
    if cond:
        steps = 500 if args.quick else CONDUCTION["steps"]
        c = CONDUCTION
        lines += ["## Conduction", "",
                  f"`pair sph/cleary/heat` (cubic spline, h = {c['hdx']} dx, eta = 0.1 h), `fix sph/stationary`; "
                  f"{c['n']} x {c['n']} particles in a periodic square, material 2 (the right half) with k2 = "
                  "k ratio x k1 and (rho cv)2 = rho cv ratio x (rho cv)1 (through cv), a 100 K jump plus +-1 K "
                  "of seeded noise, lattice positions jittered by up to the given fraction of dx; "
                  f"{steps} steps. *monotone*: T stays within its initial range (to 1e-6 of it); *bounded*: "
                  "within the range widened by the range on each side, and no LAMMPS error. M is the "
                  "coefficient of `fix sph/dt/reset 1 thermal M`: dt = M / lambda_max (constant here). *fix "
                  "limit*: 1/lambda_max in units of Cleary's h^2 rho cv / k (minimum over the particles); "
                  "*Cleary multiple*: the largest monotone or bounded dt in those units (Cleary 1998 uses "
                  "0.1). *default*: a run with `fix sph/dt/reset 1` (thermal 0.5); *Cleary 0.1*: a run with "
                  "dt = 0.1 h^2 rho cv / k.", "",
                  "| mean | k ratio | rho cv ratio | disorder (dx) | fix limit (h^2 rho cv/k) | largest monotone M "
                  "| largest bounded M | Cleary multiple, monotone | Cleary multiple, bounded | default | Cleary 0.1 |",
                  "|---|---|---|---|---|---|---|---|---|---|---|"]
        for r in cond:
            q = r["limit"] / r["cleary"]
            cm = tuple(None if v is None else v * q for v in r["mono"])
            cb = tuple(None if v is None else v * q for v in r["bnd"])
            c01s = cleary_verdict(r["cleary01"]).replace("UNSTABLE", "**UNSTABLE**")
            lines.append(f"| {r['mean']} | {r['k_ratio']:g} | {r['rhocv_ratio']:g} | {r['jitter']:g} | {q:.3g} | "
                         f"{fmt_bracket(r['mono'])} | {fmt_bracket(r['bnd'])} | {fmt_bracket(cm)} | "
                         f"{fmt_bracket(cb)} | {cleary_verdict(r['default']).replace('UNSTABLE', '**UNSTABLE**')} | "
                         f"{c01s} |")
        lines.append("")
    flow_note = ("*default*: a run with `fix sph/dt/reset 1` on the fluid (acoustic 0.1, force 0.25, viscous "
                 "0.125), to the same time: the smallest dt it chose (h/c0), its active limit(s) and the result.")
    if pois:
        p0 = poiseuille_params(65.2, 20)
        lines += ["## Flow: Poiseuille channel", "",
                  f"examples/flow-poiseuille, periodic length {p0['length']:g} m (quintic "
                  f"spline, h = dx; c0 = {p0['cfac']:g} u_max, background {p0['pb']} rho0 c0^2, delta "
                  f"{p0['delta']}, eta {p0['eta']} h; Adami walls), u_max = {p0['umax']} m/s and the "
                  "viscosity set by the Reynolds number Re = u_max W rho / mu; fixed dt = M h / c0 to t = "
                  f"{100.0 if args.quick else p0['t_end']:g} s; unstable if |v| > {p0['vmax_factor']} u_max, "
                  f"|v_y| > {p0['vy_factor']} u_max or on a LAMMPS error. {flow_note}", "",
                  "| Re | particles across (x columns) | mu (Pa s) | viscous limit h^2 rho / mu (h/c0) | "
                  "largest stable dt (h/c0) | same (h^2 rho/mu) | default: dt (h/c0) | default: active limit | "
                  "default: result |", "|---|---|---|---|---|---|---|---|---|"]
        for r in pois:
            vis = tuple(None if v is None else v / r["viscous"] for v in r["lohi"])
            lines.append(f"| {r['Re']:g} | {r['n']} x {r['ncol']} | {r['mu']:.4g} | {r['viscous']:.3g} | {fmt_bracket(r['lohi'])} | "
                         f"{fmt_bracket(vis)} | " + " | ".join(default_cells(r["default"])) + " |")
        lines.append("")
    if cols:
        p0 = column_params("tank, one fluid")
        vref = math.sqrt(p0["g"] * p0["H"])
        lines += ["## Flow: columns under gravity", "",
                  f"H = {p0['H']:g} m, g = {p0['g']} m/s^2, heavy fluid rho0 = {p0['rho_heavy']:g}, mu = "
                  f"{p0['mu_heavy']:g} Pa s, light fluid rho0 / ratio with the same kinematic viscosity; "
                  f"c0 = {p0['cfac']:g} sqrt(g H) in both (*matched*: in the heavy fluid, and sqrt(ratio) "
                  "times that in the light one, the same rho0 c0^2); quintic spline, h = dx, density diffusion of "
                  f"Fourtakas et al. (delta as given), eta {p0['eta']} h, Adami walls with the body force; "
                  "started in hydrostatic balance (compressed rows). *tank*: examples/flow-hydrostatic, coarse "
                  "(walls below and at the sides); *layers*: periodic in x, wall below, heavy fluid in the "
                  f"lower half. Fixed dt = M h / c0 (the larger c0) to t = {0.5 if args.quick else p0['t_end']:g} s; unstable "
                  f"if the largest fluid speed exceeds {100 * p0['speed_limit']:g} % of sqrt(g H) or on a "
                  f"LAMMPS error. *force limit*: 0.25 sqrt(h / g), in h/c0. {flow_note}", "",
                  "| case | fluid particles | delta | largest stable dt (h/c0) | force limit (h/c0) | "
                  "default: dt (h/c0) | default: active limit | default: result | default: largest speed (% of sqrt(g H)) |",
                  "|---|---|---|---|---|---|---|---|---|"]
        for r in cols:
            lines.append(f"| {r['case']} | {r['nx']} x {r['ny']} | {r['delta']:g} | {fmt_bracket(r['lohi'])} | "
                         f"{r['force']:.3g} | " + " | ".join(default_cells(r["default"], vref)) + " |")
        lines.append("")
    if stiff:
        vref = math.sqrt(COLUMN["g"] * COLUMN["H"])
        lines += ["## Flow: two fluids under gravity, the light fluid's stiffness", "",
                  "The layered column above (10 x 20, delta 0.1) with the light fluid's c0 a factor times the "
                  "heavy fluid's, each run with the default fix sph/dt/reset 1 on the fluid to the same time; "
                  "rho0 c0^2 of the light fluid in units of the heavy fluid's (factor^2 / ratio). pair "
                  "sph/harmonic/visc warns below 0.5.", "",
                  "| density ratio | light c0 / heavy c0 | light rho0 c0^2 / heavy's | default: dt (h/c0) | "
                  "default: active limit | default: result | default: largest speed (% of sqrt(g H)) |",
                  "|---|---|---|---|---|---|---|"]
        for r in stiff:
            lines.append(f"| {r['ratio']:g} | {r['factor']:g} | {r['modulus']:.3g} | "
                         + " | ".join(default_cells(r["default"], vref)) + " |")
        lines.append("")
    if cous:
        p0 = couette_params("Couette, ratio 1")
        lines += ["## Flow: two fluids in layered Couette flow", "",
                  f"examples/flow-two-fluid-couette at {p0['n']} particles across, {p0['ncol']} columns, no "
                  f"gravity: lower fluid rho0 = {p0['rho0']:g}, mu = {p0['mu']}, upper fluid rho0 / ratio with "
                  f"the same kinematic viscosity, upper wall at V0 = {p0['V0']} m/s; c0 = {p0['cfac']:g} V0 and "
                  f"background {p0['pb']} rho0 c0^2 of the upper (lighter) fluid in both (*heavy background*: "
                  f"of the lower fluid), Molteni's density diffusion (delta as given; between particles of the "
                  f"same rest density only), eta {p0['eta']} h. Fixed dt = M h / c0 to t = "
                  f"{100.0 if args.quick else p0['t_end']:g} s; unstable if |v| > {p0['vmax_factor']} V0, "
                  f"|v_y| > {p0['vy_factor']} V0 or on a LAMMPS error. {flow_note}", "",
                  "| case | density ratio | delta | largest stable dt (h/c0) | default: dt (h/c0) | "
                  "default: active limit | default: result |", "|---|---|---|---|---|---|---|"]
        for r in cous:
            lines.append(f"| {r['case']} | {r['ratio']:g} | {r['delta']:g} | {fmt_bracket(r['lohi'])} | "
                         + " | ".join(default_cells(r["default"])) + " |")
        lines.append("")
    lines += ["![stability map](stability_map.png)", ""]
    os.makedirs(args.out, exist_ok=True)
    path = os.path.join(args.out, "results.md")
    with open(path, "w") as f:
        f.write("\n".join(lines))
    return path


def plot(args, maps):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from matplotlib import patheffects
    cond = maps["conduction"]
    flows = [(f"Poiseuille Re {r['Re']:g}, {r['n']} across", r) for r in maps["poiseuille"]] + \
            [(r["case"], r) for r in maps["column"]] + [(r["case"], r) for r in maps["couette"]]
    panels = (2 if cond else 0) + (1 if flows else 0)
    fig, axes = plt.subplots(1, max(panels, 1), figsize=(6.4 * max(panels, 1), 6.0), squeeze=False)
    axes = list(axes[0])
    if cond:
        rowkeys = list(dict.fromkeys((r["k_ratio"], r["rhocv_ratio"]) for r in cond))
        colkeys = list(dict.fromkeys((r["mean"], r["jitter"]) for r in cond))
        for which, title in [("fix", "conduction: largest monotone dt / (1 / lambda_max)\n"
                                     "(fix sph/dt/reset thermal M; default M = 0.5)"),
                             ("cleary", "conduction: largest monotone dt / min(h^2 rho cv / k)\n"
                                        "(Cleary 1998: 0.1; red = 0.1 is not monotone)")]:
            ax = axes.pop(0)
            grid = np.full((len(rowkeys), len(colkeys)), np.nan)
            for r in cond:
                v = r["mono"][0]
                if v is None:
                    continue
                if which == "cleary":
                    v *= r["limit"] / r["cleary"]
                grid[rowkeys.index((r["k_ratio"], r["rhocv_ratio"])), colkeys.index((r["mean"], r["jitter"]))] = v
            im = ax.imshow(np.log10(grid), cmap="viridis", aspect="auto")
            for (a, b), v in np.ndenumerate(grid):
                unsafe = which == "cleary" and v < 0.1
                ax.text(b, a, f"{v:.3g}", ha="center", va="center", fontsize=8,
                        color="red" if unsafe else "black", fontweight="bold",
                        path_effects=[patheffects.withStroke(linewidth=2.5, foreground="white")])
            ax.set_yticks(range(len(rowkeys)))
            ax.set_yticklabels([f"k ratio {k:g}\nrho cv ratio {c:g}" for k, c in rowkeys], fontsize=7)
            ax.set_xticks(range(len(colkeys)))
            ax.set_xticklabels([f"{m[:5]}.\njitter {j:g}" for m, j in colkeys], fontsize=7)
            ax.set_title(title, fontsize=9)
            fig.colorbar(im, ax=ax, label="log10 of the multiple", shrink=0.8)
    if flows:
        ax = axes.pop(0)
        floor = 0.006
        y = np.arange(len(flows))
        los = [r["lohi"][0] if r["lohi"][0] is not None else np.nan for _, r in flows]
        his = [r["lohi"][1] if r["lohi"][1] is not None else np.nan for _, r in flows]
        ax.barh(y, [0.0 if np.isnan(v) else v for v in los], color="tab:blue", label="largest stable fixed dt")
        ax.plot(his, y, "x", color="black", label="smallest dt that failed (alone: all failed)")
        first = {True: True, False: True}
        for k, (_, r) in enumerate(flows):
            d = r["default"]
            ok = d["stable"]
            ax.plot([d.get("dt_min", np.nan)], [k], "o" if ok else "s", color="tab:green" if ok else "red", ms=7,
                    label=("default fix sph/dt/reset: stable" if ok else "default fix sph/dt/reset: UNSTABLE")
                    if first[ok] else None)
            first[ok] = False
        ax.axvline(DEFAULTS["acoustic"], color="gray", ls="--", lw=1, label="acoustic 0.1 (default)")
        ax.set_yticks(y)
        ax.set_yticklabels([name for name, _ in flows], fontsize=7)
        ax.invert_yaxis()
        ax.set_xscale("log")
        ax.set_xlim(floor, 10)
        ax.set_xlabel("dt / (h / c0)")
        ax.set_title("flow: largest stable fixed dt, and the default fix's dt", fontsize=9)
        ax.legend(fontsize=7, loc="lower right")
    fig.tight_layout()
    path = os.path.join(args.out, "stability_map.png")
    fig.savefig(path, dpi=100)
    return path


MAPS = {"conduction": conduction_map, "poiseuille": poiseuille_map, "column": column_map,
        "couette": couette_map, "stiffness": stiffness_map}


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--lmp", default=os.path.join(root, "build", "lmp"))
    p.add_argument("--plugin", default=os.path.join(root, "build", "sphthermalplugin.so"))
    p.add_argument("--out", default=here, help="where results.md and stability_map.png go")
    p.add_argument("--work", default=os.path.join(here, "out"), help="inputs and screen output of the runs")
    p.add_argument("--quick", action="store_true", help="fewer cases, shorter runs, bisection to 25 %%")
    p.add_argument("--only", choices=list(MAPS), action="append", help="run only these maps (repeatable)")
    p.add_argument("--timeout", type=float, default=120.0, help="seconds per LAMMPS run (then: unstable)")
    p.add_argument("--from-json", help="no runs: tables and plot from the results.json of an earlier run "
                   "(written to --work)")
    args = p.parse_args()
    args.tol = 0.25 if args.quick else 0.05
    args.plugin = os.path.abspath(args.plugin)
    args.lmp = os.path.abspath(args.lmp)
    for path in (args.lmp, args.plugin):
        if not os.path.exists(path):
            sys.exit(f"missing {path}: build first (tools/main.sh)")
    only = args.only or list(MAPS)
    runner = Runner(args)
    if args.from_json:
        with open(args.from_json) as f:
            saved = json.load(f)
        maps, elapsed = saved["maps"], saved["elapsed"]
        runner.nruns, args.quick, args.tol = saved["nruns"], saved["quick"], saved["tol"]
    else:
        start = time.time()
        maps = {name: (fn(args, runner) if name in only else []) for name, fn in MAPS.items()}
        elapsed = time.time() - start
        os.makedirs(args.work, exist_ok=True)
        with open(os.path.join(args.work, "results.json"), "w") as f:
            json.dump(dict(maps=maps, elapsed=elapsed, nruns=runner.nruns, quick=args.quick, tol=args.tol), f)
    md = write_results(args, maps, elapsed, runner)
    png = plot(args, maps)
    print(f"wrote {md} and {png}; {runner.nruns} LAMMPS runs, {elapsed:.0f} s", flush=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
