#!/usr/bin/env python3
"""The heated channel's CI case (examples/forced-channel, `run.sh quick`:
Re = 65.2, 10 across, to t = 800 s) with pair sph/cleary/heat's default
consistent factors (made anew every step) and with 'warm hold' (made at
neighbour-list builds only, each pair's factor from them at its current
separation between builds): the errors that run.sh prints against the
exact solution and the loop time of each. The two run at the same time,
one per core, so that their loop times are compared under the same load.
Writes bench/forced/channel_hold.md.

  tools/sphpython bench/forced/channel_hold.py [--lmp L] [--plugin P]
"""

import argparse
import os
import re
import subprocess
import tempfile

from sphthermal_tools.log import loop_runs

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.normpath(os.path.join(HERE, "..", ".."))
RUN_SH = os.path.join(ROOT, "examples", "forced-channel", "run.sh")
CASES = [("default (factors every step)", ""), ("warm hold", "warm hold")]


def summary(text, log):
    """The lines of run.sh's verdict and the time loop's seconds and steps."""
    loop, steps, _ = max(loop_runs(log), key=lambda run: run[1])
    bulk = re.search(r"bulk temperature: largest error (\S+) %", text).group(1)
    sections = re.findall(r"x =\s+(\S+) m:.*largest error (\S+) %", text)
    nu = re.findall(r"Nu at x =\s+(\S+) m: (\S+) \(reference (\S+)\)", text)
    flow = re.search(r"largest \|u - u_Poiseuille\| (\S+) %", text).group(1)
    return {"loop": loop, "steps": steps, "bulk": bulk, "sections": sections, "nu": nu, "flow": flow}


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--lmp", default=os.path.join(ROOT, "build", "lmp"))
    p.add_argument("--plugin", default=os.path.join(ROOT, "build", "sphthermalplugin.so"))
    a = p.parse_args()
    rows = []
    with tempfile.TemporaryDirectory() as work:
        running = []
        for label, conduction in CASES:
            out = os.path.join(work, label.split()[0])
            env = dict(os.environ, LMP=os.path.abspath(a.lmp), PLUGIN=os.path.abspath(a.plugin),
                       OUT=out, OMP_NUM_THREADS="1")
            if conduction:
                env["CONDUCTION"] = conduction
            running.append((label, out, subprocess.Popen(["sh", RUN_SH, "quick"], env=env, text=True,
                                                         stdout=subprocess.PIPE,
                                                         stderr=subprocess.STDOUT)))
        for label, out, proc in running:
            text = proc.communicate()[0]
            if proc.returncode != 0:
                raise SystemExit(f"channel_hold.py: {label} failed:\n{text[-2000:]}")
            log = open(os.path.join(out, "log.channel-dirichlet")).read()
            rows.append((label, summary(text, log)))
            print(label, rows[-1][1], flush=True)
    xs = [x for x, _ in rows[0][1]["sections"]]
    lines = ["# The channel's CI case with the consistent factors held between builds", "",
             "Written by `bench/forced/channel_hold.py` (do not edit): `examples/forced-channel/run.sh "
             "quick` (Re = 65.2, 10 across, to t = 800 s), pair sph/cleary/heat's default factors "
             "against 'warm hold', run side by side (one per core). Errors: the largest error of "
             "the temperature across each section and of the bulk temperature (% of T_w - T_in) "
             "and of u (% of u_max) against the exact solution, as run.sh prints them.", "",
             "| pair sph/cleary/heat | " + " | ".join(f"T at x = {x} m" for x in xs)
             + " | bulk T | u | Nu at x = 100 m (reference) | steps | loop (s) |",
             "|---|" + "---|" * (len(xs) + 5)]
    for label, r in rows:
        nu = {x: (v, ref) for x, v, ref in r["nu"]}
        nu100 = nu.get("100", ("-", "-"))
        lines.append(f"| {label} | " + " | ".join(f"{e} %" for _, e in r["sections"])
                     + f" | {r['bulk']} % | {r['flow']} % | {nu100[0]} ({nu100[1]}) | {r['steps']} "
                     f"| {r['loop']:.1f} |")
    d, h = rows[0][1]["loop"], rows[1][1]["loop"]
    lines += ["", f"Loop time with 'warm hold': {h / d:.2f} of the default's."]
    path = os.path.join(HERE, "channel_hold.md")
    with open(path, "w") as f:
        f.write("\n".join(lines) + "\n")
    print(f"wrote {path}")


if __name__ == "__main__":
    main()
