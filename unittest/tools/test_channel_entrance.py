"""tools/channel_entrance.py, the reference for laminar developing flow in a
plane channel (the entrance problem of examples/open-channel): from a
parabolic inflow the flow must stay Poiseuille's, u = 6 y (1 - y) and
-dp/dx = 12/Re, with an error that falls at the second order of the scheme;
the flow rate must be 1 at every x and the flow symmetric about the centre
line; from a uniform inflow at Re = 20 the development length and the centre
speed must approach the fine-grid values of channel_entrance.md (L_99 =
1.12474 H, extrapolated over 40, 80 and 160 cells across) at second order;
moving the outlet downstream must not change the flow upstream; the script
must print its results and write the table for the SPH comparison."""

import os
import subprocess
import sys
import tempfile
import time

import numpy as np

from checks import below, fail, finish, inside, that

TOOLS = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "tools")
import channel_entrance as ce

t_start = time.time()
RE = 20.0
# channel_entrance.md, Re = 20, uniform inflow: Richardson over ny = 40, 80, 160
L99_REF = 1.12474
UC_REF = {0.5: 0.881552, 1.0: 0.983466, 2.0: 0.999676}    # u_c / 1.5


def symmetry(r):
    """Largest departure from u(y) = u(1 - y), v(y) = -v(1 - y)."""
    return max(np.abs(r["u"] - r["u"][:, ::-1]).max(), np.abs(r["v"] + r["v"][:, ::-1]).max())


# (a) parabolic inflow stays Poiseuille's; the error falls by 4 per doubling
err_u, err_g = {}, {}
for ny in (16, 32):
    r = ce.solve(RE, "parabolic", 4 * ny, ny)
    y = r["y"]
    err_u[ny] = np.abs(r["u"] - 6.0 * y * (1.0 - y)).max() / 1.5
    err_g[ny] = abs(r["dpdx_ratio"] - 1.0)
    print(f"parabolic, {4 * ny} x {ny}: max |u - 6 y (1 - y)| / 1.5 = {err_u[ny]:.3e}, "
          f"-dp/dx / (12/Re) - 1 = {r['dpdx_ratio'] - 1.0:+.3e}, max |v| / 1.5 = {np.abs(r['v']).max() / 1.5:.1e}")
    below(np.abs(r["mass_flux"] - 1.0).max(), 1e-12, f"parabolic, ny = {ny}: flow rate 1 at every face")
    below(symmetry(r), 1e-12, f"parabolic, ny = {ny}: symmetric about y = 1/2")
below(err_u[32], 2e-3, "parabolic, ny = 32: u against Poiseuille everywhere (of 1.5 U)")
below(err_g[32], 3e-3, "parabolic, ny = 32: -dp/dx against 12/Re (relative)")
inside(err_u[32] / err_u[16], 0.2, 0.3, "parabolic: u error ratio ny = 32 / ny = 16 (second order: 0.25)")
inside(err_g[32] / err_g[16], 0.2, 0.3, "parabolic: -dp/dx error ratio ny = 32 / ny = 16 (second order: 0.25)")

# (b) uniform inflow at Re = 20: L_99 and u_c approach the fine-grid values at second order
res = {}
for ny in (20, 40):
    res[ny] = r = ce.solve(RE, "uniform", 4 * ny, ny)
    print(f"uniform, {4 * ny} x {ny}: L_99 = {r['l99']:.6f} H, -dp/dx / (12/Re) = {r['dpdx_ratio']:.6f}")
    below(np.abs(r["mass_flux"] - 1.0).max(), 1e-12, f"uniform, ny = {ny}: flow rate 1 at every face")
    below(symmetry(r), 1e-12, f"uniform, ny = {ny}: symmetric about y = 1/2")
    below(abs(r["u_c"][0] - 1.0), 1e-12, f"uniform, ny = {ny}: centre speed U at the inlet")
l20, l40 = res[20]["l99"], res[40]["l99"]
inside(l40 / L99_REF - 1.0, 0.0, 0.025, "uniform, ny = 40: L_99 relative to 1.12474 (measured +1.7 %)")
inside((l40 - L99_REF) / (l20 - L99_REF), 0.15, 0.3, "uniform: L_99 error ratio ny = 40 / ny = 20 (second order)")
l_extra = l40 + (l40 - l20) / 3.0
below(abs(l_extra / L99_REF - 1.0), 5e-3, "uniform: L_99 extrapolated from ny = 20, 40 against 1.12474 (relative)")
uc = ce.centre_speed(res[40], list(UC_REF)) / 1.5
for (x, ref), value in zip(UC_REF.items(), uc):
    below(abs(value - ref), 1e-3, f"uniform, ny = 40: u_c / 1.5 at x = {x:g} against {ref} (measured {value - ref:+.1e})")
below(abs(res[40]["dpdx_ratio"] - 1.0), 2e-3, "uniform, ny = 40: developed -dp/dx against 12/Re (relative)")
below(abs(ce.durst(RE) - 1.178), 1e-3, "Durst et al. (2005) at Re = 20: 1.178 H")

# (c) the outlet at L = 10 against the same grid continued to 15.5: no change on x <= 6
l2, du, dl, dg = ce.outflow_check(RE, "uniform", 64, 16)
print(f"outlet at 10 against {l2:.3f} H: u_c change {du:.1e}, L_99 {dl:+.1e}, -dp/dx {dg:+.1e}")
below(du, 1e-10, "outlet moved from 10 to 15.5 H: largest u_c change on x <= 6")
below(abs(dl), 1e-10, "outlet moved from 10 to 15.5 H: L_99 change")

# (d) the script: printed values and the table for the SPH comparison
with tempfile.TemporaryDirectory() as tmp:
    out = os.path.join(tmp, "uc.txt")
    run = subprocess.run([sys.executable, os.path.join(TOOLS, "channel_entrance.py"), "--ny", "20", "--write", out],
                         capture_output=True, text=True)
    print(run.stdout.split("x/H   u_c")[0], end="")
    if run.returncode != 0:
        fail(f"channel_entrance.py exited with {run.returncode} {run.stderr}")
    for word in ("flow rate", "L_99 (u_c = 0.99 x 1.5 U) = 1.2137", "Durst", "-dp/dx over x = 3 ... 6 H", "wrote"):
        if word not in run.stdout:
            fail(f"'{word}' missing from the output")
    if os.path.exists(out):
        table = np.loadtxt(out)
        that(table.shape == (121, 2), "table: 121 rows of x, u_c/1.5 (x = 0 ... 6 every 0.05)", str(table.shape))
        if table.shape == (121, 2):
            below(np.abs(table[:, 0] - np.arange(121) * 0.05).max(), 1e-9, "table: x column")
            want = ce.centre_speed(res[20], table[:, 0]) / 1.5
            below(np.abs(table[:, 1] - want).max(), 1e-7, "table: u_c/1.5 against solve() on the same grid")
    else:
        fail("--write made no file")

print(f"# {time.time() - t_start:.1f} s")
finish()
