"""Conduction across a material interface on particles that are not a lattice.

The slab of Cleary 1998, section 3.2 (80 x 20 particles on 1 m x 0.25 m,
periodic in y, free ends, material 1 at T = 0 for x < 0.5 and material 2
at T = 1 beyond), with its particles jittered or on a rotated lattice.

  disorder.py data FILE [--nx 80] [--ny 20] [--jitter J] [--angle A] [--seed S]
      writes a LAMMPS data file (atom style sph) and prints the spacing of
      the particles' lattice: J is the largest displacement of each
      coordinate, in spacings; A (degrees) is one of ANGLES, the angles at
      which a square lattice fits the periodic height (rotated lattices are
      a little denser or sparser than dx, so the masses use the spacing
      printed).
  disorder.py errors PREFIX --k2 K --rhocv2 R [--nx 80] [--label L]
      [--results FILE] [--max-error E] [--max-drift D]
      errors of PREFIX.dump against a fine 1-D finite-volume solution
      (tools/fv1d.py, its own error printed), in % of the jump, at t1 (when
      2 sqrt(alpha t) of the less diffusive material is 4 spacings) and 10 t1;
      the relative change of sum(m esph) from PREFIX.energy, whose lines
      (one per dump frame) give the frames' times. With --results,
      appends a line to FILE.
  disorder.py report FILE PNG
      the table of a results file (markdown) and its plot.
"""

import argparse
import json
import math
import os
import sys

import numpy as np

import fv1d
from sphthermal_tools.dump import read_frames

# rotated lattices that are periodic over the slab's height of ny = 20
# spacings: lattice vectors of length a at angle atan(m / n), with
# m e1 + n e2 = (0, 20 dx), so a = 20 dx / sqrt(m^2 + n^2)
ROTATIONS = {0.0: (0, 20), 8.5: (3, 20), 20.2: (7, 19), 36.9: (12, 16), 45.0: (14, 14)}
ANGLES = sorted(ROTATIONS)


def positions(nx, ny, jitter, angle, seed):
    dx = 1.0 / nx
    height = ny * dx
    m, n = ROTATIONS[angle]
    if ny != 20 and angle != 0.0:
        raise SystemExit("rotated lattices are made for ny = 20")
    spacing = height / math.hypot(m, n)
    theta = math.atan2(m, n)
    e1 = spacing * np.array([math.cos(theta), math.sin(theta)])
    e2 = spacing * np.array([-math.sin(theta), math.cos(theta)])
    # enough lattice points to cover the slab, folded into the periodic height
    reach = int(2 * (nx + ny))
    i, j = np.meshgrid(np.arange(-reach, reach), np.arange(-reach, reach), indexing="ij")
    p = i.ravel()[:, None] * e1 + j.ravel()[:, None] * e2 + 0.5 * (e1 + e2)
    p[:, 1] = np.mod(p[:, 1], height)
    # the interface x = 0.5 halfway between the two nearest columns of
    # particles, as on the lattice at 0 degrees (at 20.2 and 45 degrees a
    # column would lie on it, its material a matter of round-off)
    columns = np.unique(np.round(p[:, 0], 12))
    p[:, 0] += 0.5 - 0.5 * (columns[columns <= 0.5].max() + columns[columns > 0.5].min())
    p = p[(p[:, 0] > 0.0) & (p[:, 0] < 1.0)]
    # the fold maps each lattice point of the strip onto itself many times
    key = np.round(p / (1e-6 * spacing)).astype(np.int64)
    key[:, 1] %= int(round(height / (1e-6 * spacing)))
    _, first = np.unique(key, axis=0, return_index=True)
    p = p[np.sort(first)]
    if jitter > 0.0:
        rng = np.random.default_rng(seed)
        p = p + rng.uniform(-jitter * dx, jitter * dx, p.shape)
        p[:, 1] = np.mod(p[:, 1], height)
        p[:, 0] = np.clip(p[:, 0], 1e-9, 1.0 - 1e-9)
    return p, spacing, height


def write_data(path, p, height):
    with open(path, "w") as f:
        f.write("two-material slab (examples/conduction-disorder/disorder.py)\n\n")
        f.write(f"{len(p)} atoms\n2 atom types\n\n")
        f.write(f"0 1 xlo xhi\n0 {height:.17g} ylo yhi\n-0.5 0.5 zlo zhi\n\nAtoms # sph\n\n")
        for n, (x, y) in enumerate(p):
            # id type rho esph cv x y z: the state comes from sph/set
            f.write(f"{n + 1} {1 if x < 0.5 else 2} 0 0 0 {x:.17g} {y:.17g} 0\n")


def layers_for(k2, rhocv2):
    # material 1: k = 1, rho = 1000, cv = 1; material 2: k2 and rho cv = rhocv2 * 1000
    return [fv1d.Layer(0.0, 0.5, "constant:1", 1000.0, 1.0, 0.0),
            fv1d.Layer(0.5, 1.0, f"constant:{k2}", 1000.0 * rhocv2, 1.0, 1.0)]


def diffusivities(layers):
    return [float(L.k(np.array(L.T0))) / (L.rho * L.cv) for L in layers]


def t1_of(layers, nx):
    """when 2 sqrt(alpha t) of the less diffusive material is 4 spacings"""
    dx = 1.0 / nx
    return 4.0 * dx * dx / min(diffusivities(layers))


def errors(a):
    layers = layers_for(a.k2, a.rhocv2)
    t1 = t1_of(layers, a.nx)
    energy = np.loadtxt(a.prefix + ".energy", ndmin=2)
    frames = [(t, c) for t, (step, c) in zip(energy[:, 0], read_frames(a.prefix + ".dump"))
              if step > 0]
    wanted = [t1, 10.0 * t1]
    picked = [min(frames, key=lambda f: abs(f[0] - t)) for t in wanted]
    if a.cells is None:
        # fv1d is explicit: its step follows the most diffusive material
        alphas = diffusivities(layers)
        a.cells = 1000 if max(alphas) / min(alphas) <= 30.0 else 200
    x_fv, T_fv = fv1d.solve(layers, 1.0, a.cells, [t for t, _ in picked])
    fv_error = 100.0 * fv1d.reference_error(layers, 1.0, a.cells, [t for t, _ in picked])
    errs = []
    for (t, c), T_ref in zip(picked, T_fv):
        errs.append(100.0 * np.max(np.abs(c["c_T"] - np.interp(c["x"], x_fv, T_ref))))
    # for scale: the same finite-volume scheme (second order, the interface on a cell face)
    # with one cell per particle spacing
    x_nx, T_nx = fv1d.solve(layers, 1.0, a.nx, [t for t, _ in picked])
    errs_nx = [100.0 * np.max(np.abs(T - np.interp(x_nx, x_fv, T_ref)))
               for T, T_ref in zip(T_nx, T_fv)]
    drift = float(np.max(np.abs(energy[:, 1] / energy[0, 1] - 1.0)))
    print(f"finite-volume reference: {a.cells} cells, own error {fv_error:.4f} % of the jump")
    print(f"finite volumes on {a.nx} cells (one per spacing): max error at t1 {errs_nx[0]:.3f} %, "
          f"at 10 t1 {errs_nx[1]:.3f} %")
    print(f"{a.label}: max error at t1 = {picked[0][0]:g} s: {errs[0]:.3f} %, at 10 t1: "
          f"{errs[1]:.3f} %; largest change of sum(m esph): {drift:.1e}")
    if a.results:
        with open(a.results, "a") as f:
            f.write(json.dumps({"label": a.label, "t1": errs[0], "t10": errs[1], "drift": drift,
                                "fv_error": fv_error}) + "\n")
    failed = (a.max_error is not None and max(errs) > a.max_error) or \
        (a.max_drift is not None and drift > a.max_drift)
    if failed:
        print(f"FAIL: max error above {a.max_error} % or energy drift above {a.max_drift}")
    return 1 if failed else 0


# the operators of run.sh: label suffix, name in the table and the plot, marker
OPERATORS = [("none", "plain", "o--"), ("consistent", "consistent", "s-"),
             ("consistent+interface", "consistent + interface", "^-"),
             ("consistent+given", "consistent + given distance", "v-"),
             ("second+given", "second + given distance", "D-")]


def report(path, png):
    rows = [json.loads(line) for line in open(path) if line.strip()]
    by_case = {}
    for r in rows:
        case, _, op = r["label"].rpartition(" ")
        by_case.setdefault(case, {})[op] = r
    ops = [o for o in OPERATORS if any(o[0] in v for v in by_case.values())]
    print("| particles | " + " | ".join(f"{name}: t1 | 10 t1" for _, name, _ in ops) + " |")
    print("|---|" + "---|---|" * len(ops))
    for case, results in by_case.items():
        cells = [f"{results[op]['t1']:.2f} | {results[op]['t10']:.3f}" if op in results else " | "
                 for op, _, _ in ops]
        print(f"| {case} | " + " | ".join(cells) + " |")
    print(f"largest change of sum(m esph) in any run: {max(r['drift'] for r in rows):.0e}; "
          f"largest own error of the reference: {max(r['fv_error'] for r in rows):.3f} %")

    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    groups = [("jitter", "jitter (dx)"), ("angle", "lattice angle (degrees)"),
              ("ratio", "property ratio case")]
    fig, axes = plt.subplots(1, 3, figsize=(13, 4.2))
    for ax, (kind, xlabel) in zip(axes, groups):
        for op, name, style in ops:
            sel = [r for r in rows if r["label"].startswith(kind + " ")
                   and r["label"].endswith(" " + op)]
            labels = [r["label"].split()[1] for r in sel]
            xs = np.arange(len(sel)) if kind == "ratio" else [float(v) for v in labels]
            for key, colour in [("t1", "C0"), ("t10", "C1")]:
                ax.plot(xs, [r[key] for r in sel], style, color=colour,
                        mfc="none" if op == "none" else colour,
                        label=f"{name}, {'t1' if key == 't1' else '10 t1'}")
            if kind == "ratio":
                ax.set_xticks(xs)
                ax.set_xticklabels(labels, fontsize=7, rotation=20)
        ax.set_yscale("log")
        ax.set_xlabel(xlabel)
        ax.set_ylabel("max error (% of the jump)")
        ax.grid(alpha=0.3)
    axes[0].legend(fontsize=7)
    fig.suptitle("two-material slab, 80 x 20, cubic kernel, h = 1.3 dx: pair sph/cleary/heat "
                 "plain, with correction consistent or second, with mean interface estimated "
                 "or given", fontsize=9)
    fig.tight_layout()
    fig.savefig(png, dpi=110)
    print("plot:", os.path.abspath(png))


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    sub = p.add_subparsers(dest="command", required=True)
    d = sub.add_parser("data")
    d.add_argument("file")
    d.add_argument("--nx", type=int, default=80)
    d.add_argument("--ny", type=int, default=20)
    d.add_argument("--jitter", type=float, default=0.0)
    d.add_argument("--angle", type=float, default=0.0, choices=ANGLES)
    d.add_argument("--seed", type=int, default=1)
    e = sub.add_parser("errors")
    e.add_argument("prefix")
    e.add_argument("--k2", type=float, required=True)
    e.add_argument("--rhocv2", type=float, required=True)
    e.add_argument("--nx", type=int, default=80)
    e.add_argument("--cells", type=int, help="finite-volume cells (default 1000, or 200 when "
                   "the diffusivities differ by more than 10)")
    e.add_argument("--label", default="slab")
    e.add_argument("--results")
    e.add_argument("--max-error", type=float)
    e.add_argument("--max-drift", type=float)
    r = sub.add_parser("report")
    r.add_argument("file")
    r.add_argument("png")
    a = p.parse_args()
    if a.command == "data":
        pts, spacing, height = positions(a.nx, a.ny, a.jitter, a.angle, a.seed)
        write_data(a.file, pts, height)
        print(f"{spacing:.17g}")
        return 0
    if a.command == "errors":
        return errors(a)
    report(a.file, a.png)
    return 0


if __name__ == "__main__":
    sys.exit(main())
