"""The short set-up (sph/set) gives the state of the long one.

usage: test_short_form.py --lmp LMP --plugin PLUGIN --potentials DIR --case materials|hydrostatic

materials:   in.short_form: masses, densities, specific heats and energies of
             a steel block in water, by hand or with sph/set, equal to 1e-15;
             also with sph/set's keywords in the other order (temperature
             before materials: sph/set applies materials first).
hydrostatic: in.hydrostatic_start: the column of examples/flow-hydrostatic
             started by hand or with 'sph/set all hydrostatic H': the same
             positions (up to the translation of the whole tank: the long form
             keeps the fluid's bottom in place, sph/set the deepest wall row),
             fluid densities and first forces; and the column is at rest: the
             largest acceleration of the fluid below its top 3 rows is below
             0.1 % of g.
"""

import argparse
import os
import subprocess
import sys
import tempfile

import numpy as np

from sphthermal_tools.dump import read_frames

from sphtest import lammps_arguments

HERE = os.path.dirname(os.path.abspath(__file__))


PRINTED = {}


def state(a, script, form, tmp):
    out = os.path.join(tmp, f"{form}.dump")
    proc = subprocess.run([a.lmp, "-log", "none", "-in", os.path.join(HERE, script), "-var", "plugin",
                           a.plugin, "-var", "potentials", a.potentials, "-var", "form", form,
                           "-var", "out", out], cwd=tmp, capture_output=True, text=True)
    if proc.returncode != 0 or not os.path.exists(out):
        print(proc.stdout + proc.stderr)
        sys.exit(f"FAIL: the {form} form of {script} did not run")
    for line in proc.stdout.splitlines():
        if line.startswith("PROPERTIES "):
            PRINTED["properties"] = [float(w) for w in line.split()[1:]]
    return read_frames(out)[-1][1]


def relative(a, b):
    scale = max(np.max(np.abs(b)), 1e-300)
    return np.max(np.abs(a - b)) / scale


def main():
    p = argparse.ArgumentParser(description=__doc__)
    lammps_arguments(p, mpi=False)
    p.add_argument("--potentials", required=True)
    p.add_argument("--case", choices=["materials", "hydrostatic"], required=True)
    a = p.parse_args()
    failures = []
    with tempfile.TemporaryDirectory() as tmp:
        if a.case == "materials":
            short, reversed_, long_ = (state(a, "in.short_form", f, tmp)
                                       for f in ("short", "reversed", "long"))
            for form, got in (("short", short), ("reversed", reversed_)):
                for column in ("type", "mass", "x", "y", "c_rho", "c_cv", "c_e"):
                    err = relative(got[column], long_[column])
                    print(f"{form:8s} {column:6s} largest relative difference {err:.2e}")
                    if err > 1e-15:
                        failures.append(f"{form} {column}")
            # fix sph/materials exposes the properties of the material file
            want = [276.1e-6, -1.0, 14.9, 1652e-6]
            print(f"properties {PRINTED.get('properties')}, expected {want}")
            if PRINTED.get("properties") != want:
                failures.append("properties")
            # the state is the materials' (a check of both forms at once)
            steel = short["type"] == 2
            temperature = short["c_e"] / short["c_cv"]
            if not (np.allclose(temperature[steel], 350.0, rtol=1e-15) and
                    np.allclose(temperature[~steel], 300.0 + 100.0 * short["x"][~steel], rtol=1e-15)):
                failures.append("temperatures")
        else:
            short, long_ = (state(a, "in.hydrostatic_start", f, tmp) for f in ("short", "long"))
            H, g = 0.5, 9.81
            dx = H / 20
            fluid = short["type"] == 1
            # side-wall particles above the surface carry no pressure; the long
            # form stretches them, sph/set leaves them on the lattice
            below = long_["y"] < np.max(long_["y"][fluid]) + 0.5 * dx
            shift = short["y"][0] - long_["y"][0]
            print(f"translation of the tank between the forms: {shift:.3e} m")
            err_y = np.max(np.abs(short["y"] - shift - long_["y"])[below]) / H
            err_x = np.max(np.abs(short["x"] - long_["x"])) / H
            err_rho = relative(short["c_rho"][fluid], long_["c_rho"][fluid])
            mass = 1000.0 * dx ** 2
            acc_short = np.hypot(short["fx"], short["fy"])[fluid] / mass
            acc_long = np.hypot(long_["fx"], long_["fy"])[fluid] / mass
            # below the top rows, whose kernel the free surface truncates (and
            # where the side walls above the surface differ)
            interior = (long_["y"] < np.max(long_["y"][fluid]) - 3 * dx)[fluid]
            err_acc = np.max(np.abs(acc_short - acc_long)[interior]) / g
            rest = np.max(acc_short[interior]) / g
            print(f"positions {max(err_x, err_y):.2e} H, fluid densities {err_rho:.2e}, first "
                  f"accelerations {err_acc:.2e} g (below the top 3 rows); largest fluid acceleration below the top 3 "
                  f"rows {rest:.2e} g (short), {np.max(acc_long[interior]) / g:.2e} g (long)")
            if max(err_x, err_y) > 1e-12 or err_rho > 1e-12 or err_acc > 1e-6:
                failures.append("same state")
            if rest > 1e-3:
                failures.append("at rest")
    if failures:
        sys.exit("FAIL: " + ", ".join(failures))
    print("ok")


if __name__ == "__main__":
    main()
