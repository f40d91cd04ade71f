"""tools/phase_fv.py, the finite-volume reference of the melting and
freezing examples: on the two-phase Stefan problem its melt depth within
1.5e-2 (dx = 0.1) and 6e-3 (dx = 0.05) of Neumann's over t in [0.25, 1]
(measured 1.4e-2 and 5.9e-3: it converges), the energy balance closed to
1e-10; the de Vahl Davis cavity at Ra = 1e4 on 32 x 32 cells: Nu within
1.5 % of 2.243 (measured +1.09 %) and equal on both walls to 1e-6."""

import sys

import phase_fv

failures = []
stefan = phase_fv.stefan_runs(grids=(40, 80))["grids"]
for n, bound in (("40", 1.5e-2), ("80", 6e-3)):
    if not stefan[n]["max_err_depth"] < bound:
        failures.append(f"Stefan, {n} cells: depth error {stefan[n]['max_err_depth']:.2e} >= {bound}")
    if not stefan[n]["max_energy_balance"] < 1e-10:
        failures.append(f"Stefan, {n} cells: energy balance {stefan[n]['max_energy_balance']:.1e}")
if not stefan["80"]["max_err_depth"] < stefan["40"]["max_err_depth"]:
    failures.append("Stefan: the depth error does not fall with the spacing")
cavity = phase_fv.cavity_runs(cases=((1e4, (32,)),))["10000"]["32"]
if not abs(cavity["err_left"]) < 0.015:
    failures.append(f"cavity: Nu {cavity['Nu_left']:.4f} against 2.243")
if not abs(cavity["Nu_left"] - cavity["Nu_right"]) < 1e-6 * cavity["Nu_left"]:
    failures.append(f"cavity: Nu {cavity['Nu_left']:.6f} (hot) and {cavity['Nu_right']:.6f} (cold) differ")
if failures:
    sys.exit("FAIL: " + ", ".join(failures))
print("ok")
