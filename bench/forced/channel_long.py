#!/usr/bin/env python3
"""The heated channel of examples/forced-channel (in.channel with its
defaults: Re = 652, 200 m, from the developed flow) run long, in pieces
that survive an interrupted session, and whether it stays laminar.

The run writes a restart file every --restart seconds of simulated time;
started again with the same --work, it goes on from the newest restart
file there (each piece has its own log, log.<k>). The summary reads the
thermo rows of every piece (a later piece's rows replace those of the
earlier ones from its start on) and writes <out>/<name>.md and
<out>/<name>.png (name: channel_<n> unless --name): per --every seconds
the largest |v| of the fluid (% of u_max), the largest u (of u_max) and
the mean density; laminar
means the largest |v| stays below 1 % of u_max (a break-up takes it to
several % within 10-20 s).

  tools/sphpython bench/forced/channel_long.py --n 30 --tend 2000 --work /tmp/ch30
  tools/sphpython bench/forced/channel_long.py --n 30 --work /tmp/ch30 --summary   # no run
  # the 40 m channel at 30 across with the earlier fixed timestep, 0.15 h / c0:
  tools/sphpython bench/forced/channel_long.py --n 30 --tend 220 --var length 40 \
      --var dtreset "acoustic 0.165" --work /tmp/ch30old --name channel_30_40m_dt015 --every 10
"""

import argparse
import glob
import os
import subprocess

import numpy as np

from sphthermal_tools.log import longest_thermo_table

from channel_2000 import logged_wall_time

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.normpath(os.path.join(HERE, "..", ".."))
CHANNEL = os.path.join(ROOT, "examples", "forced-channel", "in.channel")
LAMINAR_VY = 1.0  # % of u_max


def input_default(name):
    """The value in.channel gives its variable 'name' (variable NAME index VALUE)."""
    with open(CHANNEL) as f:
        for line in f:
            words = line.split()
            if words[:3] == ["variable", name, "index"]:
                return words[3]
    raise SystemExit(f"in.channel has no variable {name}")


def pieces(work):
    """The logs of the pieces, in order."""
    logs = glob.glob(os.path.join(work, "log.*"))
    return sorted(logs, key=lambda p: int(p.rsplit(".", 1)[1]))


def newest_restart(work):
    files = glob.glob(os.path.join(work, "piece*.restart.*"))
    return max(files, key=os.path.getmtime) if files else None


def run_piece(a):
    k = len(pieces(a.work))
    resume = newest_restart(a.work)
    mpirun = []
    if a.np > 1:
        mpirun = ["mpirun", "--oversubscribe", "-np", str(a.np)]
        mpirun += ["--allow-run-as-root"] if os.geteuid() == 0 else []
    cmd = mpirun + [a.lmp, "-in", CHANNEL, "-var", "plugin", a.plugin, "-var", "n", str(a.n),
                    "-var", "re", str(a.re), "-var", "tend", str(a.tend),
                    "-var", "restart", str(a.restart), "-var", "every", str(a.dump_every),
                    "-var", "out", f"piece{k}", "-log", f"log.{k}"]
    for name, value in a.var:
        cmd += ["-var", name, value]
    if resume:
        cmd += ["-var", "resume", os.path.basename(resume)]
    print(("piece %d from %s" % (k, os.path.basename(resume))) if resume else "piece 0 from the start")
    subprocess.run(cmd, cwd=a.work, check=True, stdout=subprocess.DEVNULL)


def gather(work):
    """Time, largest |v| (% u_max), largest u (of u_max), mean rho / rho0 of all pieces;
    the loop seconds and steps."""
    t, vy, u, rho = [], [], [], []
    for path in pieces(work):
        text = open(path).read()
        table = longest_thermo_table(text)
        if table is None:
            continue
        start = table["Time"][0]
        keep = [i for i, ti in enumerate(t) if ti < start]
        t, vy, u, rho = ([x[i] for i in keep] for x in (t, vy, u, rho))
        t += list(table["Time"])
        vy += list(100.0 * table["v_vymax"])
        u += list(table["c_vxmax"])
        rho += list(table["v_rhomean"])
    return (np.array(t), np.array(vy), np.array(u), np.array(rho)) + logged_wall_time(pieces(work))


def summary(a):
    t, vy, u, rho, seconds, steps = gather(a.work)
    if len(t) == 0:
        raise SystemExit(f"no thermo rows in {a.work}")
    u_max = a.re * 0.248 / 20.0
    broken = np.nonzero((vy > LAMINAR_VY) & (t > a.settle))[0]
    if len(broken):
        verdict = (f"breaks up: the largest |v| first above {LAMINAR_VY:g} % of u_max at "
                   f"t = {t[broken[0]]:.0f} s")
    else:
        verdict = (f"laminar to t = {t[-1]:.0f} s: the largest |v| below {LAMINAR_VY:g} % of "
                   f"u_max after t = {a.settle:g} s")
    lines = []
    for t0 in np.arange(0.0, t[-1] + 1e-9, a.every):
        # thermo rows come every so many steps of the first dt: a row a little
        # after t0 counts for t0
        slack = 0.05 * a.every
        rows = (t > t0 - a.every + slack) & (t <= t0 + slack) if t0 > 0 else t <= slack
        if not rows.any():
            continue
        lines.append(f"| {t0:.0f} | {vy[rows].max():.4f} | {u[rows].max() / u_max:.5f} | "
                     f"{rho[rows][-1]:.7f} |")
    name = a.name or f"channel_{a.n}"
    given = "".join(f", {k} = {v}" for k, v in a.var)
    shiftc = dict(a.var).get("shiftc", input_default("shiftc"))
    with open(os.path.join(a.out, name + ".md"), "w") as f:
        f.write(f"# Heated channel, Re = {a.re:g}, {a.n} particles across, run long\n\n")
        f.write("examples/forced-channel/in.channel with its defaults (the package's for every "
                "numerical setting: c0 = 10 u_max, the timestep of fix sph/dt/reset, delta-plus "
                f"shifting with C = {shiftc}, the fluid's volume held), from the developed flow"
                + (f"; variables given: {given[2:]}" if given else "")
                + f"; {len(pieces(a.work))} piece(s). Written by `bench/forced/channel_long.py`.\n\n")
        cost = (f"Loop time {seconds:.0f} s for {steps} steps ({1e3 * seconds / steps:.3f} ms "
                f"per step on {a.np} rank(s))" if steps else "No piece has finished yet")
        f.write(f"Verdict: {verdict}. {cost}.\n\n")
        f.write(f"Per {a.every:g} s up to each time: the largest |v| of the fluid (% of u_max), "
                "the largest u (of u_max), the mean density (of rho0) at the end.\n\n")
        f.write("| t (s) | largest \\|v\\| (%) | largest u / u_max | mean rho / rho0 |\n"
                "|---|---|---|---|\n")
        f.write("\n".join(lines) + "\n")
    print(verdict)
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        fig, ax = plt.subplots(figsize=(6.5, 4))
        ax.semilogy(t, vy)
        ax.axhline(LAMINAR_VY, ls=":", color="k", lw=1)
        ax.set_xlabel("t (s)")
        ax.set_ylabel("largest |v| of the fluid (% of u_max)")
        ax.set_title(f"Heated channel, Re = {a.re:g}, {a.n} across: spanwise velocity")
        fig.tight_layout()
        fig.savefig(os.path.join(a.out, name + ".png"), dpi=110)
    except ImportError:
        print("no matplotlib: no PNG")


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawTextHelpFormatter)
    p.add_argument("--lmp", default=os.path.join(ROOT, "build", "lmp"))
    p.add_argument("--plugin", default=os.path.join(ROOT, "build", "sphthermalplugin.so"))
    p.add_argument("--np", type=int, default=2, help="MPI ranks (default 2)")
    p.add_argument("--n", type=int, default=30, help="particles across (default 30)")
    p.add_argument("--re", type=float, default=652.0)
    p.add_argument("--tend", type=float, default=2000.0, help="s (default 2000)")
    p.add_argument("--restart", type=float, default=25.0, help="s between restart files")
    p.add_argument("--dump-every", type=float, default=50.0, help="s between dump frames")
    p.add_argument("--every", type=float, default=50.0, help="s per row of the summary")
    p.add_argument("--settle", type=float, default=20.0,
                   help="s after which |v| counts (the start's transient)")
    p.add_argument("--work", required=True, help="run directory (kept between pieces)")
    p.add_argument("--out", default=HERE)
    p.add_argument("--name", help="results file name, without .md (default channel_<n>)")
    p.add_argument("--var", nargs=2, action="append", default=[], metavar=("NAME", "VALUE"),
                   help="another variable of in.channel (e.g. length 40 for a trial)")
    p.add_argument("--summary", action="store_true", help="only write the summary")
    a = p.parse_args()
    a.lmp, a.plugin = os.path.abspath(a.lmp), os.path.abspath(a.plugin)
    os.makedirs(a.work, exist_ok=True)
    if not a.summary:
        run_piece(a)
    summary(a)


if __name__ == "__main__":
    main()
