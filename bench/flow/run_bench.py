"""Flow benchmark: cost per particle-step of a thermal-flow step (continuity,
momentum, energy) with this package's pair sph/harmonic/visc + pair
sph/cleary/heat against LAMMPS's sph/taitwater/morris + sph/heatconduction
(both as pair hybrid/overlay) on the same particles, kernel (Lucy) and
cutoff, measured in the same run of this script; and the cost of each of
our two pairs alone, to judge whether fusing them into one pair loop would
pay. Serial runs, one at a time, each the fastest of --repeat runs. Writes
results.md here (or in --out).

  tools/sphpython bench/flow/run_bench.py [--quick] [--lmp ...] [--plugin ...]
"""

import argparse
import os
import tempfile

from sphthermal_tools import bench

here = os.path.dirname(os.path.abspath(__file__))
root = os.path.normpath(os.path.join(here, "..", ".."))


NOTES_MARK = "<!-- notes written by hand from here on; run_bench.py keeps them -->"


def kept_notes(path, mark):
    """The notes written by hand below `mark` in the file's last version ("" if none)."""
    if not os.path.exists(path):
        return ""
    text = open(path).read()
    return text[text.index(mark):] if mark in text else ""


def cost(args, workdir, lmp_vars, whole_run=False):
    """sphthermal_tools.bench.cost of this directory's in.bench."""
    return bench.cost(os.path.join(here, "in.bench"), args, workdir, lmp_vars, whole_run)


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--lmp", default=os.path.join(root, "build", "lmp"))
    p.add_argument("--plugin", default=os.path.join(root, "build", "sphthermalplugin.so"))
    p.add_argument("--repeat", type=int, help="runs per point (default 3, 1 with --quick)")
    p.add_argument("--quick", action="store_true", help="one size, one repeat")
    p.add_argument("--out", default=here)
    args = p.parse_args()
    if args.repeat is None:
        args.repeat = 1 if args.quick else 3
    # (n, dim): n x n particles in 2-D, n x n x n in 3-D
    sizes = [(60, 2)] if args.quick else [(60, 2), (120, 2), (24, 3)]
    steps = 300 if args.quick else 1000
    workdir = tempfile.mkdtemp(prefix="sphflowbench")

    rows = []
    for n, dim in sizes:
        base = {"n": n, "steps": steps if dim == 2 else steps // 4, "dim": dim}
        label = f"{n} x {n}" + (f" x {n}" if dim == 3 else "")
        # the same particles, kernel (Lucy) and cutoff (2.6 dx) for both packages
        lammps = cost(args, workdir, dict(base, pair="lammps", kernel="lucy", hdx=2.6))
        ours = cost(args, workdir, dict(base, pair="ours", kernel="lucy", hdx=2.6))
        own = cost(args, workdir, dict(base, pair="own", kernel="lucy", hdx=2.6))
        flow = cost(args, workdir, dict(base, pair="flow", kernel="lucy", hdx=2.6))
        heat = cost(args, workdir, dict(base, pair="heat", kernel="lucy", hdx=2.6))
        rows.append((label, "lucy, cutoff 2.6 dx", lammps, ours, own, flow, heat))
        print(f"{label}: LAMMPS {1e6 * lammps:.3f} us, ours {1e6 * ours:.3f} us "
              f"(ratio {ours / lammps:.2f}); loop own {1e6 * own:.3f}, flow alone {1e6 * flow:.3f}, "
              f"heat alone {1e6 * heat:.3f}")
        if not args.quick and dim == 2:
            for kernel, hdx in [("quintic", 1.0), ("wendland", 1.3), ("cubic", 1.3)]:
                ours_k = cost(args, workdir, dict(base, pair="ours", kernel=kernel, hdx=hdx))
                own_k = cost(args, workdir, dict(base, pair="own", kernel=kernel, hdx=hdx))
                flow_k = cost(args, workdir, dict(base, pair="flow", kernel=kernel, hdx=hdx))
                heat_k = cost(args, workdir, dict(base, pair="heat", kernel=kernel, hdx=hdx))
                cut = {"quintic": 3, "wendland": 2, "cubic": 2}[kernel] * hdx
                rows.append((label, f"{kernel}, h = {hdx} dx (cutoff {cut:.1f} dx)", None, ours_k,
                             own_k, flow_k, heat_k))
                print(f"{label}, {kernel}: ours {1e6 * ours_k:.3f} us, loop own {1e6 * own_k:.3f} us")

    path = os.path.join(args.out, "results.md")
    notes = kept_notes(path, NOTES_MARK)
    with open(path, "w") as f:
        f.write("# Flow benchmark results\n\n")
        f.write("Pair CPU time per particle-step (microseconds), serial, the fastest of "
                f"{args.repeat} runs of {steps} steps; n x n particles in a periodic box "
                "(2-D; n x n x n in 3-D), shear flow and temperature field, fix sph. *thermal flow* = continuity, "
                "momentum and energy: ours = `sph/harmonic/visc` (delta 0, as LAMMPS has no "
                "density diffusion) + `sph/cleary/heat`, whose term the flow pair evaluates in "
                "its own loop (`loop shared`, the default); *loop own*: the same with `loop own` "
                "(each pair loops over the pairs itself); LAMMPS = `sph/taitwater/morris` + "
                "`sph/heatconduction`, both as `pair hybrid/overlay`, Lucy kernel on the same "
                "cutoff. 3-D runs a quarter of the steps. Written by `bench/flow/run_bench.py`."
                "\n\n")
        f.write("| particles | kernel | LAMMPS thermal flow | ours thermal flow | ratio | ours, loop own | ours: flow pair alone | ours: heat pair alone |\n")
        f.write("|---|---|---|---|---|---|---|---|\n")
        for label, kernel, lammps, ours, own, flow, heat in rows:
            lt = f"{1e6 * lammps:.3f}" if lammps else "-"
            ratio = f"{ours / lammps:.2f}" if lammps else "-"
            f.write(f"| {label} | {kernel} | {lt} | {1e6 * ours:.3f} | {ratio} | {1e6 * own:.3f} | "
                    f"{1e6 * flow:.3f} | {1e6 * heat:.3f} |\n")
        f.write("\n" + (notes or NOTES_MARK + "\n"))
    print("wrote", os.path.join(args.out, "results.md"))


if __name__ == "__main__":
    main()
