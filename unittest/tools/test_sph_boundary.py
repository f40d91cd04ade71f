"""tools/sph_boundary.py, the boundary set-up of Cleary 1998 section 3.5:
wall particles at spacing dx on the curve with normals perpendicular to it
(unit, into the medium), no interior particle within eps*dx of the wall,
sensible particle counts for disc, annulus, rectangle and polygon, the
naive set-up, and the data file round trip (through LAMMPS too when the
environment variable LMP names a LAMMPS executable)."""

import math
import os
import subprocess
import tempfile

import numpy as np

from checks import finish, that

import sph_boundary as sb


def ring_spacing(p):
    """Distances between consecutive particles of a ring ordered by angle."""
    order = np.argsort(np.arctan2(p[:, 1], p[:, 0]))
    q = p[order]
    return np.linalg.norm(np.roll(q, -1, axis=0) - q, axis=1)


# disc, 30 particles across (R = 15 dx), as in Cleary 1998, section 3.5
dx, R, eps = 1.0 / 30, 0.5, 0.42
s = sb.disc(R, dx, eps=eps)
wall, inner = s.x[s.layer == 0], s.x[s.interior]
nw = s.normal[s.layer == 0]
d = ring_spacing(wall)
that(len(wall) == round(2 * math.pi * R / dx), "disc: wall count round(2 pi R / dx)", f"{len(wall)}")
that(abs(d / dx - 1).max() < 0.01 and np.ptp(d) < 1e-12, "disc: wall spacing equal and = dx within 1 %",
     f"{d.min() / dx:.5f} ... {d.max() / dx:.5f} dx")
that(abs(np.hypot(wall[:, 0], wall[:, 1]) - R).max() < 1e-12, "disc: wall particles on the circle")
that(abs(np.linalg.norm(nw, axis=1) - 1).max() < 1e-12, "disc: normals unit")
rhat = wall / np.hypot(wall[:, 0], wall[:, 1])[:, None]
tang = np.column_stack([-rhat[:, 1], rhat[:, 0]])
that(abs(np.sum(nw * tang, axis=1)).max() < 1e-12 and (np.sum(nw * rhat, axis=1) < -1 + 1e-12).all(),
     "disc: normals perpendicular to the circle, pointing into the disc")
gap = R - np.hypot(inner[:, 0], inner[:, 1])
that(gap.min() >= eps * dx, "disc: no interior particle within eps dx of the wall", f"closest {gap.min() / dx:.3f} dx")
that(abs(np.linalg.norm(s.normal[s.interior], axis=1)).max() == 0, "disc: interior normals zero")
area = math.pi * (R - eps * dx) ** 2 / dx ** 2
that(abs(len(inner) / area - 1) < 0.03, "disc: interior count ~ pi (R - eps dx)^2 / dx^2",
     f"{len(inner)} against {area:.0f}")
that(len(inner) == 680 and (s.type[s.interior] == 1).all() and (s.type[s.wall] == 2).all(),
     "disc: 680 interior (type 1) + 94 wall (type 2) particles for a half-offset lattice")
lat = inner / dx - 0.5
that(abs(lat - np.round(lat)).max() < 1e-9, "disc: interior on the square lattice (offset dx/2)")
for e in (0.3, 0.6):
    g = R - np.hypot(*sb.disc(R, dx, eps=e).x[sb.disc(R, dx, eps=e).interior].T)
    that(g.min() >= e * dx, f"disc eps = {e}: closest interior particle", f"{g.min() / dx:.3f} dx")

# several wall layers: concentric rings dx apart, outward
s3 = sb.disc(R, dx, layers=3)
ok = True
for k in range(3):
    p = s3.x[s3.layer == k]
    rk = np.hypot(p[:, 0], p[:, 1])
    ok &= abs(rk - (R + k * dx)).max() < 1e-12 and len(p) == round(2 * math.pi * (R + k * dx) / dx)
    ok &= abs(ring_spacing(p) / dx - 1).max() < 0.01
that(ok, "disc, 3 layers: rings at R, R + dx, R + 2 dx, spacing dx")
that(set(s3.type[s3.layer > 0]) == {3} and len(s3.x[s3.interior]) == len(inner), "disc, 3 layers: outer layers type 3")

# annulus: outer wall normals inward, inner wall normals outward (both into the medium)
a = sb.annulus(0.2, 0.5, 0.02, layers=2)
ro = a.curve == 0
ri = a.curve == 1
r = np.hypot(a.x[:, 0], a.x[:, 1])
rh = a.x / np.maximum(r, 1e-300)[:, None]
that((np.sum(a.normal[ro] * rh[ro], axis=1) < -1 + 1e-12).all()
     and (np.sum(a.normal[ri] * rh[ri], axis=1) > 1 - 1e-12).all(), "annulus: normals into the medium")
that(abs(r[ri & (a.layer == 1)] - 0.18).max() < 1e-12 and abs(r[ro & (a.layer == 1)] - 0.52).max() < 1e-12,
     "annulus: second layers at Ri - dx and Ro + dx")
ri_in = r[a.interior]
that(ri_in.min() >= 0.2 + 0.42 * 0.02 and ri_in.max() <= 0.5 - 0.42 * 0.02, "annulus: interior clear of both walls")

# rectangle aligned with the lattice: spacing exactly dx, corner normals at 45 degrees
rc = sb.rectangle(1.0, 0.5, 0.025)
w = rc.x[rc.wall]
nwr = rc.normal[rc.wall]
corner = (np.abs(np.abs(w[:, 0]) - 0.5) < 1e-12) & (np.abs(np.abs(w[:, 1]) - 0.25) < 1e-12)
that(len(w) == 2 * (40 + 20) and corner.sum() == 4, "rectangle: 120 wall particles incl. 4 corners")
that(np.allclose(np.abs(nwr[corner]), math.sqrt(0.5)) and (np.sum(nwr[corner] * w[corner], axis=1) < 0).all(),
     "rectangle: corner normals halfway (45 degrees), inward")
that(len(rc.x[rc.interior]) == 40 * 20, "rectangle: interior 40 x 20 (half a spacing from the walls)")
rr = sb.rectangle(1.0, 0.5, 0.025, angle=30)
c, sn = math.cos(math.radians(30)), math.sin(math.radians(30))
q = rr.x[rr.interior] @ np.array([[c, -sn], [sn, c]])       # back into the rectangle's frame
margin = min((0.5 - np.abs(q[:, 0])).min(), (0.25 - np.abs(q[:, 1])).min())
that(margin >= 0.42 * 0.025 - 1e-12, "rectangle at 30 degrees: interior clear of the wall", f"{margin / 0.025:.3f} dx")
that(abs(len(rr.x[rr.interior]) / ((1 - 0.84 * 0.025) * (0.5 - 0.84 * 0.025) / 0.025 ** 2) - 1) < 0.05,
     "rectangle at 30 degrees: interior count ~ area / dx^2", f"{len(rr.x[rr.interior])}")

# general polygon (triangle) and parametric curve (ellipse)
tri = sb.setup([sb.polygon([[0, 0], [1, 0], [0.5, 0.8]])], 0.02)
tw = tri.x[tri.wall]
that(abs(np.linalg.norm(tri.normal[tri.wall], axis=1) - 1).max() < 1e-12
     and sb.polygon([[0, 0], [1, 0], [0.5, 0.8]]).distance(tri.x[tri.interior]).min() >= 0.42 * 0.02,
     "triangle: unit normals, interior clear of the wall")
ell = sb.setup([sb.parametric(lambda t: (0.5 * math.cos(t), 0.3 * math.sin(t)))], 0.02)
ew, en = ell.x[ell.wall], ell.normal[ell.wall]
grad = np.column_stack([ew[:, 0] / 0.25, ew[:, 1] / 0.09])           # outward normal of the ellipse
grad /= np.linalg.norm(grad, axis=1)[:, None]
dd = np.linalg.norm(np.roll(ew, -1, axis=0) - ew, axis=1)
that(np.sum(en * grad, axis=1).max() < -1 + 1e-4 and abs(dd / 0.02 - 1).max() < 0.01,
     "ellipse: normals perpendicular to the curve (1e-4), spacing dx within 1 %")

# the naive set-up: lattice points with r <= R, the outermost tagged as wall
nv = sb.naive_disc(R, dx)
rn = np.hypot(nv.x[:, 0], nv.x[:, 1])
key = {tuple(np.round(p / dx - 0.5).astype(int)) for p in nv.x}
outer = [any((i + a_, j + b_) not in key for a_, b_ in ((1, 0), (-1, 0), (0, 1), (0, -1)))
         for i, j in np.round(nv.x / dx - 0.5).astype(int)]
that(rn.max() <= R and len(nv) == sum(1 for i in range(-16, 16) for j in range(-16, 16)
                                      if math.hypot(i + 0.5, j + 0.5) <= 15),
     "naive: all lattice points with r <= R", f"{len(nv)}")
that(np.array_equal(np.array(outer), nv.wall), "naive: wall = points with a 4-neighbour missing", f"{nv.wall.sum()}")
nn = nv.normal[nv.wall]
that(abs(np.linalg.norm(nn, axis=1) - 1).max() < 1e-12
     and (np.sum(nn * nv.x[nv.wall], axis=1) < 0).all(), "naive: lattice normals unit, pointing inward")

# data file round trip (write_data / read_data), and the command line
with tempfile.TemporaryDirectory() as tmp:
    path = os.path.join(tmp, "disc.data")
    s3.write_data(path, rho=1000.0, cv=2.0, T=1.0, Twall=0.0)
    back = sb.read_data(path)
    that(back["natoms"] == len(s3) and np.array_equal(back["type"], s3.type)
         and abs(back["x"][:, :2] - s3.x).max() < 1e-15 and back["x"][:, 2].max() == 0
         and abs(back["normal"][:, :2] - s3.normal).max() < 1e-15 and np.array_equal(back["normal_id"], back["id"]),
         "data file: positions, types and normals round-trip")
    that(all(abs(m / (1000 * dx * dx) - 1) < 1e-15 for m in back["mass"].values()) and len(back["mass"]) == 3
         and (back["rho"] == 1000).all() and (back["cv"] == 2).all()
         and np.array_equal(back["esph"], np.where(s3.interior, 2.0, 0.0)),
         "data file: masses rho dx^2, rho, cv, esph = cv T")
    inside_box = (back["x"][:, :2] > back["box"][:2, 0]).all() and (back["x"][:, :2] < back["box"][:2, 1]).all()
    that(inside_box, "data file: particles inside the box")
    cli = os.path.join(tmp, "cli.data")
    rc_ = sb.main(["disc", "--radius", "0.5", "--dx", str(dx), "--layers", "3", "-o", cli])
    c2 = sb.read_data(cli)
    that(rc_ == 0 and abs(c2["x"][:, :2] - s3.x).max() < 1e-12, "command line: same particles as the module")

    lmp = os.environ.get("LMP")
    if lmp and os.access(lmp, os.X_OK):
        inp = os.path.join(tmp, "in.read")
        with open(inp, "w") as f:
            f.write("units si\ndimension 2\natom_style sph\nboundary f f p\n"
                    "fix normals all property/atom d_nx d_ny d_nz\n"
                    f"read_data {path} fix normals NULL Normals\n"
                    f"write_dump all custom {tmp}/back.dump id type mass x y d_nx d_ny d_nz modify sort id "
                    "format float %.17g\n")
        out = subprocess.run([lmp, "-in", inp, "-log", "none", "-screen", "none"], cwd=tmp)
        from sphthermal_tools.dump import read_frames
        fr = read_frames(os.path.join(tmp, "back.dump"))[0][1] if out.returncode == 0 else None
        ok = fr is not None and len(fr["id"]) == len(s3)
        if ok:
            ok = (abs(fr["x"] - s3.x[:, 0]).max() < 1e-15 and abs(fr["y"] - s3.x[:, 1]).max() < 1e-15
                  and abs(fr["d_nx"] - s3.normal[:, 0]).max() < 1e-15 and abs(fr["d_ny"] - s3.normal[:, 1]).max() < 1e-15
                  and np.array_equal(fr["type"].astype(int), s3.type))
        that(ok, "LAMMPS read_data ... fix normals NULL Normals: positions, types, d_nx d_ny round-trip")
    else:
        print("skip LAMMPS round trip (set LMP to a LAMMPS executable)")

# a body in a fluid, the half-spacing convention (--body): a disc of R = 0.05
# at D / dx = 20, three wall rings (k + 1/2) dx inside and three fluid rings
# (k + 1/2) dx outside, each of round(2 pi r / dx) equally spaced particles
dxb, Rb, cb = 0.005, 0.05, (0.2, 0.2)
b = sb.body([sb.circle(cb[0], cb[1], Rb, hole=True)], dxb, layers=3, fluid_layers=3)
rb = np.hypot(b.x[:, 0] - cb[0], b.x[:, 1] - cb[1])
for k in range(3):
    for name, sel, r_expect, t_expect in (
            ("wall", (b.layer == k), Rb - (k + 0.5) * dxb, 2 if k == 0 else 3),
            ("fluid", None, Rb + (k + 0.5) * dxb, 1)):
        if sel is None:
            sel = b.interior & (abs(rb - r_expect) < 0.25 * dxb)
        ring = b.x[sel]
        that(len(ring) == round(2 * math.pi * r_expect / dxb) and abs(rb[sel] - r_expect).max() < 1e-12
             and (b.type[sel] == t_expect).all(),
             f"body: {name} ring {k} at r = R {'-' if name == 'wall' else '+'} ({k} + 1/2) dx, "
             f"round(2 pi r / dx) particles, type {t_expect}", f"{len(ring)} particles")
        sp = ring_spacing(ring - np.asarray(cb))
        that(np.ptp(sp) < 1e-12 and abs(sp / dxb - 1).max() < 0.02, f"body: {name} ring {k} spacing dx within 2 %",
             f"{sp.min() / dxb:.4f} .. {sp.max() / dxb:.4f} dx")
that(len(b) == int((b.layer >= 0).sum()) + int(b.interior.sum()) and b.interior.sum() > 0,
     "body: only wall and fluid rings, no lattice")
nb = b.normal[b.layer >= 0]
rhat_b = (b.x[b.layer >= 0] - np.asarray(cb)) / rb[b.layer >= 0][:, None]
that(abs(np.sum(nb * rhat_b, axis=1) - 1).max() < 1e-12, "body: wall normals point out of the body, into the fluid")
that(abs(b.normal[b.interior]).max() == 0, "body: fluid particles have no normal")
# a square body, one corner up: its wall layers stay inside, the fluid's outside
sq = sb.body([sb.polygon(np.array([[0, 0], [0.1, 0], [0.1, 0.1], [0, 0.1]]), hole=True)], 0.01, 2, 2)
inside_sq = (sq.x > 0).all(axis=1) & (sq.x < 0.1).all(axis=1)
that((inside_sq == (sq.layer >= 0)).all(), "body: a square's wall layers inside it, its fluid layers outside")
try:
    sb.body([sb.circle(0, 0, 1.0)], 0.1)
    that(False, "body: a curve with the fluid inside is refused")
except ValueError as e:
    that("hole=True" in str(e), "body: a curve with the fluid inside is refused", str(e))
with tempfile.TemporaryDirectory() as tmp:
    path = os.path.join(tmp, "body.data")
    rc_ = sb.main(["disc", "--body", "--radius", str(Rb), "--center", "0.2,0.2", "--dx", str(dxb),
                   "--layers", "3", "--section", "none", "-o", path])
    back = sb.read_data(path, section=None)
    that(rc_ == 0 and back["natoms"] == len(b) and abs(back["x"][:, :2] - b.x).max() < 1e-15
         and "Normals" not in open(path).read(),
         "body command line: the module's particles, no normals section (--section none)")

finish()
