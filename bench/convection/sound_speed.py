#!/usr/bin/env python3
"""The cavity's accuracy and steps against its speed of sound.

Runs the differentially heated cavity (examples/convection-cavity/run.sh)
at each Rayleigh number twice, one MPI rank each:
  auto     the flagship in.cavity: fix sph/materials 'eos linear auto', c0
           at which the buoyancy's pressure compresses the fluid by 0.05;
  tenfold  in.cavity-options with c0 = 10 times the benchmark's largest
           speed (de Vahl Davis 1983, v_max on y = 1/2), every other
           setting as in.cavity (the compression is then 0.15 to 0.25);
  potential in.cavity-options with fix sph/boussinesq 'potential 1' (the
           buoyancy's pressure solved, so it compresses nothing) and the
           package's c0 for it ('eos linear auto': 10 times a speed
           estimated from the buoyancy), every other setting as in.cavity.
It writes, for each run, c0 and the compression g beta dT L / c0^2 of
the pressure that balances the buoyancy (L the cavity's side; twice fix
sph/boussinesq's measure, whose bound is 0.05), the mean Nu of the walls' heat against the
benchmark, the largest v on y = 1/2 against the benchmark, the L2 error of
v on y = 1/2 against the reference solver, the fluid's density range over
the run (in.cavity-options' thermo; not logged by in.cavity), the steps and
the loop time.

  tools/sphpython bench/convection/sound_speed.py                 # Ra 1e3, 1e4, 1e5 at 40 across (about 30 min on 2 cores)
  tools/sphpython bench/convection/sound_speed.py --ra 1e4 --n 20  # one case (about 1 min)

Options: --ra RA ..., --n N, --jobs (runs at once, default 2), --out FILE
(the table, default bench/convection/sound_speed.md), --dir (the runs'
directories), --reuse (read the runs already in --dir instead of running
them again).
"""

import argparse
import concurrent.futures
import os
import re
import subprocess
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "tools"))
from sphthermal_tools.log import longest_thermo_table  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.abspath(os.path.join(HERE, "..", ".."))

PR = 0.71


def number(pattern, text, what):
    m = re.search(pattern, text)
    if not m:
        raise RuntimeError(f"no {what} in the output")
    return float(m.group(1))


def run(ra, n, mode, top, reuse=False):
    out = os.path.join(top, f"ra{ra:g}.n{n}.{mode}")
    os.makedirs(out, exist_ok=True)
    if reuse and os.path.exists(os.path.join(out, "run.txt")):
        return measure(ra, n, mode, out, open(os.path.join(out, "run.txt")).read())
    env = dict(os.environ, OUT=out, RA=f"{ra:g}", N=str(n))
    env.pop("SQUEEZE", None)
    if mode == "tenfold":
        # in.cavity-options: c0 = 10 v_max unless the compression bound
        # asks for more; a bound of 10 never does
        env["SQUEEZE"] = "10"
    elif mode == "potential":
        env["POTENTIAL"] = "1"
    proc = subprocess.run([os.path.join(ROOT, "examples/convection-cavity/run.sh")], env=env,
                          capture_output=True, text=True)
    text = proc.stdout
    with open(os.path.join(out, "run.txt"), "w") as f:
        f.write(text)
    if proc.returncode != 0:
        return {"ra": ra, "n": n, "mode": mode, "failed": proc.stderr.strip()[-200:]}
    return measure(ra, n, mode, out, text)


def measure(ra, n, mode, out, text):
    log = open(os.path.join(out, "log.cavity")).read()
    if mode == "tenfold":
        c0 = number(r"c0 = (\S+),", text, "c0")
    else:
        c0 = number(r"speed of sound of atom type 1 is (\S+) \(auto", log, "c0")
    density = "-"
    if mode != "auto":
        table = longest_thermo_table(log)
        density = f"{min(table['c_rho_min']):.4f}-{max(table['c_rho_max']):.4f}"
    loops = re.findall(r"Loop time of (\S+) on \d+ procs for (\d+) steps", log)
    steps = sum(int(s) for _, s in loops)
    v_ref = number(r"largest v on y = 0.5: \S+ \(reference (\S+)\)", text, "v_max")
    return {
        "ra": ra, "n": n, "mode": mode, "c0": c0,
        "squeeze": ra * PR / c0**2,
        "c0_over_v": c0 / v_ref,
        "nu_error": number(r"error of the mean Nu from the heat \(time average\): (\S+) %", text, "Nu"),
        "v": number(r"largest v on y = 0.5: (\S+)", text, "v_max"),
        "v_ref": v_ref,
        "l2_v": number(r"L2 errors on y = 0.5[^:]*: theta \S+, v (\S+);", text, "L2 of v"),
        "density": density,
        "steps": steps,
        "seconds": sum(float(t) for t, _ in loops),
    }


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawTextHelpFormatter)
    p.add_argument("--ra", type=float, nargs="+", default=[1e3, 1e4, 1e5])
    p.add_argument("--n", type=int, default=40)
    p.add_argument("--jobs", type=int, default=2)
    p.add_argument("--out", default=os.path.join(HERE, "sound_speed.md"))
    p.add_argument("--dir", default=os.path.join(HERE, "out", "sound_speed"))
    p.add_argument("--reuse", action="store_true")
    a = p.parse_args()
    cases = [(ra, a.n, mode) for ra in a.ra for mode in ("auto", "tenfold", "potential")]
    with concurrent.futures.ThreadPoolExecutor(a.jobs) as pool:
        results = list(pool.map(lambda c: run(*c, a.dir, a.reuse), cases))
    lines = [
        "# The cavity against its speed of sound",
        "",
        "Written by `tools/sphpython bench/convection/sound_speed.py"
        + (f" --ra {' '.join(f'{r:g}' for r in a.ra)}" if a.ra != [1e3, 1e4, 1e5] else "")
        + (f" --n {a.n}" if a.n != 40 else "") + "` (one MPI rank per run, "
        f"{a.jobs} runs at once). *auto*: examples/convection-cavity/in.cavity, c0 from "
        "`eos linear auto` (compression 0.05); *tenfold*: in.cavity-options with "
        "c0 = 10 times the benchmark's largest speed; *potential*: in.cavity-options with "
        "fix sph/boussinesq 'potential 1' and its c0 (`eos linear auto`: 10 times a speed "
        "estimated from the buoyancy). Compression: g beta dT L / c0^2 "
        "(L the side; fix sph/boussinesq's bound is half of it: 0.05; with the potential, what "
        "the buoyancy's pressure would compress without it). "
        "Nu: the mean of the walls' heat against de Vahl Davis (1983); v: the largest v "
        "on y = 1/2 (reference: the benchmark); L2 v: against tools/cavity_fv.py "
        "(Reece et al. 2024, eq 36); density: the fluid's range over the run (not logged "
        "by in.cavity).",
        "",
        "| Ra | particles | c0 | c0 / v_max | compression | Nu error | largest v (reference) "
        "| L2 v | density | steps | loop (s) |",
        "|---|---|---|---|---|---|---|---|---|---|---|",
    ]
    failed = 0
    for r in results:
        if "failed" in r:
            failed += 1
            lines.append(f"| {r['ra']:g} | {r['n']} x {r['n']} | {r['mode']}: failed | | | | | | | | |")
            continue
        lines.append(
            f"| {r['ra']:g} | {r['n']} x {r['n']} | {r['c0']:.4g} ({r['mode']}) | {r['c0_over_v']:.1f} "
            f"| {r['squeeze']:.3f} | {r['nu_error']:+.2f} % | {r['v']:.3f} ({r['v_ref']:.3f}) "
            f"| {r['l2_v']:.4f} | {r['density']} | {r['steps']} | {r['seconds']:.0f} |")
    text = "\n".join(lines) + "\n"
    print(text)
    with open(a.out, "w") as f:
        f.write(text)
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
