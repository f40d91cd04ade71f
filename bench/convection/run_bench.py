#!/usr/bin/env python3
"""Natural convection: error of the mean Nusselt number against run time.

Runs examples/convection-cavity/in.cavity (differentially heated square
cavity, Pr = 0.71) at a Rayleigh number over resolutions and kernels, one
MPI rank, and writes a table and a PNG of |Nu error| (time-averaged heat
estimate, against de Vahl Davis 1983) against LAMMPS's loop time.

  tools/sphpython bench/convection/run_bench.py            # Ra 1e5: 40, 60, 80 across, Wendland
                                                            # h = 2 dx and quintic h = 1.5 dx (about 1 h)
  tools/sphpython bench/convection/run_bench.py --quick    # Ra 1e4: 20 and 40 across (about 2 min)

Options: --ra, --n N N ..., --kernels wendland:2.0 quintic:1.5 ..., --out DIR.
"""

import argparse
import os
import re
import subprocess
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.abspath(os.path.join(HERE, "..", ".."))
from cavity_fv import DE_VAHL_DAVIS
from sphthermal_tools.log import late_rows, longest_thermo_table


def run(lmp, plugin, ra, n, kernel, hdx, out):
    log = os.path.join(out, f"log.ra{ra:g}.{kernel}{hdx:g}.n{n}")
    cmd = [lmp, "-in", os.path.join(ROOT, "examples/convection-cavity/in.cavity-options"), "-var", "plugin",
           plugin, "-var", "ra", f"{ra:g}", "-var", "n", str(n), "-var", "kernel", kernel,
           "-var", "hdx", str(hdx), "-var", "out", os.path.join(out, "bench.dump"), "-log", log,
           "-screen", "none"]
    proc = subprocess.run(cmd, capture_output=True, text=True)
    text = open(log).read() if os.path.exists(log) else ""
    if proc.returncode != 0 or "final:" not in text:
        return None
    table = longest_thermo_table(text)
    late = late_rows(table)
    nu = 0.5 * (table["c_nu_hot[1]"][late].mean() + table["c_nu_cold[1]"][late].mean())
    loops = [float(m) for m in re.findall(r"Loop time of (\S+) on \d+ procs for [1-9]", text)]
    steps = int(table["Step"][-1])
    return {"n": n, "kernel": kernel, "hdx": hdx, "nu": nu, "error": 100.0 * (nu / DE_VAHL_DAVIS[ra][0] - 1.0),
            "seconds": sum(loops), "steps": steps}


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawTextHelpFormatter)
    p.add_argument("--quick", action="store_true")
    p.add_argument("--ra", type=float)
    p.add_argument("--n", type=int, nargs="+")
    p.add_argument("--kernels", nargs="+")
    p.add_argument("--lmp", default=os.environ.get("LMP", os.path.join(ROOT, "build", "lmp")))
    p.add_argument("--plugin", default=os.environ.get("PLUGIN",
                                                      os.path.join(ROOT, "build", "sphthermalplugin.so")))
    p.add_argument("--out", default=os.path.join(HERE, "out"))
    a = p.parse_args()
    ra = a.ra or (1e4 if a.quick else 1e5)
    ns = a.n or ([20, 40] if a.quick else [40, 60, 80])
    kernels = [k.split(":") for k in (a.kernels or (["wendland:2.0"] if a.quick else
                                                    ["wendland:2.0", "quintic:1.5"]))]
    os.makedirs(a.out, exist_ok=True)
    rows = []
    print(f"Ra = {ra:g}, Pr = 0.71; de Vahl Davis Nu = {DE_VAHL_DAVIS[ra][0]}")
    print("| kernel, h | particles | steps | loop time (s) | mean Nu | error |")
    print("|---|---|---|---|---|---|")
    for kernel, hdx in kernels:
        for n in ns:
            r = run(a.lmp, a.plugin, ra, n, kernel, float(hdx), a.out)
            if r is None:
                print(f"| {kernel}, {hdx} dx | {n} x {n} | failed | | | |")
                continue
            rows.append(r)
            print(f"| {kernel}, {hdx} dx | {n} x {n} | {r['steps']} | {r['seconds']:.1f} | "
                  f"{r['nu']:.4f} | {r['error']:+.2f} % |", flush=True)
    if not rows:
        return 1
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(figsize=(6, 4.5))
    for kernel, hdx in kernels:
        pts = [(r["seconds"], abs(r["error"]), r["n"]) for r in rows
               if r["kernel"] == kernel and r["hdx"] == float(hdx)]
        if pts:
            t, e, n = zip(*pts)
            ax.loglog(t, e, "o-", label=f"{kernel}, h = {hdx} dx")
            for ti, ei, ni in pts:
                ax.annotate(f"{ni}", (ti, ei), fontsize=8)
    ax.set_xlabel("loop time on one core (s)")
    ax.set_ylabel("|error of mean Nu| (%)")
    ax.set_title(f"heated cavity, Ra = {ra:g}")
    ax.legend()
    fig.tight_layout()
    png = os.path.join(a.out, f"nu_error_time_ra{ra:g}.png")
    fig.savefig(png, dpi=110)
    print(f"wrote {png}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
