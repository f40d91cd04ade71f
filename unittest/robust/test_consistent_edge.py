"""pair sph/cleary/heat 'correction consistent' on a lattice rotated against
free edges (robust.consistent_edge.<case>, called by ctest).

A square lattice rotated by atan(1/2) (lattice sq with orient x 2 -1 0,
orient y 1 2 0) fills a box whose corners are lattice points, so the free
edges cut the lattice rows: atoms lie exactly on the edges and the corner
atoms see a quarter of a support at odd angles. A linear temperature field,
run 0 and run 1 (dumped at steps 0 and 1) with fix sph/stationary. Checked:
- desph is finite on every atom (the run does not stop on a NaN);
- compute sph/correction/atom reports 0 on the four corner atoms (the
  plain term of incomplete support) and 1 deep inside;
- sum m desph = 0 to round-off (the free edges are adiabatic);
- deep inside (beyond the reach of the edges through S and the 5 Jacobi
  sweeps of lambda: eight supports) desph of the linear field is
  0 to round-off, as the consistent operator conducts it exactly.
"""

import argparse
import os
import sys

import numpy as np

from sphtest import lammps_arguments, run_script

DX = 0.01
CASES = {
    # name: (kernel, h / dx, boundary)
    "cubic_f": ("cubic", 1.0, "f"),
    "wendland_s": ("wendland", 1.3, "s"),
    "quintic_f": ("quintic", 1.2, "f"),
}

INPUT = """
plugin load {plugin}
units si
dimension 2
atom_style sph
atom_modify map array
boundary {b} {b} p
lattice sq {dx} orient x 2 -1 0 orient y 1 2 0
region box block -26 26 -26 26 -0.5 0.5
create_box 1 box
create_atoms 1 box
mass 1 0.1
set group all sph/rho 1000.0
set group all sph/cv 1.0
variable e atom 300.0+1000.0*x+500.0*y
set group all sph/e v_e
fix materials all sph/materials type 1 conductivity constant 1.0
pair_style sph/cleary/heat {kernel} {cut} correction consistent
pair_coeff * *
fix integrate all sph/stationary
compute c all sph/correction/atom
compute d all property/atom desph
dump 1 all custom 1 {dump} id x y c_c c_d
dump_modify 1 format float %.17g sort id
run 0
run 1
print "DONE"
"""


def frames(path):
    """the dump's frames, each an array id x y c desph"""
    out, lines = [], open(path).read().split("\n")
    k = 0
    while k < len(lines):
        if lines[k].startswith("ITEM: NUMBER OF ATOMS"):
            n = int(lines[k + 1])
            while not lines[k].startswith("ITEM: ATOMS"):
                k += 1
            out.append(np.array([[float(v) for v in lines[k + 1 + a].split()] for a in range(n)]))
            k += n
        k += 1
    return out


def main():
    p = argparse.ArgumentParser(description=__doc__)
    lammps_arguments(p, mpi=False)
    p.add_argument("--case", choices=sorted(CASES), required=True)
    a = p.parse_args()
    kernel, hfac, b = CASES[a.case]
    cut = hfac * DX * (3.0 if kernel == "quintic" else 2.0)
    dump = os.path.join(os.getcwd(), f"consistent_edge_{a.case}.dump")
    text = INPUT.format(plugin=a.plugin, b=b, dx=DX, kernel=kernel, cut=cut, dump=dump)
    rc, out = run_script(a.lmp, text)
    failed = 0

    def check(ok, msg):
        nonlocal failed
        failed += not ok
        print(f"{'ok' if ok else 'FAIL'} {a.case}: {msg}")

    check(rc == 0 and "DONE" in out, "run 0 and run 1 finish " +
          "".join(line for line in out.splitlines() if line.startswith("ERROR")))
    if failed:
        print(out[-3000:])
        return 1
    fr = frames(dump)
    os.remove(dump)
    check(len(fr) == 2, f"{len(fr)} frames dumped (steps 0 and 1 expected)")
    for f in fr:
        x, y, state, desph = f[:, 1], f[:, 2], f[:, 3], f[:, 4]
        check(np.all(np.isfinite(desph)), f"desph finite on all {len(f)} atoms")
        # the corners: extreme x + y and x - y
        corners = {int(np.argmax(x + y)), int(np.argmin(x + y)), int(np.argmax(x - y)),
                   int(np.argmin(x - y))}
        check(all(state[c] == 0.0 for c in corners), "the corner atoms keep the plain term (0)")
        lo_x, hi_x, lo_y, hi_y = x.min(), x.max(), y.min(), y.max()
        edge = np.minimum.reduce([x - lo_x, hi_x - x, y - lo_y, hi_y - y])
        # beyond the reach of the edges: S and the 5 Jacobi sweeps of lambda
        deep = edge > 8.0 * cut
        check(deep.sum() > 0 and np.all(state[deep] == 1.0),
              f"the {deep.sum()} atoms eight supports inside are corrected (1)")
        scale = np.abs(desph).max()
        check(scale > 0.0, f"the edges conduct (max |desph| {scale:.3g})")
        total = 0.1 * desph.sum()
        check(abs(total) <= 1e-10 * 0.1 * np.abs(desph).sum(),
              f"sum m desph = {total:.3g} (adiabatic free edges)")
        worst = np.abs(desph[deep]).max()
        check(worst <= 1e-8 * scale, f"deep inside |desph| of the linear field {worst:.3g} "
              f"(<= 1e-8 of the edges' {scale:.3g})")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
