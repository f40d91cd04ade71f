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
rectangle, and any closed polygon or parametric curve (module use), all 2-d;
and one 3-d shape, the closed cylindrical tank (below).

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

A body in a fluid (--body; disc, rectangle, polygon), with the half-spacing
convention of the Adami and mirror walls instead of Cleary's: the shape's
curve is the body's surface, halfway between the wall particles and the
fluid's; --layers wall layers (k + 1/2) dx inside it (types 2, then 3) and
--fluid-layers fluid layers (k + 1/2) dx outside it (type 1), each equally
spaced about dx along its curve; no lattice. The rest of the fluid is the
input's, e.g. LAMMPS's lattice outside fluid-layers dx from the surface,
and the file is added to it (--section none: no normals section):

    python3 tools/sph_boundary.py disc --body --radius 0.05 --center 0.2,0.2 --dx 0.005 \
        --layers 3 --fluid-layers 3 --section none -o cylinder.data
    (in LAMMPS: region rings cylinder z 0.2 0.2 0.065 INF INF units box side out,
     create_atoms 1 region ..., read_data cylinder.data add append)

as examples/open-cylinder does.

3-d: the closed cylindrical tank (cylinder), axis z through --center, fluid
in r < R, 0 < z < H, the same rules on its surfaces:

* curved wall: rings of round(2 pi r / dx) equally spaced particles on the
  circles r = R + k dx (layer k = 0 .. layers-1), in the planes z = j H/m,
  j = 1 .. m-1, m = round(H/dx) (spacing dx, stretched to fit H, as along a
  2-d curve); normals (-x/r, -y/r, 0), radial into the fluid;
* lids: the planes z = -b dx (bottom) and H + b dx (top), b = 0 .. layers-1,
  each the disc of radius R + (layers-1) dx in concentric rings (a particle
  on the axis, rings i R/n (i = 1 .. n = round(R/dx)), and the rings
  R + a dx, a = 1 .. layers-1, of the curved wall's layers, so that the
  corner is filled and every radius R + a dx is one column of rings from the
  lowest lid plane to the highest); normals (0, 0, 1) at the bottom,
  (0, 0, -1) at the top, the corner included; with --lids lattice, each lid
  plane is the interior's square lattice over that disc instead, so that
  every column of interior particles ends under a lid particle;
* rings of alternate planes turned by half their spacing (--no-stagger: not);
* interior: the simple cubic lattice ((i, j, k) + offset) dx from the axis and
  z = 0 (offset 0.5, 0.5, 0.5), without the points closer than eps dx to the
  curved wall (r > R - eps dx) or to a lid (z < eps dx or z > H - eps dx).

Types of the tank (fixed, whichever are empty; 5 declared, 6 with a split):

    1  interior (the fluid; with --split-z Z: the fluid below z = Z)
    2  curved wall, first layer (on r = R, 0 < z < H)
    3  curved wall, further layers (r = R + k dx)
    4  lids, first layer (on z = 0 and z = H, r <= R)
    5  lids, further layers (z = -b dx, H + b dx, and the corner r > R)
    6  interior with z >= Z (only with --split-z Z: a second fluid on top)

so a heated curved wall with adiabatic lids is, e.g., "group side type 2 3",
"group lids type 4 5"; the first layers (types 2 and 4) are the particles on
the surfaces, about dx^2 of surface each (a direct heat-flux estimate, compute
sph/heatflux/atom ... spacing dx, sums over them). Data file: x y z, masses
rho dx^3, normals nx ny nz, the box the particles' bounding box grown by
1.5 dx. Read it with

    dimension 3
    atom_style sph
    boundary f f f          # the box is only 1.5 dx wider than the walls
    fix normals all property/atom d_nx d_ny d_nz
    read_data tank.data fix normals NULL Normals

    python3 tools/sph_boundary.py cylinder --radius 0.0193 --height 0.0386 --dx 0.002 --layers 3 -o tank.data
    python3 tools/sph_boundary.py cylinder --radius 0.02 --height 0.04 --dx 0.002 --split-z 0.02 -o two.data

Module: setup = sph_boundary.cylinder(R, H, dx, layers=3, z_split=None);
setup.write_data("tank.data", rho=1000, cv=4180, T=300, Twall=350).
Pure Python 3 + numpy.
"""

import argparse
import math
import sys

import numpy as np

__all__ = ["Curve", "Setup", "circle", "polygon", "parametric", "setup", "disc", "annulus",
           "rectangle", "cylinder", "CYLINDER_TYPES", "naive", "naive_disc", "read_data", "main"]


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
    """A particle set: x (n x dim), type (n, int), normal (n x dim, into the
    medium, zero for interior particles), layer (n, -1 interior, 0 on the
    curve or surface, k outer layers), curve (n, index of the boundary curve or
    surface, -1 interior), and dx. dim = 2 (per unit depth) or 3; ntypes = the
    number of atom types of the data file (default: the largest type)."""

    def __init__(self, x, type_, normal, layer, curve, dx, comment="", dim=2, ntypes=None):
        self.dim = int(dim)
        self.x = np.asarray(x, dtype=float).reshape(-1, self.dim)
        self.type = np.asarray(type_, dtype=int)
        self.normal = np.asarray(normal, dtype=float).reshape(-1, self.dim)
        self.layer = np.asarray(layer, dtype=int)
        self.curve = np.asarray(curve, dtype=int)
        self.dx = float(dx)
        self.comment = comment
        self.ntypes = ntypes

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
        particles, cv*Twall for walls (fix sph/wall/isothermal sets them anyway).
        Masses rho dx^2 (per unit depth, z = 0, a box dx thick) in 2-d, rho dx^3
        in 3-d; the box is the particles' bounding box grown by margin (1.5 dx)."""
        Twall = T if Twall is None else Twall
        dx = self.dx
        margin = 1.5 * dx if margin is None else margin
        lo = self.x.min(axis=0) - margin
        hi = self.x.max(axis=0) + margin
        ntypes = int(self.type.max()) if self.ntypes is None else int(self.ntypes)
        mass = rho * dx * dx if self.dim == 2 else rho * dx * dx * dx
        esph = np.where(self.interior, cv * T, cv * Twall)
        if self.dim == 2:
            zbox = f"{-0.5 * dx:.16g} {0.5 * dx:.16g}"
            xyz = [f"{p[0]:.16g} {p[1]:.16g} 0" for p in self.x]
            nrm = [f"{n[0]:.16g} {n[1]:.16g} 0" for n in self.normal]
        else:
            zbox = f"{lo[2]:.16g} {hi[2]:.16g}"
            xyz = [f"{p[0]:.16g} {p[1]:.16g} {p[2]:.16g}" for p in self.x]
            nrm = [f"{n[0]:.16g} {n[1]:.16g} {n[2]:.16g}" for n in self.normal]
        with open(path, "w") as f:
            f.write(f"LAMMPS data file (atom_style sph) from sph_boundary.py: {self.comment}\n\n")
            f.write(f"{len(self)} atoms\n{ntypes} atom types\n\n")
            f.write(f"{lo[0]:.16g} {hi[0]:.16g} xlo xhi\n{lo[1]:.16g} {hi[1]:.16g} ylo yhi\n")
            f.write(f"{zbox} zlo zhi\n\nMasses\n\n")
            for t in range(1, ntypes + 1):
                f.write(f"{t} {mass:.16g}\n")
            f.write("\nAtoms # sph\n\n")
            for i in range(len(self)):
                f.write(f"{i + 1} {self.type[i]} {rho:.16g} {esph[i]:.16g} {cv:.16g} {xyz[i]}\n")
            if section is None or section == "none":
                return
            f.write(f"\n{section}\n\n")
            for i in range(len(self)):
                f.write(f"{i + 1} {nrm[i]}\n")

    def summary(self):
        s = [f"{len(self)} particles: {int(self.interior.sum())} interior, {int(self.wall.sum())} wall"]
        for k in range(int(self.layer.max()) + 1):
            s.append(f"wall layer {k}: {int((self.layer == k).sum())}")
        if self.dim == 3:
            ntypes = int(self.type.max()) if self.ntypes is None else int(self.ntypes)
            s.append("types " + ", ".join(f"{t}: {int((self.type == t).sum())}" for t in range(1, ntypes + 1)))
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


def body(curves, dx, layers=3, fluid_layers=3, comment=""):
    """A body in a fluid with the half-spacing convention of the Adami and
    mirror walls (the surface halfway between the wall particles and the
    fluid's, as a flat wall on the lattice): wall layer k on the curve offset
    by (k + 1/2) dx into the body (k = 0 .. layers-1), fluid layer k on it
    offset by (k + 1/2) dx into the fluid (k = 0 .. fluid_layers-1), each
    equally spaced about dx along it (a circle's ring of radius r holds
    round(2 pi r / dx) particles), so each particle stands for dx^2 of the
    body or fluid. The curves are the bodies' surfaces (the medium outside:
    hole=True). The rest of the fluid, beyond fluid_layers dx from the
    surface, is the caller's (e.g. LAMMPS's lattice outside that distance).
    Types: 1 fluid layers, 2 the first wall layer, 3 the further ones;
    normals of the wall particles point out of the body, into the fluid."""
    x, typ, nrm, lay, cur = [], [], [], [], []
    for c, curve in enumerate(curves):
        if not curve.hole:
            raise ValueError("body: the fluid lies outside the body's surface (hole=True)")
        for k in range(fluid_layers):
            p, n = curve.points(-(k + 0.5), dx)
            x.append(p)
            nrm.append(np.zeros_like(p))
            typ.append(np.ones(len(p), dtype=int))
            lay.append(np.full(len(p), -1))
            cur.append(np.full(len(p), -1))
        for k in range(layers):
            p, n = curve.points(k + 0.5, dx)
            x.append(p)
            nrm.append(n)
            typ.append(np.full(len(p), 3 if k else 2))
            lay.append(np.full(len(p), k))
            cur.append(np.full(len(p), c))
    return Setup(np.vstack(x), np.concatenate(typ), np.vstack(nrm), np.concatenate(lay),
                 np.concatenate(cur), dx, comment, ntypes=3)


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


# ---------------------------------------------------------------- 3-d: closed cylindrical tank

CYLINDER_TYPES = {1: "interior (fluid; below z_split if a split is given)",
                  2: "curved wall, first layer (on r = R)",
                  3: "curved wall, further layers (r = R + k dx)",
                  4: "lids, first layer (on z = 0 and z = H, r <= R)",
                  5: "lids, further layers (z = -k dx, H + k dx; and the corner, r > R)",
                  6: "interior above z_split (only with a split)"}


def _ring(r, n, phase, z):
    """n points equally spaced on the circle of radius r about the axis, at height z;
    their angles phase + 2 pi i / n."""
    phi = phase + 2.0 * math.pi * np.arange(n) / n
    return phi, np.column_stack([r * np.cos(phi), r * np.sin(phi), np.full(n, float(z))])


def cylinder(radius, height, dx, eps=0.42, layers=1, offset=(0.5, 0.5, 0.5), center=(0.0, 0.0),
             z_split=None, stagger=True, lids="rings", ring_multiple=1):
    """Closed cylindrical tank, axis along z through center = (cx, cy): the
    fluid fills r < radius, 0 < z < height. Cleary's rules in 3-d:

    curved wall (types 2, 3; curve 0): rings of round(2 pi r / dx) equally
      spaced particles on the circles r = radius + k dx (layer k = 0 ..
      layers - 1, type 2 for k = 0, else 3), in the planes z = j height / m,
      j = 1 .. m - 1, m = round(height / dx) (spacing dx, stretched to fit the
      height exactly, as along a 2-d curve); normals (-x/r, -y/r, 0);
    lids (types 4, 5; curve 1 = bottom, 2 = top): planes z = -b dx and
      height + b dx (b = 0 .. layers - 1), each a disc of radius
      radius + (layers - 1) dx of concentric rings: a particle on the axis,
      rings at r = i radius / n_r (i = 1 .. n_r = round(radius / dx)), and
      the rings r = radius + a dx of the curved wall's layers (a = 1 ..
      layers - 1), so that the corner is filled and the curved wall's columns
      of rings go on through it at spacing dx; normals (0, 0, 1) at the
      bottom, (0, 0, -1) at the top (all of them, the corner too); layer =
      max(b, a): type 4 for the lid surfaces themselves (b = 0, r <= radius),
      5 for the rest;
    interior (type 1, and 6 for z >= z_split if given): the simple cubic
      lattice ((i + ox) dx + cx, (j + oy) dx + cy, (k + oz) dx) with the points
      closer than eps dx to the curved wall (r > radius - eps dx) or to a lid
      (z < eps dx or z > height - eps dx) omitted.

    lids="lattice": each lid plane is instead the interior's square lattice
      (the same x, y offsets) over the disc r <= radius + (layers - 1) dx, so
      that every column of interior particles ends under a lid particle (a
      uniform body force, e.g. the buoyancy of a fluid warmer than the
      Boussinesq reference, pushes interior particles through ring lids).

    stagger: the rings of alternate planes (counted from the bottom through
    lids and curved wall alike) are turned by half their angular spacing.

    ring_multiple: each ring's count rounded to a multiple of this instead
    (4: with the interior's offsets (0.5, 0.5) the tank is the same after a
    quarter turn about its axis; with 1, the default, a ring whose count is
    not a multiple of 4 is symmetric about the plane y = 0 only).
    The data file always declares 6 atom types with a split, 5 without (types
    3 and 5 are empty with one layer)."""
    R, H, L = float(radius), float(height), int(layers)
    if R < 2 * dx or H < 2 * dx:
        raise ValueError("cylinder: radius and height must be at least 2 dx")
    if L < 1:
        raise ValueError("cylinder: layers must be at least 1")
    if z_split is not None and not 0.0 < z_split < H:
        raise ValueError("cylinder: z_split must lie between 0 and the height")
    cx, cy = float(center[0]), float(center[1])
    off = tuple(offset) + (0.5,) * (3 - len(offset))
    m = max(1, int(round(H / dx)))
    hz = H / m

    def phase(v, n):
        return math.pi / n if (stagger and v % 2) else 0.0

    x, nrm, typ, lay, cur = [], [], [], [], []

    def add(p, n, t, k, c):
        x.append(p)
        nrm.append(n)
        typ.append(np.full(len(p), t))
        lay.append(np.full(len(p), k))
        cur.append(np.full(len(p), c))

    def ring_count(r):
        q = int(ring_multiple)
        return max(3, q * int(round(2.0 * math.pi * r / dx / q)))

    # curved wall: layer k on r = R + k dx, planes j = 1 .. m - 1 (vertical index v = j)
    for k in range(L):
        r = R + k * dx
        n = ring_count(r)
        for j in range(1, m):
            phi, p = _ring(r, n, phase(j, n), j * hz)
            add(p, np.column_stack([-np.cos(phi), -np.sin(phi), np.zeros(n)]), 2 if k == 0 else 3, k, 0)

    # lids: the same rings in every plane; bottom plane b at z = -b dx (v = -b), top at H + b dx (v = m + b)
    if lids not in ("rings", "lattice"):
        raise ValueError("cylinder: lids must be 'rings' or 'lattice'")
    n_r = max(1, int(round(R / dx)))
    radii = [(0.0, 0)] + [(i * R / n_r, 0) for i in range(1, n_r + 1)] + [(R + a * dx, a) for a in range(1, L)]
    reach = R + (L - 1) * dx
    ni_lid = int(math.ceil(reach / dx)) + 1
    i_lid = np.arange(-ni_lid, ni_lid + 1)
    lx, ly = np.meshgrid((i_lid + off[0]) * dx, (i_lid + off[1]) * dx, indexing="ij")
    lx, ly = lx.ravel(), ly.ravel()
    lr = np.hypot(lx, ly)
    on_disc = lr <= reach + 1e-9 * dx
    lx, ly, lr = lx[on_disc], ly[on_disc], lr[on_disc]
    # the lattice point's layer: beyond the surface's radius, how many spacings
    lattice_layer = np.clip(np.ceil((lr - R) / dx - 1e-9), 0, L - 1).astype(int)
    for c, (z0, sign, v0) in enumerate([(0.0, -1.0, 0), (H, 1.0, m)], start=1):
        for b in range(L):
            z = z0 + sign * b * dx
            v = v0 + int(sign) * b
            if lids == "lattice":
                for a in range(L):
                    sel = lattice_layer == a
                    p = np.column_stack([lx[sel], ly[sel], np.full(sel.sum(), z)])
                    k = max(a, b)
                    add(p, np.tile([0.0, 0.0, -sign], (len(p), 1)), 4 if k == 0 else 5, k, c)
                continue
            for r, a in radii:
                if r == 0.0:
                    p = np.array([[0.0, 0.0, z]])
                else:
                    n = ring_count(r)
                    p = _ring(r, n, phase(v, n), z)[1]
                k = max(a, b)
                add(p, np.tile([0.0, 0.0, -sign], (len(p), 1)), 4 if k == 0 else 5, k, c)
    wall = np.vstack(x)
    wall[:, 0] += cx
    wall[:, 1] += cy

    # interior: simple cubic lattice, clear of the walls by eps dx
    ni = int(math.ceil(R / dx)) + 2
    nk = int(math.ceil(H / dx)) + 2
    i = np.arange(-ni, ni + 1)
    gx, gy, gz = np.meshgrid((i + off[0]) * dx, (i + off[1]) * dx, (np.arange(-1, nk) + off[2]) * dx,
                             indexing="ij")
    lat = np.column_stack([gx.ravel(), gy.ravel(), gz.ravel()])
    rr = np.hypot(lat[:, 0], lat[:, 1])
    keep = (R - rr >= eps * dx) & (lat[:, 2] >= eps * dx) & (H - lat[:, 2] >= eps * dx)
    lat = lat[keep]
    lat[:, 0] += cx
    lat[:, 1] += cy
    ltype = np.ones(len(lat), dtype=int)
    if z_split is not None:
        ltype[lat[:, 2] >= z_split] = 6

    comment = (f"cylinder R={R:g} H={H:g} dx={dx:g} eps={eps:g} layers={L}"
               + (f" split-z={z_split:g}" if z_split is not None else "")
               + "; types 1 interior" + (", 6 interior z>=split" if z_split is not None else "")
               + ", 2/3 curved wall first/further layers, 4/5 lids first/further layers")
    return Setup(np.vstack([lat, wall]), np.concatenate([ltype] + typ),
                 np.vstack([np.zeros_like(lat)] + nrm), np.concatenate([np.full(len(lat), -1)] + lay),
                 np.concatenate([np.full(len(lat), -1)] + cur), dx, comment, dim=3,
                 ntypes=6 if z_split is not None else 5)


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
    p.add_argument("shape", choices=["disc", "annulus", "rectangle", "polygon", "cylinder"])
    p.add_argument("--dx", type=float, required=True, help="interior lattice spacing (= wall spacing)")
    p.add_argument("--radius", type=float, help="disc radius; annulus inner radius; cylinder radius")
    p.add_argument("--height", type=float, help="cylinder: height (fluid 0 < z < height)")
    p.add_argument("--split-z", type=float,
                   help="cylinder: interior particles with z >= this get type 6 (two fluids)")
    p.add_argument("--no-stagger", action="store_true",
                   help="cylinder: do not turn the rings of alternate planes by half a spacing")
    p.add_argument("--lids", choices=["rings", "lattice"], default="rings",
                   help="cylinder: lids of concentric rings (default) or of the interior's square lattice")
    p.add_argument("--outer-radius", type=float, help="annulus outer radius")
    p.add_argument("--lx", type=float)
    p.add_argument("--ly", type=float)
    p.add_argument("--angle", type=float, default=0.0, help="rectangle: rotation against the lattice, degrees")
    p.add_argument("--vertices", help='polygon: "x1,y1 x2,y2 ..."')
    p.add_argument("--center", default="0,0", help="x,y of the shape's centre (cylinder: axis) (default 0,0)")
    p.add_argument("--eps", type=float, default=0.42, help="omit interior particles within eps*dx (0.42)")
    p.add_argument("--layers", type=int, default=1, help="wall layers, dx apart (1)")
    p.add_argument("--offset", default="0.5,0.5",
                   help="lattice offset in units of dx from the centre (default 0.5,0.5; "
                        "cylinder: x,y[,z], z from the bottom, default 0.5)")
    p.add_argument("--naive", action="store_true",
                   help="naive set-up: lattice points inside, outermost tagged as wall, lattice normals")
    p.add_argument("--connectivity", type=int, choices=[4, 8], default=4,
                   help="naive: outermost = a 4- (default) or 8-neighbour outside")
    p.add_argument("--type-per-curve", action="store_true", help="types 2+2c, 3+2c for curve c")
    p.add_argument("--body", action="store_true",
                   help="disc, rectangle, polygon: a body in a fluid, half-spacing convention: "
                        "--layers wall layers (k + 1/2) dx inside the surface and --fluid-layers "
                        "fluid layers (k + 1/2) dx outside it, no lattice")
    p.add_argument("--fluid-layers", type=int, default=3, help="--body: fluid layers (3)")
    p.add_argument("--rho", type=float, default=1.0)
    p.add_argument("--cv", type=float, default=1.0)
    p.add_argument("--T", type=float, default=1.0, help="initial temperature of the interior")
    p.add_argument("--Twall", type=float, help="wall temperature (default T)")
    p.add_argument("--section", default="Normals",
                   help="name of the normals section (Normals); none: no normals")
    p.add_argument("--outward", action="store_true", help="write normals pointing out of the medium")
    p.add_argument("-o", "--output", required=True, help="data file to write")
    a = p.parse_args(argv)

    off = tuple(float(t) for t in a.offset.split(","))
    cen = tuple(float(t) for t in a.center.split(","))
    if a.shape != "cylinder" and (a.height is not None or a.split_z is not None or a.no_stagger
                                  or a.lids != "rings"):
        p.error("--height, --split-z, --no-stagger and --lids are for the cylinder")
    if a.shape == "cylinder":
        if a.radius is None or a.height is None:
            p.error("cylinder needs --radius and --height")
        if a.naive or a.type_per_curve:
            p.error("cylinder: --naive and --type-per-curve are for the 2-d shapes")
        try:
            s = cylinder(a.radius, a.height, a.dx, a.eps, a.layers, off, cen, a.split_z, not a.no_stagger,
                         a.lids)
        except ValueError as e:
            p.error(str(e))
    elif a.shape == "disc":
        curves = [circle(cen[0], cen[1], a.radius, hole=a.body)]
        desc = f"disc R={a.radius:g}"
    elif a.shape == "annulus":
        curves = [circle(cen[0], cen[1], a.outer_radius), circle(cen[0], cen[1], a.radius, hole=True)]
        desc = f"annulus Ri={a.radius:g} Ro={a.outer_radius:g}"
    elif a.shape == "rectangle":
        c, s = math.cos(math.radians(a.angle)), math.sin(math.radians(a.angle))
        v = np.array([[-a.lx / 2, -a.ly / 2], [a.lx / 2, -a.ly / 2], [a.lx / 2, a.ly / 2], [-a.lx / 2, a.ly / 2]])
        curves = [polygon(v @ np.array([[c, s], [-s, c]]) + np.asarray(cen), hole=a.body)]
        desc = f"rectangle {a.lx:g}x{a.ly:g} angle={a.angle:g}"
    else:
        v = np.array([[float(t) for t in xy.split(",")] for xy in a.vertices.split()])
        curves = [polygon(v, hole=a.body)]
        desc = f"polygon of {len(v)} vertices"
    if a.body:
        if a.shape not in ("disc", "rectangle", "polygon") or a.naive or a.type_per_curve:
            p.error("--body is for a disc, rectangle or polygon, without --naive and --type-per-curve")
        s = body(curves, a.dx, a.layers, a.fluid_layers,
                 comment=f"body {desc} dx={a.dx:g} layers={a.layers} fluid-layers={a.fluid_layers}")
    elif a.shape != "cylinder":
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
