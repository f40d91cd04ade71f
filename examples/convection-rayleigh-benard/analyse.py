"""Rayleigh-Benard onset: growth rates of in.rb against linear theory.

    analyse.py fit log.rb [log.rb ...] [--window T0 T1]
        the growth rate of each log (its Ra and width from the log's
        'Ra = ...' line) against tools/rb_linear.py, and the onset between
        the logs' highest decaying and lowest growing Ra
    analyse.py onset [--lo 1000 --hi 4000 --steps 6 --method falsi]
        runs in.rb (LAMMPS from $LMP, the plugin from $PLUGIN) at Ra values
        that bracket the onset and narrows the bracket on the sign of the
        measured growth rate; prints each step, the onset estimate and its
        error against the linear theory; writes a PNG
    analyse.py nu [log.rb ...] [--run RA ...] [--from 0.4] [--out FILE]
        convection above onset: the mean Nusselt number of each log (both
        plates, over t >= FROM) against the steady rolls of tools/rb_fv.py
        (its results file), and the drift of the fluid's mean density;
        --run first runs in.rb with 'settings convection' at each RA (--n,
        --tend; LAMMPS from $LMP, the plugin from $PLUGIN, logs in --dir)

The growth rate of the perturbation's kinetic energy KE ~ exp(2 sigma t):
sigma = 0.5 d ln(KE)/dt, fitted by least squares over the thermo rows of
the window [T0, T1] (default 0.1 to 0.3 H^2/alpha; a run that stops early,
at KE > kemax, is fitted over its rows in the window). Linear theory:
sigma of the wavenumber a = 2 pi H / W at Pr (rb_linear.growth_rate), and
the onset Ra_c of that mode (rb_linear.rayleigh_at: 1707.92 for W = 2H,
1955.81 for W = 1.5H).

Onset search (--method): 'bisect' halves the bracket [lo, hi] on the sign of
sigma; 'falsi' (the default) takes the zero of the straight line through
(lo, sigma_lo) and (hi, sigma_hi) (regula falsi, Illinois variant: the
sigma of an end kept twice is halved). Either way the estimate after the
last step is the zero of the line through the bracket's two ends.
"""

import argparse
import math
import os
import re
import subprocess
import sys
import time

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.abspath(os.path.join(HERE, "..", ".."))
import rb_linear
import rb_fv
from sphthermal_tools.log import longest_thermo_table


def thermo_table(log):
    """The longest thermo table of the log: {column name: array}."""
    table = longest_thermo_table(open(log).read())
    if table is None:
        sys.exit(f"analyse: no thermo table in {log}")
    return table


def run_parameters(log):
    """Ra, Pr and width of the run, from its 'Ra = ...' line."""
    text = open(log).read()
    m = re.search(r"^Ra = (\S+), Pr = (\S+), width = (\S+),", text, re.M)
    if not m:
        sys.exit(f"analyse: no 'Ra = ..., Pr = ..., width = ...' line in {log}")
    return float(m.group(1)), float(m.group(2)), float(m.group(3))


def fit_growth(table, t0, t1):
    """(sigma, its standard error, the rows used): least squares of
    0.5 ln KE against time over t0 <= t <= t1."""
    t, ke = table["Time"], table["c_ke"]
    use = (t >= t0) & (t <= t1) & (ke > 0)
    if use.sum() < 3:
        return float("nan"), float("nan"), use
    y = 0.5 * np.log(ke[use])
    x = t[use]
    (slope, icpt), res, *_ = np.polyfit(x, y, 1, full=True)
    n = use.sum()
    resid = y - (slope * x + icpt)
    se = math.sqrt((resid ** 2).sum() / max(n - 2, 1) / ((x - x.mean()) ** 2).sum())
    return float(slope), se, use


def linear_theory(ra, pr, width):
    a = 2.0 * math.pi / width
    return rb_linear.growth_rate(ra, a, pr), rb_linear.rayleigh_at(a)


def cmd_fit(args):
    rows = []
    for log in args.logs:
        ra, pr, width = run_parameters(log)
        table = thermo_table(log)
        sigma, se, use = fit_growth(table, *args.window)
        lin, ra_c = linear_theory(ra, pr, width)
        rows.append((ra, sigma, se, lin))
        print(f"{log}: Ra = {ra:g}, W/H = {width:g}: sigma = {sigma:+.3f} +- {se:.3f} "
              f"(t {args.window[0]:g}..{min(args.window[1], table['Time'][-1]):.3g}, "
              f"{use.sum()} rows), linear theory {lin:+.3f}, difference {sigma - lin:+.3f}")
    # the onset between the highest Ra that decays and the lowest that grows
    # (the logs of one width)
    neg = [r for r in rows if r[1] < 0.0]
    pos = [r for r in rows if r[1] > 0.0]
    widths = {run_parameters(log)[2] for log in args.logs}
    if neg and pos and len(widths) == 1:
        (r0, s0, *_), (r1, s1, *_) = max(neg), min(pos)
        est = r0 - s0 * (r1 - r0) / (s1 - s0)
        ra_c = linear_theory(1.0, 1.0, widths.pop())[1]
        print(f"onset between Ra {r0:g} and {r1:g}: {est:.1f}, linear theory {ra_c:.2f}, "
              f"error {100.0 * (est / ra_c - 1.0):+.2f} %")
    return 0


def cmd_nu(args):
    """Mean Nu over t >= args.start of each log against the reference."""
    for ra in args.run or []:
        args.eps, args.width = 1e-2, 2.0
        args.var = (args.var or []) + ["settings=convection"]
        log, wall = run_lammps(ra, args, args.dir, args.tend)
        print(f"Ra = {ra:g}, {args.n} per H, to t = {args.tend:g}: {wall:.0f} s ({log})", flush=True)
        args.logs.append(log)
    if not args.logs:
        sys.exit("analyse: nu needs logs or --run")
    reference = rb_fv.read_results(args.reference)
    lines = ["| Ra | particles per H | mean Nu (hot, cold) | reference | error | "
             "std of Nu | mean density, start -> end | steps |",
             "|---|---|---|---|---|---|---|---|"]
    worst = 0.0
    for log in args.logs:
        ra, pr, width = run_parameters(log)
        n = int(re.search(r"x (\d+) fluid particles", open(log).read()).group(1))
        table = thermo_table(log)
        t = table["Time"]
        use = t >= args.start
        if use.sum() < 3:
            sys.exit(f"analyse: {log} has fewer than 3 thermo rows at t >= {args.start}")
        hot, cold = table["c_nu_hot[1]"][use], table["c_nu_cold[1]"][use]
        nu = 0.5 * (hot.mean() + cold.mean())
        key = min(reference, key=lambda k: abs(k[0] / ra - 1) + abs(k[1] - pr) + abs(k[2] - width))
        if abs(key[0] / ra - 1) > 1e-6 or abs(key[1] - pr) > 1e-9 or abs(key[2] - width) > 1e-9:
            sys.exit(f"analyse: no reference for Ra {ra:g}, Pr {pr:g}, W {width:g} in {args.reference}")
        ref, ref_err = reference[key]["nu"]
        err = 100.0 * (nu / ref - 1.0)
        worst = max(worst, abs(err))
        rho = table["c_rhoave"]
        lines.append(f"| {ra:g} | {n} | {nu:.4f} ({hot.mean():.4f}, {cold.mean():.4f}) | "
                     f"{ref:.4f} +- {ref_err:.1g} | {err:+.2f} % | {np.std(0.5 * (hot + cold)):.4f} | "
                     f"{rho[0]:.5f} -> {rho[-1]:.5f} (t = {t[-1]:.3g}) | {int(table['Step'][-1])} |")
    text = "\n".join(lines) + "\n"
    print(f"mean Nu over t >= {args.start:g} (H^2/alpha) against tools/rb_fv.py")
    print(text, end="")
    if args.out:
        with open(args.out, "w") as f:
            f.write(f"# analyse.py nu --from {args.start:g}: mean Nu of in.rb above onset "
                    f"against tools/rb_fv.py\n{text}")
    if args.max_error is not None and worst > args.max_error:
        print(f"FAIL: |Nu error| {worst:.2f} % > {args.max_error} %")
        return 1
    return 0


def run_lammps(ra, args, outdir, tend=None):
    """Runs in.rb at ra to tend (default the fit window's end); returns (log
    path, wall time in s)."""
    log = os.path.join(outdir, f"log.rb.w{args.width:g}.n{args.n}.{ra:.2f}")
    cmd = [args.lmp, "-in", os.path.join(HERE, "in.rb"), "-var", "plugin", args.plugin,
           "-var", "ra", f"{ra:.6g}", "-var", "width", f"{args.width:g}",
           "-var", "n", str(args.n), "-var", "tend", f"{tend if tend else args.window[1]:g}",
           "-var", "eps", f"{args.eps:g}", "-log", log, "-screen", "none"]
    for kv in args.var or []:
        cmd += ["-var"] + kv.split("=", 1)
    start = time.time()
    done = subprocess.run(cmd, cwd=outdir)
    wall = time.time() - start
    if done.returncode != 0:
        sys.exit(f"analyse: LAMMPS failed at Ra = {ra:g} (see {log}): {' '.join(cmd)}")
    return log, wall


def cmd_onset(args):
    outdir = os.path.abspath(args.out)
    os.makedirs(outdir, exist_ok=True)
    pr = args.pr
    a = 2.0 * math.pi / args.width
    ra_c = rb_linear.rayleigh_at(a)
    runs = {}

    def measure(ra):
        log, wall = run_lammps(ra, args, outdir)
        table = thermo_table(log)
        sigma, se, use = fit_growth(table, *args.window)
        lin = rb_linear.growth_rate(ra, a, pr)
        runs[ra] = dict(log=log, table=table, sigma=sigma, se=se, linear=lin, wall=wall,
                        steps=int(table["Step"][-1]), t_end=table["Time"][-1])
        print(f"  Ra = {ra:8.2f}: sigma = {sigma:+7.3f} +- {se:.3f} (linear theory {lin:+7.3f}), "
              f"t_end {table['Time'][-1]:.3f}, {int(table['Step'][-1])} steps, {wall:.1f} s",
              flush=True)
        if not math.isfinite(sigma):
            sys.exit(f"analyse: no growth rate at Ra = {ra:g} (too few thermo rows in the window)")
        return sigma

    print(f"onset search: W/H = {args.width:g} (a = {a:.5f}), Pr = {pr:g}, {args.n} particles per H, "
          f"eps = {args.eps:g}, window t = {args.window[0]:g}..{args.window[1]:g}, method {args.method}; "
          f"linear theory Ra_c = {ra_c:.2f}", flush=True)
    lo, hi = args.lo, args.hi
    s_lo, s_hi = measure(lo), measure(hi)
    if not (s_lo < 0.0 < s_hi):
        sys.exit(f"analyse: [{lo:g}, {hi:g}] does not bracket the onset (sigma {s_lo:+.3f}, {s_hi:+.3f})")
    w_lo, w_hi = s_lo, s_hi      # the Illinois weights
    side = 0
    for step in range(1, args.steps + 1):
        if hi - lo <= args.tol * hi:
            print(f"stop: the bracket is narrower than {args.tol:g} Ra")
            break
        if args.method == "bisect":
            ra = 0.5 * (lo + hi)
        else:
            ra = lo - w_lo * (hi - lo) / (w_hi - w_lo)
        s = measure(ra)
        if s < 0.0:
            lo, s_lo, w_lo = ra, s, s
            if side == -1:
                w_hi *= 0.5
            side = -1
        else:
            hi, s_hi, w_hi = ra, s, s
            if side == 1:
                w_lo *= 0.5
            side = 1
        est = lo - s_lo * (hi - lo) / (s_hi - s_lo)
        print(f"step {step}: bracket [{lo:.2f}, {hi:.2f}], onset estimate {est:.1f} "
              f"({100.0 * (est / ra_c - 1.0):+.2f} % against {ra_c:.2f})", flush=True)
        if abs(s) <= runs[ra]["se"]:
            print(f"stop: |sigma| at Ra = {ra:.2f} is within its fit error")
            break
    est = lo - s_lo * (hi - lo) / (s_hi - s_lo)
    err = 100.0 * (est / ra_c - 1.0)
    # the fit errors of the two ends, through the line's slope
    slope = (s_hi - s_lo) / (hi - lo)
    d_est = math.hypot(runs[lo]["se"], runs[hi]["se"]) / slope
    total = sum(r["wall"] for r in runs.values())
    print(f"onset: Ra_c = {est:.1f} +- {d_est:.1f} (SPH, zero of sigma between {lo:.2f} and {hi:.2f}; "
          f"+- from the fit errors); linear theory {ra_c:.2f}; error {err:+.2f} %")
    print(f"{len(runs)} runs, {total:.0f} s of LAMMPS")
    print("| Ra | sigma (SPH) | sigma (linear) | steps | run time (s) |")
    print("|---|---|---|---|---|")
    for ra in sorted(runs):
        r = runs[ra]
        print(f"| {ra:.1f} | {r['sigma']:+.3f} +- {r['se']:.3f} | {r['linear']:+.3f} | "
              f"{r['steps']} | {r['wall']:.1f} |")
    if args.png:
        plot(runs, args, a, ra_c, est, os.path.join(outdir, args.png))
    if args.results:
        write_onset_result(args.results, args, est, d_est, ra_c, err, len(runs), total)
    if args.max_error is not None and abs(err) > args.max_error:
        print(f"FAIL: |onset error| {abs(err):.2f} % > {args.max_error} %")
        return 1
    return 0


def write_onset_result(path, args, est, d_est, ra_c, err, nruns, total):
    """One row per width and resolution in the results file: this search's
    replaces the row of the same width, particles per H and window."""
    head = ["# analyse.py onset --results: the Rayleigh-Benard onset of in.rb (the package's "
            "defaults) against linear theory (tools/rb_linear.py)",
            "| W/H | particles per H | window | onset Ra_c | linear theory | error | runs | "
            "LAMMPS time (s) |",
            "|---|---|---|---|---|---|---|---|"]
    key = f"| {args.width:g} | {args.n} | {args.window[0]:g}-{args.window[1]:g} |"
    rows = []
    if os.path.exists(path):
        rows = [r for r in open(path).read().splitlines()[len(head):] if not r.startswith(key)]
    rows.append(f"{key} {est:.1f} +- {d_est:.1f} | {ra_c:.2f} | {err:+.2f} % | {nruns} | {total:.0f} |")
    rows.sort(key=lambda r: (float(r.split("|")[1]), int(r.split("|")[2])))
    with open(path, "w") as f:
        f.write("\n".join(head + rows) + "\n")


def plot(runs, args, a, ra_c, est, png):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(1, 2, figsize=(12, 4.8))
    cmap = plt.get_cmap("coolwarm")
    ras = sorted(runs)
    span = (max(ras) - min(ras)) or 1.0
    for ra in ras:
        r = runs[ra]
        t, ke = r["table"]["Time"], r["table"]["c_ke"]
        ok = ke > 0
        ax[0].plot(t[ok], np.log(ke[ok]), color=cmap((ra - min(ras)) / span), label=f"Ra {ra:.0f}")
    ax[0].axvspan(*args.window, color="0.9", zorder=0)
    ax[0].set_xlabel("t (H^2 / alpha)")
    ax[0].set_ylabel("ln KE")
    ax[0].set_title(f"kinetic energy of the fluid (fit window shaded)")
    ax[0].legend(fontsize=7, ncol=2)
    grid = np.linspace(min(ras) * 0.95, max(ras) * 1.02, 60)
    ax[1].plot(grid, [rb_linear.growth_rate(x, a, args.pr) for x in grid], "-", label="linear theory")
    ax[1].errorbar(ras, [runs[x]["sigma"] for x in ras], yerr=[runs[x]["se"] for x in ras],
                   fmt="o", label="SPH (in.rb)")
    ax[1].axhline(0.0, color="k", lw=0.6)
    ax[1].axvline(ra_c, color="C0", ls=":", label=f"Ra_c linear {ra_c:.1f}")
    ax[1].axvline(est, color="C1", ls="--", label=f"Ra_c SPH {est:.1f}")
    ax[1].set_xlabel("Ra")
    ax[1].set_ylabel("growth rate sigma (alpha / H^2)")
    ax[1].set_title(f"W/H = {args.width:g}, a = {a:.4f}, Pr = {args.pr:g}, {args.n} particles per H")
    ax[1].legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(png, dpi=110)
    print(f"wrote {png}")


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    sub = p.add_subparsers(dest="mode", required=True)
    f = sub.add_parser("fit", help="growth rates of existing logs")
    f.add_argument("logs", nargs="+")
    f.add_argument("--window", type=float, nargs=2, default=(0.1, 0.3), metavar=("T0", "T1"))
    o = sub.add_parser("onset", help="run in.rb and search the onset")
    o.add_argument("--lo", type=float, default=1000.0)
    o.add_argument("--hi", type=float, default=4000.0)
    o.add_argument("--steps", type=int, default=6)
    o.add_argument("--method", choices=("falsi", "bisect"), default="falsi")
    o.add_argument("--tol", type=float, default=0.002,
                   help="stop when the bracket is narrower than tol * Ra (default 0.002)")
    o.add_argument("--width", type=float, default=2.0)
    o.add_argument("--pr", type=float, default=0.71)
    o.add_argument("--n", type=int, default=20, help="particles per H")
    o.add_argument("--eps", type=float, default=1e-2)
    o.add_argument("--window", type=float, nargs=2, default=(0.1, 0.3), metavar=("T0", "T1"),
                   help="fit window; the runs end at T1")
    o.add_argument("--var", action="append", metavar="NAME=VALUE", help="more -var for in.rb")
    o.add_argument("--lmp", default=os.environ.get("LMP", os.path.join(ROOT, "build", "lmp")))
    o.add_argument("--plugin", default=os.environ.get("PLUGIN",
                                                      os.path.join(ROOT, "build", "sphthermalplugin.so")))
    o.add_argument("--out", default=".", help="directory of the logs and the PNG")
    o.add_argument("--png", default="onset.png")
    o.add_argument("--max-error", type=float, help="fail (exit 1) above this onset error, %%")
    o.add_argument("--results", help="keep this search's onset as a row of this results file")
    u = sub.add_parser("nu", help="mean Nu of logs above onset against tools/rb_fv.py")
    u.add_argument("logs", nargs="*")
    u.add_argument("--run", type=float, nargs="+", metavar="RA", help="run in.rb at these Ra first")
    u.add_argument("--n", type=int, default=20, help="particles per H (--run)")
    u.add_argument("--tend", type=float, default=0.8, help="end time (--run)")
    u.add_argument("--dir", default=".", help="directory of the logs (--run)")
    u.add_argument("--var", action="append", metavar="NAME=VALUE", help="more -var for in.rb (--run)")
    u.add_argument("--lmp", default=os.environ.get("LMP", os.path.join(ROOT, "build", "lmp")))
    u.add_argument("--plugin", default=os.environ.get("PLUGIN",
                                                      os.path.join(ROOT, "build", "sphthermalplugin.so")))
    u.add_argument("--from", dest="start", type=float, default=0.4,
                   help="average over t >= FROM (default 0.4 H^2/alpha)")
    u.add_argument("--reference", default=os.path.join(ROOT, "tools", "rb_fv_results.txt"))
    u.add_argument("--out", help="write the table to this file")
    u.add_argument("--max-error", type=float, help="fail (exit 1) above this |Nu error|, %%")
    args = p.parse_args()
    if args.mode == "fit":
        return cmd_fit(args)
    if args.mode == "nu":
        return cmd_nu(args)
    if args.pr != 0.71:
        args.var = (args.var or []) + [f"pr={args.pr:g}"]
    return cmd_onset(args)


if __name__ == "__main__":
    sys.exit(main())
