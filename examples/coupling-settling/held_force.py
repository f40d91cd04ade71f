"""The pressure force on the held disc of in.tank at its release, from a
snapshot (in.tank -var snapshot yes), against the exact force of the
water's own pressure field.

    held_force.py tank_neutral.release --log log.tank_neutral [--dx 0.002] [--c0 20]
                  [--max-mismatch 0.005]

The disc's force in LAMMPS is read from the log ("net upward force on the
held disc"; force = (1 + that) times the weight); the recomputation here
must agree with it (to 1e-3 of the weight), or this script's model is not
LAMMPS's. Exits 1 when LAMMPS's force and the exact force of the fitted
field differ by more than --max-mismatch of the disc's weight.

It recomputes what pair sph/harmonic/visc (averaged pressure form) and
fix sph/wall/adami give the disc's particles: the wall pressure
extrapolated from the water (Adami et al. 2012: kernel-weighted pressure
plus the hydrostatic term), its density from the Tait equation and the
pair force summed over disc-water pairs (in.tank's Wendland C2, h = 1.3
dx). Then it fits p = p_c + b . (x - x_c) to the water within 3 h of the
disc and prints b against rho0 g and the exact force -b V of that field on
the disc's area V. When the disc's SPH force matches -b V but b differs
from rho0 g, the water's pressure, not the coupling, is what is off.
"""

import argparse
import re

import numpy as np
from scipy.spatial import cKDTree

import wendland2d
from sphthermal_tools.dump import read_frames

RHO0, GAMMA, G = 1000.0, 7.0, 9.81


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("snapshot")
    ap.add_argument("--dx", type=float, default=0.002)
    ap.add_argument("--c0", type=float, default=20.0)
    ap.add_argument("--log", required=True)
    ap.add_argument("--max-mismatch", type=float)
    args = ap.parse_args()
    atoms = read_frames(args.snapshot)[-1][1]
    kind, mass, rho = atoms["type"], atoms["mass"], atoms["c_rho_all"]
    x = np.c_[atoms["x"], atoms["y"]]
    n = len(kind)
    dx, h = args.dx, 1.3 * args.dx
    b_tait = RHO0 * args.c0 ** 2 / GAMMA

    def pressure(density):
        return b_tait * ((density / RHO0) ** GAMMA - 1.0)

    def density(p):
        return RHO0 * (1.0 + p / b_tait) ** (1.0 / GAMMA)

    water = np.where(kind == 1)[0]
    disc = np.where(kind == 2)[0]
    tree = cKDTree(x[water])
    p_water = np.zeros(n)
    p_water[water] = pressure(rho[water])
    vol = np.where(kind == 1, mass / rho, dx * dx)
    gravity = np.array([0.0, -G])

    def force_on_disc(p_field, wall_pressure):
        total = np.zeros(2)
        for w in disc:
            nb = water[tree.query_ball_point(x[w], 2 * h)]
            if len(nb) == 0:
                continue
            r = x[w] - x[nb]
            dist = np.linalg.norm(r, axis=1)
            p_w = wall_pressure(w, nb, wendland2d.w(dist, h), r)
            rho_w = density(p_w)
            v_w = dx * dx * RHO0 / rho_w    # the solid's volume compressed with the water
            p_avg = (p_w * rho[nb] + p_field[nb] * rho_w) / (rho_w + rho[nb])
            s = -(v_w ** 2 + vol[nb] ** 2) * p_avg * wendland2d.dwdr(dist, h) / dist
            total += (s[:, None] * r).sum(axis=0)
        return total

    def adami(w, nb, weight, r):
        return (np.sum(weight * p_water[nb]) + np.sum(weight * rho[nb] * (r @ gravity))) / weight.sum()

    weight = mass[disc].sum() * G
    f_sph = force_on_disc(p_water, adami)
    centre = x[disc].mean(axis=0)
    radius = np.sqrt(len(disc) / np.pi) * dx
    near = (kind == 1) & (np.linalg.norm(x - centre, axis=1) < radius + 3 * h)
    design = np.c_[np.ones(near.sum()), x[near] - centre]
    coef = np.linalg.lstsq(design, p_water[near], rcond=None)[0]
    rms = np.sqrt(np.mean((design @ coef - p_water[near]) ** 2))
    exact = -coef[1:] * len(disc) * dx * dx
    print(f"disc of {len(disc)} particles; SPH pressure force on it / its weight: "
          f"({f_sph[0] / weight:.4e}, {f_sph[1] / weight:.5f})")
    print(f"water within 3 h of the disc: p = {coef[0]:.2f} Pa + ({coef[1]:.4g}, {coef[2]:.6g}) Pa/m "
          f". (x - x_c), rms residual {rms:.2f} Pa; rho0 g = {RHO0 * G:.1f} Pa/m "
          f"(gradient / rho0 g = {-coef[2] / (RHO0 * G):.4f})")
    print(f"exact force of that field on the disc's area / its weight: ({exact[0] / weight:.4e}, "
          f"{exact[1] / weight:.5f})")
    with open(args.log) as f:
        found = re.findall(r"^released at t = \S+ s, net upward force on the held disc (\S+) of its weight",
                           f.read(), re.M)
    if not found:
        print(f"FAIL: no 'net upward force' line in {args.log}")
        return 1
    lammps = 1.0 + float(found[-1])
    print(f"LAMMPS: pressure force on the disc / its weight {lammps:.5f} (recomputed here: "
          f"{f_sph[1] / weight:.5f})")
    if abs(lammps - f_sph[1] / weight) > 1e-3:
        print("FAIL: the recomputation here does not reproduce LAMMPS's force")
        return 1
    mismatch = abs(lammps - exact[1] / weight)
    print(f"mismatch {mismatch:.4f} of the weight")
    if args.max_mismatch is not None and mismatch > args.max_mismatch:
        print(f"FAIL: the disc's SPH force differs from the exact force of the water's pressure by "
              f"{mismatch:.4f} of its weight (more than {args.max_mismatch})")
        return 1
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
