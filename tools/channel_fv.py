#!/usr/bin/env python3
"""Finite-volume reference for laminar channel flow with conjugate heat transfer.

Steady, 2-D, hydrodynamically fully developed flow in a stack of horizontal
layers between y = y0 and y = y_top, for 0 <= x <= L (the cases of
Ng, Ng, Sheu & Mukhtar (2020), Fluid-solid conjugate heat transfer modelling
using weakly compressible smoothed particle hydrodynamics, sections 4.3 to
4.5). Each layer is either

  fluid: plane Poiseuille flow u(y) = s 4 u_max (y - a)(b - y) / W^2 between
         its faces a and b = a + W (s = +1 towards +x, -1 towards -x),
         conductivity k, volumetric heat capacity rho cp; T = T_in at the
         inlet end (x = 0 for s = +1, x = L for s = -1), dT/dx = 0 at the
         outlet end;
  solid: u = 0, conductivity k, dT/dx = 0 at x = 0 and x = L.

The bottom and top boundaries are each isothermal (given T) or adiabatic.
The temperature obeys, in every layer,

    rho cp u dT/dx = d/dx (k dT/dx) + d/dy (k dT/dy)

(axial conduction included), with T and the normal heat flux continuous
across the layer interfaces.

Method: cell-centred finite volumes, nx uniform cells in x, uniform cells in
y inside each layer with a face on every interface (cells per layer in
proportion to its height, ny across the first fluid layer, unless given).
Diffusive fluxes are two-point; between cells of different conductivity the
face conductance is the series (harmonic) one, d1/(2 k1) + d2/(2 k2), which
holds T and flux continuous. The isothermal walls and the inlet are held at
half a cell from the centre (second order). The convective flux through an
x face uses the exact cell mean of u(y) (so the discrete flow rate is the
exact one) and either central interpolation (scheme "central", second order;
it needs a cell Peclet number u dx / alpha below 2, which solve() checks and
warns about) or exponential fitting (scheme "exponential", Scharfetter-
Gummel/Il'in-Allen-Southwell: monotone at any cell Peclet number, second
order as dx -> 0, first order upwind for cell Peclet numbers >> 2). The
outlet face carries the upwind (outlet cell) value and no conduction. The
problem is linear: one sparse direct solve (scipy.sparse.linalg.spsolve).
The scheme is conservative: the heat entering through the outer walls
equals the enthalpy gained by the streams plus the heat conducted back out
through their inlet faces, to round-off.

Accuracy: second order in dx and dy where the solution is smooth (observed
order 2.0 by Richardson extrapolation over three grids in the heated
channel). Where a fluid inlet meets the adiabatic end of a solid layer the
temperature is singular, T ~ r^a with tan^2(a pi/2) = k_fluid / k_solid
(a = 1/2 for k_s = k, 0.27 for k_s = 5 k), and the error away from such a
corner falls only like h^(2a); channel_fv.md lists the measured error of the
recommended grids for every case. The fully developed Nusselt number of
isothermal plates comes out 3e-4 below Shah & London (1978), Laminar Flow
Forced Convection in Ducts (Adv. Heat Transfer, Suppl. 1, Academic Press),
Nu = 7.5407 (D_h = 2 W, Pe -> infinity), with 40 cells across, 7e-5 with 80,
and 7.54070 extrapolated; nu_fully_developed() solves the fully developed
eigenproblem with axial conduction (Nu -> pi^4/12 = 8.1174 as Pe -> 0) as an
independent check.

Outputs: T at the cell centres, the bulk (mixing-cup) temperature of each
stream along x, the heat flux, wall temperature and local Nusselt number
Nu = q'' D_h / (k (T_wall - T_bulk)) (D_h = 2 W, q'' into the fluid) on each
face of each fluid layer, the energy balance, profiles across all layers at
given x, and for the heat exchanger the effectiveness with an
effectiveness-NTU comparison.

As a module: preset(case, ...) -> Problem, solve(problem, nx, ny) -> dict,
profile_at(result, x, y=None), bulk_at(result, fluid, x), nu_at(result, x),
richardson(problem, nx, ny), exchanger_summary(result), graetz_summary(result),
nu_fully_developed(pe), effectiveness(ntu, cr, arrangement), to_json(result).
As a script, see --help and channel_fv.md.
"""

import argparse
import json
import math
import sys
import time
from dataclasses import dataclass, field, replace

import numpy as np
import scipy.sparse as sp
import scipy.sparse.linalg as spla

# Shah & London (1978): parallel plates, D_h = 2 W
NU_T = 7.5407                 # both walls isothermal, no axial conduction
NU_T_PE0 = math.pi ** 4 / 12  # both walls isothermal, Pe -> 0 (8.1174)
NU_T_ONE_SIDED = 4.8608       # one wall isothermal, the other adiabatic

STATION_FRACTIONS = (0.025, 0.25, 0.5, 0.75, 0.975)   # x = 5, 50, 100, 150, 195 m for L = 200 m


# ------------------------------------------------------------------ problem

@dataclass
class Layer:
    """One horizontal layer. kind "fluid" or "solid"; height in m; k in
    W/(m K); rho_cp in J/(m^3 K) (only fluids use it); u_max in m/s and
    direction +1/-1 (fluids); t_in the inlet temperature (fluids); cells
    across the layer (None: set by solve() from its ny)."""
    kind: str
    height: float
    k: float
    rho_cp: float = 0.0
    u_max: float = 0.0
    direction: int = 1
    t_in: float = None
    name: str = ""
    cells: int = None


@dataclass
class Problem:
    """A stack of layers from y0 upwards over 0 <= x <= length. t_bottom,
    t_top: wall temperatures, None for adiabatic. delta_t: temperature scale
    of the error report; stations: x of the profiles; nx, ny, scheme: the
    default grid (ny = cells across the first fluid layer)."""
    name: str
    layers: list
    length: float
    y0: float = 0.0
    t_bottom: float = None
    t_top: float = None
    delta_t: float = 1.0
    stations: tuple = ()
    nx: int = 1280
    ny: int = 80
    scheme: str = "central"
    info: dict = field(default_factory=dict)


def preset(case, re=None, ks_ratio=1.0, counter=False, pe=1e4, length_over_w=None, adiabatic_top=False):
    """The problems of the SPH comparisons (SI units), from Ng, Ng, Sheu &
    Mukhtar (2020):

    heated      section 4.3: one channel W = 20 m, L = 200 m, rho = 1,
                mu = 0.248, k = 131914.89, cp = 1e5, u_max = Re mu / (rho W) = 8.0848 m/s at
                re = 652, T_in = 300 K, both
                walls at 420 K.
    thick-wall  section 4.4: solid 10 m / fluid 20 m / solid 10 m, fluid as
                above, k_s = ks_ratio k, outer faces (y = -10, 30) at 420 K.
    exchanger   section 4.5: cold fluid 0.1 m / solid 0.1 m / hot fluid
                0.1 m, L = 2 m; fluid rho = 1000, mu = 0.15, k = 10, cp = 25;
                solid rho = 8000, k = 50, cp = 500; u_max = f W^2 / (8 nu)
                with f = 0.024 (hot, T_in = 800 K, +x) and 0.012 (cold,
                T_in = 300 K, +x; -x if counter); outer walls adiabatic.
    graetz      check: one channel in units W = k = rho cp = 1, T_in = 0,
                walls at T = 1 (the top adiabatic if adiabatic_top), Peclet
                number pe = u_mean D_h / alpha (D_h = 2 W), length
                length_over_w (default max(20, 0.15 pe): x / (D_h Pe) up to
                0.075, the flow is thermally developed from about 0.03; with
                the top adiabatic max(20, 0.6 pe), developed from about 0.15).
    """
    if case in ("heated", "thick-wall"):
        re = 652.0 if re is None else float(re)
        rho, mu, k, cp, w = 1.0, 0.248, 131914.89, 1.0e5, 20.0
        u_max = re * mu / (rho * w)    # 8.0848 m/s at Re = 652 (the paper rounds it to 8.08)
        fluid = Layer("fluid", w, k, rho * cp, u_max, +1, 300.0, "fluid")
        info = {"re": re, "re_from_u_max": rho * u_max * w / mu, "pr": mu * cp / k,
                "pe": (2.0 / 3.0) * u_max * 2 * w / (k / (rho * cp)), "mu": mu, "rho": rho, "cp": cp}
        if case == "heated":
            layers, y0 = [fluid], 0.0
        else:
            solid = dict(kind="solid", height=10.0, k=ks_ratio * k, rho_cp=rho * cp)
            layers = [Layer(name="solid bottom", **solid), fluid, Layer(name="solid top", **solid)]
            y0 = -10.0
            info["ks_ratio"] = float(ks_ratio)
        return Problem(case, layers, 200.0, y0, 420.0, 420.0, 120.0,
                       tuple(f * 200.0 for f in STATION_FRACTIONS), 1280, 80, "central", info)
    if case == "exchanger":
        rho, mu, k, cp, w = 1000.0, 0.15, 10.0, 25.0, 0.1
        nu = mu / rho
        u_hot = 0.024 * w * w / (8 * nu)
        u_cold = 0.012 * w * w / (8 * nu)
        alpha = k / (rho * cp)
        cold = Layer("fluid", w, k, rho * cp, u_cold, -1 if counter else +1, 300.0, "cold")
        plate = Layer("solid", w, 50.0, 8000.0 * 500.0, name="plate")
        hot = Layer("fluid", w, k, rho * cp, u_hot, +1, 800.0, "hot")
        info = {"arrangement": "counter" if counter else "parallel",
                "re_hot": u_hot * w / nu, "re_cold": u_cold * w / nu,
                "pe_hot": (2.0 / 3.0) * u_hot * 2 * w / alpha, "pe_cold": (2.0 / 3.0) * u_cold * 2 * w / alpha,
                "f_hot": 0.024, "f_cold": -0.012 if counter else 0.012}
        return Problem("exchanger", [cold, plate, hot], 2.0, 0.0, None, None, 500.0,
                       tuple(f * 2.0 for f in STATION_FRACTIONS), 1280, 40, "central", info)
    if case == "graetz":
        pe = float(pe)
        lw = max(20.0, (0.6 if adiabatic_top else 0.15) * pe) if length_over_w is None else float(length_over_w)
        u_max = 0.75 * pe                     # u_mean = pe alpha / D_h = pe / 2
        fluid = Layer("fluid", 1.0, 1.0, 1.0, u_max, +1, 0.0, "fluid")
        info = {"pe": pe, "length_over_w": lw, "x_plus_end": lw / (2.0 * pe),
                "adiabatic_top": bool(adiabatic_top)}
        return Problem("graetz", [fluid], lw, 0.0, 1.0, None if adiabatic_top else 1.0, 1.0,
                       tuple(f * lw for f in STATION_FRACTIONS), 400, 40, "exponential", info)
    raise ValueError(f"unknown case {case!r}")


# --------------------------------------------------------------- discretisation

def _bernoulli(z):
    """B(z) = z / (exp(z) - 1), B(0) = 1."""
    z = np.asarray(z, dtype=float)
    out = np.ones_like(z)
    big = np.abs(z) > 1e-8
    pos, neg = big & (z > 0), big & (z < 0)
    out[pos] = z[pos] * np.exp(-z[pos]) / -np.expm1(-z[pos])
    out[neg] = z[neg] / np.expm1(z[neg])
    out[~big] = 1.0 - 0.5 * z[~big]
    return out


def _face(F, D, scheme):
    """Coefficients (a, b) of the flux towards +x, a T_left - b T_right,
    through a face between two centres with mass-heat flux F = rho cp u dy
    and conductance D = k dy / h; a - b = F always (conservation)."""
    if scheme == "central":
        return D + 0.5 * F, D - 0.5 * F
    pe = F / D
    return D * _bernoulli(-pe), D * _bernoulli(pe)


def _dirichlet_face(F, D0, scheme, side):
    """(a, b) of the inlet face, flux towards +x = a T_left - b T_right, where
    one of the two points is the inlet value on the face (side "left": x = 0,
    "right": x = L) and D0 = k dy / (dx/2). central: the convected value is
    the inlet value itself."""
    if scheme == "central":
        return (D0 + F, D0) if side == "left" else (D0, D0 - F)
    return _face(F, D0, scheme)


def _cell_mean_u(layer, a, lo, hi):
    """Mean of the Poiseuille profile of `layer` (faces a, a + W) over [lo, hi]."""
    if layer.kind != "fluid":
        return np.zeros_like(lo)
    w = layer.height
    t1, t2 = (lo - a) / w, (hi - a) / w
    prim = lambda t: t * t / 2.0 - t ** 3 / 3.0  # noqa: E731
    return layer.direction * 4.0 * layer.u_max * (prim(t2) - prim(t1)) / (t2 - t1)


def layer_cells(problem, ny):
    """Cells across each layer: the layer's own count, or its height over
    the spacing of ny cells across the first fluid layer (at least 1)."""
    ref = next((l.height for l in problem.layers if l.kind == "fluid"), problem.layers[0].height)
    dy = ref / ny
    return [l.cells if l.cells else max(1, int(round(l.height / dy))) for l in problem.layers]


def solve(problem, nx=None, ny=None, scheme=None, cells=None):
    """Steady temperature of `problem` on nx cells in x and `cells` (list per
    layer; default layer_cells(problem, ny)) in y. Returns a dict (arrays are
    numpy arrays; to_json() makes lists):

      case, scheme, nx, cells, length, y0, y_top, delta_t, stations, info,
      runtime (s), cell_pe_max (largest u dx / alpha), warnings (list)
      x, y            cell centres (nx), (NY = sum(cells))
      x_faces, y_faces
      T               (nx, NY) cell-centre temperatures, indexed [i_x, j_y]
      u               (NY) cell-mean velocity of each row
      layers          [{kind, name, y0, y1, k, rho_cp, u_max, direction,
                        t_in, j0, j1 (rows j0 <= j < j1)}]
      fluids          per fluid layer: {name, layer, direction, t_in, x (x with
                      the inlet and outlet faces, nx + 2), t_bulk (mixing cup
                      there), t_out (mixing cup leaving), capacity
                      (rho cp int |u| dy, W/(m K)), enthalpy_rise
                      (capacity (t_out - t_in), W/m), inlet_conduction (heat
                      conducted back out through the inlet face, W/m), heat_gain
                      (their sum: net heat taken up by the stream, W/m),
                      pe (u_mean D_h / alpha), u_max, height, k}
      walls           per face of each fluid layer: {fluid (index into fluids),
                      layer, side ("bottom"/"top"), y, kind ("isothermal",
                      "adiabatic", "solid", "fluid"), x (nx centres), t_wall,
                      q (heat flux into the fluid, W/m^2), nu (local Nusselt
                      number, D_h = 2 W), dh, heat (int q dx, W/m)}
      balance         {boundaries (heat in through the outer walls, W/m),
                      streams (sum of heat_gain), residual, relative}
      profile         {x (nx + 2: 0, centres, L), y (walls, interfaces and
                      centres), T} for profile_at
      nodes           {x (nx + 1), y (NY + 1), T}: T at the cell corners
    """
    t0 = time.time()
    nx = problem.nx if nx is None else int(nx)
    scheme = problem.scheme if scheme is None else scheme
    if scheme not in ("central", "exponential"):
        raise ValueError("scheme must be 'central' or 'exponential'")
    if cells is None:
        cells = layer_cells(problem, problem.ny if ny is None else ny)
    cells = [int(c) for c in cells]
    layers, L = problem.layers, float(problem.length)
    if len(cells) != len(layers) or min(cells) < 1 or nx < 2:
        raise ValueError("need at least 2 cells in x and 1 per layer")
    for l in layers:
        if l.kind == "fluid" and l.t_in is None:
            raise ValueError(f"fluid layer {l.name!r} has no inlet temperature")

    # ---- grid
    dx = L / nx
    xf = np.linspace(0.0, L, nx + 1)
    xc = 0.5 * (xf[:-1] + xf[1:])
    yf_parts, bounds, lay_rows = [np.array([problem.y0])], [], []
    y = problem.y0
    for m, (l, n) in enumerate(zip(layers, cells)):
        yf_parts.append(y + l.height * np.arange(1, n + 1) / n)
        bounds.append((y, y + l.height))
        y += l.height
        lay_rows += [m] * n
    yf = np.concatenate(yf_parts)
    for m, (lo, hi) in enumerate(bounds):              # exact interface positions
        yf[sum(cells[:m])] = lo
        yf[sum(cells[:m + 1])] = hi
    yc = 0.5 * (yf[:-1] + yf[1:])
    dy = np.diff(yf)
    NY = len(yc)
    lay_rows = np.array(lay_rows)
    k = np.array([layers[m].k for m in lay_rows])
    rc = np.array([layers[m].rho_cp if layers[m].kind == "fluid" else 0.0 for m in lay_rows])
    u = np.zeros(NY)
    for m, l in enumerate(layers):
        rows = lay_rows == m
        u[rows] = _cell_mean_u(l, bounds[m][0], yf[:-1][rows], yf[1:][rows])
    F = rc * u * dy                     # W/(m K), towards +x
    D = k * dy / dx
    D0 = 2.0 * D
    with np.errstate(divide="ignore", invalid="ignore"):
        cell_pe = np.where(k > 0, np.abs(F) / D, 0.0)
    cell_pe_max = float(cell_pe.max())
    warnings = []
    if scheme == "central" and cell_pe_max > 2.0:
        warnings.append(f"cell Peclet number {cell_pe_max:.3g} > 2 with central convection "
                        f"(nx >= {int(math.ceil(nx * cell_pe_max / 2.0))} keeps it below 2; "
                        f"or use the exponential scheme)")

    is_fluid = np.array([layers[m].kind == "fluid" for m in lay_rows])
    direction = np.array([layers[m].direction if layers[m].kind == "fluid" else 0 for m in lay_rows])
    t_in = np.array([layers[m].t_in if layers[m].kind == "fluid" else np.nan for m in lay_rows], dtype=float)
    inlet_left = is_fluid & (direction > 0)
    inlet_right = is_fluid & (direction < 0)

    # ---- matrix: sum of the fluxes out of each cell = 0
    N = nx * NY
    idx = np.arange(N).reshape(nx, NY)
    diag = np.zeros((nx, NY))
    rhs = np.zeros((nx, NY))
    r_list, c_list, v_list = [], [], []

    def off(rows, cols, vals):
        r_list.append(rows.ravel())
        c_list.append(cols.ravel())
        v_list.append(np.broadcast_to(vals, rows.shape).ravel())

    # interior x faces
    a, b = _face(F, D, scheme)
    diag[:-1, :] += a
    diag[1:, :] += b
    off(idx[:-1, :], idx[1:, :], -b)
    off(idx[1:, :], idx[:-1, :], -a)
    # x = 0: inlet rows (direction +1), outlet rows (direction -1); solids adiabatic
    aL, bL = _dirichlet_face(F, D0, scheme, "left")
    aR, bR = _dirichlet_face(F, D0, scheme, "right")
    diag[0, inlet_left] += bL[inlet_left]
    rhs[0, inlet_left] += aL[inlet_left] * t_in[inlet_left]
    diag[0, inlet_right] += -F[inlet_right]
    # x = L
    diag[-1, inlet_left] += F[inlet_left]
    diag[-1, inlet_right] += aR[inlet_right]
    rhs[-1, inlet_right] += bR[inlet_right] * t_in[inlet_right]
    # interior y faces: series conductance
    g_half = k / (0.5 * dy)                                   # per unit length of face
    G = dx / (1.0 / g_half[:-1] + 1.0 / g_half[1:])           # (NY - 1)
    diag[:, :-1] += G
    diag[:, 1:] += G
    off(idx[:, :-1], idx[:, 1:], -G)
    off(idx[:, 1:], idx[:, :-1], -G)
    Gb, Gt = dx * g_half[0], dx * g_half[-1]
    if problem.t_bottom is not None:
        diag[:, 0] += Gb
        rhs[:, 0] += Gb * problem.t_bottom
    if problem.t_top is not None:
        diag[:, -1] += Gt
        rhs[:, -1] += Gt * problem.t_top
    rows = np.concatenate([idx.ravel()] + r_list)
    cols = np.concatenate([idx.ravel()] + c_list)
    vals = np.concatenate([diag.ravel()] + v_list)
    A = sp.csc_matrix((vals, (rows, cols)), shape=(N, N))
    Tv = spla.spsolve(A, rhs.ravel(), permc_spec="MMD_AT_PLUS_A")
    T = Tv.reshape(nx, NY)

    # ---- values on the faces
    x_left = np.where(inlet_left, t_in, T[0])                 # T on x = 0 (inlet or zero gradient)
    x_right = np.where(inlet_right, t_in, T[-1])

    def y_faces(cols_T):
        """(m, NY) cell values -> (m, NY + 1) values on the y faces."""
        out = np.empty((cols_T.shape[0], NY + 1))
        out[:, 1:-1] = (g_half[:-1] * cols_T[:, :-1] + g_half[1:] * cols_T[:, 1:]) / (g_half[:-1] + g_half[1:])
        out[:, 0] = cols_T[:, 0] if problem.t_bottom is None else problem.t_bottom
        out[:, -1] = cols_T[:, -1] if problem.t_top is None else problem.t_top
        return out

    Tx_pad = np.vstack([x_left, T, x_right])                  # (nx + 2, NY)
    Tyf_pad = y_faces(Tx_pad)                                 # (nx + 2, NY + 1)
    iface = np.concatenate(([0], np.cumsum(cells)))           # face index of each layer boundary
    prof_y, prof_cols = [], []
    for m in range(len(layers)):
        prof_y.append([yf[iface[m]]])
        prof_cols.append(Tyf_pad[:, [iface[m]]])
        prof_y.append(yc[iface[m]:iface[m + 1]])
        prof_cols.append(Tx_pad[:, iface[m]:iface[m + 1]])
    prof_y.append([yf[-1]])
    prof_cols.append(Tyf_pad[:, [-1]])
    profile = {"x": np.concatenate(([0.0], xc, [L])), "y": np.concatenate(prof_y),
               "T": np.hstack(prof_cols)}
    Txf = np.vstack([x_left, 0.5 * (T[:-1] + T[1:]), x_right])   # (nx + 1, NY)
    nodes = {"x": xf.copy(), "y": yf.copy(), "T": y_faces(Txf)}

    # ---- streams
    fluids, fluid_of_layer = [], {}
    for m, l in enumerate(layers):
        if l.kind != "fluid":
            continue
        js = np.arange(iface[m], iface[m + 1])
        Fj = np.abs(F[js])
        cap = float(Fj.sum())
        tb = (T[:, js] @ Fj) / cap
        if l.direction > 0:
            inflow = float(np.sum(aL[js] * l.t_in - bL[js] * T[0, js]))
            t_out = float(tb[-1])
            tb_pad = np.concatenate(([l.t_in], tb, [t_out]))
        else:
            inflow = float(np.sum(-(aR[js] * T[-1, js] - bR[js] * l.t_in)))
            t_out = float(tb[0])
            tb_pad = np.concatenate(([t_out], tb, [l.t_in]))
        alpha = l.k / l.rho_cp
        fluid_of_layer[m] = len(fluids)
        fluids.append({
            "name": l.name, "layer": m, "direction": int(l.direction), "t_in": float(l.t_in),
            "x": profile["x"].copy(), "t_bulk": tb_pad, "t_out": t_out, "capacity": cap,
            "enthalpy_rise": cap * (t_out - l.t_in), "inlet_conduction": cap * l.t_in - inflow,
            "heat_gain": cap * t_out - inflow,
            "pe": (2.0 / 3.0) * l.u_max * 2.0 * l.height / alpha, "u_max": float(l.u_max),
            "height": float(l.height), "k": float(l.k)})

    # ---- walls of the fluid layers
    walls = []
    for m, fi in fluid_of_layer.items():
        l, fl = layers[m], fluids[fi]
        tb = fl["t_bulk"][1:-1]
        for side in ("bottom", "top"):
            if side == "bottom":
                j, f, jn = iface[m], iface[m], iface[m] - 1
                t_bound, g_b = problem.t_bottom, Gb
            else:
                j, f, jn = iface[m + 1] - 1, iface[m + 1], iface[m + 1]
                t_bound, g_b = problem.t_top, Gt
            if 0 <= jn < NY:
                q = G[min(j, jn)] * (T[:, jn] - T[:, j]) / dx
                kind = layers[lay_rows[jn]].kind
            elif t_bound is not None:
                q = g_b * (t_bound - T[:, j]) / dx
                kind = "isothermal"
            else:
                q = np.zeros(nx)
                kind = "adiabatic"
            t_wall = Tyf_pad[1:-1, f]
            dh = 2.0 * l.height
            with np.errstate(divide="ignore", invalid="ignore"):
                nu = np.where(q != 0.0, q * dh / (l.k * (t_wall - tb)), 0.0)
            walls.append({"fluid": fi, "layer": m, "side": side, "y": float(yf[f]), "kind": kind,
                          "x": xc.copy(), "t_wall": t_wall.copy(), "q": q, "nu": nu, "dh": dh,
                          "heat": float(np.sum(q) * dx)})

    q_bound = 0.0
    if problem.t_bottom is not None:
        q_bound += float(np.sum(Gb * (problem.t_bottom - T[:, 0])))
    if problem.t_top is not None:
        q_bound += float(np.sum(Gt * (problem.t_top - T[:, -1])))
    streams = float(sum(f["heat_gain"] for f in fluids))
    scale = max(abs(q_bound), sum(abs(f["heat_gain"]) for f in fluids), 1e-300)
    balance = {"boundaries": q_bound, "streams": streams, "residual": q_bound - streams,
               "relative": (q_bound - streams) / scale}

    layer_info = [{"kind": l.kind, "name": l.name, "y0": bounds[m][0], "y1": bounds[m][1], "k": l.k,
                   "rho_cp": l.rho_cp, "u_max": l.u_max if l.kind == "fluid" else 0.0,
                   "direction": l.direction if l.kind == "fluid" else 0,
                   "t_in": l.t_in if l.kind == "fluid" else None,
                   "j0": int(iface[m]), "j1": int(iface[m + 1])} for m, l in enumerate(layers)]
    return {"case": problem.name, "scheme": scheme, "nx": nx, "cells": cells, "length": L,
            "y0": float(problem.y0), "y_top": float(yf[-1]), "t_bottom": problem.t_bottom,
            "t_top": problem.t_top, "delta_t": problem.delta_t, "stations": list(problem.stations),
            "info": dict(problem.info), "cell_pe_max": cell_pe_max, "warnings": warnings,
            "x": xc, "y": yc, "x_faces": xf, "y_faces": yf, "T": T, "u": u, "layers": layer_info,
            "fluids": fluids, "walls": walls, "balance": balance, "profile": profile, "nodes": nodes,
            "runtime": time.time() - t0}


# ---------------------------------------------------------------- analysis

def profile_at(result, x, y=None):
    """T across all layers on the vertical line x (linear interpolation in x
    between the cell centres and the x = 0, L faces). Returns (y, T): y are
    the walls, the layer interfaces and the cell centres, or the given y
    (then T is interpolated linearly in y between those points). Works on
    the dict of solve() and on its JSON form."""
    p = result["profile"]
    px, py, pT = np.asarray(p["x"]), np.asarray(p["y"]), np.asarray(p["T"])
    x = float(x)
    if not px[0] <= x <= px[-1]:
        raise ValueError(f"x = {x} outside [0, {px[-1]}]")
    i = int(np.clip(np.searchsorted(px, x) - 1, 0, len(px) - 2))
    w = (x - px[i]) / (px[i + 1] - px[i])
    col = (1.0 - w) * pT[i] + w * pT[i + 1]
    if y is None:
        return py.copy(), col
    y = np.asarray(y, dtype=float)
    return y, np.interp(y, py, col)


def bulk_at(result, fluid, x):
    """Mixing-cup temperature of stream `fluid` (index or name) at x."""
    fl = _fluid(result, fluid)
    return np.interp(np.asarray(x, dtype=float), fl["x"], fl["t_bulk"])


def nu_at(result, x, fluid=0, side="bottom"):
    """Local Nusselt number on the `side` face of stream `fluid` at x
    (linear between the cell centres)."""
    fi = _fluid_index(result, fluid)
    for wall in result["walls"]:
        if wall["fluid"] == fi and wall["side"] == side:
            return np.interp(np.asarray(x, dtype=float), wall["x"], wall["nu"])
    raise KeyError(side)


def _fluid_index(result, fluid):
    if isinstance(fluid, str):
        for n, fl in enumerate(result["fluids"]):
            if fl["name"] == fluid:
                return n
        raise KeyError(fluid)
    return int(fluid)


def _fluid(result, fluid):
    return result["fluids"][_fluid_index(result, fluid)]


def profiles(result, xs):
    """{x: (y, T)} at each x of xs."""
    return {float(x): profile_at(result, x) for x in xs}


def effectiveness(ntu, cr, arrangement):
    """Effectiveness-NTU relation of a parallel- or counter-flow exchanger."""
    if arrangement == "parallel":
        return (1.0 - math.exp(-ntu * (1.0 + cr))) / (1.0 + cr)
    if abs(1.0 - cr) < 1e-12:
        return ntu / (1.0 + ntu)
    e = math.exp(-ntu * (1.0 - cr))
    return (1.0 - e) / (1.0 - cr * e)


def exchanger_summary(result):
    """Outlet temperatures, heat duty and effectiveness of a two-stream
    exchanger (fluid, solid, fluid), and the effectiveness-NTU comparison:
      ua_local: int U(x) dx with U = q_plate / (T_bulk,hot - T_bulk,cold),
                q_plate the mean of the heat fluxes through the two faces of
                the solid; eps_ntu_local: the effectiveness-NTU value of the
                solved arrangement at NTU = ua_local / C_min;
      ua_nominal: 1 / (D_h/(Nu k) + t_s/k_s + D_h/(Nu k)) times L with the
                fully developed Nu = 4.8608 (one wall isothermal, one
                adiabatic; Shah & London 1978); eps_ntu_nominal_parallel,
                eps_ntu_nominal_counter at NTU = ua_nominal / C_min."""
    fl = result["fluids"]
    if len(fl) != 2:
        raise ValueError("needs two streams")
    ih, ic = (0, 1) if fl[0]["t_in"] > fl[1]["t_in"] else (1, 0)
    hot, cold = fl[ih], fl[ic]
    dt_in = hot["t_in"] - cold["t_in"]
    c_min, c_max = min(hot["capacity"], cold["capacity"]), max(hot["capacity"], cold["capacity"])
    cr = c_min / c_max
    arrangement = "parallel" if hot["direction"] == cold["direction"] else "counter"
    q_cold = cold["capacity"] * (cold["t_out"] - cold["t_in"])
    q_hot = hot["capacity"] * (hot["t_in"] - hot["t_out"])
    wh = [w for w in result["walls"] if w["fluid"] == ih and w["kind"] == "solid"]
    wc = [w for w in result["walls"] if w["fluid"] == ic and w["kind"] == "solid"]
    if len(wh) != 1 or len(wc) != 1:
        raise ValueError("needs one solid face per stream")
    q_plate = 0.5 * (np.asarray(wc[0]["q"]) - np.asarray(wh[0]["q"]))     # hot -> cold, W/m^2
    dtb = np.asarray(hot["t_bulk"])[1:-1] - np.asarray(cold["t_bulk"])[1:-1]
    dx = result["length"] / result["nx"]
    ua_local = float(np.sum(q_plate / dtb) * dx)
    solid = next(l for l in result["layers"] if l["kind"] == "solid")
    h_h = NU_T_ONE_SIDED * hot["k"] / (2.0 * hot["height"])
    h_c = NU_T_ONE_SIDED * cold["k"] / (2.0 * cold["height"])
    u_nom = 1.0 / (1.0 / h_h + (solid["y1"] - solid["y0"]) / solid["k"] + 1.0 / h_c)
    ua_nom = u_nom * result["length"]
    return {"arrangement": arrangement, "t_hot_in": hot["t_in"], "t_hot_out": hot["t_out"],
            "t_cold_in": cold["t_in"], "t_cold_out": cold["t_out"], "c_hot": hot["capacity"],
            "c_cold": cold["capacity"], "c_min": c_min, "cr": cr, "q_hot": q_hot, "q_cold": q_cold,
            "heat_gain_hot": hot["heat_gain"], "heat_gain_cold": cold["heat_gain"],
            "q_plate_hot_face": -wh[0]["heat"], "q_plate_cold_face": wc[0]["heat"],
            "eps": q_cold / (c_min * dt_in), "eps_hot": q_hot / (c_min * dt_in),
            "ua_local": ua_local, "ntu_local": ua_local / c_min,
            "eps_ntu_local": effectiveness(ua_local / c_min, cr, arrangement),
            "ua_nominal": ua_nom, "ntu_nominal": ua_nom / c_min,
            "eps_ntu_nominal_parallel": effectiveness(ua_nom / c_min, cr, "parallel"),
            "eps_ntu_nominal_counter": effectiveness(ua_nom / c_min, cr, "counter")}


def graetz_summary(result, x_eval=None):
    """Downstream Nu of the graetz preset: the bottom-wall Nu at x_eval
    (default 2/3 of the length), and its spread (max - min) over
    [L/2, 0.85 L], a measure of how developed the flow is."""
    L = result["length"]
    x_eval = 2.0 * L / 3.0 if x_eval is None else x_eval
    w = next(w for w in result["walls"] if w["side"] == "bottom")
    wx, wnu = np.asarray(w["x"]), np.asarray(w["nu"])
    sel = (wx >= 0.5 * L) & (wx <= 0.85 * L)
    pe = result["fluids"][0]["pe"]
    return {"x_eval": x_eval, "x_plus": x_eval / (2.0 * pe) / result["fluids"][0]["height"],
            "nu": float(np.interp(x_eval, wx, wnu)),
            "nu_spread": float(wnu[sel].max() - wnu[sel].min())}


def nu_fully_developed(pe, m=1000, top="isothermal", extrapolate=True):
    """Fully developed Nu (D_h = 2 W, mixing-cup bulk) of plane Poiseuille
    flow with the bottom wall isothermal and the top isothermal or
    "adiabatic", with axial conduction at Peclet number pe = u_mean D_h /
    alpha (pe = inf: none). T - T_wall = f(y) exp(-lambda x) gives
    f'' + lambda (u/alpha) f + lambda^2 f = 0, f(0) = 0 and f(W) = 0 or
    f'(W) = 0: a quadratic eigenproblem for the slowest decay lambda > 0,
    solved by second-order finite differences on m intervals (linearised to
    a sparse 2m-square problem, shift-invert about 0), Richardson-
    extrapolated from m/2 and m unless extrapolate is False. Independent of
    solve()."""
    def one(mm):
        h = 1.0 / mm
        s = np.arange(1, mm + (1 if top == "adiabatic" else 0)) * h     # unknown nodes
        n = len(s)
        e = np.ones(n)
        A = sp.diags([e[:-1], -2.0 * e, e[:-1]], [-1, 0, 1], format="lil") / h ** 2
        if top == "adiabatic":
            A[n - 1, n - 2] = 2.0 / h ** 2
        A = A.tocsc()
        prof = 4.0 * s * (1.0 - s)
        if math.isinf(pe):
            vals, vecs = spla.eigs(-A, k=4, M=sp.diags(prof).tocsc(), sigma=0.0)
        else:
            U = sp.diags(0.75 * pe * prof)                          # u / alpha with W = alpha = 1
            M = sp.bmat([[None, sp.identity(n)], [-A, -U]], format="csc")
            vals, vecs = spla.eigs(M, k=6, sigma=0.0)
        good = np.where((np.abs(vals.imag) <= 1e-9 * np.abs(vals)) & (vals.real > 0))[0]
        j = good[np.argmin(vals.real[good])]
        f = vecs[:n, j].real
        w = np.full(n, h)
        if top == "adiabatic":
            w[-1] = 0.5 * h
        fb = np.sum(w * prof * f) / np.sum(w * prof)
        fp0 = (4.0 * f[0] - f[1]) / (2.0 * h)
        return fp0 * 2.0 / fb
    if not extrapolate:
        return one(m)
    a, b = one(m // 2), one(m)
    return b + (b - a) / 3.0


# ---------------------------------------------------------------- Richardson

def _scalars(res):
    """Grid-convergent scalars: outlet mixing-cup temperatures and the local
    Nu at the middle station on every heated face. (Integrals of the wall
    heat flux are not among them: with T_in different from the wall or
    solid temperature at the inlet corner they grow like log(1/h).)"""
    out = {}
    for fl in res["fluids"]:
        out[f"t_out {fl['name']}"] = fl["t_out"]
    xm = res["stations"][len(res["stations"]) // 2] if res["stations"] else 0.5 * res["length"]
    for w in res["walls"]:
        if w["kind"] != "adiabatic":
            name = f"Nu {res['fluids'][w['fluid']]['name']} {w['side']} x={xm:g}"
            out[name] = float(np.interp(xm, w["x"], w["nu"]))
    return out


def inlet_corners(problem):
    """Singular corners where a fluid inlet (T = T_in on the end face) meets
    a neighbouring layer whose end face is not held at T_in (adiabatic solid
    edge or outlet): T ~ r^a there with tan^2(a pi/2) = k_inlet / k_other
    (a = 1/2 for equal k, 0.27 for k_other = 5 k_inlet). The error then
    falls as h^a next to the corner and as h^(2a) away from it (pollution).
    Returns [(x, y, a)]."""
    out, y = [], problem.y0
    bottoms = []
    for l in problem.layers:
        bottoms.append(y)
        y += l.height
    for m, l in enumerate(problem.layers):
        if l.kind != "fluid":
            continue
        end = 0.0 if l.direction > 0 else problem.length
        for n, yc in ((m - 1, bottoms[m]), (m + 1, bottoms[m] + l.height)):
            if not 0 <= n < len(problem.layers):
                continue
            o = problem.layers[n]
            if o.kind == "fluid" and o.direction == l.direction and o.t_in == l.t_in:
                continue
            out.append((end, yc, 2.0 / math.pi * math.atan(math.sqrt(l.k / o.k))))
    return out


def lowest_order(problem):
    """Lowest order of convergence to expect away from the inlet corners:
    2 a for the most singular corner of inlet_corners(), at most 1 (the
    lower bound of the extrapolation)."""
    a = [c[2] for c in inlet_corners(problem)]
    return min([1.0] + [2.0 * v for v in a])


def _order(d_coarse, d_fine):
    """Observed order from two successive differences; nan if not decreasing."""
    return math.log2(d_coarse / d_fine) if d_fine > 0 and d_coarse > d_fine else float("nan")


def _used(order, low=1.0):
    """Order used for the extrapolation: the observed one clamped to
    [low, 2] (low when it is not defined): conservative where the
    singularities of the inlet corners pull the convergence below second
    order (low = lowest_order(problem))."""
    return low if not math.isfinite(order) else min(2.0, max(low, order))


def richardson(problem, nx=None, ny=None, scheme=None):
    """Solve on (nx/4, ny/4), (nx/2, ny/2), (nx, ny) (cells of every layer
    halved twice) and estimate the error of the finest by Richardson
    extrapolation, with the observed order clamped to [p_low, 2], p_low =
    lowest_order(problem) (1 without singular inlet corners).
    Fields are compared on the corners of the coarsest grid: all of them,
    those at least the first station x0 away from both ends ("interior",
    x0 <= x <= L - x0), and those on each station x that is a face of the
    coarsest grid. Returns (results
    [coarse, medium, fine], table) with table:
      order_low: p_low
      field, interior: {err_max (max |T_fine - T_extrapolated|), err_max_rel
              (/ delta_t), x_at_max, y_at_max, order (observed, from the max
              differences), order_used}
      stations: {x: {err_max, err_max_rel, y_at_max, order, order_used}}
      scalars: {name: (value_fine, extrapolated, error of fine, observed order)}"""
    nx = problem.nx if nx is None else int(nx)
    scheme = problem.scheme if scheme is None else scheme
    cells = layer_cells(problem, problem.ny if ny is None else ny)
    if nx % 4 or any(c % 4 for c in cells):
        raise ValueError(f"Richardson needs nx and the cells of every layer ({cells}) divisible by 4")
    res = [solve(problem, nx // d, scheme=scheme, cells=[c // d for c in cells]) for d in (4, 2, 1)]
    nodes = [r["nodes"]["T"] for r in res]
    c0, m1, m2 = nodes[0], nodes[1][::2, ::2], nodes[2][::4, ::4]
    xn, yn = res[0]["nodes"]["x"], res[0]["nodes"]["y"]
    dt = problem.delta_t
    low = lowest_order(problem)

    def estimate(sel):
        a, b = np.abs(m1[sel] - c0[sel]).max(), np.abs(m2[sel] - m1[sel]).max()
        order = _order(a, b)
        err = np.zeros_like(m2)
        err[sel] = (m2[sel] - m1[sel]) / (2.0 ** _used(order, low) - 1.0)
        i, j = np.unravel_index(np.argmax(np.abs(err)), err.shape)
        e = float(abs(err[i, j]))
        return {"err_max": e, "err_max_rel": e / dt, "x_at_max": float(xn[i]), "y_at_max": float(yn[j]),
                "order": order, "order_used": _used(order, low)}

    everywhere = np.ones(c0.shape, dtype=bool)
    margin = (problem.stations[0] if problem.stations else 0.0) - 1e-9 * problem.length
    interior = everywhere & ((xn >= margin) & (xn <= problem.length - margin))[:, None]
    table = {"order_low": low, "field": estimate(everywhere), "interior": estimate(interior),
             "stations": {}, "scalars": {}}
    for xs in problem.stations:
        i = int(np.argmin(np.abs(xn - xs)))
        if abs(xn[i] - xs) > 1e-9 * problem.length:
            continue
        sel = np.zeros(c0.shape, dtype=bool)
        sel[i, :] = True
        e = estimate(sel)
        del e["x_at_max"]
        table["stations"][float(xs)] = e
    s = [_scalars(r) for r in res]
    for key in s[2]:
        a, b, c = s[0][key], s[1][key], s[2][key]
        order = _order(abs(b - a), abs(c - b)) if (b - a) * (c - b) > 0 else float("nan")
        extra = c + (c - b) / (2.0 ** _used(order, low) - 1.0)
        table["scalars"][key] = (c, extra, c - extra, order)
    return res, table


def to_json(result):
    def conv(v):
        if isinstance(v, dict):
            return {str(k): conv(x) for k, x in v.items()}
        if isinstance(v, (list, tuple)):
            return [conv(x) for x in v]
        if isinstance(v, np.ndarray):
            return v.tolist()
        if isinstance(v, (np.floating, np.integer)):
            return v.item()
        return v
    return conv(result)


# ---------------------------------------------------------------- script

def _plot(res, path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(3, 1, figsize=(9, 10), constrained_layout=True)
    X, Y = np.meshgrid(res["x"], res["y"], indexing="ij")
    cs = ax[0].contourf(X, Y, res["T"], 40, cmap="inferno")
    for l in res["layers"]:
        ax[0].axhline(l["y1"], color="w", lw=0.5)
    fig.colorbar(cs, ax=ax[0], label="T")
    ax[0].set_ylabel("y")
    ax[0].set_title(f"{res['case']}: nx = {res['nx']}, cells {res['cells']}, {res['scheme']}")
    for fl in res["fluids"]:
        ax[1].plot(fl["x"], fl["t_bulk"], label=f"bulk {fl['name']}")
    ax[1].set_ylabel("T bulk")
    ax[1].legend()
    for w in res["walls"]:
        if w["kind"] != "adiabatic":
            ax[2].plot(w["x"], w["nu"], label=f"{res['fluids'][w['fluid']]['name']} {w['side']} ({w['kind']})")
    ax[2].set_ylim(0, 30)
    ax[2].set_xlabel("x")
    ax[2].set_ylabel("local Nu")
    ax[2].legend()
    fig.savefig(path, dpi=110)


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--case", choices=("heated", "thick-wall", "exchanger", "graetz"), default="heated")
    p.add_argument("--re", type=float, help="Reynolds number rho u_max W / mu (heated, thick-wall; default 652)")
    p.add_argument("--ks-ratio", type=float, default=1.0, help="k_solid / k_fluid (thick-wall; default 1)")
    p.add_argument("--counter", action="store_true", help="counter-flow (exchanger; default parallel)")
    p.add_argument("--pe", type=float, default=1e4, help="Peclet number u_mean D_h / alpha (graetz)")
    p.add_argument("--length-over-w", type=float, help="channel length / W (graetz; default max(20, 0.15 Pe), "
                   "with --adiabatic-top max(20, 0.6 Pe))")
    p.add_argument("--adiabatic-top", action="store_true", help="graetz: top wall adiabatic")
    p.add_argument("--nx", type=int, help="cells along x (default 1280, graetz 400)")
    p.add_argument("--ny", type=int, help="cells across the (first) fluid channel (default 80, exchanger 40, graetz 40)")
    p.add_argument("--scheme", choices=("central", "exponential"),
                   help="convection scheme (default central, graetz exponential)")
    p.add_argument("--profiles", help="comma-separated x of T profiles across all layers ('stations': "
                   "the 5 stations of the case)")
    p.add_argument("--profiles-out", help="write the profiles to this .csv (columns y, T at each x) or .json")
    p.add_argument("--json", help="write the whole result as JSON to this file")
    p.add_argument("--richardson", action="store_true",
                   help="also solve on nx/4, ny/4 and nx/2, ny/2 and print the error of the finest")
    p.add_argument("--png", help="write a plot (T field, bulk T, local Nu) to this file")
    args = p.parse_args()

    prob = preset(args.case, re=args.re, ks_ratio=args.ks_ratio, counter=args.counter, pe=args.pe,
                  length_over_w=args.length_over_w, adiabatic_top=args.adiabatic_top)
    prob = replace(prob, nx=args.nx or prob.nx, ny=args.ny or prob.ny, scheme=args.scheme or prob.scheme)
    t0 = time.time()
    table = None
    if args.richardson:
        all_res, table = richardson(prob)
        res = all_res[-1]
    else:
        res = solve(prob)
    elapsed = time.time() - t0
    for wmsg in res["warnings"]:
        print(f"warning: {wmsg}", file=sys.stderr)

    print(f"case {res['case']}: L = {res['length']:g}, layers " +
          ", ".join(f"{l['name'] or l['kind']} {l['y0']:g}..{l['y1']:g}" for l in res["layers"]) +
          f"; nx = {res['nx']}, cells {res['cells']}, {res['scheme']} convection, "
          f"max cell Peclet {res['cell_pe_max']:.3g}")
    info = res["info"]
    if info:
        print("  " + ", ".join(f"{k} {v:.6g}" if isinstance(v, float) else f"{k} {v}" for k, v in info.items()))
    for fl in res["fluids"]:
        print(f"stream {fl['name']}: Pe {fl['pe']:.4g}, T_in {fl['t_in']:g}, T_out (mixing cup) "
              f"{fl['t_out']:.6f}, rho cp int|u|dy {fl['capacity']:.6g} W/(m K), enthalpy rise "
              f"{fl['enthalpy_rise']:.6g} W/m, conducted out through the inlet {fl['inlet_conduction']:.4g} W/m")
    b = res["balance"]
    print(f"energy balance: outer walls {b['boundaries']:.10g} W/m, streams {b['streams']:.10g} W/m, "
          f"relative residual {b['relative']:.1e}")
    st = res["stations"]
    if res["walls"]:
        print("local Nu at x = " + ", ".join(f"{x:g}" for x in st))
        for w in res["walls"]:
            if w["kind"] == "adiabatic":
                continue
            nus = np.interp(st, w["x"], w["nu"])
            print(f"  {res['fluids'][w['fluid']]['name']} {w['side']} ({w['kind']}, y = {w['y']:g}): " +
                  ", ".join(f"{v:.4f}" for v in nus) + f"; heat {w['heat']:.6g} W/m")
    for fl in res["fluids"]:
        print(f"bulk T {fl['name']} at x = stations: " +
              ", ".join(f"{v:.4f}" for v in np.interp(st, fl["x"], fl["t_bulk"])))
    if res["case"] == "graetz":
        g = graetz_summary(res)
        top = "adiabatic" if info.get("adiabatic_top") else "isothermal"
        ref = NU_T_ONE_SIDED if top == "adiabatic" else NU_T
        nu1d = nu_fully_developed(info["pe"], top=top)
        print(f"downstream Nu at x = {g['x_eval']:g} (x/(D_h Pe) = {g['x_plus']:.4f}): {g['nu']:.6f} "
              f"(spread over [L/2, 0.85 L] {g['nu_spread']:.1e})")
        print(f"  fully developed eigenproblem at this Pe: {nu1d:.6f}; Shah & London (1978), Pe -> inf: "
              f"{ref}; deviation {g['nu'] / ref - 1:+.2e}")
    if res["case"] == "exchanger":
        e = exchanger_summary(res)
        print(f"{e['arrangement']} flow: hot {e['t_hot_in']:g} -> {e['t_hot_out']:.4f} K, cold "
              f"{e['t_cold_in']:g} -> {e['t_cold_out']:.4f} K, C_cold/C_hot = {e['cr']:.4g}")
        print(f"  heat: lost by hot {e['q_hot']:.6g}, gained by cold {e['q_cold']:.6g} W/m (enthalpy); "
              f"net with inlet conduction: hot {e['heat_gain_hot']:.10g}, cold {e['heat_gain_cold']:.10g}")
        print(f"  effectiveness {e['eps']:.5f} (hot side {e['eps_hot']:.5f})")
        print(f"  eps-NTU with UA = int q/(Tb_hot - Tb_cold) dx = {e['ua_local']:.4g} W/(m K) "
              f"(NTU {e['ntu_local']:.4f}): {e['eps_ntu_local']:.5f}")
        print(f"  eps-NTU with UA from Nu = 4.8608 per side = {e['ua_nominal']:.4g} (NTU {e['ntu_nominal']:.4f}): "
              f"parallel {e['eps_ntu_nominal_parallel']:.5f}, counter {e['eps_ntu_nominal_counter']:.5f}")
    if table:
        print(f"Richardson over nx = {res['nx'] // 4}, {res['nx'] // 2}, {res['nx']} (delta T = {prob.delta_t:g}; "
              f"order used = observed order clamped to [{table['order_low']:.2f}, 2]):")
        x0 = res["stations"][0]
        band = f"field {x0:g} <= x <= {res['length'] - x0:g}"
        for name, f in (("field", table["field"]), (band, table["interior"])):
            print(f"  {name}: error of the finest max {f['err_max']:.3e} = {f['err_max_rel']:.2e} delta T "
                  f"at x = {f['x_at_max']:g}, y = {f['y_at_max']:g}; observed order {f['order']:.2f}")
        for xs, v in table["stations"].items():
            print(f"  profile x = {xs:g}: error of the finest max {v['err_max']:.3e} = {v['err_max_rel']:.2e} "
                  f"delta T (at y = {v['y_at_max']:g}), observed order {v['order']:.2f}")
        for key, (val, extra, err, order) in table["scalars"].items():
            print(f"  {key}: {val:.8g} extrapolated {extra:.8g} error {err:+.2e} observed order {order:.2f}")
    print(f"# {elapsed:.2f} s")

    prof = None
    if args.profiles:
        xs = res["stations"] if args.profiles == "stations" else [float(v) for v in args.profiles.split(",")]
        prof = profiles(res, xs)
        res["profiles"] = {str(x): {"y": yv, "T": tv} for x, (yv, tv) in prof.items()}
        if args.profiles_out and args.profiles_out.endswith(".json"):
            with open(args.profiles_out, "w") as fh:
                json.dump(to_json(res["profiles"]), fh)
        else:
            ys = next(iter(prof.values()))[0]
            lines = ["y," + ",".join(f"T(x={x:g})" for x in prof)]
            lines += [f"{ys[j]:.10g}," + ",".join(f"{tv[j]:.10g}" for _, tv in prof.values())
                      for j in range(len(ys))]
            text = "\n".join(lines) + "\n"
            if args.profiles_out:
                with open(args.profiles_out, "w") as fh:
                    fh.write(text)
            else:
                print(text, end="")
    if args.json:
        out = dict(res)
        if res["case"] == "exchanger":
            out["exchanger"] = exchanger_summary(res)
        if res["case"] == "graetz":
            out["graetz"] = graetz_summary(res)
        if table:
            out["richardson"] = table
        with open(args.json, "w") as fh:
            json.dump(to_json(out), fh)
    if args.png:
        _plot(res, args.png)
    return 0


if __name__ == "__main__":
    sys.exit(main())
