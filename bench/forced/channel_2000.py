#!/usr/bin/env python3
"""Wall time of the heated channel of Ng et al. 2020, section 4.3 (Re = 652,
20 particles across, 200 m, from rest) to t = 2000 s on NP MPI ranks, with
and without particle shifting, and the cost of shifting per step.

The flow without shifting breaks up after about 130 s, so neither run is
taken to 2000 s here: each is run for --steps steps from rest (the same
particles and neighbours as the start of the full run), its wall time per
step (LAMMPS's loop time) is the fastest of --repeat runs, and the time to
2000 s is that times the run's steps to 2000 s (fixed dt). A log of a full
run (--log, several for a run in pieces) adds its measured wall time.

  tools/sphpython bench/forced/channel_2000.py                 # 2 ranks, 2000 steps, 3 repeats
  tools/sphpython bench/forced/channel_2000.py --quick         # 500 steps, 1 repeat
  tools/sphpython bench/forced/channel_2000.py --log examples/forced-channel/out/log.rest2000 \
      --log-note "pb 0.002, correct all, on a machine shared with other runs"
"""

import argparse
import os
import re
import subprocess
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.normpath(os.path.join(HERE, "..", ".."))
CHANNEL = os.path.join(ROOT, "examples", "forced-channel", "in.channel")
LOOP = re.compile(r"Loop time of ([0-9.eE+-]+) on (\d+) procs for (\d+) steps with (\d+) atoms")
TIMESTEP = re.compile(r"^dt = ([0-9.eE+-]+) s\s*$", re.M)


def run(a, workdir, shift, follow, tend):
    """Wall seconds per step of one run of in.channel from rest to tend."""
    log = os.path.join(workdir, f"log.{shift}.{follow}")
    mpirun = ["mpirun", "--oversubscribe"] + (["--allow-run-as-root"] if os.geteuid() == 0 else [])
    cmd = mpirun + ["-np", str(a.np), a.lmp, "-in", CHANNEL, "-var", "plugin", a.plugin,
                    "-var", "start", "rest", "-var", "shift", shift, "-var", "follow", follow,
                    "-var", "tend", repr(tend), "-var", "every", "1e5",
                    "-var", "out", os.path.join(workdir, shift), "-log", log]
    subprocess.run(cmd, cwd=workdir, check=True, stdout=subprocess.DEVNULL)
    seconds, _, nsteps, _ = LOOP.findall(open(log).read())[-1]
    return float(seconds) / int(nsteps)


def timestep(a, workdir):
    """The channel's first dt (fix sph/dt/reset's, printed by the input), read from a run
    of the input to a time shorter than one step."""
    log = os.path.join(workdir, "log.dt")
    subprocess.run([a.lmp, "-in", CHANNEL, "-var", "plugin", a.plugin, "-var", "start", "rest",
                    "-var", "tend", "1e-9", "-var", "every", "1e5",
                    "-var", "out", os.path.join(workdir, "dt"), "-log", log],
                   cwd=workdir, check=True, stdout=subprocess.DEVNULL)
    return float(TIMESTEP.findall(open(log).read())[-1])


def logged_wall_time(paths):
    """Total loop time and steps of a run in pieces (one log per piece)."""
    seconds = steps = 0
    for path in paths:
        for s, procs, n, _ in LOOP.findall(open(path).read()):
            seconds += float(s)
            steps += int(n)
    return seconds, steps


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawTextHelpFormatter)
    p.add_argument("--lmp", default=os.path.join(ROOT, "build", "lmp"))
    p.add_argument("--plugin", default=os.path.join(ROOT, "build", "sphthermalplugin.so"))
    p.add_argument("--np", type=int, default=2, help="MPI ranks (default 2)")
    p.add_argument("--steps", type=int, help="steps per run (default 2000, 500 with --quick)")
    p.add_argument("--repeat", type=int, help="runs per case (default 3, 1 with --quick)")
    p.add_argument("--quick", action="store_true")
    p.add_argument("--log", nargs="*", default=[], help="logs of a full shifted run to 2000 s")
    p.add_argument("--log-note", default="", help="how the logged run was made (settings, machine)")
    p.add_argument("--out", default=HERE)
    a = p.parse_args()
    a.steps = a.steps or (500 if a.quick else 2000)
    a.repeat = a.repeat or (1 if a.quick else 3)
    workdir = tempfile.mkdtemp(prefix="sphchannelbench")

    # (label, shift, the shift's correct keyword)
    cases = [("not shifted", "no", "no"),
             ("shifted (delta-plus), correct no (the default)", "yes", "no"),
             ("shifted (delta-plus), correct all (rho, v and T follow the shift)", "yes", "all")]
    dt = timestep(a, workdir)
    per_step = [min(run(a, workdir, shift, follow, a.steps * dt) for _ in range(a.repeat))
                for _, shift, follow in cases]
    steps_2000 = round(2000.0 / dt)
    lines = []
    for (label, _, _), cost in zip(cases, per_step):
        extra = "-" if cost is per_step[0] else f"{(cost - per_step[0]) / per_step[0]:.0%}"
        lines.append(f"| {label} | {1e3 * cost:.3f} | {extra} | {cost * steps_2000 / 3600:.2f} |")
    print(f"dt {dt:.6g} s, {steps_2000} steps to t = 2000 s on {a.np} ranks")
    print("\n".join(lines))
    logged = ""
    if a.log:
        seconds, steps = logged_wall_time(a.log)
        if steps == 0:
            raise SystemExit("no finished run in " + " ".join(a.log) + " (no 'Loop time' line)")
        logged = (f"The full shifted run ({', '.join(os.path.basename(x) for x in a.log)}): "
                  f"{steps} steps in {seconds:.0f} s of loop time ({seconds / 3600:.2f} h, "
                  f"{1e3 * seconds / steps:.3f} ms per step)" + (f"; {a.log_note}" if a.log_note else "")
                  + ".\n")
        print(logged.strip())
    with open(os.path.join(a.out, "channel_2000.md"), "w") as f:
        f.write("# Heated channel to t = 2000 s: wall time with and without shifting\n\n")
        f.write(f"Ng et al. 2020, section 4.3: Re = 652, 20 particles across, 200 m, from rest "
                f"(examples/forced-channel/in.channel), {a.np} MPI ranks, dt = {dt:.6g} s, "
                f"{steps_2000} steps to t = 2000 s. Wall time per step: LAMMPS's loop time of "
                f"{a.steps} steps from rest, the fastest of {a.repeat} runs; the time to 2000 s "
                "is that times the steps (the unshifted flow breaks up after about 130 s, so it "
                "is not run to the end). Written by `bench/forced/channel_2000.py`.\n\n")
        f.write("| run | ms per step | shifting's extra | hours to t = 2000 s |\n|---|---|---|---|\n")
        f.write("\n".join(lines) + "\n")
        if logged:
            f.write("\n" + logged)
    print("wrote", os.path.join(a.out, "channel_2000.md"))


if __name__ == "__main__":
    main()
