"""Writes flow.data, the regression system of the flow styles (run once; the
file is committed so that atom ids do not depend on the number of ranks):
a channel periodic in x and y, 12 x 12 jittered fluid particles of two
fluids (types 1, 2) between three layers of wall particles (type 3) below
and above; the upper wall slides at 0.05 m/s; random fluid velocities,
densities 1 % off their reference."""

import random

dx = 0.01
nx, ny, layers = 12, 12, 3
random.seed(20261122)
atoms, velocities = [], []
for j in range(-layers, ny + layers):
    for i in range(nx):
        x, y = (i + 0.5) * dx, (j + 0.5) * dx
        if 0 <= j < ny:
            kind = 2 if (i + 2 * j) % 3 == 0 else 1
            rho0 = 1000.0 if kind == 1 else 800.0
            x += random.uniform(-0.2, 0.2) * dx
            y += random.uniform(-0.2, 0.2) * dx
            v = (random.uniform(-0.1, 0.1), random.uniform(-0.1, 0.1))
            rho = rho0 * (1.0 + random.uniform(-0.01, 0.01))
        else:
            kind, rho = 3, 1000.0
            v = (0.05, 0.0) if j >= ny else (0.0, 0.0)
        atoms.append((kind, rho, 1.0 + 0.5 * kind, x, y))
        velocities.append(v)

with open("flow.data", "w") as f:
    f.write("# flow regression system, written by make_flow_data.py\n\n")
    f.write(f"{len(atoms)} atoms\n3 atom types\n\n")
    f.write(f"0 {nx * dx} xlo xhi\n{-layers * dx} {(ny + layers) * dx} ylo yhi\n-0.005 0.005 zlo zhi\n\n")
    f.write("Masses\n\n1 0.1\n2 0.08\n3 0.1\n\nAtoms # sph\n\n")
    for n, (kind, rho, cv, x, y) in enumerate(atoms, 1):
        f.write(f"{n} {kind} {rho:.12g} {cv * 300.0:.12g} {cv:.12g} {x:.12g} {y:.12g} 0\n")
    f.write("\nVelocities\n\n")
    for n, v in enumerate(velocities, 1):
        f.write(f"{n} {v[0]:.12g} {v[1]:.12g} 0\n")
