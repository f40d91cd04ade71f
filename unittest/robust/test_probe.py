"""Every style of the package on 2 ranks and across a restart
(robust.probe.<probe>, called by ctest; robust.probe.coverage checks the
table against the styles the sources declare).

Each probe is a small scene (a heated cavity with flow, or a periodic
channel) that runs the style with the package's other styles around it:
- A: 1 rank, 10 steps, write_restart, 10 steps more;
- B: the same on 2 ranks;
- C: 2 ranks, read_restart of A's file, the styles given again, 10 steps.
Checked: every atom's x, y, vx, vy, rho, esph and the style's own outputs
(thermo) agree between A and B and between A and C to round-off, and they
are finite. A style that kept state it does not write to the restart file,
or that sums differently with the atoms split over ranks, fails here.

  --list       the probes' names (for ctest)
  --syntax     bad forms of the probe's command line instead (missing, extra
               and nonsense words; numbers 0, -1, 1e300 and NaN; an empty
               group): no crash or hang, an error that names the style or
               stops at the command, no NaN taken silently
  --list-syntax  the probes with a command line of their own
  --coverage   every style the sources declare has a probe
"""

import argparse
import glob
import math
import os
import re
import subprocess
import sys
import tempfile

from sphtest import Checks, finish, lammps_arguments, mpi_env, mpi_prefix

SOURCES = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "src",
                       "USER-SPHTHERMAL")

LATTICE = """
variable dx equal 1.0/12
lattice sq ${dx} origin 0.5 0.5 0.0
"""

# the atoms and regions (regions are not in a restart file: given again)
CAVITY_ATOMS = """
region box block -3 15 -3 15 -0.5 0.5
create_box 2 box
create_atoms 1 region box
"""
CAVITY_GROUPS = """
group fluid region cavity
group wall subtract all fluid
set group wall type 2
group hot region left
group cold region right
group hot_or_cold union hot cold
group top_bottom subtract wall hot_or_cold
group upper region upper
group toprow region toprow
"""
CAVITY_GROUPS_FACES = """
sph/faces all cavity inside fluid outside wall xlo hot xhi cold others top_bottom
set group wall type 2
group hot_or_cold union hot cold
group upper region upper
group toprow region toprow
"""
CAVITY_REGIONS = """
region cavity block 0 12 0 12 INF INF
region left block INF 0 INF INF INF INF
region right block 12 INF INF INF INF INF
region upper block 0 12 6 12 INF INF
region toprow block 0 12 11 12 INF INF
"""
CAVITY_STATE = """
variable T0 atom 0.5+0.1*sin(2*PI*x)
sph/set all materials spacing ${dx} temperature v_T0
variable u atom 2.0*sin(PI*x)*cos(PI*y)
variable w atom -2.0*cos(PI*x)*sin(PI*y)
set group fluid vx v_u
set group fluid vy v_w
"""
MATERIALS = """
fix materials all sph/materials type * conductivity constant 1.0 cv 1.0 &
    viscosity constant 0.71 expansion 1.0 eos linear 40.0 background 160.0 rho0 1.0
"""
PAIRS = """
comm_modify vel yes
pair_style hybrid/overlay {visc} wendland 0.2167 eta 0.01 delta 0.1 {flow} &
    {heat} wendland 0.2167 eta 0.01 {conduction}
pair_coeff * * {visc}
pair_coeff * * {heat}
neighbor $(0.2*v_dx) bin
neigh_modify delay 0 every 1 check yes exclude type 2 2
timestep 2.5e-4
"""
CAVITY_WALLS = """
fix flow_walls wall sph/wall/adami
fix hot hot sph/wall/dirichlet 1.0 surface cavity
fix cold cold sph/wall/dirichlet 0.0 surface cavity
fix adiabatic top_bottom sph/wall/adiabatic surface cavity
fix integrate fluid sph
"""

# a channel periodic in x, driven along +x, heated from both walls
CHANNEL_ATOMS = """
region box block 0 12 -3 9 -0.5 0.5
create_box 2 box
create_atoms 1 region box
"""
CHANNEL_REGIONS = """
region channel block INF INF 0 6 INF INF
region low block INF INF INF 0 INF INF
"""
CHANNEL_GROUPS = """
group fluid region channel
group wall subtract all fluid
set group wall type 2
group hot region low
group cold subtract wall hot
"""
CHANNEL_STATE = """
sph/set all materials spacing ${dx} temperature 0.0
variable u atom 4.0*y*(0.5-y)
set group fluid vx v_u
"""
CHANNEL_WALLS = """
fix flow_walls wall sph/wall/adami
fix hot hot sph/wall/dirichlet 1.0
fix cold cold sph/wall/dirichlet 1.0
fix integrate fluid sph
fix drive fluid addforce 0.02 0.0 0.0
"""

# a channel along x with an inlet and an outlet buffer (fix sph/open), not
# periodic in x: the fluid from x = 0 to 12 dx, three buffer layers at each end
OPEN_ATOMS = """
region box block -4 16 -3 9 -0.5 0.5
create_box 2 box
region inside block -3 15 INF INF INF INF
create_atoms 1 region inside
"""
OPEN_REGIONS = """
region channel block 0 12 0 6 INF INF
region upstream block -3 0 0 6 INF INF
region downstream block 12 15 0 6 INF INF
"""
OPEN_GROUPS = """
group fluid region channel
group inflow region upstream
group outflow region downstream
group wall subtract all fluid inflow outflow
set group wall type 2
"""
OPEN_STATE = CHANNEL_STATE
OPEN_WALLS = """
fix flow_walls wall sph/wall/adami
fix integrate fluid sph
"""

SCENES = {
    "cavity": (CAVITY_ATOMS, CAVITY_REGIONS, CAVITY_GROUPS, CAVITY_STATE, CAVITY_WALLS),
    "channel": (CHANNEL_ATOMS, CHANNEL_REGIONS, CHANNEL_GROUPS, CHANNEL_STATE, CHANNEL_WALLS),
    "open": (OPEN_ATOMS, OPEN_REGIONS, OPEN_GROUPS, OPEN_STATE, OPEN_WALLS),
}

# probe: (scene, the style's commands, its outputs for thermo, options);
# options: conduction (of sph/cleary/heat), flow (of sph/harmonic/visc),
# walls (replacing the scene's), omp, rtol (the agreement asked, when the
# style's sums make round-off grow faster than the default 1e-12)
PROBES = {
    "pair_sph_harmonic_visc": ("cavity", "", "ke", {}),
    "pair_sph_cleary_heat": ("cavity", "", "ke", {}),
    "pair_sph_cleary_heat_consistent": ("cavity", "", "ke", {"conduction": "correction consistent"}),
    "pair_sph_cleary_heat_second": ("cavity", "", "ke", {"conduction": "correction second"}),
    "pair_sph_harmonic_visc_symmetric_cleary": (
        "cavity", "", "ke", {"flow": "pressure symmetric viscosity cleary xi 1.0"}),
    "pair_sph_harmonic_visc_sum_morris": ("cavity", "", "ke",
                                          {"flow": "pressure sum viscosity morris"}),
    "pair_sph_harmonic_visc_gradient": ("cavity", "", "ke", {"flow": "correction gradient"}),
    "pair_sph_harmonic_visc_molteni_heating": (
        "cavity", "", "ke", {"flow": "diffusion molteni heating 1.0"}),
    "pair_sph_harmonic_visc_mean_pressure": ("cavity", "", "ke", {"flow": "mean_pressure 0.0"}),
    "pair_sph_cleary_heat_interface": ("cavity", "", "ke", {"conduction": "mean interface"}),
    "pair_sph_harmonic_visc_omp": ("cavity", "", "ke", {"omp": 1}),
    "pair_sph_cleary_heat_omp": ("cavity", "", "ke", {"omp": 1,
                                                      "conduction": "correction consistent"}),
    "fix_sph_materials": ("cavity", "", "ke", {}),
    "fix_sph_wall_adami": ("cavity", "", "ke", {}),
    "fix_sph_wall_dirichlet": ("cavity", "", "f_hot f_cold", {}),
    "fix_sph_wall_adiabatic": ("cavity", "", "ke", {}),
    "fix_sph_wall_isothermal": (
        "cavity", "", "f_hot[1] f_cold[1]",
        {"walls": "fix flow_walls wall sph/wall/adami\n"
                  "fix hot hot sph/wall/isothermal 1.0 spacing ${dx}\n"
                  "fix cold cold sph/wall/isothermal 0.0 spacing ${dx}\n"
                  "fix integrate fluid sph\n"}),
    "fix_sph_boussinesq": ("cavity", "fix buoyancy fluid sph/boussinesq 0.5 gravity 0.0 -200.0 0.0",
                           "ke", {}),
    "fix_sph_shift": ("cavity", "fix shift fluid sph/shift skillen 2.0", "f_shift[1] f_shift[2]", {}),
    "fix_sph_shift_delta_plus": ("cavity", "fix shift fluid sph/shift delta-plus 1.0 40.0 correct yes",
                                 "f_shift[1] f_shift[2]", {}),
    "fix_sph_boussinesq_fix_gravity": (
        "cavity", "fix g fluid gravity 200.0 vector 0 -1 0\nfix buoyancy fluid sph/boussinesq 0.5",
        "ke", {}),
    "fix_sph_wall_adami_body": (
        "cavity", "", "ke",
        {"walls": CAVITY_WALLS.replace("sph/wall/adami", "sph/wall/adami body 0.0 -1.0 0.0")}),
    "fix_sph_dt_reset": ("cavity", "fix dt fluid sph/dt/reset 1 acoustic 0.1", "dt time", {}),
    "fix_sph_dt_reset_limits": (
        "cavity", "fix dt fluid sph/dt/reset 3 acoustic 0.2 force 0.2 viscous 0.1 thermal 0.1 "
        "min 1.0e-6 max 1.0e-3", "dt time", {}),
    "fix_sph_heatflow": ("cavity", "fix into fluid sph/heatflow hot", "f_into", {}),
    # a mushy zone about the mean temperature: some atoms melt and freeze
    "fix_sph_phase": ("cavity", "fix phase all sph/phase type 1 solidus 0.45 liquidus 0.55 latent 0.05",
                      "f_phase[1] f_phase[2]", {}),
    # the same with the mushy zone's damping, whose solid atoms are held
    "fix_sph_phase_mushy": (
        "cavity", "fix phase fluid sph/phase type 1 solidus 0.45 liquidus 0.55 latent 0.05 mushy 2.0",
        "f_phase[1] f_phase[2]", {}),
    "fix_sph_hold_volume": ("cavity", "fix hold fluid sph/hold/volume", "f_hold", {}),
    "fix_sph_flowrate": ("channel", "fix rate fluid sph/flowrate x 0.05 relax 0.01", "f_rate[*]", {}),
    # T0 by layers: sums over a few atoms per layer, whose order the ranks
    # change; 10 steps take their round-off to about 3e-12
    "fix_sph_boussinesq_layers": (
        "cavity", "fix buoyancy fluid sph/boussinesq layers gravity 0.0 -200.0 0.0", "ke",
        {"rtol": 1e-11}),
    "fix_sph_surface_flux": ("cavity", "fix heater toprow sph/surface/flux flux 2.0 spacing ${dx}",
                             "f_heater", {}),
    "fix_sph_inlet_temperature": ("channel", "fix inlet fluid sph/inlet/temperature 0.0",
                                  "f_inlet[1]", {}),
    "fix_sph_inlet_temperature_held": (
        "channel", "fix inlet fluid sph/inlet/temperature 0.0 ghosts held", "f_inlet[1]", {}),
    # the inlet's plane 0.01 ahead of its buffer, which does not reach it in
    # 20 steps (atoms created then would have no lattice site to compare
    # by; tests open.mpi.* and open.restart cover them); the outlet's just
    # past the last fluid column, which the faster rows cross
    "fix_sph_open": (
        "open", "fix in inflow sph/open inlet +x $(-0.5*v_dx+0.01) fluid fluid "
        "velocity parabolic 0.25 y 0.0 0.5 temperature 1.0\n"
        "fix out outflow sph/open outlet +x $(11.5*v_dx+0.0005) fluid fluid",
        "f_out[1] f_out[2] f_out[3] f_out[6]", {}),
    "compute_sph_correction_atom": (
        "cavity", "compute c all sph/correction/atom\ncompute csum all reduce sum c_c", "c_csum",
        {"conduction": "correction consistent"}),
    "compute_sph_heatflux_atom": (
        "cavity", "compute q fluid sph/heatflux/atom\ncompute qsum fluid reduce sum c_q[1] c_q[2]",
        "c_qsum[1] c_qsum[2]", {}),
    "compute_sph_force": ("cavity", "compute force hot sph/force center 0.1 0.5 0.0", "c_force[*]", {}),
    "compute_sph_mixing": ("cavity", "compute mix fluid sph/mixing upper", "c_mix[*]", {}),
    "compute_sph_nusselt": ("cavity", "compute nu hot sph/nusselt hot 1.0 1.0 1.0", "c_nu[*]", {}),
    "compute_sph_thermal": ("cavity", "compute th fluid sph/thermal", "c_th[*]", {}),
    "command_sph_set": ("cavity", "", "ke", {}),
    # the cavity's groups from sph/faces instead of a region per side
    "command_sph_faces": ("cavity", "", "ke", {"groups": CAVITY_GROUPS_FACES}),
}

STEPS = 10

# styles whose scene the probes' 2-d atom style sph cannot hold, with the
# tests that run them on 1 and 2 ranks and across a restart
ELSEWHERE = {
    "fix_sph_grains": "granular.mpi.conservation_np2, granular.restart (3-d, atom_style hybrid sph sphere)",
}


def script(probe, plugin, restart_file, continue_from=None):
    scene, commands, outputs, options = PROBES[probe]
    atoms, regions, groups, state, walls = SCENES[scene]
    omp = options.get("omp", 0)
    suffix = "/omp" if omp else ""
    text = f"plugin load {plugin}\nunits si\ndimension 2\natom_style sph\natom_modify map array\n"
    text += "boundary p f p\n" if scene == "channel" else "boundary f f p\n"
    if omp:
        text += "package omp 2\n"
    if continue_from:
        text = f"plugin load {plugin}\n" + ("package omp 2\n" if omp else "")
        text += f"read_restart {continue_from}\n" + LATTICE + regions
    else:
        text += LATTICE + atoms + regions + options.get("groups", groups)
    # each atom's lattice site: atom IDs depend on the number of ranks
    text += "fix origin all property/atom i_site\n"
    if not continue_from:
        text += "variable site atom round(x/${dx}+100)*1000+round(y/${dx}+100)\nset group all i_site v_site\n"
    text += MATERIALS
    if not continue_from:
        text += state
    text += PAIRS.format(visc="sph/harmonic/visc" + suffix, heat="sph/cleary/heat" + suffix,
                         conduction=options.get("conduction", ""), flow=options.get("flow", ""))
    text += options.get("walls", walls) + commands + "\n"
    text += "compute rho all sph/rho/atom\ncompute esph all sph/e/atom\n"
    text += f"thermo_style custom step {outputs}\nthermo_modify format float %.17g\nthermo {STEPS}\n"
    if not continue_from:
        text += f"run {STEPS}\nwrite_restart {restart_file}\n"
    # a dump at the run's end (29Sep2021's write_dump wants computes current)
    text += (f"dump final all custom {STEPS} final.dump i_site x y vx vy c_rho c_esph\n"
             "dump_modify final sort 1 format float %.17g\n")
    text += f"run {STEPS}\n"
    return text


def run(lmp, text, np_, mpirun, workdir, name):
    path = os.path.join(workdir, f"in.{name}")
    with open(path, "w") as f:
        f.write(text)
    cmd = mpi_prefix(np_, mpirun) + [lmp, "-log", f"log.{name}", "-in", path]
    proc = subprocess.run(cmd, cwd=workdir, capture_output=True, text=True, env=mpi_env())
    output = proc.stdout + proc.stderr
    if proc.returncode != 0 or "ERROR" in output:
        sys.stderr.write(output[-3000:])
        sys.exit(f"FAIL: run {name} ({np_} ranks) stopped")
    os.replace(os.path.join(workdir, "final.dump"), os.path.join(workdir, f"{name}.dump"))
    return output


def last_thermo(output, outputs):
    """The style's outputs on the last thermo line."""
    lines = output.splitlines()
    heads = [k for k, line in enumerate(lines) if line.split()[:1] == ["Step"]]
    columns = lines[heads[-1]].split()
    rows = [line.split() for line in lines[heads[-1] + 1:]]
    rows = [r for r in rows if len(r) == len(columns) and re.match(r"^-?\d+$", r[0])]
    return dict(zip(columns[1:], (float(v) for v in rows[-1][1:])))


def atoms(path):
    with open(path) as f:
        lines = f.read().splitlines()
    # the last snapshot
    at = max(k for k, line in enumerate(lines) if line.startswith("ITEM: ATOMS"))
    names = [n[2:] if n[:2] in ("c_", "i_") else n for n in lines[at].split()[2:]]
    rows = [[float(v) for v in line.split()] for line in lines[at + 1:]]
    return {name: [r[c] for r in rows] for c, name in enumerate(names)}


def agree(check, a, b, label, rtol):
    if a["site"] != b["site"]:
        check(False, f"{label}: the atoms differ ({len(a['site'])} and {len(b['site'])})")
        return
    for name in ("x", "y", "vx", "vy", "rho", "esph"):
        finite = all(math.isfinite(v) for v in a[name] + b[name])
        scale = max(abs(v) for v in a[name]) or 1.0
        if name in ("x", "y"):
            scale = 1.0 / 12    # the particle spacing
        if name in ("vx", "vy"):
            scale = max(abs(v) for v in a["vx"] + a["vy"]) or 1.0
        worst = max(abs(p - q) for p, q in zip(a[name], b[name])) / scale
        check(finite and worst <= rtol,
              f"{label}: {name} finite, largest difference {worst:.2e} of {scale:.4g} <= {rtol:g}")


def agree_outputs(check, a, b, label, rtol):
    # a value that is 0 to round-off (a balance) is compared on the scale
    # of the largest output
    floor = 1e-12 * max(abs(v) for v in a.values())
    for key in a:
        ok = math.isfinite(a[key]) and math.isfinite(b[key]) and \
            abs(a[key] - b[key]) <= rtol * max(abs(a[key]), abs(b[key])) + floor
        check(ok, f"{label}: {key} {a[key]:.15g} and {b[key]:.15g}")


def is_number(word):
    try:
        float(word)
        return True
    except ValueError:
        return False


def mutations(line):
    """Bad forms of a style's command line: (what, line)."""
    words = line.split()
    head, args = words[:4], words[4:]    # fix|compute ID group style
    yield "no arguments", " ".join(head)
    if args:
        yield "last argument missing", " ".join(head + args[:-1])
    yield "an extra word", " ".join(words + ["extra"])
    yield "an extra number", " ".join(words + ["1.0"])
    yield "an empty group", " ".join([words[0], words[1], "nobody"] + words[3:])
    for k, word in enumerate(args):
        if is_number(word):
            for value in ("0", "-1", "1e300", "${nan}"):
                bad = list(args)
                bad[k] = value
                yield f"argument {k + 1} = {value}", " ".join(head + bad)
        elif not word.startswith("$"):
            bad = list(args)
            bad[k] = "nosuch"
            yield f"argument {k + 1} = nosuch", " ".join(head + bad)


def syntax(args, check):
    """Each bad form of each of the probe's command lines: no crash or hang; an error
    names the style (or stops at the command itself); a non-finite value is
    never taken silently. Accepted forms are listed for review."""
    scene, commands, outputs, options = PROBES[args.probe]
    good = script(args.probe, args.plugin, "probe.restart")
    good = good.replace(f"run {STEPS}\nwrite_restart probe.restart\n", "")
    good = good.replace("run {STEPS}\n".format(STEPS=STEPS), "run 2\n")
    prelude = "variable nan equal (1.0e308*10.0)-(1.0e308*10.0)\ngroup nobody empty\n"
    with tempfile.TemporaryDirectory() as tmp:
        # the package's styles and fix gravity, whose acceleration they read
        lines = [ln for ln in commands.splitlines()
                 if ln.split()[3].startswith("sph/") or ln.split()[3] == "gravity"]
        for line, what, bad in ((line, what, bad) for line in lines
                                for what, bad in mutations(line)):
            style = line.split()[3]
            text = good.replace(line, prelude + bad, 1)
            path = os.path.join(tmp, "in.bad")
            with open(path, "w") as f:
                f.write(text)
            try:
                proc = subprocess.run([args.lmp, "-log", "none", "-in", path], cwd=tmp,
                                      capture_output=True, text=True, env=mpi_env(), timeout=60)
            except subprocess.TimeoutExpired:
                check(False, f"{style} with {what}: no end within 60 s")
                continue
            output = proc.stdout + proc.stderr
            errors = [ln for ln in output.splitlines() if ln.startswith("ERROR")]
            warned = any(ln.startswith("WARNING") and style in ln for ln in output.splitlines())
            last = re.search(r"^Last (input line|command): (.*)$", output, re.M)
            if proc.returncode < 0 or (proc.returncode != 0 and not errors):
                check(False, f"{style} with {what}: crashed (exit {proc.returncode})")
            elif errors:
                at_command = last is not None and last.group(2).split()[:1] == [line.split()[0]]
                named = style in errors[0] or line.split()[1] in errors[0]
                check(at_command or named, f"{style} with {what}: {errors[0][:150]}")
            elif "${nan}" in bad:
                check(warned, f"{style} with {what}: a NaN taken without an error")
            else:
                print(f"note {style} with {what}: accepted{' with a warning' if warned else ''}")


def declared_styles():
    """The user-facing styles the sources declare (upper-case names are internal)."""
    found = []
    for header in sorted(glob.glob(os.path.join(SOURCES, "*.h"))):
        with open(header) as f:
            for kind, name in re.findall(r"^(Fix|Compute|Pair|Command)Style\(([^,]+),", f.read(),
                                         re.M):
                if name != name.upper():
                    found.append(f"{kind.lower()}_{name.replace('/', '_')}")
    return found


def main():
    parser = lammps_arguments(argparse.ArgumentParser(description=__doc__), ranks=False)
    parser.add_argument("--probe")
    parser.add_argument("--list", action="store_true")
    parser.add_argument("--list-syntax", action="store_true")
    parser.add_argument("--coverage", action="store_true")
    parser.add_argument("--syntax", action="store_true",
                        help="bad forms of the probe's style line instead")
    parser.add_argument("--rtol", type=float, default=1e-12)
    args = parser.parse_args()
    if args.list:
        print(";".join(PROBES))
        return
    if args.list_syntax:    # the probes that add a command line of their own
        print(";".join(name for name, probe in PROBES.items() if probe[1]))
        return
    check = Checks()
    if args.coverage:
        for style in declared_styles():
            if style in ELSEWHERE:
                check(True, f"style {style} is probed by {ELSEWHERE[style]}")
            else:
                check(style in PROBES, f"style {style} has a probe")
        check(len(declared_styles()) >= 20, f"{len(declared_styles())} styles found in {SOURCES}")
        finish(check.failures)
        return
    if args.syntax:
        syntax(args, check)
        finish(check.failures)
        return
    outputs = PROBES[args.probe][2]
    rtol = PROBES[args.probe][3].get("rtol", args.rtol)
    with tempfile.TemporaryDirectory() as tmp:
        restart = os.path.join(tmp, "probe.restart")
        out_a = run(args.lmp, script(args.probe, args.plugin, restart), 1, args.mpirun, tmp, "A")
        out_b = run(args.lmp, script(args.probe, args.plugin, os.path.join(tmp, "b.restart")), 2,
                    args.mpirun, tmp, "B")
        out_c = run(args.lmp, script(args.probe, args.plugin, None, continue_from=restart), 2,
                    args.mpirun, tmp, "C")
        a, b, c = (atoms(os.path.join(tmp, f"{n}.dump")) for n in "ABC")
        moved = max(abs(v) for v in a["vx"] + a["vy"]) > 0.0
        check(moved, "the fluid moves (the probe is not a still scene)")
        agree(check, a, b, "1 rank and 2 ranks", rtol)
        agree(check, a, c, "continuous and restarted on 2 ranks", rtol)
        thermo = [last_thermo(o, outputs) for o in (out_a, out_b, out_c)]
        agree_outputs(check, thermo[0], thermo[1], "1 rank and 2 ranks", rtol)
        agree_outputs(check, thermo[0], thermo[2], "continuous and restarted", rtol)
    finish(check.failures)


if __name__ == "__main__":
    main()
