"""tools/channel_fv.py, the finite-volume reference for laminar channel flow
with conjugate heat transfer (the heated channel, thick-wall channel and
two-stream heat exchanger of Ng, Ng, Sheu & Mukhtar 2020): the fully
developed Nusselt number of isothermal plates must come out as Shah & London
(1978) give it, 7.5407; the scheme must conserve energy to round-off in the
heated, thick-wall and exchanger cases; the error must fall at second order
where the solution is smooth; counter-flow must heat the cold stream more
than parallel flow; pure conduction must be exact; the script must print
its results and write the documented JSON."""

import json
import math
import os
import subprocess
import sys
import tempfile
import time

import numpy as np

from checks import below, fail, finish, inside, that

TOOLS = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "tools")
import channel_fv as cfv

t_start = time.time()

# (a) fully developed Nu of isothermal plates at Pe = 1e4 (axial conduction
# negligible: the eigenproblem gives Nu(1e4) - Nu(inf) = 1e-7)
g = {}
for ny in (20, 40, 80):
    prob = cfv.preset("graetz", pe=1e4)
    r = cfv.solve(prob, nx=10 * ny, ny=ny)
    g[ny] = cfv.graetz_summary(r)
    print(f"graetz Pe = 1e4, L = {prob.length:g} W, {10 * ny} x {ny}: Nu at x/(D_h Pe) = "
          f"{g[ny]['x_plus']:.3f}: {g[ny]['nu']:.6f} (spread downstream {g[ny]['nu_spread']:.1e})")
below(abs(g[40]["nu"] / cfv.NU_T - 1.0), 5e-3, "Pe = 1e4, 40 cells across: Nu against 7.5407 (relative)", fmt=".3e")
below(abs(g[80]["nu"] / cfv.NU_T - 1.0), 5e-4, "Pe = 1e4, 80 cells across: Nu against 7.5407 (relative)", fmt=".3e")
below(g[40]["nu_spread"], 1e-3, "Pe = 1e4: Nu constant over [L/2, 0.85 L] (fully developed)", fmt=".3e")
nu_1d = cfv.nu_fully_developed(1e4)
below(abs(nu_1d - cfv.NU_T), 2e-5, "fully developed eigenproblem, Pe = 1e4, against 7.5407", fmt=".3e")
below(abs(cfv.nu_fully_developed(1e-3) / cfv.NU_T_PE0 - 1.0), 1e-3,
      "fully developed eigenproblem, Pe = 1e-3, against pi^4/12 = 8.1174 (relative)", fmt=".3e")
below(abs(cfv.nu_fully_developed(math.inf, top="adiabatic") - cfv.NU_T_ONE_SIDED), 1e-4,
      "fully developed eigenproblem, one wall adiabatic, against 4.8608", fmt=".3e")
nu_pe = cfv.nu_fully_developed(163.338)
print(f"axial conduction at the heated case's Pe = 163.3: Nu {nu_pe:.6f} = 7.5407 {nu_pe / cfv.NU_T - 1:+.1e}")
inside(nu_pe / nu_1d - 1.0, 1e-5, 2e-4, "Pe = 163: small positive shift of Nu by axial conduction")

# (b) energy balance, heated and thick-wall (k_s = k): heat in through the
# isothermal walls = enthalpy rise of the stream + heat conducted back out
# through the inlet face (axial conduction), to round-off
for case, kw in (("heated", {}), ("thick-wall", {"ks_ratio": 1.0})):
    prob = cfv.preset(case, **kw)
    r = cfv.solve(prob, nx=640, ny=40)
    fl = r["fluids"][0]
    b = r["balance"]
    rise = prob.layers[[l.kind for l in prob.layers].index("fluid")].rho_cp * np.sum(
        np.abs(r["u"]) * np.diff(r["y_faces"]) * (r["T"][-1] - fl["t_in"]))
    print(f"{case}: walls {b['boundaries']:.10g} W/m, enthalpy rise rho cp int u (T_out - T_in) dy "
          f"{rise:.10g}, conducted out through the inlet {fl['inlet_conduction']:.6g} W/m "
          f"({fl['inlet_conduction'] / b['boundaries']:.2%})")
    below(abs(b["boundaries"] - rise - fl["inlet_conduction"]) / b["boundaries"], 1e-8,
          f"{case}: walls - (enthalpy rise + inlet conduction), relative", fmt=".3e")
    walls = sum(w["heat"] for w in r["walls"])
    if case == "heated":
        below(abs(walls - b["boundaries"]) / b["boundaries"], 1e-12, "heated: wall heat from the Nu faces", fmt=".3e")
    else:
        below(abs(walls - b["boundaries"]) / b["boundaries"], 1e-8,
              "thick-wall: heat through the fluid-solid interfaces = heat through the outer walls", fmt=".3e")
    inside(fl["t_out"], 300.0, 420.0, f"{case}: outlet bulk temperature between T_in and T_wall")

# (c) second order: successive differences fall by ~4 per halving of dx and
# dy (heated channel, profiles at x = 50 ... 195; Nu of the Graetz check)
prob = cfv.preset("heated")
res = [cfv.solve(prob, nx=160 * m, ny=10 * m) for m in (1, 2, 4)]
nodes = [res[0]["nodes"]["T"], res[1]["nodes"]["T"][::2, ::2], res[2]["nodes"]["T"][::4, ::4]]
xn = res[0]["nodes"]["x"]
sel = np.isin(np.round(xn, 9), prob.stations[1:])
d01 = np.abs(nodes[1] - nodes[0])[sel].max()
d12 = np.abs(nodes[2] - nodes[1])[sel].max()
print(f"heated, profiles at x = 50 ... 195: max change {d01:.3e} (160 -> 320), {d12:.3e} (320 -> 640)")
inside(d01 / d12, 3.0, 5.0, "heated: ratio of successive changes of the profiles")
inside((g[40]["nu"] - g[20]["nu"]) / (g[80]["nu"] - g[40]["nu"]), 3.0, 5.0,
       "graetz: ratio of successive changes of Nu")
below(abs(res[2]["stations"][2] - 100.0), 1e-12, "stations at x = 5, 50, 100, 150, 195", fmt=".3e")

# (d) exchanger: counter-flow heats the cold stream more; the heat lost by
# the hot stream is gained by the cold one (outer walls adiabatic)
ex = {}
for counter in (False, True):
    r = cfv.solve(cfv.preset("exchanger", counter=counter), nx=640, ny=20)
    e = cfv.exchanger_summary(r)
    ex[e["arrangement"]] = e
    print(f"exchanger {e['arrangement']}: cold 300 -> {e['t_cold_out']:.4f} K, hot 800 -> "
          f"{e['t_hot_out']:.4f} K, effectiveness {e['eps']:.4f}, eps-NTU at the solution's UA "
          f"{e['eps_ntu_local']:.4f}; enthalpy lost by hot {e['q_hot']:.6g}, gained by cold {e['q_cold']:.6g} W/m")
    below(abs(e["heat_gain_hot"] + e["heat_gain_cold"]) / e["heat_gain_cold"], 1e-8,
          f"{e['arrangement']}: heat lost by hot = heat gained by cold (with inlet conduction)", fmt=".3e")
    below(abs(e["q_plate_hot_face"] - e["q_plate_cold_face"]) / e["q_plate_cold_face"], 1e-8,
          f"{e['arrangement']}: heat into the plate = heat out of the plate", fmt=".3e")
    below(abs(r["balance"]["boundaries"]), 0.0, f"{e['arrangement']}: no heat through the adiabatic outer walls",
          fmt=".3e")
    below(abs(e["eps_ntu_local"] / e["eps"] - 1.0), 0.03,
          f"{e['arrangement']}: effectiveness against eps-NTU at the solution's UA (relative)", fmt=".3e")
inside(ex["counter"]["t_cold_out"] - ex["parallel"]["t_cold_out"], 20.0, 80.0,
       "cold outlet counter-flow minus parallel-flow (K)")
inside(ex["counter"]["eps"] - ex["parallel"]["eps"], 0.05, 0.15, "effectiveness counter minus parallel")
inside(ex["parallel"]["t_cold_out"], 300.0, ex["parallel"]["t_hot_out"],
       "parallel flow: cold outlet below the hot outlet")

# (e) conduction: solid layers between isothermal walls give the exact
# piecewise-linear profile (series conductances)
lay = [cfv.Layer("solid", 1.0, 1.0), cfv.Layer("solid", 2.0, 4.0)]
prob = cfv.Problem("conduction", lay, 3.0, y0=-1.0, t_bottom=250.0, t_top=400.0, delta_t=150.0)
r = cfv.solve(prob, nx=6, cells=[5, 7])
q = 150.0 / (1.0 / 1.0 + 2.0 / 4.0)                    # flux through the stack
t_if = 250.0 + q * 1.0 / 1.0
exact = np.where(r["y"] < 0.0, 250.0 + q * (r["y"] + 1.0), t_if + q * r["y"] / 4.0)
below(np.abs(r["T"] - exact[None, :]).max(), 1e-10, "two solid layers: T - piecewise linear", fmt=".3e")
yp, tp = cfv.profile_at(r, 1.7)
exact_p = np.where(yp < 0.0, 250.0 + q * (yp + 1.0), t_if + q * yp / 4.0)
below(np.abs(tp - exact_p).max(), 1e-10, "two solid layers: profile_at incl. the interface value", fmt=".3e")
below(abs(r["balance"]["boundaries"]), 1e-9, "two solid layers: net heat through the walls", fmt=".3e")
one = cfv.Problem("slab", [cfv.Layer("solid", 2.0, 3.0)], 1.0, t_bottom=300.0, t_top=420.0, delta_t=120.0)
r = cfv.solve(one, nx=4, cells=[9])
below(np.abs(r["T"] - (300.0 + 60.0 * r["y"])[None, :]).max(), 1e-10, "one solid layer: T - linear", fmt=".3e")

# warning of the central scheme above cell Peclet number 2
r = cfv.solve(cfv.preset("heated"), nx=80, ny=8)
that(bool(r["warnings"]), f"central scheme at cell Peclet number {r['cell_pe_max']:.3g}: warned")

# (f) the script: output, profiles and JSON
with tempfile.TemporaryDirectory() as tmp:
    out, prof = os.path.join(tmp, "r.json"), os.path.join(tmp, "p.csv")
    run = subprocess.run([sys.executable, os.path.join(TOOLS, "channel_fv.py"), "--case", "thick-wall",
                          "--nx", "160", "--ny", "8", "--richardson", "--json", out, "--profiles", "stations",
                          "--profiles-out", prof], capture_output=True, text=True)
    print(run.stdout, end="")
    if run.returncode != 0:
        fail(f"channel_fv.py exited with {run.returncode} {run.stderr}")
    for word in ("energy balance", "local Nu at x", "T_out (mixing cup)", "Richardson", "profile x = 50"):
        if word not in run.stdout:
            fail(f"'{word}' missing from the output")
    with open(out) as f:
        data = json.load(f)
    want = {"T": None, "x": None, "y": None, "fluids": ("t_bulk", "t_out", "capacity", "heat_gain"),
            "walls": ("x", "q", "nu", "t_wall"), "balance": ("boundaries", "streams", "relative"),
            "profile": ("x", "y", "T"), "nodes": ("x", "y", "T"), "richardson": ("field", "stations", "scalars")}
    missing = [k for k in want if k not in data]
    for k, sub in want.items():
        if sub and k in data:
            obj = data[k][0] if isinstance(data[k], list) else data[k]
            missing += [f"{k}.{s}" for s in sub if s not in obj]
    that(not missing, "JSON keys", "missing " + ", ".join(missing) if missing else "")
    if not missing:
        shape_ok = np.shape(data["T"]) == (160, sum(data["cells"])) and len(data["walls"]) == 2
        that(shape_ok, "JSON array shapes")
        y, t = cfv.profile_at(data, 100.0)
        csv = np.loadtxt(prof, delimiter=",", skiprows=1)
        below(np.abs(csv[:, 0] - y).max() + np.abs(csv[:, 3] - t).max(), 1e-6,
              "profiles CSV against profile_at on the JSON at x = 100", fmt=".3e")
        below(abs(t[0] - 420.0) + abs(t[-1] - 420.0), 1e-12, "profile ends at the wall temperature", fmt=".3e")

elapsed = time.time() - t_start
print(f"# {elapsed:.1f} s")
finish()
