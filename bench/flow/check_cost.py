"""Cost of the per-step particle check (SPHCheck::particles, issue 57) in the
flow benchmark: in.bench's thermal flow of this package (`ours`:
sph/harmonic/visc + sph/cleary/heat in hybrid/overlay, the shared loop) with a
plugin built before the check (--old) against one with it (--new), the same
lmp. Runs alternate old/new (the order swapped each round), --repeat runs of
each; pair CPU time per particle-step as run_bench.py measures it (its
`cost`, one run per call). Writes check_cost.md here (or in --out): the
fastest and median of each, new/old of the fastest, of the medians and of
the two runs of each round (their median), and the spread of each (median /
fastest - 1) as the noise. About 8 minutes on a busy 2-core machine.

  tools/sphpython bench/flow/check_cost.py --old OLD.so --new NEW.so \
      [--old-label 67873ff] [--new-label 7ad5cbd] [--lmp build/lmp] [--repeat 9]
"""

import argparse
import os
import re
import statistics
import tempfile
import time
from types import SimpleNamespace

here = os.path.dirname(os.path.abspath(__file__))
import run_bench

# (n, steps, kernel, hdx, label): n x n particles in 2-D, run_bench.py's kernels
POINTS = [(120, 1000, "lucy", 2.6, "lucy, cutoff 2.6 dx"), (60, 2000, "lucy", 2.6, "lucy, cutoff 2.6 dx"),
          (120, 1000, "wendland", 1.3, "wendland, h = 1.3 dx"), (60, 2000, "wendland", 1.3, "wendland, h = 1.3 dx")]


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--old", required=True, help="plugin built before the check")
    p.add_argument("--new", required=True, help="plugin with the check")
    p.add_argument("--old-label", default="old")
    p.add_argument("--new-label", default="new")
    p.add_argument("--lmp", default=os.path.join(run_bench.root, "build", "lmp"))
    p.add_argument("--repeat", type=int, default=9, help="runs of each plugin per point (default 9)")
    p.add_argument("--out", default=here)
    args = p.parse_args()
    workdir = tempfile.mkdtemp(prefix="sphcheckcost")
    # the runs' working directory is a temporary one: absolute paths
    plugins = {"old": os.path.abspath(args.old), "new": os.path.abspath(args.new)}
    args.lmp = os.path.abspath(args.lmp)
    os.makedirs(args.out, exist_ok=True)
    version = None
    start = time.time()

    rows = []
    for n, steps, kernel, hdx, klabel in POINTS:
        lmp_vars = {"n": n, "steps": steps, "dim": 2, "pair": "ours", "kernel": kernel, "hdx": hdx}
        samples = {"old": [], "new": []}
        for r in range(args.repeat):
            for which in (("old", "new") if r % 2 == 0 else ("new", "old")):
                one = SimpleNamespace(lmp=args.lmp, plugin=plugins[which], repeat=1)
                samples[which].append(run_bench.cost(one, workdir, lmp_vars))
        if version is None:
            m = re.search(r"LAMMPS \(([^)]*)\)", open(os.path.join(workdir, "log.lammps")).read())
            version = m.group(1) if m else "?"
        fast = {k: min(v) for k, v in samples.items()}
        med = {k: statistics.median(v) for k, v in samples.items()}
        # new/old of the two runs of each round (run next to each other): drift cancels
        paired = statistics.median(b / a for a, b in zip(samples["old"], samples["new"]))
        rows.append((f"{n} x {n}", klabel, steps, fast, med, paired))
        print(f"{n} x {n} {kernel}: old {1e6 * fast['old']:.4f} us (median {1e6 * med['old']:.4f}), "
              f"new {1e6 * fast['new']:.4f} us (median {1e6 * med['new']:.4f}); new/old "
              f"{fast['new'] / fast['old']:.3f} (medians {med['new'] / med['old']:.3f}, rounds {paired:.3f})",
              flush=True)

    path = os.path.join(args.out, "check_cost.md")
    with open(path, "w") as f:
        f.write("# Cost of the per-step particle check in the flow benchmark\n\n")
        f.write(f"`in.bench` thermal flow, `ours` (`sph/harmonic/visc` delta 0 + "
                f"`sph/cleary/heat`, hybrid/overlay, shared loop), n x n particles in 2-D, serial. "
                f"Plugin before the check ({args.old_label}) against the plugin with "
                f"`SPHCheck::particles` ({args.new_label}), the same `lmp` (LAMMPS {version}); "
                f"{args.repeat} runs of each, alternating (the order swapped each round). Pair CPU "
                f"time per particle-step in ns (run_bench.py's measure: the run's CPU time times "
                f"the pair's share of the loop). Rounds: the median over the rounds of new/old of the round's two runs. "
                f"Noise: median / fastest - 1 of each plugin's runs; within noise: new/old of the "
                f"fastest differs from 1 by no more than the larger noise of the two. "
                f"Written by `bench/flow/check_cost.py` in {time.time() - start:.0f} s.\n\n")
        f.write("| particles | kernel | steps | old fastest | new fastest | new/old (fastest) "
                "| old median | new median | new/old (medians) | new/old (rounds) | noise old | noise new "
                "| within noise |\n")
        f.write("|---|---|---|---|---|---|---|---|---|---|---|---|---|\n")
        for label, klabel, steps, fast, med, paired in rows:
            noise = {k: med[k] / fast[k] - 1 for k in fast}
            within = abs(fast["new"] / fast["old"] - 1) <= max(noise.values())
            f.write(f"| {label} | {klabel} | {steps} | {1e9 * fast['old']:.1f} | "
                    f"{1e9 * fast['new']:.1f} | {fast['new'] / fast['old']:.3f} | "
                    f"{1e9 * med['old']:.1f} | {1e9 * med['new']:.1f} | "
                    f"{med['new'] / med['old']:.3f} | {paired:.3f} | {100 * noise['old']:.1f} % | "
                    f"{100 * noise['new']:.1f} % | {'yes' if within else 'no'} |\n")
    print("wrote", path)


if __name__ == "__main__":
    main()
