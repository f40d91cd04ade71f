"""The hot-block scene of doc/src/Howto_thermal_scene.rst runs as written and
its heat flows balance.

usage: test_hot_block.py --lmp LMP --plugin PLUGIN [--np N --mpirun CMD]

The Howto shows examples/howto-hot-block/in.hot-block (literalinclude). Checked:
- the page includes that file, and the scene is at most 30 commands besides
  'plugin load' (the issue's limit for a scene with flow and gravity);
- the input, run as written (included by a driver that only reads values
  afterwards), finishes; the block's loss of thermal energy equals the heat
  fix sph/heatflow counted into the water, to 1e-12 relative (round-off:
  measured 1e-14); the block cools (its mean T falls);
- sph/set hydrostatic left the steel as it was: every steel atom keeps
  density 7900 and its lattice place, and the log says so;
- the water stays at rest under gravity: its largest speed at the end is
  below 4 % of sqrt(g H) (measured 1.7 %; 8.9 % without the hydrostatic
  start of sph/set; with the Wendland kernel at h = 1.3 dx instead of the
  quintic at h = dx, 4.6 %).
"""

import argparse
import math
import os
import re
import subprocess
import sys
import tempfile

ROOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..")
from sphtest import lammps_arguments, mpi_env, mpi_prefix

EXAMPLE = os.path.join(ROOT, "examples", "howto-hot-block", "in.hot-block")
HOWTO = os.path.join(ROOT, "doc", "src", "Howto_thermal_scene.rst")

DRIVER = """include {example}
variable speed2 atom vx*vx+vy*vy
compute vmax water reduce max v_speed2
compute rho steel sph/rho/atom
compute rho_range steel reduce min c_rho
compute rho_top steel reduce max c_rho
variable dx_max atom abs(x-(floor(x/0.001)+0.5)*0.001)+abs(y-(floor(y/0.001)+0.5)*0.001)
compute moved steel reduce max v_dx_max
thermo_style custom step c_vmax c_rho_range c_rho_top c_moved c_block[1] f_from_block
run 0 post no
print "CHECK $(c_block[1]:%.17g) $(f_from_block:%.17g) $(count(block)) $(sqrt(c_vmax):%.6g) $(c_rho_range:%.17g) $(c_rho_top:%.17g) $(c_moved:%.3g)"
"""


def main():
    p = argparse.ArgumentParser(description=__doc__)
    lammps_arguments(p)
    a = p.parse_args()
    failures = []

    howto = open(HOWTO).read()
    if not re.search(r"\.\. literalinclude:: \.\./\.\./examples/howto-hot-block/in\.hot-block", howto):
        failures.append(f"{HOWTO} does not include examples/howto-hot-block/in.hot-block")
    lines = [ln.split("#", 1)[0].strip() for ln in open(EXAMPLE)]
    commands = [ln for ln in lines if ln and not ln.startswith("plugin")]
    print(f"the scene: {len(commands)} commands besides plugin load")
    if len(commands) > 30:
        failures.append(f"the scene has {len(commands)} commands, more than 30")

    with tempfile.TemporaryDirectory() as tmp:
        driver = os.path.join(tmp, "in.driver")
        with open(driver, "w") as f:
            f.write(DRIVER.format(example=os.path.abspath(EXAMPLE)))
        cmd = mpi_prefix(a.np, a.mpirun) + [a.lmp, "-log", "none", "-in", driver, "-var", "plugin",
                                            a.plugin]
        proc = subprocess.run(cmd, cwd=tmp, capture_output=True, text=True, env=mpi_env())
    text = proc.stdout + proc.stderr
    check = re.search(r"^CHECK (\S+) (\S+) (\S+) (\S+) (\S+) (\S+) (\S+)$", text, re.M)
    start = re.search(r"^\s+0\s+0\s+(\S+)\s+(\S+)\s+(\S+)\s*$", text, re.M)
    if proc.returncode != 0 or not check or not start:
        print(text)
        sys.exit("FAIL: the scene did not run as written")
    energy, flow, count, vmax, rho_lo, rho_hi, moved = (float(v) for v in check.groups())
    # every block atom starts at 350 K: E0 = N m cv T, m = rho0 dx^2 (spacing 0.001)
    energy0 = count * (7900 * 0.001 * 0.001) * 477 * 350.0
    loss = energy0 - energy
    books = abs(loss - flow) / abs(flow)
    print(f"block: lost {loss:.12e} J/m, heat flow into the water {flow:.12e} J/m: {books:.1e}")
    if not books <= 1e-12:
        failures.append(f"block's loss and the heat flow differ by {books:.1e} (limit 1e-12)")
    final_T = [float(m.group(1)) for m in re.finditer(r"^\s+\d+\s+0\.2\s+(\S+)", text, re.M)]
    if not final_T or not final_T[0] < 350.0 - 0.5:
        failures.append(f"the block did not cool: final mean T {final_T}")
    print(f"block mean T: 350 -> {final_T[0] if final_T else '?'} K in 0.2 s")
    if not (rho_lo == 7900.0 and rho_hi == 7900.0 and moved < 1e-12):
        failures.append(f"the steel changed: density {rho_lo}..{rho_hi}, moved {moved}")
    if "1 solid type(s) (no equation of state) left as they are" not in text:
        failures.append("sph/set hydrostatic did not report the steel left as it was")
    scale = math.sqrt(9.81 * 0.04)
    print(f"water: largest speed {vmax:.3g} m/s = {vmax / scale * 100:.3f} % of sqrt(g H)")
    if not vmax < 0.04 * scale:
        failures.append(f"the water moves: {vmax / scale * 100:.2f} % of sqrt(g H) (limit 4 %)")
    for f in failures:
        print("FAIL:", f)
    print("ok" if not failures else "")
    sys.exit(1 if failures else 0)


if __name__ == "__main__":
    main()
