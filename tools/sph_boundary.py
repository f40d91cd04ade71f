#!/usr/bin/env python3
"""Boundary set-up for SPH particle scenes (Cleary 1998, section 3.5).

Cleary's rules for boundaries that are not aligned with the particle lattice:

* boundary (wall) particles are set up separately from the interior ones,
  on smoothly varying curves, equally spaced at the interior spacing dx;
* their normals are perpendicular to the underlying curve (corners of a
  polyline: halfway between the normals on either side);
* interior particles (a square lattice) within eps*dx of the boundary are
  omitted (eps = 0.42, Cleary's optimum).

Optionally the wall has several layers: curves offset away from the medium
by dx, 2 dx, ... (again at spacing dx along each), so that the kernel
support of the particles next to the wall is filled (a cubic spline with
h = 1.3 dx reaches 2.6 dx).

For comparison, the "naive" set-up that Cleary warns against: the lattice
points inside the shape, the outermost ones (a lattice neighbour outside)
tagged as wall, with normals from the lattice (pointing away from the
missing neighbours).

Shapes: disc (circle), annulus (cylinder cross-section: two circles),
rectangle, and any closed polygon or parametric curve (module use), all 2-d.

Output: a LAMMPS data file for atom_style sph (Atoms line: id type rho esph
cv x y z, per-type masses rho dx^2 per unit depth), types 1 = interior,
2 = wall particles on the boundary curve(s), 3 = further wall layers (with
--type-per-curve, curve c gets types 2 + 2c and 3 + 2c), and a section
(default "Normals": id nx ny nz) with the unit wall normals pointing into the
medium (zero for interior particles), as compute sph/heatflux/atom wants
them. Read it with

    atom_style sph
    fix normals all property/atom d_nx d_ny d_nz
    read_data disc.data fix normals NULL Normals

Command line, e.g. (the disc of examples/conduction-disc: 30 particles across, one wall ring):

    python3 tools/sph_boundary.py disc --radius 0.5 --dx 0.0333333333333 -o disc.data
    python3 tools/sph_boundary.py disc --radius 15 --dx 1 --naive -o naive.data
    python3 tools/sph_boundary.py annulus --radius 0.2 --outer-radius 0.5 --dx 0.02 --layers 3 -o ann.data
    python3 tools/sph_boundary.py rectangle --lx 1 --ly 0.5 --dx 0.025 --angle 30 -o rect.data
    python3 tools/sph_boundary.py polygon --vertices "0,0 1,0 0.5,0.8" --dx 0.02 -o tri.data

Module: setup = sph_boundary.disc(R, dx); setup.write_data("disc.data").
Pure Python 3 + numpy.
"""

import argparse
import math
import sys

import numpy as np

__all__ = ["Curve", "Setup", "circle", "polygon", "parametric", "setup", "disc", "annulus",
           "rectangle", "naive", "naive_disc", "read_data", "main"]


# ---------------------------------------------------------------- curves

class Curve:
    """A closed boundary curve.

    points(k) gives the particles of wall layer k (0 = on the curve, k > 0
    offset by k*dx away from the medium) and their unit normals into the
    medium. `hole` = the medium lies outside the curve (inner wall of an
    annulus); otherwise inside. `dense` is a fine counter-clockwise polyline
    of the curve for the inside test and distances.
    """

    def __init__(self, dense, hole, layer_fn, contains_fn=None, distance_fn=None):
        self.dense = dense
        self.hole = hole
        self._layer = layer_fn
        self._contains = contains_fn
        self._distance = distance_fn

    def points(self, k, dx):
        return self._layer(k, dx)

    def contains(self, p):
        """True for points inside the closed curve (ray casting on the dense polyline)."""
        if self._contains is not None:
            return self._contains(np.atleast_2d(p))
        return _inside_polygon(p, self.dense)

    def distance(self, p):
        """Distance from points p (n x 2) to the curve."""
        if self._distance is not None:
            return self._distance(np.atleast_2d(p))
        return _distance_to_polyline(p, self.dense)


def _ccw(v):
    v = np.asarray(v, dtype=float)
    x, y = v[:, 0], v[:, 1]
    area = 0.5 * np.sum(x * np.roll(y, -1) - np.roll(x, -1) * y)
    return v if area > 0 else v[::-1].copy()


def _inside_polygon(p, v):
    p = np.atleast_2d(p)
    x, y = p[:, 0][:, None], p[:, 1][:, None]
    x1, y1 = v[:, 0][None, :], v[:, 1][None, :]
    x2, y2 = np.roll(v[:, 0], -1)[None, :], np.roll(v[:, 1], -1)[None, :]
    crosses = (y1 > y) != (y2 > y)
    with np.errstate(divide="ignore", invalid="ignore"):
        xc = x1 + (y - y1) * (x2 - x1) / (y2 - y1)
    return np.sum(crosses & (x < xc), axis=1) % 2 == 1


def _distance_to_polyline(p, v, chunk=256):
    p = np.atleast_2d(p)
    a, b = v, np.roll(v, -1, axis=0)
    ab = b - a
    ab2 = np.maximum(np.sum(ab * ab, axis=1), 1e-300)
    out = np.empty(len(p))
    for s in range(0, len(p), chunk):
        q = p[s:s + chunk, None, :]
        t = np.clip(np.sum((q - a[None]) * ab[None], axis=2) / ab2[None], 0.0, 1.0)
        d = q - (a[None] + t[..., None] * ab[None])
        out[s:s + chunk] = np.sqrt(np.min(np.sum(d * d, axis=2), axis=1))
    return out


def _resample_closed(dense, dx):
    """Equally spaced points (about dx apart, exactly L/N) along a closed polyline."""
    seg = np.linalg.norm(np.roll(dense, -1, axis=0) - dense, axis=1)
    s = np.concatenate([[0.0], np.cumsum(seg)])
    length = s[-1]
    n = max(3, int(round(length / dx)))
    closed = np.vstack([dense, dense[:1]])
    st = np.arange(n) * length / n
    return np.column_stack([np.interp(st, s, closed[:, 0]), np.interp(st, s, closed[:, 1])])


def _tangent_normals(p):
    """Unit normals (to the right of a counter-clockwise curve = outward) from central differences."""
    t = np.roll(p, -1, axis=0) - np.roll(p, 1, axis=0)
    n = np.column_stack([t[:, 1], -t[:, 0]])
    return n / np.linalg.norm(n, axis=1)[:, None]


def circle(cx, cy, radius, hole=False, dense_points=4096):
    """Circle of the given radius; medium inside (hole=False) or outside (hole=True)."""
    def layer(k, dx):
        r = radius - k * dx if hole else radius + k * dx
        if r < 0.25 * dx:
            return np.zeros((0, 2)), np.zeros((0, 2))
        n = max(1, int(round(2.0 * math.pi * r / dx)))
        phi = 2.0 * math.pi * np.arange(n) / n
        out = np.column_stack([np.cos(phi), np.sin(phi)])
        return np.column_stack([cx + r * out[:, 0], cy + r * out[:, 1]]), (out if hole else -out)
    phi = 2.0 * math.pi * np.arange(dense_points) / dense_points
    dense = np.column_stack([cx + radius * np.cos(phi), cy + radius * np.sin(phi)])
    return Curve(dense, hole, layer, lambda p: np.hypot(p[:, 0] - cx, p[:, 1] - cy) < radius,
                 lambda p: np.abs(np.hypot(p[:, 0] - cx, p[:, 1] - cy) - radius))


def polygon(vertices, hole=False):
    """Closed polyline through the vertices. Each edge is divided into
    round(length/dx) equal parts, so every vertex carries a particle whose
    normal is halfway between those of the two edges (Cleary's corner rule).
    Wall layer k is the polygon offset by k*dx away from the medium (mitred
    vertices; fine for convex corners, for concave ones keep k*dx small
    against the edges)."""
    v = _ccw(vertices)

    def offset(k, dx):
        if k == 0:
            return v
        e_in = v - np.roll(v, 1, axis=0)
        e_out = np.roll(v, -1, axis=0) - v
        n_in = np.column_stack([e_in[:, 1], -e_in[:, 0]]) / np.linalg.norm(e_in, axis=1)[:, None]
        n_out = np.column_stack([e_out[:, 1], -e_out[:, 0]]) / np.linalg.norm(e_out, axis=1)[:, None]
        bis = n_in + n_out
        bis /= np.linalg.norm(bis, axis=1)[:, None]
        cos_half = np.sum(bis * n_out, axis=1)
        sign = -1.0 if hole else 1.0
        return v + sign * k * dx * bis / cos_half[:, None]

    def layer(k, dx):
        w = offset(k, dx)
        pts, nrm = [], []
        m = len(w)
        edge_n = []
        for i in range(m):
            e = w[(i + 1) % m] - w[i]
            edge_n.append(np.array([e[1], -e[0]]) / np.linalg.norm(e))
        for i in range(m):
            a, b = w[i], w[(i + 1) % m]
            ne = max(1, int(round(np.linalg.norm(b - a) / dx)))
            corner = edge_n[i - 1] + edge_n[i]
            corner /= np.linalg.norm(corner)
            for j in range(ne):
                pts.append(a + (b - a) * j / ne)
                nrm.append(corner if j == 0 else edge_n[i])
        pts, nrm = np.array(pts), np.array(nrm)
        return pts, (nrm if hole else -nrm)
    return Curve(v, hole, layer)


def parametric(fn, t0=0.0, t1=2.0 * math.pi, hole=False, dense_points=4096):
    """Smooth closed curve fn(t) -> (x, y) for t0 <= t < t1, traced either way.
    Wall particles are equally spaced in arc length; normals from the tangent;
    layer k is the curve offset along its normals by k*dx (keep k*dx below the
    smallest radius of curvature on the concave side)."""
    t = t0 + (t1 - t0) * np.arange(dense_points) / dense_points
    xy = np.array([fn(ti) for ti in t], dtype=float)
    dense = _ccw(xy)
    n_out = _tangent_normals(dense)

    def layer(k, dx):
        off = dense + (-1.0 if hole else 1.0) * k * dx * n_out
        pts = _resample_closed(off, dx)
        nrm = _tangent_normals(pts)
        return pts, (nrm if hole else -nrm)
    return Curve(dense, hole, layer)


# ---------------------------------------------------------------- set-ups

class Setup:
    """A particle set: x (n x 2), type (n, int), normal (n x 2, into the medium,
    zero for interior particles), layer (n, -1 interior, 0 on the curve, k outer
    layers), curve (n, index of the boundary curve, -1 interior), and dx."""

    def __init__(self, x, type_, normal, layer, curve, dx, comment=""):
        self.x = np.asarray(x, dtype=float).reshape(-1, 2)
        self.type = np.asarray(type_, dtype=int)
        self.normal = np.asarray(normal, dtype=float).reshape(-1, 2)
        self.layer = np.asarray(layer, dtype=int)
        self.curve = np.asarray(curve, dtype=int)
        self.dx = float(dx)
        self.comment = comment

    def __len__(self):
        return len(self.x)

    @property
    def interior(self):
        return self.layer < 0

    @property
    def wall(self):
        return self.layer >= 0

    def write_data(self, path, rho=1.0, cv=1.0, T=1.0, Twall=None, section="Normals", margin=None):
        """Write a LAMMPS data file (atom_style sph). esph = cv*T for interior
        particles, cv*Twall for walls (fix sph/wall/isothermal sets them anyway)."""
        Twall = T if Twall is None else Twall
        dx = self.dx
        margin = 1.5 * dx if margin is None else margin
        lo = self.x.min(axis=0) - margin
        hi = self.x.max(axis=0) + margin
        ntypes = int(self.type.max())
        mass = rho * dx * dx
        esph = np.where(self.interior, cv * T, cv * Twall)
        with open(path, "w") as f:
            f.write(f"LAMMPS data file (atom_style sph) from sph_boundary.py: {self.comment}\n\n")
            f.write(f"{len(self)} atoms\n{ntypes} atom types\n\n")
            f.write(f"{lo[0]:.16g} {hi[0]:.16g} xlo xhi\n{lo[1]:.16g} {hi[1]:.16g} ylo yhi\n")
            f.write(f"{-0.5 * dx:.16g} {0.5 * dx:.16g} zlo zhi\n\nMasses\n\n")
            for t in range(1, ntypes + 1):
                f.write(f"{t} {mass:.16g}\n")
            f.write("\nAtoms # sph\n\n")
            for i in range(len(self)):
                f.write(f"{i + 1} {self.type[i]} {rho:.16g} {esph[i]:.16g} {cv:.16g} "
                        f"{self.x[i, 0]:.16g} {self.x[i, 1]:.16g} 0\n")
            f.write(f"\n{section}\n\n")
            for i in range(len(self)):
                f.write(f"{i + 1} {self.normal[i, 0]:.16g} {self.normal[i, 1]:.16g} 0\n")

    def summary(self):
        s = [f"{len(self)} particles: {int(self.interior.sum())} interior, {int(self.wall.sum())} wall"]
        for k in range(int(self.layer.max()) + 1):
            s.append(f"wall layer {k}: {int((self.layer == k).sum())}")
        return "; ".join(s)


def _lattice(lo, hi, dx, offset, angle=0.0, center=(0.0, 0.0)):
    """Square lattice points (i + ox) dx, (j + oy) dx, rotated by angle (deg) about center, covering lo..hi."""
    r = np.linalg.norm(np.array(hi) - np.array(lo)) + 2 * dx
    n = int(math.ceil(r / dx)) + 2
    i = np.arange(-n, n + 1)
    gx, gy = np.meshgrid(i + offset[0], i + offset[1], indexing="ij")
    p = np.column_stack([gx.ravel(), gy.ravel()]) * dx
    c, s = math.cos(math.radians(angle)), math.sin(math.radians(angle))
    p = p @ np.array([[c, s], [-s, c]]) + np.asarray(center)
    keep = np.all((p >= np.array(lo) - dx) & (p <= np.array(hi) + dx), axis=1)
    return p[keep]


def setup(curves, dx, eps=0.42, layers=1, offset=(0.5, 0.5), angle=0.0, center=(0.0, 0.0),
          type_per_curve=False, comment=""):
    """Cleary's set-up: wall particles on the curves (layers of them), the
    square lattice (spacing dx, shifted by offset*dx, rotated by angle degrees
    about center) inside the medium, without the points within eps*dx of a
    curve. The medium is inside every curve with hole=False and outside every
    curve with hole=True."""
    x, typ, nrm, lay, cur = [], [], [], [], []
    for c, curve in enumerate(curves):
        base = 2 + 2 * c if type_per_curve else 2
        for k in range(layers):
            p, n = curve.points(k, dx)
            x.append(p)
            nrm.append(n)
            typ.append(np.full(len(p), base + (1 if k else 0)))
            lay.append(np.full(len(p), k))
            cur.append(np.full(len(p), c))
    allpts = np.vstack([c.dense for c in curves])
    lat = _lattice(allpts.min(axis=0), allpts.max(axis=0), dx, offset, angle, center)
    keep = np.ones(len(lat), dtype=bool)
    for curve in curves:
        inside = curve.contains(lat)
        keep &= ~inside if curve.hole else inside
    lat = lat[keep]
    if len(lat):
        dmin = np.min([curve.distance(lat) for curve in curves], axis=0)
        lat = lat[dmin >= eps * dx]
    x.insert(0, lat)
    nrm.insert(0, np.zeros_like(lat))
    typ.insert(0, np.ones(len(lat), dtype=int))
    lay.insert(0, np.full(len(lat), -1))
    cur.insert(0, np.full(len(lat), -1))
    return Setup(np.vstack(x), np.concatenate(typ), np.vstack(nrm), np.concatenate(lay),
                 np.concatenate(cur), dx, comment)


def naive(curves, dx, layers=1, offset=(0.5, 0.5), connectivity=4, comment=""):
    """The naive set-up: lattice points inside the medium; the outermost (a
    lattice neighbour, 4- or 8-connected, outside) are the wall; normals
    from the lattice: away from the missing 8-neighbours. layers > 1 adds
    layers of lattice points outside (dilation by 4-neighbours)."""
    allpts = np.vstack([c.dense for c in curves])
    lo, hi = allpts.min(axis=0) - (layers + 2) * dx, allpts.max(axis=0) + (layers + 2) * dx
    i0 = np.floor(lo / dx - np.asarray(offset)).astype(int)
    i1 = np.ceil(hi / dx - np.asarray(offset)).astype(int)
    gi, gj = np.meshgrid(np.arange(i0[0], i1[0] + 1), np.arange(i0[1], i1[1] + 1), indexing="ij")
    p = np.column_stack([(gi.ravel() + offset[0]) * dx, (gj.ravel() + offset[1]) * dx])
    inside = np.ones(len(p), dtype=bool)
    for curve in curves:
        c = curve.contains(p)
        inside &= ~c if curve.hole else c
    inside = inside.reshape(gi.shape)

    def shifted(a, di, dj):
        out = np.zeros_like(a)
        nx, ny = a.shape
        out[max(0, -di):nx - max(0, di), max(0, -dj):ny - max(0, dj)] = \
            a[max(0, di):nx - max(0, -di), max(0, dj):ny - max(0, -dj)]
        return out
    four = [(1, 0), (-1, 0), (0, 1), (0, -1)]
    eight = four + [(1, 1), (1, -1), (-1, 1), (-1, -1)]
    nb = four if connectivity == 4 else eight
    edge = np.zeros_like(inside)
    for di, dj in nb:
        edge |= inside & ~shifted(inside, di, dj)
    layer = np.full(inside.shape, -2)
    layer[inside] = -1
    layer[edge] = 0
    occupied = inside.copy()
    for k in range(1, layers):
        grown = occupied.copy()
        for di, dj in four:
            grown |= shifted(occupied, di, dj)
        layer[grown & ~occupied] = k
        occupied = grown
    normal = np.zeros(inside.shape + (2,))
    for di, dj in eight:
        missing = ~shifted(inside, di, dj)
        normal[..., 0] -= missing * di / math.hypot(di, dj)
        normal[..., 1] -= missing * dj / math.hypot(di, dj)
    norm = np.linalg.norm(normal, axis=2)
    normal = np.where(norm[..., None] > 0, normal / np.maximum(norm, 1e-300)[..., None], 0.0)
    sel = layer.ravel() >= -1
    lay = layer.ravel()[sel]
    nrm = normal.reshape(-1, 2)[sel]
    nrm[lay < 0] = 0.0
    typ = np.where(lay < 0, 1, np.where(lay == 0, 2, 3))
    order = np.argsort(lay, kind="stable")
    return Setup(p[sel][order], typ[order], nrm[order], lay[order],
                 np.where(lay[order] < 0, -1, 0), dx, comment)


def disc(radius, dx, eps=0.42, layers=1, offset=(0.5, 0.5), center=(0.0, 0.0)):
    """Disc of the given radius about center: one ring of wall particles at r = radius (layers rings, dx apart)."""
    return setup([circle(center[0], center[1], radius)], dx, eps, layers, offset, 0.0, center,
                 comment=f"disc R={radius:g} dx={dx:g} eps={eps:g} layers={layers}")


def naive_disc(radius, dx, layers=1, offset=(0.5, 0.5), center=(0.0, 0.0), connectivity=4):
    """The naive disc: lattice points with r <= radius, the outermost tagged as wall."""
    return naive([circle(center[0], center[1], radius)], dx, layers, offset, connectivity,
                 comment=f"naive disc R={radius:g} dx={dx:g} layers={layers}")


def annulus(inner, outer, dx, eps=0.42, layers=1, offset=(0.5, 0.5), center=(0.0, 0.0), type_per_curve=False):
    """Annulus (cross-section of a hollow cylinder) inner < r < outer; curve 0 = outer wall, 1 = inner wall."""
    curves = [circle(center[0], center[1], outer), circle(center[0], center[1], inner, hole=True)]
    return setup(curves, dx, eps, layers, offset, 0.0, center, type_per_curve,
                 comment=f"annulus Ri={inner:g} Ro={outer:g} dx={dx:g} eps={eps:g} layers={layers}")


def rectangle(lx, ly, dx, eps=0.42, layers=1, offset=(0.5, 0.5), angle=0.0, center=(0.0, 0.0),
              lattice_angle=0.0):
    """Rectangle lx x ly centred on center, rotated by angle (degrees) against the lattice."""
    c, s = math.cos(math.radians(angle)), math.sin(math.radians(angle))
    v = np.array([[-lx / 2, -ly / 2], [lx / 2, -ly / 2], [lx / 2, ly / 2], [-lx / 2, ly / 2]])
    v = v @ np.array([[c, s], [-s, c]]) + np.asarray(center)
    return setup([polygon(v)], dx, eps, layers, offset, lattice_angle, center,
                 comment=f"rectangle {lx:g}x{ly:g} angle={angle:g} dx={dx:g} eps={eps:g} layers={layers}")


# ---------------------------------------------------------------- reading back

def read_data(path, section="Normals"):
    """Read a data file written by write_data: returns dict with id, type, rho, esph, cv, x (n x 3),
    normal (n x 3), mass (per type), box (3 x 2)."""
    with open(path) as f:
        lines = [ln.split("#")[0].strip() for ln in f.read().splitlines()[1:]]
    out = {"box": np.zeros((3, 2)), "mass": {}}
    i = 0
    natoms = 0
    while i < len(lines):
        w = lines[i].split()
        if len(w) == 2 and w[1] == "atoms":
            natoms = int(w[0])
        elif len(w) == 4 and w[2].endswith("lo") and w[3].endswith("hi"):
            out["box"]["xyz".index(w[2][0])] = [float(w[0]), float(w[1])]
        elif lines[i] in ("Masses", "Atoms", section):
            name = lines[i]
            i += 2
            rows = []
            while i < len(lines) and lines[i]:
                rows.append([float(t) for t in lines[i].split()])
                i += 1
            a = np.array(rows)
            if name == "Masses":
                out["mass"] = {int(r[0]): r[1] for r in a}
            elif name == "Atoms":
                a = a[np.argsort(a[:, 0])]
                out.update(id=a[:, 0].astype(int), type=a[:, 1].astype(int), rho=a[:, 2],
                           esph=a[:, 3], cv=a[:, 4], x=a[:, 5:8])
            else:
                a = a[np.argsort(a[:, 0])]
                out["normal_id"] = a[:, 0].astype(int)
                out["normal"] = a[:, 1:4]
            continue
        i += 1
    out["natoms"] = natoms
    return out


# ---------------------------------------------------------------- command line

def main(argv=None):
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("shape", choices=["disc", "annulus", "rectangle", "polygon"])
    p.add_argument("--dx", type=float, required=True, help="interior lattice spacing (= wall spacing)")
    p.add_argument("--radius", type=float, help="disc radius; annulus inner radius")
    p.add_argument("--outer-radius", type=float, help="annulus outer radius")
    p.add_argument("--lx", type=float)
    p.add_argument("--ly", type=float)
    p.add_argument("--angle", type=float, default=0.0, help="rectangle: rotation against the lattice, degrees")
    p.add_argument("--vertices", help='polygon: "x1,y1 x2,y2 ..."')
    p.add_argument("--center", default="0,0", help="x,y of the shape's centre (default 0,0)")
    p.add_argument("--eps", type=float, default=0.42, help="omit interior particles within eps*dx (0.42)")
    p.add_argument("--layers", type=int, default=1, help="wall layers, dx apart (1)")
    p.add_argument("--offset", default="0.5,0.5",
                   help="lattice offset in units of dx from the centre (default 0.5,0.5)")
    p.add_argument("--naive", action="store_true",
                   help="naive set-up: lattice points inside, outermost tagged as wall, lattice normals")
    p.add_argument("--connectivity", type=int, choices=[4, 8], default=4,
                   help="naive: outermost = a 4- (default) or 8-neighbour outside")
    p.add_argument("--type-per-curve", action="store_true", help="types 2+2c, 3+2c for curve c")
    p.add_argument("--rho", type=float, default=1.0)
    p.add_argument("--cv", type=float, default=1.0)
    p.add_argument("--T", type=float, default=1.0, help="initial temperature of the interior")
    p.add_argument("--Twall", type=float, help="wall temperature (default T)")
    p.add_argument("--section", default="Normals", help="name of the normals section (Normals)")
    p.add_argument("--outward", action="store_true", help="write normals pointing out of the medium")
    p.add_argument("-o", "--output", required=True, help="data file to write")
    a = p.parse_args(argv)

    off = tuple(float(t) for t in a.offset.split(","))
    cen = tuple(float(t) for t in a.center.split(","))
    if a.shape == "disc":
        curves = [circle(cen[0], cen[1], a.radius)]
        desc = f"disc R={a.radius:g}"
    elif a.shape == "annulus":
        curves = [circle(cen[0], cen[1], a.outer_radius), circle(cen[0], cen[1], a.radius, hole=True)]
        desc = f"annulus Ri={a.radius:g} Ro={a.outer_radius:g}"
    elif a.shape == "rectangle":
        c, s = math.cos(math.radians(a.angle)), math.sin(math.radians(a.angle))
        v = np.array([[-a.lx / 2, -a.ly / 2], [a.lx / 2, -a.ly / 2], [a.lx / 2, a.ly / 2], [-a.lx / 2, a.ly / 2]])
        curves = [polygon(v @ np.array([[c, s], [-s, c]]) + np.asarray(cen))]
        desc = f"rectangle {a.lx:g}x{a.ly:g} angle={a.angle:g}"
    else:
        v = np.array([[float(t) for t in xy.split(",")] for xy in a.vertices.split()])
        curves = [polygon(v)]
        desc = f"polygon of {len(v)} vertices"
    if a.naive:
        s = naive(curves, a.dx, a.layers, off, a.connectivity,
                  comment=f"naive {desc} dx={a.dx:g} layers={a.layers}")
    else:
        s = setup(curves, a.dx, a.eps, a.layers, off, 0.0, cen, a.type_per_curve,
                  comment=f"{desc} dx={a.dx:g} eps={a.eps:g} layers={a.layers}")
    if a.outward:
        s.normal = -s.normal
    s.write_data(a.output, a.rho, a.cv, a.T, a.Twall, a.section)
    print(f"{a.output}: {s.summary()}", file=sys.stderr)
    return 0


if __name__ == "__main__":
    sys.exit(main())
