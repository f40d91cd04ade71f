#!/usr/bin/env python3
"""Two cores on a whole scene: the flagship cavity, the air cavity
(Reece et al. 2024, 154 x 154), the Re = 652 channel and the 3-d mixing
tank (whose walls, shifting and corrections are most of their step) run a
short stretch of their flow serially,
on 2 MPI ranks (one thread each) and on 2 OpenMP threads of one rank
(-sf omp -pk omp 2: the /omp pair styles, and on the same threads the
conduction's correction factors, the pressure-gradient correction and the
mirror walls' interpolation; the other fixes on one thread), each the
fastest of --repeat runs. Writes the loop times,
the speed-ups over the serial run (efficiency: speed-up / 2) and the
largest difference of the scene's final Nusselt numbers from the serial
run, which should be round-off (for the scenes that print one).

  parallel.py [--lmp build/lmp] [--plugin build/sphthermalplugin.so]
              [--scenes cavity air channel tank3d] [--repeat 2]
              [--out bench/profile/out] [--results bench/profile/parallel.md]

Needs 2 free cores and mpirun; run on an otherwise idle machine.
"""

import importlib.util
import os
import re
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
sys.path.insert(0, os.path.join(ROOT, "tools"))
from sphthermal_tools.log import loop_runs  # noqa: E402
# this directory's profile.py (the scenes' command lines) and overhead.py
# (the scenes' short stretches), by their paths: the standard library has a
# module named profile


def _load(name, file):
    spec = importlib.util.spec_from_file_location(name, os.path.join(HERE, file))
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


profile = _load("scene_profile", "profile.py")
overhead = _load("scene_overhead", "overhead.py")

# name: (input, variables for a short stretch), those of overhead.py
SCENES = {name: overhead.SCENES[name][:2] for name in ("cavity", "air", "channel", "tank3d")}
# how: (label, command prefix, suffix arguments, OMP_NUM_THREADS)
MPIRUN = ["mpirun", "--oversubscribe", "-np", "2"]
LAYOUTS = [
    ("serial", [], [], "1"),
    ("2 ranks", MPIRUN, [], "1"),
    ("2 threads", [], ["-sf", "omp", "-pk", "omp", "2"], "2"),
]
# the numbers a scene prints at its end whose agreement is checked
FINAL = re.compile(r"(Nu\w*) = (-?[0-9.eE+-]+)")


def run(cmd, work, threads):
    env = dict(os.environ, OMP_NUM_THREADS=threads, OMPI_ALLOW_RUN_AS_ROOT="1",
               OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
    out = subprocess.run(cmd, cwd=work, capture_output=True, text=True, env=env)
    if out.returncode != 0:
        sys.exit(f"parallel.py: {' '.join(cmd)} failed:\n{out.stdout[-2000:]}{out.stderr[-2000:]}")
    time, steps, atoms = [r for r in loop_runs(out.stdout) if r[1] > 0][-1]
    last = [line for line in out.stdout.splitlines() if FINAL.search(line)]
    finals = [float(v) for _, v in FINAL.findall(last[-1])] if last else []
    return time, steps, atoms, finals


def main():
    p = profile.scene_arguments(__doc__, SCENES, "parallel.md")
    p.add_argument("--repeat", type=int, default=2, help="runs of each layout, the fastest kept (default 2)")
    args = p.parse_args()
    args.lmp, args.plugin, args.out = (os.path.abspath(a) for a in (args.lmp, args.plugin, args.out))

    rows = []
    for scene in args.scenes:
        path, variables = SCENES[scene]
        work, cmd = profile.scene_command(args, scene, path, variables)
        serial = None
        for label, prefix, suffix, threads in LAYOUTS:
            runs = [run(prefix + cmd + suffix, work, threads) for _ in range(args.repeat)]
            time, steps, atoms, finals = min(runs)
            if serial is None:
                serial = (time, finals)
            speedup = serial[0] / time
            spread = max((abs(a - b) / abs(b) for a, b in zip(finals, serial[1]) if b != 0.0), default=float("nan"))
            rows.append((scene, atoms, steps, label, time, speedup, spread))
            print(f"{scene} {label}: {time:.2f} s loop, speed-up {speedup:.2f}, Nu within {spread:.1e}",
                  flush=True)

    with open(args.results, "w") as f:
        f.write("# Two cores on a whole scene\n\n"
                "Written by `bench/profile/parallel.py` (do not edit). Loop time of a short\n"
                "stretch of each scene's flow, the fastest of "
                f"{args.repeat} runs: serially, on 2 MPI ranks (one thread\n"
                "each) and on 2 OpenMP threads of one rank (`-sf omp -pk omp 2`: the /omp pair\n"
                "styles, and on the same threads the conduction's correction factors, the\n"
                "pressure-gradient correction and the mirror walls' interpolation; the other\n"
                "fixes on one thread). Speed-up over the serial run, efficiency = speed-up / 2; the last column is the largest relative\n"
                "difference of the scene's final Nusselt numbers from the serial run (nan:\n"
                "the scene prints none).\n\n"
                "| scene | atoms | steps | layout | loop (s) | speed-up | efficiency | Nu against serial |\n"
                "|---|---|---|---|---|---|---|---|\n")
        for scene, atoms, steps, label, time, speedup, spread in rows:
            f.write(f"| {scene} | {atoms} | {steps} | {label} | {time:.2f} | {speedup:.2f} | "
                    f"{speedup / 2:.2f} | {spread:.1e} |\n")
    print(f"wrote {args.results}")


if __name__ == "__main__":
    main()
