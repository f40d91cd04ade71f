"""fix sph/dt/reset with its defaults keeps conduction stable where material
ratios and disorder are extreme (robust.dt_stable.<case>, called by ctest).

Two materials side by side in a periodic box, a sharp temperature jump,
jittered positions; the fix chooses dt every step with its default
coefficients. The explicit update with the fix's thermal limit (C_t <= 1)
is a convex combination of old temperatures, so T must stay within its
initial range (a maximum principle) for 300 steps. The same case with
'thermal 4' (four times past the limit) must break that bound: the check
can fail.
"""

import argparse
import re
import sys

from sphtest import lammps_arguments, run_script

CASES = {
    # name: (mean, k2 / k1, rho2 cv2 / (rho1 cv1), jitter in spacings)
    "arithmetic_k1e4": ("arithmetic", 1.0e4, 1.0, 0.0),
    "harmonic_k1e4": ("harmonic", 1.0e4, 1.0, 0.0),
    "arithmetic_k1e4_rhocv1e3": ("arithmetic", 1.0e4, 1.0e-3, 0.3),
    "harmonic_rhocv1e3_disorder": ("harmonic", 1.0, 1.0e3, 0.3),
}

INPUT = """
plugin load {plugin}
units si
dimension 2
atom_style sph
atom_modify map array
boundary p p p
lattice sq 0.01 origin 0.5 0.5 0.0
region box block 0 16 0 8 -0.5 0.5
create_box 2 box
create_atoms 1 box
displace_atoms all random {jitter} {jitter} 0.0 4321 units box
region right block 8 INF INF INF INF INF
group right region right
set group right type 2
mass 1 0.1
mass 2 {mass2}
set group all sph/rho 1000.0
set type 2 sph/rho {rho2}
set group all sph/cv 1.0
set type 2 sph/cv {cv2}
variable e0 atom (300.0+100.0*(type-1))*(1.0+0.2*(type-1)*(y>0.04))
variable cv atom 1.0+{cv2m1}*(type-1)
variable e atom v_cv*v_e0
set group all sph/e v_e
fix materials all sph/materials type 1 conductivity constant 1.0 type 2 conductivity constant {k2}
pair_style sph/cleary/heat cubic 0.026 mean {mean}
pair_coeff * *
fix integrate all sph/stationary
fix dt all sph/dt/reset 1 {dtargs}
compute T all sph/t/atom
compute Tmin all reduce min c_T
compute Tmax all reduce max c_T
thermo_style custom step dt f_dt[2] c_Tmin c_Tmax
thermo_modify format float %.17g
thermo 300
run 0
variable lo equal $(c_Tmin:%.17g)
variable hi equal $(c_Tmax:%.17g)
thermo 10
run 300
print "RANGE $(v_lo:%.17g) $(v_hi:%.17g) $(c_Tmin:%.17g) $(c_Tmax:%.17g)"
"""


def run(a, case, dtargs):
    mean, k2, rhocv2, jitter = CASES[case]
    # the second material's rho cv from its density (and mass) or its cv
    rho2, cv2 = (1000.0 * rhocv2, 1.0) if rhocv2 < 1.0 else (1000.0, rhocv2)
    text = INPUT.format(plugin=a.plugin, jitter=jitter * 0.01, mass2=0.1 * rho2 / 1000.0,
                        rho2=rho2, cv2=cv2, cv2m1=cv2 - 1.0, k2=k2, mean=mean, dtargs=dtargs)
    _, out = run_script(a.lmp, text)
    m = re.search(r"^RANGE (\S+) (\S+) (\S+) (\S+)$", out, re.M)
    if m:
        lo, hi, tmin, tmax = map(float, m.groups())
        return lo, hi, tmin, tmax, ""
    error = re.search(r"^ERROR.*$", out, re.M)
    return None, None, None, None, error.group(0) if error else "no RANGE line"


def main():
    p = argparse.ArgumentParser(description=__doc__)
    lammps_arguments(p, mpi=False)
    p.add_argument("--case", choices=sorted(CASES), required=True)
    a = p.parse_args()
    failed = 0
    lo, hi, tmin, tmax, error = run(a, a.case, "")
    tol = 1e-9 * (hi - lo) if lo is not None else 0.0
    ok = lo is not None and tmin >= lo - tol and tmax <= hi + tol
    failed += not ok
    print(f"{'ok' if ok else 'FAIL'} {a.case}, defaults: T in [{tmin}, {tmax}] after 300 steps, "
          f"initially [{lo}, {hi}] {error}")
    lo, hi, tmin, tmax, error = run(a, a.case, "thermal 4")
    broke = lo is None or tmin < lo - tol or tmax > hi + tol
    failed += not broke
    print(f"{'ok' if broke else 'FAIL'} {a.case}, thermal 4 (past the limit): the bound breaks "
          f"({'T in [%s, %s]' % (tmin, tmax) if lo is not None else error})")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
