"""Accuracy and cost of pair sph/cleary/heat's consistent correction on a
moving scene against its Jacobi sweeps: the flagship cavity (Ra = 1e4,
40 x 40, examples/convection-cavity/run.sh) with

  - 'sweeps 5 warm 0': five sweeps from zero at every step;
  - 'sweeps 30 warm 0': thirty (the factors close to converged);
  - 'sweeps 5 warm 1' (the default) and 'warm 2': five from zero at each
    neighbour-list build, one or two per step between builds from the last
    step's factors;
  - 'sweeps 5 warm hold': five from zero at each build and none between,
    each pair's factor from the build's S and lambda at its current
    separation; then also with pair sph/harmonic/visc's 'correction
    gradient/hold' (its B made at builds only).

For each: the mean Nu's error against de Vahl Davis (1983), the L2 errors
of the temperature and velocity profiles on the mid-lines against the
reference solver (Reece et al. 2024, eqs 35-36, as run.sh prints them),
the loop time, its Pair part, and the step count. Serial, one run each, in
this run of the script. Writes bench/conduction/warm_sweeps.md.

  tools/sphpython bench/conduction/warm_sweeps.py [--lmp L] [--plugin P] [--cases 0,2]
"""

import argparse
import os
import re
import subprocess
import tempfile

from sphthermal_tools.log import loop_runs

here = os.path.dirname(os.path.abspath(__file__))
root = os.path.join(here, "..", "..")
run_sh = os.path.join(root, "examples", "convection-cavity", "run.sh")

# pair sph/cleary/heat's options, then (after '/') pair sph/harmonic/visc's
# correction where not the flagship's gradient
CASES = ["sweeps 5 warm 0", "sweeps 30 warm 0", "sweeps 5 warm 1", "sweeps 5 warm 2",
         "sweeps 5 warm hold", "sweeps 5 warm hold / gradient/hold"]


def run_case(lmp, plugin, workdir, case):
    sweeps, _, gradient = case.partition(" / ")
    out = os.path.join(workdir, case.replace(" ", "_").replace("/", "_"))
    env = dict(os.environ, LMP=lmp, PLUGIN=plugin, OUT=out,
               CONDUCTION="correction consistent eta 0.01 " + sweeps)
    if gradient:
        env["GRADIENT"] = gradient
    text = subprocess.run(["sh", run_sh], env=env, check=True, capture_output=True,
                          text=True).stdout
    log = open(os.path.join(out, "log.cavity")).read()
    # the time loop: the run with the most steps
    loop, steps, _ = max(loop_runs(log), key=lambda run: run[1])
    pairs = [float(p) for p in re.findall(r"^Pair\s+\|\s+(\S+)", log, re.M)]
    l2 = re.search(r"L2 errors on y = 0.5 .*: theta (\S+), v (\S+); on x = 0.5: theta (\S+), u (\S+)",
                   text)
    return {
        "nu": re.search(r"error of the mean Nu from the heat \(time average\): (\S+ %)", text).group(1),
        "l2": l2.groups(),
        "vmax": re.search(r"largest v on y = 0.5: (\S+)", text).group(1),
        "loop": loop,
        "pair": max(pairs),
        "steps": steps,
    }


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--lmp", default=os.path.join(root, "build", "lmp"))
    p.add_argument("--plugin", default=os.path.join(root, "build", "sphthermalplugin.so"))
    p.add_argument("--cases", default=",".join(str(k) for k in range(len(CASES))),
                   help="indices into the cases (default all)")
    a = p.parse_args()
    lmp, plugin = os.path.abspath(a.lmp), os.path.abspath(a.plugin)
    chosen = [CASES[int(k)] for k in a.cases.split(",")]
    rows = []
    with tempfile.TemporaryDirectory() as workdir:
        for sweeps in chosen:
            r = run_case(lmp, plugin, workdir, sweeps)
            print(sweeps, r, flush=True)
            rows.append((sweeps, r))
    lines = [
        "# Jacobi sweeps of the consistent correction on a moving scene",
        "",
        "The flagship cavity (Ra = 1e4, 40 x 40, to t = 0.3), serial, one run each in one run of "
        "`bench/conduction/warm_sweeps.py`. Nu: the time-averaged mean Nu from the walls' heat "
        "against de Vahl Davis (1983); L2: the mid-line profiles against the reference solver "
        "(Reece et al. 2024, eqs 35-36); largest v on y = 0.5 against 19.604.",
        "",
        "| pair sph/cleary/heat (/ sph/harmonic/visc correction) | Nu error | L2 theta (y = 0.5) | L2 v (y = 0.5) | L2 theta (x = 0.5) "
        "| L2 u (x = 0.5) | largest v | steps | loop (s) | Pair (s) |",
        "|---|---|---|---|---|---|---|---|---|---|",
    ]
    for sweeps, r in rows:
        lines.append("| {} | {} | {} | {} | {} | {} | {} | {} | {:.1f} | {:.1f} |".format(
            sweeps, r["nu"], *r["l2"], r["vmax"], r["steps"], r["loop"], r["pair"]))
    with open(os.path.join(here, "warm_sweeps.md"), "w") as f:
        f.write("\n".join(lines) + "\n")
    print("wrote bench/conduction/warm_sweeps.md")


if __name__ == "__main__":
    main()
