"""tools/rb_fv.py, the reference for steady 2-D Rayleigh-Benard rolls
(periodic width W, no-slip isothermal plates, solved as one roll in a cell
of width W/2 with free-slip adiabatic sides): below onset the solution must
be the conduction state to round-off; the onset at which the computed
branch leaves Nu = 1 must be linear theory's (rb_linear.py, an independent
spectral method) for W = 2H and 1.5H, which fails with a wrong wall
condition, width or buoyancy; at Ra = 1e4 the roll must rise at x = 0, the
plates' fluxes agree, both energy balances hold, and Nu on coarse grids
must lie within their stated error of the extrapolated value of
tools/rb_fv_results.txt and converge at second order; the script must
print its values and write a file that read_results reads back."""

import os
import subprocess
import sys
import tempfile

import numpy as np

from checks import below, fail, inside, that, finish

TOOLS = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "tools")
import rb_fv

# (a) below the onset of the box (1707.92 for W = 2H) only conduction is
# steady: the march from a roll decays and Newton lands on theta = 1 - y
r = rb_fv.solve(1500.0, n=16, n_start=16)
y = r["centres"]["y"]
below(abs(r["nu_bottom"] - 1.0) + abs(r["nu_top"] - 1.0), 1e-12, "Ra = 1500: plates' Nu - 1")
below(np.abs(r["centres"]["theta"] - (1.0 - y)[None, :]).max(), 1e-12, "Ra = 1500: theta - (1 - y)")
below(max(np.abs(r["centres"]["u"]).max(), np.abs(r["centres"]["v"]).max()), 1e-10, "Ra = 1500: velocity")

# (b) the onset of the computed branch: Nu - 1 is quadratic in Ra through
# Ra = 1.03, 1.06, 1.1 Ra_c; its zero against linear theory (measured at
# n = 32: +8.5e-4 for W = 2H, +1.7e-3 for 1.5H; second order in n).
# Free-slip plates would put it near 779, no-slip sides far above
for width in (2.0, 1.5):
    ra_c = rb_fv.onset(width)
    ras = np.array([1.03, 1.06, 1.1]) * ra_c
    nus = np.array([rb_fv.solve(ra, n=32, width=width, n_start=32)["nu"] - 1.0 for ra in ras])
    that(bool(np.all(nus > 0.02)), f"W = {width:g}: convecting just above onset", f"Nu - 1 = {nus}")
    roots = np.roots(np.polyfit(ras - ra_c, nus, 2)).real
    ra_0 = ra_c + roots[np.argmin(np.abs(roots))]
    print(f"W = {width:g}: branch leaves Nu = 1 at Ra {ra_0:.2f}, linear theory {ra_c:.2f}")
    below(abs(ra_0 / ra_c - 1.0), 3e-3, f"W = {width:g}: onset of the branch against rb_linear")

# (c) Ra = 1e4 on 16 and 32 cells against the extrapolated reference
ref = rb_fv.read_results(os.path.join(TOOLS, "rb_fv_results.txt"))[(1e4, 0.71, 2.0)]
nu_ref, nu_err = ref["nu"]
below(nu_err / nu_ref, 1e-5, "Ra = 1e4: stated error of the reference Nu (relative)")
res = {n: rb_fv.solve(1e4, n=n, n_start=16) for n in (16, 32)}
r = res[32]
below(abs(r["nu_top"] - r["nu_bottom"]) / r["nu_bottom"], 1e-12, "Ra = 1e4: top and bottom Nu")
that(r["vmax"] > 0 and abs(r["x_vmax"]) < 1e-12 and r["centres"]["theta"][0, 15] > 0.6,
     "Ra = 1e4: the hot plume rises at x = 0",
     f"v_max {r['vmax']:.3f} at x {r['x_vmax']:g}, theta {r['centres']['theta'][0, 15]:.3f}")
below(abs(r["vtheta"] - (r["nu"] - 1.0)), 1e-11, "Ra = 1e4: <v theta> = Nu - 1")
below(abs(r["dissipation"] / (1e4 * (r["nu"] - 1.0)) - 1.0), 2e-4,
      "Ra = 1e4, n = 32: <|grad u|^2> = Ra (Nu - 1)")
err = {n: res[n]["nu"] / nu_ref - 1.0 for n in res}
print(f"Ra = 1e4: Nu {res[32]['nu']:.7f} (n = 32), reference {nu_ref:.7f}; "
      f"relative error {err[16]:+.2e} (16), {err[32]:+.2e} (32)")
# rb_fv.md states -1.3e-2 for n = 16 and -3.3e-3 for n = 32
below(abs(err[32]), 4e-3, "Ra = 1e4, n = 32: Nu within its stated error")
below(abs(err[16]), 2e-2, "Ra = 1e4, n = 16: Nu within its stated error")
inside(err[16] / err[32], 3.5, 4.5, "Ra = 1e4: error ratio n = 16 / n = 32 (second order)")

# (d) the script: printed values, and the --converge file read back
run = subprocess.run([sys.executable, os.path.join(TOOLS, "rb_fv.py"), "--ra", "1e4", "--n", "16"],
                     capture_output=True, text=True)
print(run.stdout, end="")
if run.returncode != 0:
    fail(f"rb_fv.py exited with {run.returncode} {run.stderr}")
for word in ("Nu bottom plate", "Nu top plate", "u_max on x = W/4", "v_max on y = 1/2"):
    if word not in run.stdout:
        fail(f"'{word}' missing from the output")
with tempfile.TemporaryDirectory() as tmp:
    out = os.path.join(tmp, "r.txt")
    run = subprocess.run([sys.executable, os.path.join(TOOLS, "rb_fv.py"), "--converge", "--ra", "1e4",
                          "--grids", "8", "16", "32", "--out", out], capture_output=True, text=True)
    print(run.stdout, end="")
    if run.returncode != 0:
        fail(f"rb_fv.py --converge exited with {run.returncode} {run.stderr}")
    else:
        back = rb_fv.read_results(out).get((1e4, 0.71, 2.0), {})
        that(sorted(back) == sorted(rb_fv.QUANTITIES), "--out file: the quantities read back")
        if "nu" in back:
            below(abs(back["nu"][0] - nu_ref), back["nu"][1], "--converge 8 16 32: Nu within its stated error")

finish()
