"""Cost of pair sph/cleary/heat's 'correction consistent' and 'mean interface'
against the plain term.

The jittered (0.2 dx) two-material slab of examples/conduction-disorder,
80 x 20 particles, 4800 steps, serial: LAMMPS's "Pair" time per particle
and step for the plain term, correction consistent, mean interface and
both, with fixed particles (the factors and distances are kept) and with
every particle moving every step (they are made anew), each the fastest of
--repeat runs, all in this run of the script. Writes
bench/conduction/correction.md.

  tools/sphpython bench/conduction/correction_cost.py [--repeat 3] [--lmp L] [--plugin P]
"""

import argparse
import os
import re
import subprocess
import sys
import tempfile

here = os.path.dirname(os.path.abspath(__file__))
root = os.path.join(here, "..", "..")
example = os.path.join(root, "examples", "conduction-disorder")


def pair_time(lmp, plugin, workdir, data, spacing, correction, mean, move):
    log = os.path.join(workdir, "log.cost")
    subprocess.run([lmp, "-in", os.path.join(example, "in.disorder"), "-var", "plugin", plugin,
                    "-var", "data", data, "-var", "spacing", spacing, "-var", "correction",
                    correction, "-var", "mean", mean, "-var", "move", str(move),
                    "-var", "out", "cost", "-log", log],
                   cwd=workdir, check=True, stdout=subprocess.DEVNULL)
    text = open(log).read()
    pair = float(re.search(r"^Pair\s+\|\s+(\S+)", text, re.M).group(1))
    steps, atoms = re.search(r"Loop time of \S+ on \d+ procs for (\d+) steps with (\d+) atoms",
                             text).groups()
    return pair / (int(steps) * int(atoms))


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--repeat", type=int, default=3)
    p.add_argument("--lmp", default=os.path.join(root, "build", "lmp"))
    p.add_argument("--plugin", default=os.path.join(root, "build", "sphthermalplugin.so"))
    a = p.parse_args()
    lmp, plugin = os.path.abspath(a.lmp), os.path.abspath(a.plugin)
    with tempfile.TemporaryDirectory() as workdir:
        data = os.path.join(workdir, "slab.data")
        # the example's particles, written as its run.sh writes them
        spacing = subprocess.run([sys.executable, os.path.join(example, "disorder.py"), "data", data,
                                  "--nx", "80", "--ny", "20", "--jitter", "0.2", "--angle", "0",
                                  "--seed", "1"],
                                 check=True, capture_output=True, text=True).stdout.strip()
        cases = [("none", "harmonic", 0, "plain"),
                 ("consistent", "harmonic", 0, "consistent, fixed particles"),
                 ("none", "interface", 0, "interface, fixed particles"),
                 ("consistent", "interface", 0, "consistent + interface, fixed particles"),
                 ("consistent", "harmonic", 1, "consistent, every particle moving"),
                 ("none", "interface", 1, "interface, every particle moving"),
                 ("consistent", "interface", 1, "consistent + interface, every particle moving")]
        best = {}
        for _ in range(a.repeat):
            for correction, mean, move, label in cases:
                t = pair_time(lmp, plugin, workdir, data, spacing, correction, mean, move)
                best[label] = min(best.get(label, t), t)
    plain = best["plain"]
    lines = ["# Cost of correction consistent and mean interface (pair sph/cleary/heat)", "",
             "Jittered two-material slab, 80 x 20, 4800 steps, serial, fastest of "
             f"{a.repeat} runs (`bench/conduction/correction_cost.py`).", "",
             "| operator | pair time per particle-step (ns) | against plain |", "|---|---|---|"]
    for label, t in best.items():
        lines.append(f"| {label} | {1e9 * t:.0f} | {t / plain:.2f} |")
    text = "\n".join(lines) + "\n"
    print(text)
    with open(os.path.join(here, "correction.md"), "w") as f:
        f.write(text)


if __name__ == "__main__":
    main()
