"""Steady Stokes drag on a cylinder (a disc in 2-D) translating in a closed
channel or inside a concentric circular container: the reference of the
settling example (examples/coupling-settling-channel).

The fluid is at rest on the outer walls; the cylinder of radius a moves with
velocity (0, -U) (or any rigid velocity). Creeping flow,

    -div(2 mu D(u)) + grad p = 0,   div u = 0,

solved by Taylor-Hood finite elements (continuous P2 velocity, P1 pressure)
on a Delaunay triangulation graded towards the cylinder. The drag per unit
length is the reaction: the residual of the assembled momentum equations
summed over the cylinder's velocity nodes, the consistent integral of the
traction (it converges at the order of the energy, faster than a traction
sampled on the boundary; along the motion it equals the dissipated power
2 mu int D:D dA divided by the speed, exactly). The cylinder is a polygon
through its boundary nodes (straight-sided elements): the drag converges at
second order in the mesh size, and drag_converged() Richardson-extrapolates
three meshes and states the remaining error. tools/cylinder_stokes.md lists the measured numbers.

As a module: solve(a, outer, U, mu, h0, hmax) returns the flow and the drag
per unit length (outer: Channel or Annulus); drag_converged() the
extrapolated drag and its error; faxen_drag(a, l) the published series for
an infinite channel; annulus_drag(a, b) the exact drag inside a concentric
cylinder.
As a script, see --help.
"""

import argparse
import math
import sys

import numpy as np
import scipy.sparse as sp
import scipy.sparse.linalg as spla
from scipy.spatial import Delaunay, cKDTree


def annulus_drag(a, b, mu=1.0, U=1.0):
    """Exact drag per unit length on a cylinder of radius a translating at U
    inside a fixed concentric cylinder of radius b (creeping flow):
    4 pi mu U / (ln(b/a) - (b^2 - a^2) / (b^2 + a^2))."""
    return 4.0 * math.pi * mu * U / (math.log(b / a) - (b * b - a * a) / (b * b + a * a))


def faxen_drag(a, l, mu=1.0, U=1.0):
    """Faxen's series for a cylinder of radius a moving parallel to the walls
    midway between two plane walls a distance 2 l apart (fluid at rest far
    away): 4 pi mu U / (ln(l/a) - 0.9157 + 1.7244 k^2 - 1.7302 k^4 +
    2.4056 k^6 - 4.5913 k^8), k = a / l (Faxen 1946; Happel and Brenner 1983,
    section 7-5)."""
    k = a / l
    return 4.0 * math.pi * mu * U / (math.log(l / a) - 0.9157 + 1.7244 * k**2 - 1.7302 * k**4
                                     + 2.4056 * k**6 - 4.5913 * k**8)


# --------------------------------------------------------------------------- mesh


class Channel:
    """The channel |x| < l, -below < y < above, the cylinder centred at (xc, 0)."""

    def __init__(self, l, below, above, xc=0.0):
        self.l, self.below, self.above, self.xc = float(l), float(below), float(above), float(xc)

    def distance_to_outer(self, p):
        return np.minimum.reduce([self.l - p[:, 0], self.l + p[:, 0], self.above - p[:, 1], self.below + p[:, 1]])

    def boundary_points(self, size):
        """Points along the four walls, spaced by the local mesh size."""
        pts = []
        corners = [(-self.l, -self.below), (self.l, -self.below), (self.l, self.above), (-self.l, self.above)]
        for (x0, y0), (x1, y1) in zip(corners, corners[1:] + corners[:1]):
            # uniform along each wall, at the smallest local size on it
            s = np.linspace(0.0, 1.0, 401)[:, None]
            line = np.array([x0, y0]) + s * np.array([x1 - x0, y1 - y0])
            n = int(math.ceil(math.hypot(x1 - x0, y1 - y0) / float(np.min(size(line)))))
            s = np.arange(n)[:, None] / n
            pts.append(np.array([x0, y0]) + s * np.array([x1 - x0, y1 - y0]))
        return np.vstack(pts)

    def bounding_box(self):
        return -self.l, self.l, -self.below, self.above


class Annulus:
    """The container r < b around the cylinder (centred at the origin)."""

    def __init__(self, b):
        self.b, self.xc = float(b), 0.0

    def distance_to_outer(self, p):
        return self.b - np.hypot(p[:, 0], p[:, 1])

    def boundary_points(self, size):
        n = max(12, int(round(2.0 * math.pi * self.b / float(size(np.array([[self.b, 0.0]]))[0]))))
        t = 2.0 * math.pi * np.arange(n) / n
        return np.column_stack([self.b * np.cos(t), self.b * np.sin(t)])

    def bounding_box(self):
        return -self.b, self.b, -self.b, self.b


def make_mesh(a, outer, h0, hmax, grading=0.25):
    """Vertices and triangles of the fluid region between the cylinder
    (radius a, centre (outer.xc, 0)) and the outer walls. Mesh size h0 on the
    cylinder, growing by `grading` per unit distance up to hmax. Rings of
    points around the cylinder while they fit, then a square lattice; all
    Delaunay-triangulated, triangles inside the cylinder dropped."""
    centre = np.array([outer.xc, 0.0])

    def size(p):
        r = np.hypot(p[:, 0] - centre[0], p[:, 1] - centre[1])
        return np.minimum(hmax, h0 + grading * np.maximum(r - a, 0.0))

    rings, r, k = [], a, 0
    while True:
        h = min(hmax, h0 + grading * (r - a))
        n = max(12, int(round(2.0 * math.pi * r / h)))
        t = 2.0 * math.pi * (np.arange(n) + 0.5 * (k % 2)) / n
        ring = np.column_stack([centre[0] + r * np.cos(t), r * np.sin(t)])
        if k > 0 and np.min(outer.distance_to_outer(ring)) < 1.5 * h:
            break
        rings.append(ring)
        r += h * math.sqrt(3.0) / 2.0 if k > 0 else h * 0.9
        k += 1
    ring_pts = np.vstack(rings)
    r_rings = r - h  # a little beyond the last ring's radius
    walls = outer.boundary_points(size)
    # fill: a square lattice at the far-field size, thinned where it comes
    # close to the rings or the walls (the mesh is graded only by the rings:
    # in gaps narrower than a few hmax it is coarse, see cylinder_stokes.md)
    x0, x1, y0, y1 = outer.bounding_box()
    xs = np.arange(x0, x1 + hmax, hmax)
    ys = np.arange(y0, y1 + hmax, hmax)
    X, Y = np.meshgrid(xs, ys)
    fill = np.column_stack([X.ravel(), Y.ravel()])
    fill = fill[np.hypot(fill[:, 0] - centre[0], fill[:, 1]) > r_rings + 0.5 * hmax]
    fill = fill[outer.distance_to_outer(fill) > 0.6 * size(fill)]
    tree = cKDTree(np.vstack([ring_pts, walls]))
    d, _ = tree.query(fill)
    fill = fill[d > 0.7 * size(fill)]
    pts = np.vstack([ring_pts, walls, fill])
    tri = Delaunay(pts).simplices
    cen = pts[tri].mean(axis=1)
    inside_cyl = np.hypot(cen[:, 0] - centre[0], cen[:, 1]) < a
    outside = outer.distance_to_outer(cen) < 0.0
    tri = tri[~inside_cyl & ~outside]
    # orient counter-clockwise
    p0, p1, p2 = pts[tri[:, 0]], pts[tri[:, 1]], pts[tri[:, 2]]
    area2 = (p1[:, 0] - p0[:, 0]) * (p2[:, 1] - p0[:, 1]) - (p1[:, 1] - p0[:, 1]) * (p2[:, 0] - p0[:, 0])
    flip = area2 < 0
    tri[flip] = tri[flip][:, [0, 2, 1]]
    used = np.unique(tri)
    remap = -np.ones(len(pts), dtype=int)
    remap[used] = np.arange(len(used))
    return pts[used], remap[tri]


# --------------------------------------------------------------------------- Taylor-Hood P2-P1


def p2_nodes(verts, tris):
    """P2 node coordinates and the six nodes of each triangle (three vertices,
    then the midpoints of edges 12, 23, 31)."""
    edges = np.vstack([tris[:, [0, 1]], tris[:, [1, 2]], tris[:, [2, 0]]])
    edges.sort(axis=1)
    uniq, inverse = np.unique(edges, axis=0, return_inverse=True)
    inverse = inverse.ravel()
    nt, nv = len(tris), len(verts)
    mids = nv + inverse.reshape(3, nt).T
    nodes = np.vstack([verts, 0.5 * (verts[uniq[:, 0]] + verts[uniq[:, 1]])])
    return nodes, np.hstack([tris, mids]), uniq


def assemble(verts, tris, mu):
    """The Stokes matrix [[A, B^T], [B, 0]] for unknowns (ux, uy at the P2
    nodes, p at the vertices): A from 2 mu D(u):D(v), B = -int q div v.
    Integrands are of degree 2: the edge-midpoint rule is exact."""
    nodes, elem, _ = p2_nodes(verts, tris)
    nn, nv, nt = len(nodes), len(verts), len(tris)
    P = verts[tris]  # (nt, 3, 2)
    d1 = P[:, 1] - P[:, 0]
    d2 = P[:, 2] - P[:, 0]
    det = d1[:, 0] * d2[:, 1] - d1[:, 1] * d2[:, 0]
    area = 0.5 * det
    # gradients of the barycentric coordinates, (nt, 3, 2)
    gl = np.empty((nt, 3, 2))
    gl[:, 1, 0], gl[:, 1, 1] = d2[:, 1] / det, -d2[:, 0] / det
    gl[:, 2, 0], gl[:, 2, 1] = -d1[:, 1] / det, d1[:, 0] / det
    gl[:, 0] = -gl[:, 1] - gl[:, 2]
    quad = np.array([[0.5, 0.5, 0.0], [0.0, 0.5, 0.5], [0.5, 0.0, 0.5]])
    Aloc = np.zeros((nt, 12, 12))
    Bloc = np.zeros((nt, 3, 12))
    for lam in quad:
        # gradients of the six P2 functions at this point, (nt, 6, 2)
        g = np.empty((nt, 6, 2))
        for i in range(3):
            g[:, i] = (4.0 * lam[i] - 1.0) * gl[:, i]
        for e, (i, j) in enumerate([(0, 1), (1, 2), (2, 0)]):
            g[:, 3 + e] = 4.0 * (lam[i] * gl[:, j] + lam[j] * gl[:, i])
        w = (area / 3.0)[:, None, None]
        gx, gy = g[:, :, 0], g[:, :, 1]
        xx = np.einsum("ti,tj->tij", gx, gx)
        yy = np.einsum("ti,tj->tij", gy, gy)
        xy = np.einsum("ti,tj->tij", gx, gy)
        # 2 D(u):D(v) = 2 ux,x vx,x + 2 uy,y vy,y + (ux,y + uy,x)(vx,y + vy,x)
        Aloc[:, :6, :6] += w * mu * (2.0 * xx + yy)
        Aloc[:, 6:, 6:] += w * mu * (2.0 * yy + xx)
        Aloc[:, :6, 6:] += w * mu * xy.transpose(0, 2, 1)
        Aloc[:, 6:, :6] += w * mu * xy
        # pressure test functions: the barycentric coordinates themselves
        q = np.broadcast_to(lam, (nt, 3))
        Bloc[:, :, :6] -= w * np.einsum("ti,tj->tij", q, gx)
        Bloc[:, :, 6:] -= w * np.einsum("ti,tj->tij", q, gy)
    vdof = np.hstack([elem, elem + nn])  # (nt, 12)
    pdof = 2 * nn + tris  # (nt, 3)
    rows = [np.repeat(vdof, 12, axis=1).ravel(), np.repeat(pdof, 12, axis=1).ravel(),
            np.tile(vdof, (1, 3)).ravel()]
    cols = [np.tile(vdof, (1, 12)).ravel(), np.tile(vdof, (1, 3)).ravel(),
            np.repeat(pdof, 12, axis=1).ravel()]
    vals = [Aloc.ravel(), Bloc.ravel(), Bloc.ravel()]  # B^T: the same entries, rows and columns swapped
    n = 2 * nn + nv
    K = sp.coo_matrix((np.concatenate(vals), (np.concatenate(rows), np.concatenate(cols))), shape=(n, n)).tocsr()
    return K, nodes, elem


def solve(a, outer, U=(0.0, -1.0), mu=1.0, h0=None, hmax=None, grading=0.25):
    """Creeping flow around the cylinder moving at velocity U (fluid at rest
    on the outer walls). Returns a dict: drag (force of the fluid on the
    cylinder per unit length, a 2-vector), nodes, velocity, vertices,
    triangles, pressure."""
    h0 = h0 if h0 is not None else a / 8.0
    hmax = hmax if hmax is not None else 4.0 * h0
    verts, tris = make_mesh(a, outer, h0, hmax, grading)
    K, nodes, elem = assemble(verts, tris, mu)
    nn, nv = len(nodes), len(verts)
    rc = np.hypot(nodes[:, 0] - outer.xc, nodes[:, 1])
    # boundary nodes: on edges used by one triangle only
    edges = np.vstack([elem[:, [0, 3, 1]], elem[:, [1, 4, 2]], elem[:, [2, 5, 0]]])
    key = np.sort(edges[:, [0, 2]], axis=1)
    _, idx, counts = np.unique(key, axis=0, return_index=True, return_counts=True)
    bnodes = np.unique(edges[idx[counts == 1]].ravel())
    on_cylinder = bnodes[rc[bnodes] < 0.5 * (a + a + h0)]
    on_outer = np.setdiff1d(bnodes, on_cylinder)
    x = np.zeros(2 * nn + nv)
    x[on_cylinder] = U[0]
    x[nn + on_cylinder] = U[1]
    fixed = np.concatenate([on_cylinder, on_outer, nn + on_cylinder, nn + on_outer, [2 * nn]])
    free = np.setdiff1d(np.arange(2 * nn + nv), fixed)
    rhs = -K[free][:, fixed] @ x[fixed]
    x[free] = spla.spsolve(K[free][:, free].tocsc(), rhs)
    residual = K @ x  # the force the boundary exerts on the fluid at each node
    force_on_fluid = np.array([residual[on_cylinder].sum(), residual[nn + on_cylinder].sum()])
    u = np.column_stack([x[:nn], x[nn:2 * nn]])
    return {"drag": -force_on_fluid, "nodes": nodes, "velocity": u,
            "vertices": verts, "triangles": tris, "pressure": x[2 * nn:], "h0": h0, "hmax": hmax,
            "elements": len(tris), "dofs": len(free)}


def drag_converged(a, outer, h0, hmax, mu=1.0, levels=3, grading=0.25):
    """Drag along the motion (speed 1) on `levels` meshes, each with the sizes
    halved, and the Richardson extrapolation of the last two at the order
    observed on the three finest (2 with fewer levels). Returns (list of
    (h0, drag, elements), the extrapolated drag, its error estimate (a
    third of the extrapolation's correction: the correction itself is the
    finest mesh's error estimate, and extrapolation removes the leading
    term), the order)."""
    rows = []
    for j in range(levels):
        res = solve(a, outer, (0.0, -1.0), mu, h0 / 2**j, hmax / 2**j, grading)
        rows.append((h0 / 2**j, float(res["drag"][1]), res["elements"]))
    f = [r[1] for r in rows]
    order = 2.0
    if levels >= 3 and (f[-2] - f[-3]) * (f[-1] - f[-2]) > 0:
        order = math.log2((f[-2] - f[-3]) / (f[-1] - f[-2]))
    if not 1.5 <= order <= 3.0:
        # not yet in the asymptotic range (an erratic coarse mesh): no
        # extrapolation, and the last correction as the error
        return rows, f[-1], abs(f[-1] - f[-2]), order
    best = f[-1] + (f[-1] - f[-2]) / (2.0**order - 1.0)
    return rows, best, abs(best - f[-1]) / 3.0, order


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--a", type=float, default=1.0, help="cylinder radius")
    ap.add_argument("--l", type=float, help="channel half-width (a channel)")
    ap.add_argument("--below", type=float, help="distance from the centre to the bottom")
    ap.add_argument("--above", type=float, help="distance from the centre to the top")
    ap.add_argument("--xc", type=float, default=0.0, help="offset of the centre from the channel's middle")
    ap.add_argument("--b", type=float, help="radius of a concentric container (instead of a channel)")
    ap.add_argument("--h0", type=float, help="mesh size on the cylinder (default a/8)")
    ap.add_argument("--hmax", type=float, help="largest mesh size (default 4 h0)")
    ap.add_argument("--levels", type=int, default=3, help="meshes, each halving the sizes")
    args = ap.parse_args(argv)
    if (args.l is None) == (args.b is None):
        ap.error("give either --l (a channel) or --b (a concentric container)")
    a = args.a
    h0 = args.h0 or a / 8.0
    hmax = args.hmax or 4.0 * h0
    if args.b:
        outer = Annulus(args.b)
        exact = annulus_drag(a, args.b)
        label = f"annulus b/a = {args.b / a:g}, exact {exact:.8g}"
    else:
        outer = Channel(args.l, args.below or 4 * args.l, args.above or 4 * args.l, args.xc)
        exact = faxen_drag(a, args.l) if args.xc == 0 else None
        label = f"channel l/a = {args.l / a:g}, ends at -{outer.below:g}, +{outer.above:g}"
        if exact:
            label += f"; Faxen (infinite channel) {exact:.8g}"
        if min(outer.below, outer.above) < 2.0 * args.l:
            label += " (ends closer than 2 l: not comparable)"
            exact = None
    rows, best, err, order = drag_converged(a, outer, h0, hmax, levels=args.levels)
    print(f"# drag / (mu U) per unit length, {label}")
    print("# h0         elements  drag")
    for h, f, ne in rows:
        print(f"{h:<12.5g} {ne:<9d} {f:.10g}")
    print(f"extrapolated {best:.8g} +- {err:.2g} (order {order:.2f})")
    if exact:
        print(f"relative to that value: {best / exact - 1:+.3e}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
