"""tools/cavity_fv.py, the reference for the differentially heated square
cavity (de Vahl Davis, G. (1983) Natural convection of air in a square
cavity: a bench mark numerical solution, Int. J. Numer. Methods Fluids 3,
249-264): pure conduction must come out exact (Nu = 1, linear theta) on the
stretched grid; on coarse grids Nu, u_max and v_max must lie within 1 % of
de Vahl Davis with the hot- and cold-wall heat fluxes equal; the error must
fall with resolution at the second order of the scheme; the transient mode
must settle on the steady solution; the JSON output must carry its keys."""

import json
import os
import subprocess
import sys
import tempfile

import numpy as np

from checks import below, fail, finish, that

TOOLS = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "tools")
import cavity_fv

# (a) conduction, solved from uniform theta = 0.5 on the stretched grid
r = cavity_fv.solve(0.0, n=24)
x = r["centres"]["x"]
below(abs(r["nu_mean_hot"] - 1.0), 1e-8, "Ra = 0: hot-wall Nu - 1")
below(abs(r["nu_mean_cold"] - 1.0), 1e-8, "Ra = 0: cold-wall Nu - 1")
below(np.abs(r["centres"]["theta"] - (1.0 - x)[:, None]).max(), 1e-10, "Ra = 0: theta - (1 - x)")
below(max(np.abs(r["centres"]["u"]).max(), np.abs(r["centres"]["v"]).max()), 1e-10, "Ra = 0: velocity")

# (b) de Vahl Davis at Ra = 1e3 and 1e4 on 32 x 32
for ra in (1e3, 1e4):
    r = cavity_fv.solve(ra, 0.71, 32)
    nu, umax, vmax = cavity_fv.DE_VAHL_DAVIS[ra]
    below(abs(r["nu_mean_hot"] / nu - 1.0), 1e-2, f"Ra = {ra:g}, N = 32: Nu against de Vahl Davis")
    below(abs(r["umax"] / umax - 1.0), 1e-2, f"Ra = {ra:g}, N = 32: u_max against de Vahl Davis")
    below(abs(r["vmax"] / vmax - 1.0), 1e-2, f"Ra = {ra:g}, N = 32: v_max against de Vahl Davis")
    below(abs(r["nu_mean_hot"] - r["nu_mean_cold"]) / nu, 1e-9, f"Ra = {ra:g}: hot- and cold-wall Nu")
    xs = np.linspace(0.0, 1.0, 11)
    theta, v = cavity_fv.profiles_at(r, xs)
    below(abs(theta[0] - 1.0) + abs(theta[-1]) + abs(v[0]) + abs(v[-1]), 1e-12,
          f"Ra = {ra:g}: profiles_at wall values")
    below(abs(theta[5] - 0.5) + abs(v[5]), 1e-9, f"Ra = {ra:g}: centro-symmetry at the centre")

# (c) Ra = 1e4: the Nu error falls by ~4 from N = 24 to 48; reference 2.24482,
# Richardson over N = 64, 128, 256 (cavity_fv.md)
nu_ref = 2.24482
e24 = abs(cavity_fv.solve(1e4, 0.71, 24)["nu_mean_hot"] - nu_ref)
e48 = abs(cavity_fv.solve(1e4, 0.71, 48)["nu_mean_hot"] - nu_ref)
print(f"Ra = 1e4: Nu error {e24:.2e} (N = 24), {e48:.2e} (N = 48)")
below(e48 / e24, 0.3, "Ra = 1e4: error ratio N = 48 / N = 24")
below(e48 / nu_ref, 1e-3, "Ra = 1e4, N = 48: relative Nu error")

# the transient mode settles on the steady solution of the same grid
steady = cavity_fv.solve(1e3, 0.71, 16)
late = cavity_fv.transient(1e3, 0.71, 16, t_end=2.0, dt=0.05)
below(abs(late["nu_mean_hot"] - steady["nu_mean_hot"]), 1e-7, "transient at t = 2 against steady Nu")

# (d) the script: printed values and the JSON keys
with tempfile.TemporaryDirectory() as tmp:
    out = os.path.join(tmp, "r.json")
    run = subprocess.run([sys.executable, os.path.join(TOOLS, "cavity_fv.py"), "--ra", "1e3", "--n", "32",
                          "--out", out, "--richardson"], capture_output=True, text=True)
    print(run.stdout, end="")
    if run.returncode != 0:
        fail(f"cavity_fv.py exited with {run.returncode} {run.stderr}")
    for word in ("Nu mean hot wall", "Nu mean cold wall", "u_max on x = 0.5", "v_max on y = 0.5",
                 "extrapolated"):
        if word not in run.stdout:
            fail(f"'{word}' missing from the output")
    with open(out) as f:
        data = json.load(f)
    want = {"ra": None, "pr": None, "n": None, "nu_mean_hot": None, "nu_mean_cold": None, "umax": None,
            "y_umax": None, "vmax": None, "x_vmax": None, "hmid": ("x", "theta", "v"),
            "vmid": ("y", "theta", "u"), "hot_wall": ("y", "nu_local"),
            "centres": ("x", "y", "theta", "u", "v", "p"), "nodes": ("x", "y", "psi")}
    missing = [k for k in want if k not in data]
    missing += [f"{k}.{s}" for k, sub in want.items() if sub and k in data for s in sub if s not in data[k]]
    that(not missing, "JSON keys", "missing " + ", ".join(missing) if missing else "")
    if not missing:
        n = data["n"]
        shapes = (len(data["hmid"]["x"]) == n + 2 and np.shape(data["centres"]["theta"]) == (n, n)
                  and np.shape(data["nodes"]["psi"]) == (n + 1, n + 1) and len(data["hot_wall"]["y"]) == n)
        that(shapes, "JSON array shapes")
        local = np.sum(np.array(data["hot_wall"]["nu_local"]) * np.diff(data["nodes"]["y"]))
        below(abs(local - data["nu_mean_hot"]), 1e-12, "JSON: local Nu integrates to the mean")

finish()
