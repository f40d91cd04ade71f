"""Energy books of the thermal fixes do not depend on the order of the fixes
(robust.books.<pair>, called by ctest).

For a pair of fixes among sph/wall/isothermal (tallies the heat the wall
takes up), sph/surface/flux (tallies the heat it adds) and
sph/wall/dirichlet (sets dummy temperatures), on the same atoms or on
different ones, the run is made with the fixes in both orders. Checked:
  - both orders give the same tallies and the same energy of the medium
    (every atom held by no wall fix) to 1e-12;
  - without Dirichlet dummies (whose heat no fix tallies) the books close:
    change of the medium's energy = heat added by the flux - heat taken up
    by the isothermal wall, to 1e-10 of the heat moved.
"""

import argparse
import re
import sys

from sphtest import lammps_arguments, run_script

FIXES = {
    "iso": "fix {id} {group} sph/wall/isothermal 350.0",
    "flux": "fix {id} {group} sph/surface/flux flux 2.0e4 spacing 0.01",
    "dir": "fix {id} {group} sph/wall/dirichlet 250.0",
}
# pair name: (first fix, its group, second fix, its group)
PAIRS = {
    "iso_flux_same_atoms": ("iso", "left", "flux", "left"),
    "iso_flux": ("iso", "left", "flux", "right"),
    "iso_dir": ("iso", "left", "dir", "right"),
    "flux_dir": ("flux", "left", "dir", "right"),
}

INPUT = """
plugin load {plugin}
units si
dimension 2
atom_style sph
atom_modify map array
boundary p p p
lattice sq 0.01 origin 0.5 0.5 0.0
region box block 0 20 0 6 -0.5 0.5
create_box 2 box
create_atoms 1 box
region left block INF 2 INF INF INF INF
region right block 9 11 INF INF INF INF
group left region left
group right region right
set group right type 2
mass * 0.1
set group all sph/rho 1000.0
set group all sph/cv 1000.0
variable e0 atom 1000.0*(300.0+50.0*sin(2*PI*x/0.2)+5.0*cos(2*PI*y/0.06))
set group all sph/e v_e0
fix materials all sph/materials type 1 conductivity constant 1.0 type 2 conductivity constant 3.0
pair_style sph/cleary/heat cubic 0.026
pair_coeff * *
fix integrate all sph/stationary
{fixes}
timestep 2.0
compute e all sph/e/atom
variable me atom mass*c_e
group walls union {wall_groups}
group medium subtract all walls
compute energy medium reduce sum v_me
thermo_style custom step c_energy {tallies}
thermo_modify format float %.17g
run 0
variable e_start equal c_energy
variable e_start_value equal ${{e_start}}
run 200
print "BOOKS medium_change $(c_energy-v_e_start_value:%.17g) {tally_prints}"
"""


def run(lmp, plugin, order, pair):
    a, ga, b, gb = PAIRS[pair]
    fixes = [(a, ga, "fa"), (b, gb, "fb")]
    if order == "ba":
        fixes.reverse()
    lines = "\n".join(FIXES[kind].format(id=fid, group=group) for kind, group, fid in fixes)
    walls = sorted({g for kind, g, _ in fixes if kind in ("iso", "dir")})
    wall_groups = " ".join(walls) if walls else "left"
    tallied = [(fid, kind) for kind, _, fid in fixes if kind in ("iso", "flux")]
    text = INPUT.format(plugin=plugin, fixes=lines, wall_groups=wall_groups,
                        tallies=" ".join(f"f_{fid}" for fid, _ in tallied),
                        tally_prints=" ".join(f"{kind} $(f_{fid}:%.17g)" for fid, kind in tallied))
    if not any(kind in ("iso", "dir") for kind, _, _ in fixes):
        text = text.replace("group walls union left\ngroup medium subtract all walls", "group medium union all")
    returncode, out = run_script(lmp, text)
    m = re.search(r"^BOOKS (.*)$", out, re.M)
    if returncode != 0 or not m:
        print(out)
        sys.exit(f"FAIL {pair} ({order}): the run did not finish")
    words = m.group(1).split()
    return {k: float(v) for k, v in zip(words[::2], words[1::2])}


def main():
    p = argparse.ArgumentParser(description=__doc__)
    lammps_arguments(p, mpi=False)
    p.add_argument("--pair", choices=sorted(PAIRS), required=True)
    a = p.parse_args()
    ab = run(a.lmp, a.plugin, "ab", a.pair)
    ba = run(a.lmp, a.plugin, "ba", a.pair)
    failed = 0
    for key in ab:
        dev = abs(ab[key] - ba[key]) / max(abs(ab[key]), abs(ba[key]), 1e-300)
        ok = dev <= 1e-12
        failed += not ok
        print(f"{'ok' if ok else 'FAIL'} {a.pair}: {key} {ab[key]:.12g} (order ab), {ba[key]:.12g} (ba): "
              f"rel. difference {dev:.1e}")
    if "dir" not in PAIRS[a.pair]:
        for order, books in (("ab", ab), ("ba", ba)):
            moved = books.get("flux", 0.0) - books.get("iso", 0.0)
            scale = abs(books.get("flux", 0.0)) + abs(books.get("iso", 0.0))
            dev = abs(books["medium_change"] - moved) / scale
            ok = scale > 0 and dev <= 1e-10
            failed += not ok
            print(f"{'ok' if ok else 'FAIL'} {a.pair} ({order}): medium energy change "
                  f"{books['medium_change']:.12g} = flux {books.get('flux', 0.0):.12g} - wall uptake "
                  f"{books.get('iso', 0.0):.12g} (rel. deviation {dev:.1e})")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
