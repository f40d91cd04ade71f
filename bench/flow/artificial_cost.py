"""Cost of pair sph/harmonic/visc's default artificial viscosity under
gravity (Monaghan's term on pairs with a particle at a free surface or a
wall particle, and the Shepard pass that finds the surface) on the scene it
is the default for: the dam break of examples/flow-dam-break (in.dam_break)
at n particles across the column, to t = tend, with the default (alpha
0.1) against 'artificial 0', the same lmp and plugin. Runs alternate (the
order swapped each round), --repeat of each; LAMMPS's loop time and its
Pair time. Writes artificial_cost.md here (or in --out): the fastest and
the median of each, their ratios, and the front at tend of each (the
term's effect, for scale). About 3 minutes on an idle machine.

  tools/sphpython bench/flow/artificial_cost.py [--lmp build/lmp] [--plugin build/sphthermalplugin.so]
      [--sizes 20 40] [--tend 0.1] [--repeat 3]
"""

import argparse
import os
import re
import statistics
import subprocess
import tempfile

here = os.path.dirname(os.path.abspath(__file__))
root = os.path.abspath(os.path.join(here, "..", ".."))
INPUT = os.path.join(root, "examples", "flow-dam-break", "in.dam_break")


VERSION = []    # LAMMPS's version, from the first run


def run(args, workdir, n, alpha):
    """(loop seconds, Pair seconds, steps, particles, front Z at the end, atoms at the surface)"""
    command = [args.lmp, "-in", INPUT, "-log", "none", "-var", "plugin", args.plugin, "-var", "n", str(n),
               "-var", "tend", str(args.tend), "-var", "alpha", str(alpha), "-var", "every", "100000"]
    out = subprocess.run(command, cwd=workdir, text=True, capture_output=True, env=dict(os.environ, OMP_NUM_THREADS="1"))
    if out.returncode != 0 or "ERROR" in out.stdout:
        raise SystemExit(out.stdout[-3000:] + out.stderr[-2000:])
    if not VERSION:
        VERSION.append(re.search(r"LAMMPS \(([^)]*)\)", out.stdout).group(1))
    loops = re.findall(r"Loop time of ([0-9.eE+-]+) on \d+ procs for (\d+) steps with (\d+) atoms", out.stdout)
    pairs = re.findall(r"^Pair\s*\|\s*([0-9.eE+-]+)", out.stdout, re.M)
    loop, steps, atoms = max(((float(t), int(s), int(a)) for t, s, a in loops), key=lambda r: r[1])
    front = float(re.search(r"^dam_break: T = \S+, Z = (\S+),", out.stdout, re.M).group(1))
    surface = re.findall(r"artificial viscosity \S+ on pairs with one of (\d+) atoms now at a free surface",
                         out.stdout)
    return loop, max(float(p) for p in pairs), steps, atoms, front, (int(surface[0]) if surface else 0)


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--lmp", default=os.path.join(root, "build", "lmp"))
    p.add_argument("--plugin", default=os.path.join(root, "build", "sphthermalplugin.so"))
    p.add_argument("--sizes", type=int, nargs="+", default=[20, 40])
    p.add_argument("--tend", type=float, default=0.1)
    p.add_argument("--repeat", type=int, default=3)
    p.add_argument("--out", default=here)
    args = p.parse_args()
    args.lmp, args.plugin = os.path.abspath(args.lmp), os.path.abspath(args.plugin)
    workdir = tempfile.mkdtemp(prefix="artificialcost")
    rows = []
    for n in args.sizes:
        samples = {-1: [], 0: []}
        for r in range(args.repeat):
            for alpha in ((-1, 0) if r % 2 == 0 else (0, -1)):
                samples[alpha].append(run(args, workdir, n, alpha))
        fast = {a: min(s[0] for s in v) for a, v in samples.items()}
        med = {a: statistics.median(s[0] for s in v) for a, v in samples.items()}
        pair = {a: min(s[1] for s in v) for a, v in samples.items()}
        first = {a: v[0] for a, v in samples.items()}
        rows.append((n, first, fast, med, pair))
        print(f"n = {n}: loop {fast[-1]:.2f} s with the default, {fast[0]:.2f} s without "
              f"({fast[-1] / fast[0]:.3f}), pair {pair[-1] / pair[0]:.3f}", flush=True)
    path = os.path.join(args.out, "artificial_cost.md")
    with open(path, "w") as f:
        f.write("# Cost of the default artificial viscosity under gravity\n\n")
        f.write("Written by `bench/flow/artificial_cost.py`. The dam break of `examples/flow-dam-break` "
                f"(`in.dam_break`, the column n particles across) to t = {args.tend:g} s, serial, "
                f"LAMMPS {VERSION[0]}: the package's default (`artificial` "
                "0.1 on pairs with a particle at a free surface or a wall particle, found by a Shepard "
                "pass each step) against `artificial 0`, the same build; "
                f"{args.repeat} runs of each, alternating. Loop and Pair: LAMMPS's times in s, the "
                "fastest run (median in brackets); Z: the front at the end in column widths.\n\n")
        f.write("| n | particles | steps (default / 0) | atoms at the surface at the start | loop, default | "
                "loop, artificial 0 | loop ratio | Pair ratio | Z, default / 0 |\n")
        f.write("|---|---|---|---|---|---|---|---|---|\n")
        for n, first, fast, med, pair in rows:
            f.write(f"| {n} | {first[-1][3]} | {first[-1][2]} / {first[0][2]} | {first[-1][5]} | "
                    f"{fast[-1]:.2f} ({med[-1]:.2f}) | {fast[0]:.2f} ({med[0]:.2f}) | "
                    f"{fast[-1] / fast[0]:.3f} | {pair[-1] / pair[0]:.3f} | "
                    f"{first[-1][4]:.4f} / {first[0][4]:.4f} |\n")
    print(f"wrote {path}")


if __name__ == "__main__":
    main()
