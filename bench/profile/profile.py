#!/usr/bin/env python3
"""Where whole scenes spend their time: each scene of the speed issue is run
under `perf record` (sampling at 499 Hz, serial, one thread) for a window
of its time loop, after a delay that skips its set-up, and the samples'
self time is summed by function and by the package's components (flow
pair, its pressure-gradient correction, conduction pair, the consistent
conduction's factors, shifting, mirror walls, Adami's flow walls,
neighbour lists, ...).

  profile.py [--lmp build/lmp] [--plugin build/sphthermalplugin.so]
             [--scenes cavity air channel tank3d bodies] [--window 20]
             [--out bench/profile/out] [--results bench/profile/results.md]

Scenes (the examples' inputs at the examples' resolutions):
  cavity   examples/convection-cavity/in.cavity, Ra = 1e4, 40 x 40 (the main job)
  air      examples/convection-cavity/in.air, 154 x 154 (Reece et al. 2024's finest)
  channel  examples/forced-channel/in.channel, Re = 652, 20 across, 200 m, developed start
  tank3d   examples/mixing-tank-3d/in.tank3d, 16 across, two components
  bodies   examples/coupling-hot-bodies/in.bodies, n = 5 (rigid bodies in a fluid)

A sample is charged to the function it was taken in (perf report
--no-children): a component's share is the time spent in its own code, not
in what it calls. Writes the results file (a table of components by
scene, then each scene's largest functions); the perf data stay in --out.
Needs perf (Debian's linux-perf) and a kernel.perf_event_paranoid of 2 or
less. Wall times are not compared here: the window is the same for every
scene, and the scenes run one after another on an otherwise idle machine.
"""

import argparse
import os
import re
import shutil
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
EXAMPLES = os.path.join(ROOT, "examples")
sys.path.insert(0, os.path.join(ROOT, "tools"))

# (name, input, variables, seconds of set-up to skip)
SCENES = {
    "cavity": ("convection-cavity/in.cavity", {}, 3),
    "air": ("convection-cavity/in.air", {"n": 154}, 8),
    "channel": ("forced-channel/in.channel", {}, 5),
    "tank3d": ("mixing-tank-3d/in.tank3d", {"data": "tank.data"}, 5),
    "bodies": ("coupling-hot-bodies/in.bodies", {}, 3),
}

# a component: the first pattern that matches the function's name (or its library)
COMPONENTS = [
    ("pressure-gradient correction", r"update_gradient_correction"),
    ("flow pair (its density diffusion too)", r"PairSPHHarmonicVisc::eval|sphf_|sphe_tait|sphe_hydrostatic"),
    ("consistent conduction's factors", r"SPHConsistentWeights|SPHConductionWeights|SPHSupportPairs|PairSPHClearyHeat::update_pairs"),
    ("conduction pair", r"PairSPHClearyHeat::eval|sphc_"),
    ("per-atom state (density, pressure, volume)", r"sphe_|update_state|PairSPHHarmonicVisc::"),
    ("shifting", r"FixSPHShift"),
    ("kernel-support sums (free surfaces, walls)", r"SPHSupport"),
    # the ghost points' interpolation of the thermal walls (and of
    # sph/wall/adami 'surface'), and the thermal walls' own passes
    ("mirror walls", r"SPHMirror|^sphi_|FixSPHWall(Dirichlet|Adiabatic|Isothermal|Tally)"),
    ("Adami's flow walls (wall pressure, density, no-slip velocity)", r"FixSPHWallAdami"),
    ("rigid bodies", r"FixRigid|Rigid"),
    ("buoyancy, materials, other package fixes", r"FixSPH(Boussinesq|Materials|HoldVolume|DtReset|Mixing)|ComputeSPH"),
    ("time integration", r"FixSPH::|initial_integrate|final_integrate"),
    ("neighbour lists", r"NPair|NBin|NStencil|Neighbor::"),
    ("communication", r"Comm|pack_|unpack_"),
    ("maths library", r"^libm"),
]


def component(dso, symbol):
    name = ("libm " if dso.startswith("libm") else "") + symbol
    for label, pattern in COMPONENTS:
        if re.search(pattern, name):
            return label
    return "other"


def scene_command(args, scene, path, variables):
    """The scene's working directory (made, with the 3-d tank's particles)
    and its LAMMPS command line (also bench/profile/overhead.py)."""
    work = os.path.join(args.out, scene)
    os.makedirs(work, exist_ok=True)
    if scene == "tank3d":
        import mixing_tank
        variables = dict(variables, dx=mixing_tank.write_tank_data(16, os.path.join(work, "tank.data")))
    cmd = [args.lmp, "-in", os.path.join(EXAMPLES, path), "-var", "plugin", args.plugin, "-log", "none"]
    for k, v in variables.items():
        cmd += ["-var", k, str(v)]
    return work, cmd


def scene_arguments(doc, scenes, results):
    """The options both scripts take; more may be added before parse_args."""
    p = argparse.ArgumentParser(description=doc, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--lmp", default=os.path.join(ROOT, "build", "lmp"))
    p.add_argument("--plugin", default=os.path.join(ROOT, "build", "sphthermalplugin.so"))
    p.add_argument("--scenes", nargs="+", choices=list(scenes), default=list(scenes))
    p.add_argument("--out", default=os.path.join(HERE, "out"))
    p.add_argument("--results", default=os.path.join(HERE, results))
    return p


def record(args, scene):
    path, variables, delay = SCENES[scene]
    work, cmd = scene_command(args, scene, path, variables)
    data = os.path.join(work, "perf.data")
    perf = ["perf", "record", "-F", "499", "--delay", str(1000 * delay), "-o", data, "--"] + cmd
    env = dict(os.environ, OMP_NUM_THREADS="1")
    with open(os.path.join(work, "lmp.out"), "w") as out:
        proc = subprocess.run(["timeout", "-s", "INT", str(delay + args.window)] + perf, cwd=work, env=env,
                              stdout=out, stderr=subprocess.STDOUT)
    if proc.returncode not in (0, 124):
        sys.exit(f"profile.py: {scene}: perf record ended with {proc.returncode} (see {work}/lmp.out)")
    report = subprocess.run(["perf", "report", "-i", data, "--no-children", "--stdio", "--sort", "dso,symbol",
                             "-q", "-t", "|"], capture_output=True, text=True, check=True).stdout
    functions = []
    for line in report.splitlines():
        parts = line.split("|")
        if len(parts) < 3 or not parts[0].strip().endswith("%"):
            continue
        share = float(parts[0].strip().rstrip("%"))
        symbol = re.sub(r"^\[.\]\s*", "", parts[2].strip())
        functions.append((share, parts[1].strip(), symbol))
    samples = re.search(r"\((\d+) samples\)", open(os.path.join(work, "lmp.out")).read())
    return {"command": " ".join(os.path.relpath(c, ROOT) if os.path.isabs(c) else c for c in cmd),
            "samples": int(samples.group(1)) if samples else 0, "functions": functions}


def write_results(args, profiles):
    labels = [label for label, _ in COMPONENTS] + ["other"]
    shares = {s: {label: 0.0 for label in labels} for s in profiles}
    for s, p in profiles.items():
        for share, dso, symbol in p["functions"]:
            shares[s][component(dso, symbol)] += share
    lines = ["# Where whole scenes spend their time (perf)", "",
             "Written by `bench/profile/profile.py` (do not edit): the share of each",
             "scene's perf samples (self time, serial run, one thread) by component,",
             f"over a window of {args.window:g} s of its time loop.", "",
             "| component | " + " | ".join(profiles) + " |", "|---|" + "---|" * len(profiles)]
    for label in labels:
        if any(shares[s][label] >= 0.05 for s in profiles):
            lines.append(f"| {label} | " + " | ".join(f"{shares[s][label]:.1f} %" for s in profiles) + " |")
    lines.append("| samples | " + " | ".join(str(profiles[s]["samples"]) for s in profiles) + " |")
    for s, p in profiles.items():
        lines += ["", f"## {s}", "", f"`{p['command']}`", "", "| share | library | function |", "|---|---|---|"]
        for share, dso, symbol in p["functions"][:args.top]:
            lines.append(f"| {share:.1f} % | {dso} | `{symbol[:110]}` |")
    with open(args.results, "w") as f:
        f.write("\n".join(lines) + "\n")
    print("\n".join(lines[:len(labels) + 12]))


def main():
    p = scene_arguments(__doc__, SCENES, "results.md")
    p.add_argument("--window", type=float, default=20.0, help="seconds of the time loop recorded (default 20)")
    p.add_argument("--top", type=int, default=12, help="functions listed per scene (default 12)")
    args = p.parse_args()
    if shutil.which("perf") is None:
        sys.exit("profile.py: needs perf (Debian: apt install linux-perf)")
    args.lmp, args.plugin = os.path.abspath(args.lmp), os.path.abspath(args.plugin)
    args.out = os.path.abspath(args.out)
    profiles = {s: record(args, s) for s in args.scenes}
    write_results(args, profiles)


if __name__ == "__main__":
    main()
