#!/usr/bin/env python3
"""Stress suite (coarse): every flow and convection example that has a
small CI-size case, run from that case ("base") at 2 times its resolution,
at 2 times its Reynolds number or 10 times its Rayleigh number (where the
input has such a variable), and from a jittered start (the fluid particles
displaced at random by up to 0.1 spacing, the inputs' jitter and seed
variables) with 3 seeds. Each run records: stable or not (exit code 0, no
ERROR, no lost atoms, a finite last thermo row and finite analysis), the
error against the example's reference where it has one (the example's own
analysis), and the wall time. Variants too costly for the coarse suite are
listed as "not run (cost)"; --costly runs them too.

  stress.py [--lmp build/lmp] [--plugin build/sphthermalplugin.so]
            [--cases cavity poiseuille ...] [--variants base jitter1 ...]
            [--out bench/stress/out] [--results bench/stress/results.md]
  stress.py --quick        the CI subset (2 short jittered runs, under
                           90 s): exit 1 unless each is stable and finite

The results table is written from the records (record.json) of every run
in --out, so that cases run by separate invocations share one table; each
invocation's command line is listed at the top. The same table, as an
reStructuredText list-table, is written into the stress section of
doc/src/Stability_sphthermal.rst (between its two marker comments):

  stress.py --doc          only that: the doc's table from results.md
  stress.py --doc-check    exit 1 unless the doc's table is results.md's
                           (the test docs.stress_table)
"""

import argparse
import json
import math
import os
import re
import shlex
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
TOOLS = os.path.join(ROOT, "tools")
sys.path.insert(0, TOOLS)

from sphthermal_tools.log import late_rows, longest_thermo_table  # noqa: E402
from cavity_fv import DE_VAHL_DAVIS  # noqa: E402

EX = os.path.join(ROOT, "examples")
RESULTS = os.path.join(HERE, "results.md")
DOC = os.path.join(ROOT, "doc", "src", "Stability_sphthermal.rst")
DOC_BEGIN = ".. the stress table, written by bench/stress/stress.py from its results.md"
DOC_END = ".. end of the stress table"
SEEDS = (1, 2, 3)
JITTER = "0.1"


# ---------------------------------------------------------------- analyses
# each: (workdir, log text, variables) -> (error text, finite: bool)

def number(text):
    try:
        return float(text)
    except ValueError:
        return float("nan")


def analyse_cavity(work, text, var):
    """Mean Nu (hot and cold walls) of the last third of the thermo rows
    against de Vahl Davis 1983."""
    table = longest_thermo_table(text)
    if table is None or "c_nu_hot[1]" not in table:
        return "no thermo table", False
    late = late_rows(table)
    nu = 0.5 * (table["c_nu_hot[1]"][late].mean() + table["c_nu_cold[1]"][late].mean())
    if not math.isfinite(nu):
        return "Nu not finite", False
    ref = DE_VAHL_DAVIS.get(float(var["ra"]))
    if ref is None:
        return f"Nu {nu:.4f} (no reference)", True
    return f"Nu {nu:.4f} vs {ref[0]} (de Vahl Davis): {100 * (nu / ref[0] - 1):+.2f} %", True


def python_env():
    env = dict(os.environ)
    env["PYTHONPATH"] = TOOLS + (os.pathsep + env["PYTHONPATH"] if env.get("PYTHONPATH") else "")
    env["MPLBACKEND"] = "Agg"
    return env


def run_analysis(work, args):
    done = subprocess.run([sys.executable] + args, cwd=work, env=python_env(),
                          capture_output=True, text=True)
    with open(os.path.join(work, "analysis.txt"), "w") as f:
        f.write(done.stdout + done.stderr)
    return done.stdout + done.stderr


def analyse_shear_flow(example, scale):
    """examples/<example>/analyse.py: |u - exact series| in % of the
    velocity scale (u_max of Poiseuille, V0 of Couette)."""
    def analyse(work, text, var):
        out = run_analysis(work, [os.path.join(EX, example, "analyse.py"),
                                  var["out"], "--png", "flow.png"])
        m = re.search(r"max error (\S+) % of \S+ \(all times\), (\S+) % at t = (\S+) s", out)
        if not m:
            return "analysis failed", False
        worst, steady = number(m.group(1)), number(m.group(2))
        ok = math.isfinite(worst) and math.isfinite(steady)
        return (f"u: max {worst:.3f} %, at t = {m.group(3)} s {steady:.3f} % of {scale} "
                "(exact series)"), ok
    return analyse


def analyse_column(work, text, var):
    """examples/flow-hydrostatic/analyse.py: the largest speed in % of
    sqrt(g H) and the pressure's error in % of rho0 g H at the end."""
    out = run_analysis(work, [os.path.join(EX, "flow-hydrostatic", "analyse.py"), var["out"],
                              "--png", "column.png", "--label", "stress"])
    m = re.search(r"largest speed (\S+) % of sqrt\(g H\), pressure error (\S+) %", out)
    if not m:
        return "analysis failed", False
    speed, pressure = number(m.group(1)), number(m.group(2))
    return (f"largest speed {speed:.3f} % of sqrt(g H); pressure {pressure:.3f} % of rho0 g H "
            "(exact)"), math.isfinite(speed) and math.isfinite(pressure)


def analyse_channel(work, text, var):
    """examples/forced-channel/analyse.py: T against tools/channel_fv.py in %
    of T_w - T_in (largest over its 5 stations), u against Poiseuille."""
    out = run_analysis(work, [os.path.join(EX, "forced-channel", "analyse.py"),
                              var["out"] + ".dump", "--walls", var["walls"], "--ksk", var["ksk"],
                              "--re", var["re"], "--n", var["n"], "--png", "channel.png"])
    terr = [number(v) for v in re.findall(r"largest error (\S+) % of T_w - T_in", out)]
    m = re.search(r"largest \|u - u_Poiseuille\| (\S+) % of u_max", out)
    if not terr or not m:
        return "analysis failed", False
    t, u = max(terr), number(m.group(1))
    ok = all(math.isfinite(v) for v in terr) and math.isfinite(u)
    return f"T: max {t:.3f} % of T_w - T_in (finite volume); u: max {u:.3f} % of u_max", ok


def analyse_rb(work, text, var):
    """examples/convection-rayleigh-benard/analyse.py nu: mean Nu over
    t >= 0.4 against tools/rb_fv.py (Ra 5e3 to 3e4)."""
    log = os.path.join(work, "log.lammps")
    out = run_analysis(work, [os.path.join(EX, "convection-rayleigh-benard", "analyse.py"),
                              "nu", log, "--from", "0.4"])
    m = re.search(r"^\| \S+ \| \d+ \| (\S+) \(.*?\) \| (\S+) \+- \S+ \| (\S+) % \|", out, re.M)
    if m:
        nu = number(m.group(1))
        return (f"Nu {nu:.4f} vs {m.group(2)} (tools/rb_fv.py): {m.group(3)} %",
                math.isfinite(nu))
    if "no reference" in out:
        table = longest_thermo_table(text)
        if table is None:
            return "no thermo table", False
        use = table["Time"] >= 0.4
        nu = 0.5 * (table["c_nu_hot[1]"][use].mean() + table["c_nu_cold[1]"][use].mean())
        return f"Nu {nu:.4f} (no reference)", math.isfinite(nu)
    return "analysis failed", False


def analyse_tank(work, text, var):
    """No reference: the final mean T (the run's own 'final:' line)."""
    m = re.search(r"^final: mean T at t = \S+ s: fluid (\S+) K.*largest speed (\S+) m/s", text, re.M)
    if not m:
        return "no reference (no final line)", False
    t, v = number(m.group(1)), number(m.group(2))
    return f"no reference (final mean T {t:.4f} K, largest speed {v:.4g} m/s)", \
        math.isfinite(t) and math.isfinite(v)


def analyse_tank3d(work, text, var):
    """No reference: the particles inside, the density's range and the
    temperature's axisymmetry at the end (tools/mixing_tank.py)."""
    import mixing_tank
    from sphthermal_tools.dump import read_frames
    m = re.search(r"^final: t = \S+ s, mean T (\S+) K, (\d+) fluid atoms, (\d+) inside", text, re.M)
    path = os.path.join(work, var["out"] + ".final")
    if not m or not os.path.exists(path):
        return "no reference (no final line or dump)", False
    frame = read_frames(path)[-1][1]
    fluid = mixing_tank.fluid_of(frame, 3)
    rho = frame["c_rho"][fluid] / mixing_tank.RHO0 - 1
    (t_spread, _), _ = mixing_tank.symmetry_3d({k: v[fluid] for k, v in frame.items()}, float(var["dx"]))
    finite = all(math.isfinite(x) for x in (number(m.group(1)), rho.min(), rho.max(), t_spread))
    return (f"no reference ({m.group(3)} of {m.group(2)} fluid particles inside; density "
            f"{100 * rho.min():+.2f} to {100 * rho.max():+.2f} % of rho0; T axisymmetric to "
            f"{t_spread:.1e} of theta_H - theta_C)"), finite


def analyse_open_channel(work, text, var):
    """examples/open-channel/analyse.py: the developed profile against
    Poiseuille's in % of 1.5 U and -dp/dx against 12 mu U / H^2 (x >= 3 H,
    from t = tend / 2), and at Re 20 the centre speed of the entrance
    against tools/channel_entrance.py's."""
    args = [os.path.join(EX, "open-channel", "analyse.py"), var["out"] + ".dump", "--re", var["re"],
            "--c0", "2.0", "--n", var["n"], "--from", str(float(var["tend"]) / 2)]
    if float(var["re"]) == 20.0:
        args += ["--reference", os.path.join(EX, "open-channel", "entrance_re20.txt")]
    out = run_analysis(work, args)
    m = re.search(r"profile within (\S+) % of 1.5 U; .*\((\S+) %\)", out)
    if not m:
        return "analysis failed", False
    profile, gradient = number(m.group(1)), number(m.group(2))
    entrance = re.search(r"largest difference (\S+) of 1.5 U", out)
    result = f"profile {profile:.2f} % of 1.5 U, -dp/dx {gradient:+.2f} % (Poiseuille)"
    if entrance:
        result += f"; entrance centre speed {entrance.group(1)} of 1.5 U (tools/channel_entrance.py)"
    return result, math.isfinite(profile) and math.isfinite(gradient)


def analyse_open_cylinder(work, text, var):
    """examples/open-cylinder/analyse.py: the mean C_D (from t = tend / 2)
    against Schafer and Turek's interval at Re 20, and the heated
    cylinder's Nu against tools/cylinder_heat_fe.py's."""
    args = [os.path.join(EX, "open-cylinder", "analyse.py"), var["out"] + ".forces",
            "--from", str(float(var["tend"]) / 2)]
    with open(os.path.join(TOOLS, "cylinder_heat_fe_results.txt")) as f:
        nu_ref = re.search(r"^Nu *= *(\S+)", f.read(), re.M).group(1)
    reference = float(var["re"]) == 20.0
    if reference:
        args += ["--nu-ref", nu_ref]
    out = run_analysis(work, args)
    drag = re.search(r"^C_D +mean (\S+) .*?(?:error (\S+) %)?$", out, re.M)
    nu = re.search(r"^Nu +mean (\S+) .*?(?:error (\S+) %)?$", out, re.M)
    if not drag or not nu:
        return "analysis failed", False
    cd, nu_mean = number(drag.group(1)), number(nu.group(1))
    finite = math.isfinite(cd) and math.isfinite(nu_mean)
    if not reference:
        return f"no reference (C_D {cd:.4f}, Nu {nu_mean:.4f})", finite
    return (f"C_D {cd:.4f}, {drag.group(2)} % (Schafer and Turek); Nu {nu_mean:.4f}, "
            f"{nu.group(2)} % (tools/cylinder_heat_fe.py)"), finite


def cylinder_data(work, var):
    """The cylinder's rings (examples/open-cylinder/cylinder_rings.py), n
    per diameter."""
    var = dict(var)
    data = os.path.join(work, "cylinder.data")
    subprocess.run([sys.executable, os.path.join(EX, "open-cylinder", "cylinder_rings.py"), var["n"],
                    data], check=True, capture_output=True, env=python_env())
    var["data"] = data
    return var


def tank3d_data(work, var):
    """The particles of the 3-D tank (tools/mixing_tank.py), n across."""
    import mixing_tank
    var = dict(var)
    data = os.path.join(work, "tank.data")
    var["dx"] = repr(mixing_tank.write_tank_data(int(var.pop("n")), data))
    var["data"] = data
    return var


# ---------------------------------------------------------------- the cases
# variants: (name, changed variables, None or the reason it is not run)

# the reason of the variants left out for their cost (--costly runs them)
COSTLY = "not run (cost"


def jitters():
    return [(f"jitter seed {s}", {"jitter": JITTER, "seed": str(s)}, None) for s in SEEDS]


def shear_flow_case(example, name, what, scale):
    """The Poiseuille and Couette flows: one input shape, Re fixed."""
    return dict(
        input=f"{example}/in.{name}",
        what=f"{what}, Re 65.2, 20 across, 4 columns, to t = 1200 s",
        base={"n": "20", "ncol": "4", "out": f"{name}.dump"},
        variants=[("base", {}, None), ("2x resolution", {"n": "40", "ncol": "8"}, None),
                  ("2x Re", {}, "not applicable (Re is fixed in the input)")] + jitters(),
        analyse=analyse_shear_flow(example, scale))


CASES = {
    "cavity": dict(
        input="convection-cavity/in.cavity-options",
        what="differentially heated cavity, Ra 1e4, 20 x 20, to t = 0.3",
        base={"ra": "1e4", "n": "20", "tend": "0.3", "out": "cavity.dump"},
        variants=[("base", {}, None), ("2x resolution", {"n": "40"}, None),
                  ("10x Ra", {"ra": "1e5"}, None)] + jitters(),
        analyse=analyse_cavity),
    "poiseuille": shear_flow_case("flow-poiseuille", "poiseuille", "transient Poiseuille flow",
                                  "u_max"),
    "couette": shear_flow_case("flow-couette", "couette", "Couette start-up", "V0"),
    "column": dict(
        input="flow-hydrostatic/in.hydrostatic",
        what="water column at rest under gravity, 20 x 40, 20000 steps (t = 1.6 s)",
        base={"nx": "20", "ny": "40", "steps": "20000", "out": "hydrostatic"},
        variants=[("base", {}, None),
                  ("2x resolution", {"nx": "40", "ny": "80"}, COSTLY + ": 8 times the base)"),
                  ("2x Re", {}, "not applicable (a fluid at rest)")] + jitters(),
        analyse=analyse_column),
    "channel": dict(
        input="forced-channel/in.channel",
        what="heated channel, Re 65.2, 10 across, from the developed flow to t = 800 s",
        base={"n": "10", "tend": "800", "re": "65.2", "walls": "dirichlet", "ksk": "1",
              "shift": "yes", "start": "developed", "every": "800", "out": "channel"},
        variants=[("base", {}, None),
                  ("2x resolution", {"n": "20"}, COSTLY + ": 8 times the base)"),
                  ("2x Re", {"re": "130.4"}, None)] + jitters(),
        analyse=analyse_channel),
    "rb": dict(
        input="convection-rayleigh-benard/in.rb",
        what="Rayleigh-Benard convection, Ra 1e4, 16 per H, W = 2H, to t = 0.6",
        base={"settings": "convection", "ra": "1e4", "n": "16", "tend": "0.6"},
        variants=[("base", {}, None),
                  ("2x resolution", {"n": "32"}, COSTLY + ": 8 times the base)"),
                  ("10x Ra", {"ra": "1e5"}, None)] + jitters(),
        analyse=analyse_rb),
    "tank": dict(
        input="mixing-tank-2d/in.tank",
        what="two-component heated tank (2-D), 16 x 16, to t = 40 s",
        base={"n": "16", "tend": "40", "out": "tank.dump"},
        variants=[("base", {}, None),
                  ("2x resolution", {"n": "32"}, COSTLY + ": 8 times the base)"),
                  ("2x Re / 10x Ra", {}, "not applicable (the fluid's properties are fixed)")]
        + jitters(),
        analyse=analyse_tank),
    "tank3d": dict(
        input="mixing-tank-3d/in.tank3d",
        what="two-component heated cylindrical tank (3-D), 10 across, to t = 1 s",
        base={"n": "10", "tend": "1.0", "every": "100", "dumpdt": "0.5", "out": "tank.dump",
              "mixing": "mixing.txt"},
        prepare=tank3d_data,
        variants=[("base", {}, None),
                  ("2x resolution", {"n": "20"}, None),
                  ("2x Re / 10x Ra", {}, "not applicable (the fluid's properties are fixed)")]
        + jitters(),
        analyse=analyse_tank3d),
    "open-channel": dict(
        input="open-channel/in.channel",
        what="channel with an inlet and an outlet (fix sph/open), uniform inflow, Re 20, 10 across, "
             "to t = 30 s",
        base={"n": "10", "re": "20", "inflow": "uniform", "tend": "30", "every": "1",
              "out": "channel"},
        variants=[("base", {}, None), ("2x resolution", {"n": "20"}, None),
                  ("2x Re", {"re": "40"}, None)] + jitters(),
        analyse=analyse_open_channel),
    "open-cylinder": dict(
        input="open-cylinder/in.cylinder",
        what="heated cylinder in a channel (Schafer and Turek 2D-1), Re 20, 10 per diameter, "
             "to t = 4 s",
        base={"n": "10", "re": "20", "tend": "4", "heat": "yes", "out": "cylinder"},
        prepare=cylinder_data,
        variants=[("base", {}, None),
                  ("2x resolution", {"n": "20"}, COSTLY + ": 8 times the base)"),
                  ("2x Re", {"re": "40"}, None)] + jitters(),
        analyse=analyse_open_cylinder),
}

# the CI subset: short jittered runs (under 90 s in all)
QUICK = [
    ("cavity", "quick: 12 x 12, jitter seed 1, to t = 0.1",
     {"ra": "1e4", "n": "12", "tend": "0.1", "jitter": JITTER, "seed": "1", "out": "cavity.dump"}),
    ("poiseuille", "quick: 20 across, 4 columns, jitter seed 1",
     {"n": "20", "ncol": "4", "jitter": JITTER, "seed": "1", "out": "poiseuille.dump"}),
]


# ---------------------------------------------------------------- running

def slug(text):
    return re.sub(r"[^A-Za-z0-9]+", "-", text).strip("-").lower()


def final_row_finite(text):
    table = longest_thermo_table(text)
    if table is None:
        return False
    return all(math.isfinite(col[-1]) for col in table.values())


def run_case(args, case, variant, var, cmdline):
    """Runs one input in its own directory; returns the record."""
    spec = CASES[case]
    work = os.path.join(args.out, case, slug(variant))
    os.makedirs(work, exist_ok=True)
    log = os.path.join(work, "log.lammps")
    if spec.get("prepare"):
        var = spec["prepare"](work, var)
    cmd = [args.lmp, "-in", os.path.join(EX, spec["input"]), "-var", "plugin", args.plugin]
    for name, value in var.items():
        cmd += ["-var", name, value]
    cmd += ["-log", log]
    print(f"{case} / {variant}: {' '.join(shlex.quote(c) for c in cmd)}", flush=True)
    start = time.time()
    done = subprocess.run(cmd, cwd=work, capture_output=True, text=True)
    wall = time.time() - start
    with open(os.path.join(work, "screen.txt"), "w") as f:
        f.write(done.stdout + done.stderr)
    text = open(log).read() if os.path.exists(log) else done.stdout
    whole = done.stdout + done.stderr
    problems = []
    if done.returncode != 0:
        problems.append(f"exit code {done.returncode}")
    if re.search(r"^ERROR", whole, re.M):
        problems.append("ERROR")
    if "Lost atoms" in whole:
        problems.append("lost atoms")
    if not final_row_finite(text):
        problems.append("last thermo row not finite")
    if re.search(r"^final.*\b(nan|inf)\b", whole, re.M | re.I):
        problems.append("nan/inf in the final line")
    error, finite = ("not analysed", True)
    if not problems:
        error, finite = spec["analyse"](work, text, var)
        if not finite:
            problems.append(f"analysis: {error}")
    stable = not problems
    record = dict(case=case, variant=variant, stable=stable, problems=problems,
                  error=error if stable else "-", wall=wall, variables=var,
                  command=" ".join(shlex.quote(c) for c in cmd), invocation=cmdline,
                  what=spec["what"])
    with open(os.path.join(work, "record.json"), "w") as f:
        json.dump(record, f, indent=1)
    print(f"  {'stable' if stable else 'UNSTABLE: ' + '; '.join(problems)}, {error}, {wall:.1f} s",
          flush=True)
    return record


def skipped_record(args, case, variant, reason, cmdline):
    record = dict(case=case, variant=variant, stable=None, problems=[], error=reason, wall=None,
                  variables={}, command="", invocation=cmdline, what=CASES[case]["what"])
    work = os.path.join(args.out, case, slug(variant))
    os.makedirs(work, exist_ok=True)
    with open(os.path.join(work, "record.json"), "w") as f:
        json.dump(record, f, indent=1)
    return record


def previous_results(path):
    """The rows of an earlier results table, {(case, variant): record}, and
    its invocations: a work directory of another machine is not here, and
    its rows must not be lost."""
    rows, invocations = {}, []
    if not os.path.exists(path):
        return rows, invocations
    lines = open(path).read().splitlines()
    for line in lines:
        if line.startswith("    bench/stress/stress.py"):
            invocations.append(line.strip())
        cells = [c.strip() for c in line.strip().strip("|").split("|")]
        if not line.startswith("| ") or len(cells) != 5 or cells[0] in ("case", "---"):
            continue
        case, _, what = cells[0].partition(": ")
        stable = {"yes": True, "**no**": False}.get(cells[2])
        rows[(case, cells[1])] = dict(
            case=case, variant=cells[1], stable=stable, error=cells[3], problems=[cells[3]],
            wall=None if cells[4] == "-" else float(cells[4]), invocation=None, what=what)
    whats = {case: r["what"] for (case, _), r in rows.items() if r["what"]}
    for r in rows.values():
        r["what"] = whats.get(r["case"], r["what"])
    return rows, invocations


def row_cells(rec):
    """stable, error and wall time of a record as the tables print them."""
    stable = {True: "yes", False: "**no**", None: "-"}[rec["stable"]]
    error = rec["error"] if rec["stable"] is not False else "; ".join(rec["problems"])
    wall = f"{rec['wall']:.0f}" if rec["wall"] is not None else "-"
    return [stable, error, wall]


def write_results(args, records):
    """The table of every record in args.out (and the skipped variants), in
    the order of CASES; rows of the earlier table that neither has are kept."""
    previous, invocations = previous_results(args.results)
    rows = []
    for case, spec in CASES.items():
        ran = False
        for variant, _, skip in spec["variants"]:
            rec = records.get((case, variant))
            if rec is None:
                path = os.path.join(args.out, case, slug(variant), "record.json")
                if os.path.exists(path):
                    rec = json.load(open(path))
            if rec is None:
                rec = previous.get((case, variant))
            if rec is None and skip and ran:
                rec = dict(case=case, variant=variant, stable=None, problems=[], error=skip,
                           wall=None, invocation=None, what=spec["what"])
            if rec is None:
                continue
            ran = ran or rec["stable"] is not None
            rows.append(rec)
            if rec["invocation"] and rec["invocation"] not in invocations:
                invocations.append(rec["invocation"])
    lines = ["# Stress suite: results", "",
             "Written by `bench/stress/stress.py` (do not edit); made with", ""]
    lines += [f"    {inv}" for inv in invocations]
    lines += ["", "Serial runs (one MPI rank) on a shared 2-core machine: wall times are rough. "
              "Jitter: the fluid particles displaced at random by up to "
              f"{JITTER} spacing in x and y (seeds {', '.join(map(str, SEEDS))}). Stable: exit "
              "code 0, no ERROR, no lost atoms, a finite last thermo row and a finite analysis.", "",
              "| case | variant | stable | error | wall time (s) |", "|---|---|---|---|---|"]
    seen = set()
    for rec in rows:
        case = rec["case"]
        name = case if case in seen else f"{case}: {rec['what']}"
        seen.add(case)
        lines.append("| " + " | ".join([name, rec["variant"]] + row_cells(rec)) + " |")
    lines += ["", "The LAMMPS command of each run: `record.json` in its directory under the "
              "work directory (`--out`)."]
    with open(args.results, "w") as f:
        f.write("\n".join(lines) + "\n")
    print(f"wrote {args.results}")


def doc_table(results):
    """The rst list-table of the rows of results.md, in its order."""
    rows, _ = previous_results(results)
    table = [["case", "variant", "stable", "error", "wall time (s)"]]
    for r in rows.values():
        table.append([r["case"], r["variant"]] + row_cells(r))
    lines = [".. list-table::", "   :header-rows: 1", ""]
    for cells in table:
        lines.append(f"   * - {cells[0]}")
        lines += [f"     - {c}" for c in cells[1:]]
    return lines


def doc_with_table(results, doc):
    """The doc page's text with the table between its markers made anew."""
    text = open(doc).read().split("\n")
    if DOC_BEGIN not in text or DOC_END not in text:
        sys.exit(f"stress: {doc} lacks the marker lines '{DOC_BEGIN}' and '{DOC_END}'")
    begin, end = text.index(DOC_BEGIN), text.index(DOC_END)
    return "\n".join(text[:begin + 1] + [""] + doc_table(results) + [""] + text[end:])


def write_doc(results):
    text = doc_with_table(results, DOC)    # read before the page is opened for writing
    with open(DOC, "w") as f:
        f.write(text)
    print(f"wrote the stress table of {DOC}")


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--lmp", default=os.path.join(ROOT, "build", "lmp"))
    p.add_argument("--plugin", default=os.path.join(ROOT, "build", "sphthermalplugin.so"))
    p.add_argument("--cases", nargs="+", choices=list(CASES), default=list(CASES))
    p.add_argument("--variants", nargs="+", help="only these variants (names as in the table, "
                   "e.g. base '2x resolution' 'jitter seed 1')")
    p.add_argument("--quick", action="store_true", help="the CI subset; exit 1 unless stable and finite")
    p.add_argument("--costly", action="store_true",
                   help="also run the variants the coarse suite leaves out for their cost")
    p.add_argument("--var", action="append", default=[], metavar="NAME=VALUE",
                   help="with --quick: change a variable of every quick run (a check of the check)")
    p.add_argument("--out", default=os.path.join(HERE, "out"), help="work directory")
    p.add_argument("--results", help="Markdown table (default bench/stress/results.md; "
                   "with --quick none unless given)")
    p.add_argument("--doc", action="store_true", help="no runs: the doc page's table from --results")
    p.add_argument("--doc-check", action="store_true",
                   help="no runs: exit 1 unless the doc page's table is that of --results")
    args = p.parse_args()
    if args.doc or args.doc_check:
        results = args.results or RESULTS
        new = doc_with_table(results, DOC)
        if args.doc_check:
            if new != open(DOC).read():
                print(f"FAIL: the stress table of {DOC} is not that of {results}: "
                      "run bench/stress/stress.py --doc")
                return 1
            print(f"ok: the stress table of {os.path.basename(DOC)} is that of {results}")
            return 0
        write_doc(results)
        return 0
    args.lmp, args.plugin, args.out = (os.path.abspath(a) for a in (args.lmp, args.plugin, args.out))
    cmdline = " ".join(shlex.quote(a) for a in
                       ["bench/stress/stress.py"] + [a for a in sys.argv[1:]])
    for path in (args.lmp, args.plugin):
        if not os.path.exists(path):
            sys.exit(f"stress: no {path}")

    if args.quick:
        total, failed = time.time(), []
        for case, variant, var in QUICK:
            var = dict(var)
            for kv in args.var:
                name, value = kv.split("=", 1)
                var[name] = value
            rec = run_case(args, case, variant, var, cmdline)
            if not rec["stable"]:
                failed.append(f"{case} ({'; '.join(rec['problems'])})")
        total = time.time() - total
        if args.results:
            write_quick(args, cmdline)
        if failed:
            print(f"FAIL: not stable or not finite: {', '.join(failed)} ({total:.0f} s)")
            return 1
        print(f"quick stress: {len(QUICK)} runs stable and finite ({total:.0f} s)")
        return 0

    if args.results is None:
        args.results = RESULTS
    records = {}
    for case in args.cases:
        for variant, change, skip in CASES[case]["variants"]:
            if args.variants and variant not in args.variants:
                continue
            if skip and not (args.costly and skip.startswith(COSTLY)):
                records[(case, variant)] = skipped_record(args, case, variant, skip, cmdline)
                continue
            var = dict(CASES[case]["base"])
            var.update(change)
            records[(case, variant)] = run_case(args, case, variant, var, cmdline)
    write_results(args, records)
    if os.path.abspath(args.results) == RESULTS:
        write_doc(args.results)
    unstable = [k for k, r in records.items() if r["stable"] is False]
    if unstable:
        print("not stable: " + ", ".join(f"{c} / {v}" for c, v in unstable))
    return 0


def write_quick(args, cmdline):
    lines = [f"Written by `{cmdline}`", "", "| case | variant | stable | error | wall time (s) |",
             "|---|---|---|---|---|"]
    for case, variant, _ in QUICK:
        rec = json.load(open(os.path.join(args.out, case, slug(variant), "record.json")))
        error = rec["error"] if rec["stable"] else "; ".join(rec["problems"])
        lines.append(f"| {case} | {variant} | {'yes' if rec['stable'] else '**no**'} | {error} | "
                     f"{rec['wall']:.0f} |")
    with open(args.results, "w") as f:
        f.write("\n".join(lines) + "\n")


if __name__ == "__main__":
    sys.exit(main())
