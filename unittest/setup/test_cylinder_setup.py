"""tools/sph_boundary.py cylinder: the closed cylindrical tank (axis z) of
Cleary's boundary rules (1998, section 3.5) in 3-d, R = 0.0193, H = 0.0386,
dx = 0.002, 3 wall layers, the interior split at z = H/2.

usage: test_cylinder_setup.py [--lmp LMP --plugin PLUGIN]

Checks (each prints ok/FAIL and the value):
  normals    unit; curved wall (-x/r, -y/r, 0), bottom lid (0, 0, 1), top
             lid (0, 0, -1); zero for the interior
  walls      curved wall layer k on r = R + k dx, round(2 pi r / dx) equally
             spaced particles per ring, planes j H/m strictly between the
             lids; lids in z = -b dx and H + b dx, each plane covering the
             disc of radius R + (layers-1) dx (no hole wider than 0.75 dx, count
             ~ its area / dx^2) with the rings R + a dx of the corner; every
             wall radius R + a dx a column of rings from the lowest lid plane to
             the highest, spacing dx (H/m in the curved part); types 2/3/4/5
  spacing    interior-interior >= dx (lattice), wall-wall >= 0.8 dx (the
             closest are the innermost lid ring, chord R/round(R/dx) ~ 0.97 dx,
             and the ring chords 2 r sin(pi/n)), interior-wall >= eps dx (an
             interior particle may sit eps dx in front of a wall particle on the
             surface: Cleary's rule, so that is the bound, not 0.5 dx)
  interior   every interior particle at least eps dx from the curved wall and
             both lids; exactly the lattice points (offset dx/2) that are;
             volume per particle: count dx^3 = pi (R - eps dx)^2 (H - 2 eps dx)
             within 5 % (the volume the lattice fills: the eps dx band at the
             walls is the wall particles' share; count dx^3 / pi R^2 H is
             printed, ~0.90 here), and per lattice plane the count = pi (R -
             eps dx)^2 / dx^2 within 2 %
  split      type 1 exactly the interior below z_split, type 6 above, the
             same particles as without the split
  data file  write_data / read_data round trip (positions, types, normals,
             masses rho dx^3, esph, a 3-d box around all particles); the
             command line writes the same particles as the module
  rings      ring_multiple 4: each curved ring's count a multiple of 4, and
             a quarter turn about the axis maps the tank (lattice lids,
             interior offset dx/2) onto itself, type for type; with the
             default 1 and counts not divisible by 4 it does not
  LAMMPS     (with --lmp and --plugin) read_data ... fix normals NULL Normals,
             run 0, write_dump: positions, types, masses and d_nx d_ny d_nz
             as written
"""

import argparse
import math
import os
import subprocess
import tempfile

import numpy as np
from scipy.spatial import cKDTree

from checks import finish, that
from sphthermal_tools.dump import read_frames
import sph_boundary as sb

p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
p.add_argument("--lmp", help="LAMMPS executable (the read_data check is skipped without it)")
p.add_argument("--plugin", help="sphthermalplugin.so")
args = p.parse_args()
if args.lmp and args.plugin:   # the LAMMPS run below is in a scratch directory
    args.lmp = os.path.abspath(args.lmp) if os.sep in args.lmp else args.lmp
    args.plugin = os.path.abspath(args.plugin)

R, H, dx, L, eps = 0.0193, 0.0386, 0.002, 3, 0.42
zs = H / 2
TOL = 1e-12 * R
s = sb.cylinder(R, H, dx, eps=eps, layers=L, z_split=zs)
x, n, typ, lay, cur = s.x, s.normal, s.type, s.layer, s.curve
r = np.hypot(x[:, 0], x[:, 1])
side, bot, top = cur == 0, cur == 1, cur == 2
lids = bot | top
wall, inner = s.wall, s.interior
print(f"cylinder R={R} H={H} dx={dx} layers={L} z_split={zs}: {s.summary()}")

# ---------------------------------------------------------------- normals
that(s.dim == 3 and x.shape[1] == 3 and n.shape[1] == 3, "3-d positions and normals")
that(abs(np.linalg.norm(n[wall], axis=1) - 1).max() < 1e-12, "wall normals unit",
     f"max | |n| - 1 | = {abs(np.linalg.norm(n[wall], axis=1) - 1).max():.1e}")
that(not n[inner].any(), "interior normals zero")
radial = np.column_stack([-x[side, 0] / r[side], -x[side, 1] / r[side], np.zeros(side.sum())])
that(side.any() and abs(n[side] - radial).max() < 1e-12, "curved wall normals (-x/r, -y/r, 0): radial, into the fluid",
     f"max deviation {abs(n[side] - radial).max():.1e}")
that(bot.any() and top.any() and (n[bot] == [0, 0, 1]).all() and (n[top] == [0, 0, -1]).all(),
     "lid normals (0, 0, 1) at the bottom, (0, 0, -1) at the top")

# ---------------------------------------------------------------- walls
m = round(H / dx)
planes = np.arange(1, m) * H / m
ok, detail = True, []
for k in range(L):
    rk = R + k * dx
    sel = side & (lay == k)
    nk = round(2 * math.pi * rk / dx)
    ok &= abs(r[sel] - rk).max() < TOL
    zk = np.unique(np.round(x[sel, 2] / TOL) * TOL)
    ok &= len(zk) == m - 1 and abs(zk - planes).max() < 1e-9 * H
    for z in planes:
        ring = x[sel & (abs(x[:, 2] - z) < 1e-9 * H)]
        phi = np.sort(np.arctan2(ring[:, 1], ring[:, 0]))
        gaps = np.diff(np.concatenate([phi, phi[:1] + 2 * math.pi]))
        ok &= len(ring) == nk and abs(gaps - 2 * math.pi / nk).max() < 1e-9
    detail.append(f"r = R + {k} dx: {nk} per ring")
that(ok, f"curved wall: rings of round(2 pi r / dx) equally spaced particles, r = R + k dx, "
     f"{m - 1} planes j H/m (0 < z < H)", "; ".join(detail))
that(set(typ[side & (lay == 0)]) == {2} and set(typ[side & (lay > 0)]) == {3}
     and abs(r[side & (typ == 2)] - R).max() < TOL, "curved wall types: 2 on r = R, 3 outside")
that(set(np.round(x[bot, 2] / dx, 9)) == {-b for b in range(L)} and set(np.round((x[top, 2] - H) / dx, 9))
     == {b for b in range(L)}, "lid planes z = -b dx and H + b dx, b = 0 .. layers-1")
rout = R + (L - 1) * dx
that(r[lids].max() < rout + TOL, "lids: within r = R + (layers-1) dx", f"{r[lids].max() / dx:.6f} dx")
ok, worst, counts = True, 0.0, []
gx, gy = np.meshgrid(np.linspace(-rout, rout, 241), np.linspace(-rout, rout, 241))
probe = np.column_stack([gx.ravel(), gy.ravel()])
probe = probe[np.hypot(probe[:, 0], probe[:, 1]) <= rout]
for z in sorted(set(np.round(x[lids, 2], 12))):
    q = x[lids & (abs(x[:, 2] - z) < 1e-9 * H)]
    worst = max(worst, cKDTree(q[:, :2]).query(probe)[0].max())
    counts.append(len(q))
    for a in range(L):
        ok &= (abs(np.hypot(q[:, 0], q[:, 1]) - (R + a * dx)) < TOL).sum() == round(2 * math.pi * (R + a * dx) / dx)
area = math.pi * (rout + 0.5 * dx) ** 2 / dx ** 2
that(worst <= 0.75 * dx, "lids: every plane covers the disc r <= R + (layers-1) dx (largest distance "
     "to a lid particle)", f"{worst / dx:.3f} dx (limit 0.75)")
that(abs(np.array(counts) / area - 1).max() < 0.03, "lids: particles per plane ~ pi (R + (layers-1/2) dx)^2 / dx^2 "
     "within 3 %", f"{sorted(set(counts))} against {area:.1f}")
that(ok, "lids: the corner rings r = R + a dx (a = 0 .. layers-1) in every lid plane")
first = lids & (np.isin(np.round(x[:, 2], 12), [0.0, round(H, 12)])) & (r < R + TOL)
that(np.array_equal(typ == 4, first) and np.array_equal(typ == 5, lids & ~first),
     "lid types: 4 = on z = 0 or H with r <= R, 5 = further planes and the corner r > R")
ok, gz = True, []
for a in range(L):
    col = np.unique(np.round(x[wall & (abs(r - (R + a * dx)) < TOL), 2], 12))
    g = np.diff(col)
    gz.append(g)
    ok &= abs(col[0] + (L - 1) * dx) < TOL and abs(col[-1] - H - (L - 1) * dx) < TOL
    ok &= g.min() > 0.999 * dx and g.max() < max(dx, H / m) * 1.001
gz = np.concatenate(gz)
that(ok, "corner filled: each radius R + a dx a column of rings from z = -(layers-1) dx to H + (layers-1) dx",
     f"vertical gaps {gz.min() / dx:.4f} .. {gz.max() / dx:.4f} dx")

# ---------------------------------------------------------------- spacing
def closest(a, b=None):
    """Smallest distance within a, or between a and b."""
    if b is None:
        return cKDTree(a).query(a, k=2)[0][:, 1].min()
    return cKDTree(b).query(a)[0].min()


d_ii, d_ww, d_iw = closest(x[inner]), closest(x[wall]), closest(x[inner], x[wall])
that(d_ii > dx * (1 - 1e-9), "interior-interior distances >= dx", f"{d_ii / dx:.6f} dx")
that(d_ww >= 0.8 * dx, "wall-wall distances >= 0.8 dx", f"{d_ww / dx:.4f} dx")
that(d_iw >= eps * dx * (1 - 1e-12), "interior-wall distances >= eps dx", f"{d_iw / dx:.4f} dx")

# ---------------------------------------------------------------- interior
def interior_rule(t, R, H, off, cen, label):
    """Every interior particle of setup t at least eps dx from the walls, and
    exactly the lattice points ((i, j, k) + off) dx + (cx, cy, 0) that are."""
    q = t.x[t.interior] - [cen[0], cen[1], 0.0]
    rq = np.hypot(q[:, 0], q[:, 1])
    gap = np.minimum(R - rq, np.minimum(q[:, 2], H - q[:, 2]))
    that(gap.min() >= eps * dx * (1 - 1e-12), f"{label}interior: inside, at least eps dx from the curved wall "
         "and both lids", f"closest {gap.min() / dx:.4f} dx (R - r >= {(R - rq).min() / dx:.4f}, "
         f"z >= {q[:, 2].min() / dx:.4f}, H - z >= {(H - q[:, 2]).min() / dx:.4f} dx)")
    lat = q / dx - np.asarray(off)
    want = set()
    for i in range(-int(R / dx) - 3, int(R / dx) + 3):
        for j in range(-int(R / dx) - 3, int(R / dx) + 3):
            for k in range(-3, int(H / dx) + 3):
                xi, yj, zk = (i + off[0]) * dx, (j + off[1]) * dx, (k + off[2]) * dx
                if R - math.hypot(xi, yj) >= eps * dx and zk >= eps * dx and H - zk >= eps * dx:
                    want.add((i, j, k))
    got = {tuple(v) for v in np.round(lat).astype(int)}
    that(abs(lat - np.round(lat)).max() < 1e-9 and got == want and len(got) == len(q),
         f"{label}interior: exactly the lattice points (offset {off} dx) at least eps dx from the walls",
         f"{len(q)} particles, {len(want)} such lattice points")
    return q


q = interior_rule(s, R, H, (0.5, 0.5, 0.5), (0.0, 0.0), "")
vs = math.pi * (R - eps * dx) ** 2 * (H - 2 * eps * dx)
that(abs(len(q) * dx ** 3 / vs - 1) < 0.05, "interior: volume per particle ~ dx^3: count dx^3 against "
     "pi (R - eps dx)^2 (H - 2 eps dx) within 5 %",
     f"{len(q) * dx ** 3 / vs:.4f}; count dx^3 / (pi R^2 H) = {len(q) * dx ** 3 / (math.pi * R * R * H):.4f}")
zl, per = np.unique(np.round(q[:, 2], 12), return_counts=True)
disc = math.pi * (R - eps * dx) ** 2 / dx ** 2
that(abs(per / disc - 1).max() < 0.02, "interior: per lattice plane pi (R - eps dx)^2 / dx^2 particles within 2 %",
     f"{sorted(set(per))} in {len(zl)} planes against {disc:.1f}")

# tank B: axis off the origin, lattice offset (0.3, 0.7, 0.3) and H = 19.7 dx, so that the
# lowest and the highest lattice planes (0.3 dx from a lid) are omitted; one wall layer
HB, offB, cenB = 0.0394, (0.3, 0.7, 0.3), (0.001, -0.002)
tb = sb.cylinder(R, HB, dx, eps=eps, layers=1, offset=offB, center=cenB)
qb = interior_rule(tb, R, HB, offB, cenB, "tank B: ")
that(abs(qb[:, 2].min() - 1.3 * dx) < TOL and abs(qb[:, 2].max() - 18.3 * dx) < TOL,
     "tank B: the lattice planes z = 0.3 dx and H - 0.4 dx omitted (closer than eps dx to a lid)",
     f"interior z = {qb[:, 2].min() / dx:.2f} .. {qb[:, 2].max() / dx:.2f} dx")
wb = tb.x[tb.curve == 0] - [cenB[0], cenB[1], 0.0]
rb = np.hypot(wb[:, 0], wb[:, 1])
that(abs(rb - R).max() < TOL and abs(tb.normal[tb.curve == 0] + np.column_stack([wb[:, :2] / rb[:, None],
                                                                                  np.zeros(len(wb))])).max() < 1e-12
     and tb.ntypes == 5 and set(tb.type) == {1, 2, 4},
     "tank B: curved wall on r = R about the axis, normals radial about it; 1 layer: types 1, 2, 4 of 5")

# ---------------------------------------------------------------- split
u = sb.cylinder(R, H, dx, eps=eps, layers=L)
that(np.array_equal(u.x, s.x) and np.array_equal(u.type[u.wall], s.type[s.wall])
     and set(u.type[u.interior]) == {1} and u.ntypes == 5 and s.ntypes == 6,
     "split: the same particles; without it the interior is all type 1 and 5 types are declared")
low, high = inner & (x[:, 2] < zs), inner & (x[:, 2] >= zs)
that(low.any() and high.any() and (typ[low] == 1).all() and (typ[high] == 6).all()
     and not np.isin(typ[wall], [1, 6]).any(),
     f"split: type 1 = the interior below z = {zs}, type 6 above",
     f"{low.sum()} + {high.sum()}, highest type 1 z = {x[typ == 1, 2].max() / dx:.2f} dx, "
     f"lowest type 6 z = {x[typ == 6, 2].min() / dx:.2f} dx")

# ---------------------------------------------------------------- data file, command line, LAMMPS
rho, cv, T, Tw = 1000.0, 4180.0, 300.0, 350.0
with tempfile.TemporaryDirectory() as tmp:
    path = os.path.join(tmp, "tank.data")
    s.write_data(path, rho=rho, cv=cv, T=T, Twall=Tw)
    b = sb.read_data(path)
    that(b["natoms"] == len(s) and np.array_equal(b["id"], np.arange(1, len(s) + 1))
         and np.array_equal(b["type"], typ) and abs(b["x"] - x).max() < 1e-14 * R
         and abs(b["normal"] - n).max() < 1e-15 and np.array_equal(b["normal_id"], b["id"]),
         "data file: positions (x y z), types and normals (nx ny nz) round-trip",
         f"max position error {abs(b['x'] - x).max():.1e}")
    that(sorted(b["mass"]) == list(range(1, 7))
         and all(abs(v / (rho * dx ** 3) - 1) < 1e-15 for v in b["mass"].values())
         and (b["rho"] == rho).all() and (b["cv"] == cv).all()
         and np.array_equal(b["esph"], np.where(inner, cv * T, cv * Tw)),
         "data file: 6 types, masses rho dx^3, rho, cv, esph = cv T (interior) and cv Twall (walls)")
    box = b["box"]
    that((box[:, 0] < x.min(axis=0) - dx).all() and (box[:, 1] > x.max(axis=0) + dx).all(),
         "data file: a 3-d box around all particles (margin > dx)",
         " ".join(f"{c}: {lo:.5g} {hi:.5g}" for c, (lo, hi) in zip("xyz", box)))
    cli = os.path.join(tmp, "cli.data")
    rc = sb.main(["cylinder", "--radius", str(R), "--height", str(H), "--dx", str(dx), "--layers", str(L),
                  "--split-z", str(zs), "-o", cli])
    c = sb.read_data(cli)
    that(rc == 0 and np.array_equal(c["type"], typ) and abs(c["x"] - x).max() < 1e-14 * R
         and abs(c["normal"] - n).max() < 1e-15, "command line: the same particles as the module")

    if args.lmp and args.plugin:
        dump = os.path.join(tmp, "back.dump")
        inp = os.path.join(tmp, "in.read")
        with open(inp, "w") as f:
            f.write(f"plugin load {args.plugin}\nunits si\ndimension 3\natom_style sph\nboundary f f f\n"
                    "fix normals all property/atom d_nx d_ny d_nz\n"
                    f"read_data {path} fix normals NULL Normals\nrun 0\n"
                    f"write_dump all custom {dump} id type mass x y z d_nx d_ny d_nz modify sort id "
                    "format float %.17g\n")
        proc = subprocess.run([args.lmp, "-in", inp, "-log", "none"], cwd=tmp, capture_output=True, text=True)
        fr = read_frames(dump)[0][1] if proc.returncode == 0 and os.path.exists(dump) else None
        ok = fr is not None and len(fr["id"]) == len(s)
        if ok:
            xyz = np.column_stack([fr["x"], fr["y"], fr["z"]])
            nrm = np.column_stack([fr["d_nx"], fr["d_ny"], fr["d_nz"]])
            ok = (np.array_equal(fr["type"].astype(int), typ) and abs(xyz - x).max() < 1e-14 * R
                  and abs(nrm - n).max() < 1e-15 and abs(fr["mass"] / (rho * dx ** 3) - 1).max() < 1e-15)
        else:
            print(proc.stdout[-2000:] + proc.stderr[-2000:])
        that(ok, "LAMMPS (dimension 3, atom_style sph) read_data ... fix normals NULL Normals, run 0: "
             "positions, types, masses and d_nx d_ny d_nz as written", f"{len(s)} atoms")
    else:
        print("skip the LAMMPS read (give --lmp and --plugin)")

# ---------------------------------------------------------- lattice lids
sl = sb.cylinder(R, H, dx, eps=eps, layers=L, z_split=zs, lids="lattice")
xl, tl, cl = sl.x, sl.type, sl.curve
that(np.array_equal(xl[sl.interior], x[inner]) and np.array_equal(xl[cl == 0], x[side]),
     "lattice lids: the same interior and curved wall as with ring lids")
columns = {tuple(np.round(p[:2] / dx, 6)) for p in xl[sl.interior]}
ok = True
for c, z in ((1, 0.0), (2, H)):
    plane = xl[(cl == c) & (np.abs(xl[:, 2] - z) < TOL)]
    above = {tuple(np.round(p[:2] / dx, 6)) for p in plane}
    ok &= columns <= above
    ok &= abs(np.hypot(plane[:, 0], plane[:, 1]).max() - (R + (L - 1) * dx)) < dx
that(ok, "lattice lids: every interior column ends under (above) a lid particle in the first top (bottom) plane")
rl = np.hypot(xl[:, 0], xl[:, 1])
lidl = (cl == 1) | (cl == 2)
first = lidl & ((np.abs(xl[:, 2]) < TOL) | (np.abs(xl[:, 2] - H) < TOL)) & (rl <= R + TOL)
that(np.array_equal(tl == 4, first) and np.array_equal(tl == 5, lidl & ~first),
     "lattice lids: type 4 the lid surfaces within r <= R, type 5 the rest")
that(closest(xl[lidl]) >= dx * (1 - 1e-9) and closest(xl[sl.interior], xl[lidl]) >= eps * dx * (1 - 1e-12),
     "lattice lids: lid particles dx apart, at least eps dx from the interior")

# ---------------------------------------------------------- ring_multiple
def quarter_turn_misses(setup):
    """Particles (of any type) that a quarter turn about the axis does not
    put on a particle of the same type."""
    p, t = setup.x, setup.type
    turned = np.column_stack([-p[:, 1], p[:, 0], p[:, 2]])
    key = {(round(a / dx * 1e6), round(b / dx * 1e6), round(c / dx * 1e6)): ty
           for (a, b, c), ty in zip(p, t)}
    return sum(key.get((round(a / dx * 1e6), round(b / dx * 1e6), round(c / dx * 1e6))) != ty
               for (a, b, c), ty in zip(turned, t))


for multiple in (1, 4):
    sm = sb.cylinder(R, H, dx, eps=eps, layers=L, offset=(0.5, 0.5, 0.0), z_split=zs, lids="lattice",
                     ring_multiple=multiple)
    counts = [int(round(2.0 * math.pi * (R + k * dx) / dx / multiple)) * multiple for k in range(L)]
    per_ring = [int(np.sum((sm.curve == 0) & (sm.layer == k)) // (round(H / dx) - 1)) for k in range(L)]
    that(per_ring == counts, f"ring_multiple {multiple}: each curved ring holds its count rounded to a "
         f"multiple of {multiple}", f"{per_ring}")
    misses = quarter_turn_misses(sm)
    if multiple == 4:
        that(misses == 0, "ring_multiple 4: a quarter turn about the axis maps the tank onto itself",
             f"{misses} particles missed")
    else:
        that(misses > 0 and any(c % 4 for c in counts),
             "ring_multiple 1: rings of counts not divisible by 4 are not the same after a quarter turn",
             f"counts {counts}, {misses} particles missed")

finish()
