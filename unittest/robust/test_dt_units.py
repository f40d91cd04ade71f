"""fix sph/dt/reset chooses the same timestep, in seconds, for the same
scene written in any LAMMPS unit style (robust.dt_units.<units>, called by
ctest).

Two small 2-D scenes, each written in units si and in the unit style under
test, run with fix sph/dt/reset 1 (its defaults):
  conduction  two solids side by side (conductivities 1 and 50 W/(m K)),
              jittered, a temperature jump, fix sph/stationary, 100 steps;
  flow        a periodic shear wave (linear EOS, viscosity, Mach number 1e-4)
              under gravity along the wave, fix sph, 100 steps.
The timestep and the four limits at the setup, and the timestep, the
limits and the elapsed time after the run, converted to seconds, must
agree with the si run to round-off (1e-9; 1e-4 for the flow's force and
viscous limits after the run, see DRIFT_RTOL); each run stays finite and
bounded (T within its initial range; |v| at most the initial speed plus
g t, the density within 1 % of rho0).

How a scene is converted. Every quantity is converted by its dimensions in
mass, length and time (energies as mass length^2 / time^2: specific energy
and cv in (length/time)^2). LAMMPS's fix sph (and fix sph/stationary)
advances v by dt ftm2v f / m, and rho and esph by dt ftm2v drho and
dt ftm2v desph, while the pair styles compute f, drho and desph from the
material parameters without unit factors: every rate is integrated s =
ftm2v times its pair value. So the speed of sound, the viscosity, the
conductivity and the body acceleration (fix gravity's, in force/mass
units) are given divided by s: then the equations integrated, and their
stability limits, are those of the si scene. s = 1 in si, cgs and lj,
1/1.0364269e-4 in metal, 1/48.88821291^2 in real, 0.937582899 in electron
(LAMMPS's update.cpp). A limit that leaves out s is s times off (in metal
the thermal limit 1e4 times too large: the run blows up).
"""

import argparse
import math
import re

from sphtest import Checks, finish, lammps_arguments, run_script

AMU = 1.66053906660e-27
# units: (mass, length, time in kg, m, s; s = ftm2v)
UNITS = {
    "si": (1.0, 1.0, 1.0, 1.0),
    "cgs": (1.0e-3, 1.0e-2, 1.0, 1.0),
    "metal": (AMU, 1.0e-10, 1.0e-12, 1.0 / 1.0364269e-4),
    "real": (AMU, 1.0e-10, 1.0e-15, 1.0 / 48.88821291 / 48.88821291),
    "electron": (AMU, 0.529177210903e-10, 1.0e-15, 0.937582899),
    # reduced units of a reference mass, length and time
    "lj": (1.0e-6, 1.0e-3, 1.0e-2, 1.0),
}

# the scenes in si: spacing, smoothing length / spacing, density, cv, T
DX, HDX, RHO, CV = 1.0e-3, 1.3, 1000.0, 1000.0
K1, K2 = 1.0, 50.0                      # W/(m K)
C0, MU, U, G = 10.0, 10.0, 1.0e-3, 9.81  # m/s, Pa s, m/s, m/s^2
NCELLS = 12
STEPS = 100

COMMON = """
plugin load {plugin}
units {units}
dimension 2
atom_style sph
atom_modify map array
boundary p p p
lattice sq {lattice} origin 0.5 0.5 0.0
region box block 0 {n} 0 {n} -0.5 0.5
create_box {ntypes} box
create_atoms 1 box
neighbor {skin} bin
mass * {mass}
set group all sph/rho {rho}
set group all sph/cv {cv}
"""

CONDUCTION = COMMON + """
# (displace_atoms random seeds by the coordinates: its jitter would differ)
variable jx atom {jitter}*sin(127.1*id)
variable jy atom {jitter}*cos(311.7*id)
displace_atoms all move v_jx v_jy 0.0 units box
region right block {half} INF INF INF INF INF
group right region right
set group right type 2
variable e atom {cv}*(300.0+100.0*(type-1)+50.0*(y>{yhalf}))
set group all sph/e v_e
fix materials all sph/materials type 1 conductivity constant {k1} type 2 conductivity constant {k2}
pair_style sph/cleary/heat cubic {cut}
pair_coeff * *
fix integrate all sph/stationary
fix dt all sph/dt/reset 1
compute T all sph/t/atom
compute Tmin all reduce min c_T
compute Tmax all reduce max c_T
thermo_style custom step time dt f_dt[2] f_dt[3] f_dt[4] f_dt[5] f_dt[6] c_Tmin c_Tmax
thermo_modify format float %.17g
thermo {steps}
run 0
print "SETUP $(dt:%.17g) $(f_dt[3]:%.17g) $(f_dt[4]:%.17g) $(f_dt[5]:%.17g) $(f_dt[6]:%.17g) $(c_Tmin:%.17g) $(c_Tmax:%.17g)"
run {steps}
print "END $(time:%.17g) $(dt:%.17g) $(f_dt[3]:%.17g) $(f_dt[4]:%.17g) $(f_dt[5]:%.17g) $(f_dt[6]:%.17g) $(c_Tmin:%.17g) $(c_Tmax:%.17g)"
"""

FLOW = COMMON + """
set group all sph/e {e}
variable vx atom {u}*sin(2.0*PI*y/{length})
velocity all set v_vx 0.0 0.0 units box
fix materials all sph/materials type 1 viscosity constant {mu} eos linear {c0} rho0 {rho}
pair_style sph/harmonic/visc cubic {cut}
pair_coeff * *
fix integrate all sph
fix gravity all gravity {g} vector 1.0 0.0 0.0
fix dt all sph/dt/reset 1
variable speed atom sqrt(vx*vx+vy*vy)
compute vmax all reduce max v_speed
compute rho all sph/rho/atom
compute rhomin all reduce min c_rho
compute rhomax all reduce max c_rho
thermo_style custom step time dt f_dt[2] f_dt[3] f_dt[4] f_dt[5] f_dt[6] c_vmax c_rhomin c_rhomax
thermo_modify format float %.17g
thermo {steps}
run 0
print "SETUP $(dt:%.17g) $(f_dt[3]:%.17g) $(f_dt[4]:%.17g) $(f_dt[5]:%.17g) $(f_dt[6]:%.17g) $(c_vmax:%.17g) $(c_rhomin:%.17g) $(c_rhomax:%.17g)"
run {steps}
print "END $(time:%.17g) $(dt:%.17g) $(f_dt[3]:%.17g) $(f_dt[4]:%.17g) $(f_dt[5]:%.17g) $(f_dt[6]:%.17g) $(c_vmax:%.17g) $(c_rhomin:%.17g) $(c_rhomax:%.17g)"
"""

NONE = 1.0e300    # a limit that applies to no particle
# the end-of-run limits of the flow that read the density (force, viscous):
# fix sph integrates drho with ftm2v, so in metal the shear wave's density
# deviations are 9648 times those of si (5e-6 of rho0, not 5e-10); the
# dynamics agree only as far as rho does
DRIFT_RTOL = 1.0e-4


def convert(units):
    """A function q(value, mass, length, time, rate=False) from si to 'units'."""
    m_unit, l_unit, t_unit, s = UNITS[units]

    def q(value, mass=0, length=0, time=0, rate=False):
        out = value / (m_unit ** mass * l_unit ** length * t_unit ** time)
        return out / s if rate else out
    return q


def script(scene, a, units):
    q = convert(units)
    dx = q(DX, length=1)
    rho = q(RHO, mass=1, length=-3)
    cv = q(CV, length=2, time=-2)
    values = dict(
        plugin=a.plugin, units=units, n=NCELLS, ntypes=2 if scene == "conduction" else 1,
        # lj: the scale of a lattice is a reduced density
        lattice=repr(dx ** -2 if units == "lj" else dx), skin=repr(0.3 * dx),
        mass=repr(rho * dx * dx), rho=repr(rho), cv=repr(cv), cut=repr(2.0 * HDX * dx),
        steps=STEPS)
    if scene == "conduction":
        values.update(jitter=repr(0.1 * dx), half=NCELLS // 2, yhalf=repr(0.5 * NCELLS * dx),
                      k1=repr(q(K1, mass=1, length=1, time=-3, rate=True)),
                      k2=repr(q(K2, mass=1, length=1, time=-3, rate=True)))
        return CONDUCTION.format(**values)
    values.update(e=repr(cv * 300.0), u=repr(q(U, length=1, time=-1)), length=repr(NCELLS * dx),
                  mu=repr(q(MU, mass=1, length=-1, time=-1, rate=True)),
                  c0=repr(q(C0, length=1, time=-1, rate=True)),
                  g=repr(q(G, length=1, time=-2, rate=True)))
    return FLOW.format(**values)


def run(scene, a, units):
    """The SETUP and END values, converted to si; or the error."""
    code, out = run_script(a.lmp, script(scene, a, units))
    m_unit, l_unit, t_unit, _ = UNITS[units]
    found = {}
    for tag in ("SETUP", "END"):
        m = re.search(r"^%s ((?:\S+ ?)+)$" % tag, out, re.M)
        if not m:
            error = re.search(r"^ERROR.*$", out, re.M)
            return None, error.group(0) if error else f"no {tag} line (exit code {code})"
        found[tag] = [float(w) for w in m.group(1).split()]
    # times: every value up to the limits (none stays none)
    def seconds(values):
        return [v if v >= NONE else v * t_unit for v in values]
    setup, end = found["SETUP"], found["END"]
    result = {"setup": seconds(setup[:5]), "end": seconds(end[:6])}
    if scene == "conduction":
        result["T"] = setup[5:7] + end[6:8]
    else:
        result["v"] = [setup[5] * l_unit / t_unit, end[6] * l_unit / t_unit]
        result["rho"] = [r * m_unit / l_unit ** 3 for r in setup[6:8] + end[7:9]]
    return result, ""


# the coefficients against which the pairs check a fixed timestep
# (fix_sph_timestep_check.h)
CHECK_COEFFS = "acoustic 0.25 force 0.25 viscous 0.125 thermal 1.0"
TIMESTEP_WARNING = re.compile(r"^WARNING: Pair style sph/\S+: timestep .* limit", re.M)


def fixed(check, a, scene, units):
    """A fixed timestep below the smallest limit gives no warning, one above
    it a warning, and one 4 times above it none when fix sph/dt/reset is
    defined (which sets dt itself)."""
    text = script(scene, a, units)
    head = text[:text.index("fix dt all sph/dt/reset 1")]
    _, out = run_script(a.lmp, head + f"fix dt all sph/dt/reset 1 {CHECK_COEFFS}\nrun 0\n"
                        "print \"LIMIT $(dt:%.17g)\"\n")
    m = re.search(r"^LIMIT (\S+)$", out, re.M)
    check(m is not None, f"fixed, {scene} in {units}: the smallest limit is known")
    if not m:
        return
    limit = float(m.group(1))
    for factor, with_fix, warns in ((0.9, False, False), (1.5, False, True), (4.0, True, False)):
        dt = factor * limit
        lines = f"timestep {dt!r}\n" + ("fix dt all sph/dt/reset 1\n" if with_fix else "")
        code, out = run_script(a.lmp, head + lines + "run 10\nprint \"DONE\"\n")
        warned = TIMESTEP_WARNING.search(out)
        done = re.search(r"^DONE$", out, re.M) is not None
        check(done and bool(warned) == warns,
              f"fixed, {scene} in {units}: timestep {factor} times the limit {limit:.6g}"
              f"{' with fix sph/dt/reset' if with_fix else ''}: "
              f"{'a warning' if warns else 'no warning'} "
              f"({warned.group(0) if warned else 'none'}{'' if done else ', no DONE'})")


def close(x, y, rtol=1.0e-9):
    return x == y or abs(x - y) <= rtol * max(abs(x), abs(y))


def main():
    p = argparse.ArgumentParser(description=__doc__,
                                formatter_class=argparse.RawDescriptionHelpFormatter)
    lammps_arguments(p, mpi=False)
    mode = p.add_mutually_exclusive_group(required=True)
    mode.add_argument("--units", choices=sorted(u for u in UNITS if u != "si"))
    mode.add_argument("--fixed", choices=sorted(UNITS),
                      help="check the warnings about a fixed timestep in these units instead")
    a = p.parse_args()
    check = Checks()
    if a.fixed:
        for scene in ("conduction", "flow"):
            fixed(check, a, scene, a.fixed)
        finish(check.failures)
        return
    names = {"setup": ["dt", "acoustic", "force", "viscous", "thermal"],
             "end": ["time", "dt", "acoustic", "force", "viscous", "thermal"]}
    for scene in ("conduction", "flow"):
        ref, error = run(scene, a, "si")
        check(ref is not None, f"{scene} in si runs {error}")
        got, error = run(scene, a, a.units)
        check(got is not None, f"{scene} in {a.units} runs {error}")
        if ref is None or got is None:
            continue
        for when in ("setup", "end"):
            for name, x, y in zip(names[when], ref[when], got[when]):
                # the flow's force and viscous limits read rho, whose
                # deviations from rho0 (5e-10 of it in si) the continuity
                # equation integrated with ftm2v makes s times larger
                rtol = DRIFT_RTOL if (scene, when) == ("flow", "end") and name in (
                    "force", "viscous") else 1.0e-9
                check(close(x, y, rtol), f"{scene}, {when}: {name} {y:.12g} s in {a.units}, "
                      f"{x:.12g} s in si (rtol {rtol:g})")
        # the active limit is an actual one in both scenes
        check(ref["setup"][0] < NONE, f"{scene}: some limit applies (dt {ref['setup'][0]} s)")
        if scene == "conduction":
            lo, hi, tmin, tmax = got["T"]
            tol = 1.0e-9 * (hi - lo)
            check(all(math.isfinite(t) for t in got["T"]) and tmin >= lo - tol and tmax <= hi + tol,
                  f"conduction in {a.units}: T in [{tmin}, {tmax}] after {STEPS} steps, "
                  f"initially [{lo}, {hi}]")
        else:
            v0, v1 = got["v"]
            bound = (U + G * got["end"][0]) * (1.0 + 1.0e-6)
            check(math.isfinite(v1) and v1 <= bound,
                  f"flow in {a.units}: largest speed {v1:.6g} m/s after {STEPS} steps, "
                  f"at most {bound:.6g} (initially {v0:.6g})")
            ok = all(math.isfinite(r) and abs(r / RHO - 1.0) <= 0.01 for r in got["rho"])
            check(ok, f"flow in {a.units}: density within 1 % of {RHO} kg/m^3 "
                  f"({', '.join('%.9g' % r for r in got['rho'])})")
    finish(check.failures)


if __name__ == "__main__":
    main()
