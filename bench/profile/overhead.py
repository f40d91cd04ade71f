#!/usr/bin/env python3
"""What a whole scene costs beyond its physics: each scene of the speed
issue is run for a short stretch of its flow, and its loop time per
particle-step is set against the bare shared thermal-flow loop (pair
sph/harmonic/visc + sph/cleary/heat, loop shared, fix sph; no walls,
corrections, shifting or density diffusion) on a periodic box of about as
many particles, at the scene's kernel, h / dx and dimension
(bench/flow/in.bench). The ratio is the overhead of everything else: the
corrections, walls, shifting, other fixes, neighbour lists.

The same box with LAMMPS's own styles (sph/taitwater/morris +
sph/heatconduction, Lucy kernel, h = 2.6 dx, LAMMPS's example setting)
against ours on the same particles gives the whole-step ratio (loop time,
not the pair's share).

  overhead.py [--lmp build/lmp] [--plugin build/sphthermalplugin.so]
              [--scenes cavity air channel tank3d bodies cavity-held channel-held] [--repeat 3]
              [--before PLUGIN --before-label COMMIT]
              [--out bench/profile/out] [--results bench/profile/overhead.md]

--before: a plugin built from an earlier commit (for instance
`git stash; cmake --build build --target sphthermalplugin;
cp build/sphthermalplugin.so /tmp/before.so; git stash pop`), whose scenes
run in the same session beside --plugin's, for a table of before and after.

Serial, one thread; each figure the fastest of --repeat runs (the scenes
one run each unless --repeat-scenes). Run on an otherwise idle machine.
"""

import argparse
import importlib.util
import os
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
BOX = os.path.join(ROOT, "bench", "flow", "in.bench")
sys.path.insert(0, os.path.join(ROOT, "tools"))
from sphthermal_tools.log import loop_runs  # noqa: E402
# this directory's profile.py (the scenes' command lines), by its path: the
# standard library has a module of that name
_spec = importlib.util.spec_from_file_location("scene_profile", os.path.join(HERE, "profile.py"))
profile = importlib.util.module_from_spec(_spec)
_spec.loader.exec_module(profile)

# name: (input, variables for a short stretch, kernel, h / dx, dimension),
# the kernels and h / dx as in the inputs
SCENES = {
    "cavity": ("convection-cavity/in.cavity", {"tend": 0.05}, "wendland", 2.0, 2),
    "air": ("convection-cavity/in.air", {"n": 154, "seconds": 0.1, "every": 100000}, "wendland", 2.0, 2),
    "channel": ("forced-channel/in.channel", {"tend": 1.0}, "quintic", 1.3, 2),
    "tank3d": ("mixing-tank-3d/in.tank3d", {"data": "tank.data", "tend": 0.1, "dumpdt": 100.0},
               "wendland", 2.0, 3),
    "bodies": ("coupling-hot-bodies/in.bodies", {"tend": 0.2}, "wendland", 1.3, 2),
    # the flagship and the channel with the corrections made at neighbour-list
    # builds only (pair sph/cleary/heat 'warm hold', sph/harmonic/visc
    # 'correction gradient/hold'; not the defaults)
    "cavity-held": ("convection-cavity/in.cavity-options",
                    {"tend": 0.05, "conduction": "correction consistent warm hold",
                     "gradient": "gradient/hold"}, "wendland", 2.0, 2),
    "channel-held": ("forced-channel/in.channel", {"tend": 1.0, "conduction": "warm hold"},
                     "quintic", 1.3, 2),
}


def loop_cost(cmd, workdir):
    """Loop time per particle-step (s) of the last run with steps, and its atoms."""
    out = subprocess.run(cmd, cwd=workdir, capture_output=True, text=True,
                         env=dict(os.environ, OMP_NUM_THREADS="1"))
    if out.returncode != 0:
        sys.exit(f"overhead.py: {' '.join(cmd)} failed:\n{out.stdout[-2000:]}{out.stderr[-2000:]}")
    time, steps, atoms = [run for run in loop_runs(out.stdout) if run[1] > 0][-1]
    return time / (steps * atoms), steps, atoms


def scene_cost(args, scene, plugin=None):
    path, variables, _, _, _ = SCENES[scene]
    if plugin:
        args = argparse.Namespace(**dict(vars(args), plugin=plugin))
    work, cmd = profile.scene_command(args, scene, path, variables)
    runs = [loop_cost(cmd, work) for _ in range(args.repeat_scenes)]
    return min(runs)


def box_cost(args, pair, kernel, hdx, dim, atoms, steps):
    n = max(10, round(atoms ** (1.0 / dim)))
    work = os.path.join(args.out, "box")
    os.makedirs(work, exist_ok=True)
    cmd = [args.lmp, "-in", BOX, "-var", "plugin", args.plugin, "-log", "none", "-var", "pair", pair,
           "-var", "kernel", kernel, "-var", "hdx", str(hdx), "-var", "dim", str(dim), "-var", "n", str(n),
           "-var", "steps", str(steps)]
    return min(loop_cost(cmd, work) for _ in range(args.repeat))


def main():
    p = profile.scene_arguments(__doc__, SCENES, "overhead.md")
    p.add_argument("--repeat", type=int, default=3, help="runs of each box, the fastest kept (default 3)")
    p.add_argument("--repeat-scenes", type=int, default=1, help="runs of each scene (default 1)")
    p.add_argument("--before", help="a plugin of an earlier commit: its scenes too, for before and after")
    p.add_argument("--before-label", default="before", help="what --before was built from (a commit)")
    args = p.parse_args()
    args.lmp, args.plugin, args.out = (os.path.abspath(a) for a in (args.lmp, args.plugin, args.out))
    if args.before:
        args.before = os.path.abspath(args.before)

    rows = []
    for scene in args.scenes:
        _, _, kernel, hdx, dim = SCENES[scene]
        cost, steps, atoms = scene_cost(args, scene)
        bare, _, box_atoms = box_cost(args, "ours", kernel, hdx, dim, atoms, 200)
        before = scene_cost(args, scene, args.before)[0] if args.before else None
        rows.append((scene, kernel, hdx, dim, atoms, steps, cost, box_atoms, bare, before))
        print(f"{scene}: {cost * 1e6:.3f} us per particle-step ({atoms} atoms, {steps} steps); "
              f"bare loop {bare * 1e6:.3f} us ({box_atoms} atoms): {cost / bare:.2f}"
              + (f"; {args.before_label}: {before * 1e6:.3f} us" if before else ""), flush=True)
    whole = {}
    for n in (60, 120):
        ours, _, atoms = box_cost(args, "ours", "lucy", 2.6, 2, n * n, 200)
        lammps, _, _ = box_cost(args, "lammps", "lucy", 2.6, 2, n * n, 200)
        whole[atoms] = (ours, lammps)
        print(f"box {atoms} atoms, Lucy, h = 2.6 dx: ours {ours * 1e6:.3f} us, LAMMPS's {lammps * 1e6:.3f} us: "
              f"{ours / lammps:.2f}", flush=True)

    lines = ["# Whole scenes against the bare thermal-flow loop", "",
             "Written by `bench/profile/overhead.py` (do not edit). Loop time per",
             "particle-step (LAMMPS's loop time over steps and atoms, walls included),",
             "serial, one thread; the scenes one run each of a short stretch of their",
             f"flow, the boxes the fastest of {args.repeat} runs of 200 steps",
             "(bench/flow/in.bench: jittered periodic box, the shared loop of",
             "sph/harmonic/visc + sph/cleary/heat, no density diffusion, no walls,",
             "corrections or shifting) at the scene's kernel, h / dx and dimension,",
             "about as many particles.", "",
             "| scene | kernel, h / dx, dim | atoms | steps | scene (us) | bare loop (us) | scene / bare |",
             "|---|---|---|---|---|---|---|"]
    for scene, kernel, hdx, dim, atoms, steps, cost, box_atoms, bare, _ in rows:
        lines.append(f"| {scene} | {kernel}, {hdx:g}, {dim}-d | {atoms} | {steps} | {cost * 1e6:.3f} | "
                     f"{bare * 1e6:.3f} ({box_atoms} atoms) | {cost / bare:.2f} |")
    if args.before:
        lines += ["", f"The same scenes with the plugin of {args.before_label}, run in the same",
                  "session (each the fastest of as many runs), loop time per particle-step:", "",
                  f"| scene | {args.before_label} (us) | this (us) | this / {args.before_label} |",
                  "|---|---|---|---|"]
        for scene, *_, cost, _, _, before in rows:
            lines.append(f"| {scene} | {before * 1e6:.3f} | {cost * 1e6:.3f} | {cost / before:.2f} |")
    lines += ["", "The whole thermal-flow step against LAMMPS's styles (sph/taitwater/morris +",
              "sph/heatconduction, hybrid/overlay) on the same particles, Lucy kernel,",
              "h = 2.6 dx, loop time per particle-step:", "",
              "| atoms | ours (us) | LAMMPS's (us) | ours / LAMMPS's |", "|---|---|---|---|"]
    for atoms, (ours, lammps) in whole.items():
        lines.append(f"| {atoms} | {ours * 1e6:.3f} | {lammps * 1e6:.3f} | {ours / lammps:.2f} |")
    with open(args.results, "w") as f:
        f.write("\n".join(lines) + "\n")
    print(f"wrote {args.results}")


if __name__ == "__main__":
    main()
