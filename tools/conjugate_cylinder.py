"""Fine radial finite-volume reference for a hot solid cylinder cooling in a
quiescent fluid (axisymmetric conjugate conduction, a disc in 2-D).

Solves rho cv dT/dt = (1/r) d/dr (r k dT/dr) on 0 <= r <= R_out: material 1
(the solid) for r < R, material 2 (the fluid, conduction only) for
R < r < R_out, each with its own rho, cv, constant k and uniform initial
temperature. r = 0 is the symmetry axis; the outer wall r = R_out is
adiabatic or held at a temperature. SI units throughout.

Discretisation:
- Cell-centred finite volumes per unit length, cell faces exactly on r = 0,
  R and R_out. Cells are uniform in the solid; in the fluid they are uniform
  too, or grow by the factor `stretch` from the interface outwards. The
  centre of a cell is the midpoint of its faces; its volume is
  pi (r_e^2 - r_w^2).
- Conductance between neighbouring centres: the two half-cells in series,
  each with the exact steady cylindrical resistance ln(r_outer/r_inner) /
  (2 pi k), so T and the heat flux are continuous across r = R and a
  steady ln(r) profile is exact. No flux through the axis. A held outer
  wall is reached through the half-cell resistance ln(R_out/r_N) / (2 pi k).
- Time: variable-step BDF2 (one backward-Euler step to start), L-stable, so
  the initial jump of T at r = R leaves no undamped oscillation and the step
  can be much larger than the explicit limit. The step is dt0 (the
  shortest cell diffusion time, or 1e-3 of the first output time if
  shorter) until dt/t reaches `dt_over_t`, then grows with t
  (dt = dt_over_t t), which keeps the relative time error of a diffusive
  solution roughly uniform over decades. (Once the solution decays
  exponentially, at Fourier numbers of order 1 and beyond, the relative
  error grows like (t/t_decay)^3 dt_over_t^2: use a smaller dt_over_t
  there.) Steps land exactly on the output times; one step is never more
  than twice the previous one (BDF2 stays zero-stable).
- Each step solves the tridiagonal system for the increment T^{n+1} - T^n
  (Thomas algorithm): rounding then acts on the increment, not on T, and
  the thermal energy sum(rho cv V T) is conserved to round-off with the
  adiabatic wall.
Second order in space and time. reference_error() states the solution's own
error by comparing it with a run on twice the cells (every cell split in
two) and half the time step.

As a module: solve(R, R_out, solid, fluid, times, cells=...) returns a dict
(r, T at each time, the solid's area-weighted mean temperature and the
energy at each time and at every step, ...); temperature_at(result, radii,
index) interpolates, nodes(result, index) gives r and T including the axis,
the interface and the wall. As a script, see --help; tools/conjugate_cylinder.md
gives the measured errors.
"""

import argparse
import math
import sys

import numpy as np


class Material:
    """Density rho (kg/m^3), specific heat cv (J/(kg K)), conductivity k
    (W/(m K)) and uniform initial temperature T0 (K)."""

    def __init__(self, rho, cv, k, T0):
        self.rho, self.cv, self.k, self.T0 = float(rho), float(cv), float(k), float(T0)

    @property
    def alpha(self):
        return self.k / (self.rho * self.cv)

    @classmethod
    def parse(cls, text):
        """'rho,cv,k,T0'."""
        values = [float(v) for v in text.split(",")]
        if len(values) != 4:
            raise ValueError(f"expected rho,cv,k,T0, got '{text}'")
        return cls(*values)


def thomas(lower, diag, upper, rhs):
    """Solve a tridiagonal system: lower[i] x[i-1] + diag[i] x[i] + upper[i]
    x[i+1] = rhs[i] (lower[0] and upper[-1] unused). No pivoting: the
    matrices here are diagonally dominant M-matrices. Plain Python lists:
    the sweep is sequential, and element access to lists is several times
    faster than to numpy arrays."""
    n = len(diag)
    c = [0.0] * n
    d = [0.0] * n
    m = diag[0]
    c[0] = upper[0] / m
    d[0] = rhs[0] / m
    for i in range(1, n):
        li = lower[i]
        m = diag[i] - li * c[i - 1]
        c[i] = upper[i] / m if i < n - 1 else 0.0
        d[i] = (rhs[i] - li * d[i - 1]) / m
    for i in range(n - 2, -1, -1):
        d[i] -= c[i] * d[i + 1]
    return d


def grid(R, R_out, cells, stretch=1.0):
    """Faces of the radial grid and the number of solid cells. cells: the
    total (split so that the first fluid cell is as wide as a solid cell) or
    (n_solid, n_fluid). Fluid cells grow by `stretch` outwards."""
    if not 0.0 < R < R_out:
        raise ValueError("need 0 < R < R_out")
    L = R_out - R
    if isinstance(cells, (tuple, list)):
        n1, n2 = int(cells[0]), int(cells[1])
    else:
        n = int(cells)
        if n < 2:
            raise ValueError("need at least 2 cells")
        n1s = np.arange(1, n)
        n2s = n - n1s
        with np.errstate(over="ignore", divide="ignore"):   # stretch ** n overflows for bad splits
            if stretch == 1.0:
                first = L / n2s
            else:
                first = L * (stretch - 1.0) / (stretch ** n2s - 1.0)
            n1 = int(n1s[np.argmin(np.abs(np.log(first * n1s / R)))])
        n2 = n - n1
    if n1 < 1 or n2 < 1:
        raise ValueError("need at least one cell in each material")
    j = np.arange(n2 + 1)
    if stretch == 1.0:
        frac = j / n2
    else:
        frac = (stretch ** j - 1.0) / (stretch ** n2 - 1.0)
    faces = np.concatenate([np.linspace(0.0, R, n1 + 1), R + L * frac[1:]])
    faces[n1] = R          # exactly on the interface and the outer wall
    faces[-1] = R_out
    return faces, n1


def time_points(times, dt0, dt_over_t):
    """Step end points from 0: dt = max(dt0, dt_over_t t), at most twice the
    previous step, landing on every output time."""
    pts, t, dt_prev = [], 0.0, dt0
    for t_out in sorted(set(times)):
        while t < t_out * (1.0 - 1e-13):
            dt = min(max(dt0, dt_over_t * t), 2.0 * dt_prev)
            if t + 1.5 * dt >= t_out:      # land on t_out without a tiny step
                dt = t_out - t
            t = t_out if dt == t_out - t else t + dt
            pts.append(t)
            dt_prev = dt
    return pts


def solve(R, R_out, solid, fluid, times, cells=2000, outer=None, stretch=1.0,
          dt_over_t=0.02, dt0=None):
    """R: radius of the solid; R_out: outer wall; solid, fluid: Material;
    times: output times (s); cells: total, or (n_solid, n_fluid); outer:
    None (adiabatic) or the temperature held at R_out; stretch: growth
    factor of the fluid cells; dt_over_t: dt/t once the steps grow; dt0:
    first step (default: the shortest cell diffusion time rho cv V / (sum
    of its conductances), or 1e-3 of the first output time if shorter).

    Returns a dict: faces, r (centres), volume (m^2 per m of length),
    n_solid, times, T (list of arrays, one per time), mean_solid and energy
    (at each time; energy = sum rho cv V T in J/m), history (t, mean_solid,
    energy at every step, from t = 0), steps, interface (T at r = R per time)
    and the parameters."""
    times = [float(t) for t in times]
    if min(times) <= 0.0:
        raise ValueError("output times must be > 0")
    faces, n1 = grid(R, R_out, cells, stretch)
    n = len(faces) - 1
    r = 0.5 * (faces[:-1] + faces[1:])
    volume = math.pi * (faces[1:] ** 2 - faces[:-1] ** 2)
    mats = [solid] * n1 + [fluid] * (n - n1)
    k = np.array([m.k for m in mats])
    C = np.array([m.rho * m.cv for m in mats]) * volume      # J/(m K)
    T = np.array([m.T0 for m in mats])
    # series conductance (W/(m K)) through the inner face of cell i+1
    f = faces[1:-1]
    G = 2.0 * math.pi / (np.log(f / r[:-1]) / k[:-1] + np.log(r[1:] / f) / k[1:])
    Gb = 0.0 if outer is None else 2.0 * math.pi * k[-1] / math.log(R_out / r[-1])
    Tb = 0.0 if outer is None else float(outer)
    if dt0 is None:
        tau = np.min(C / np.maximum(np.concatenate([[0.0], G]) + np.concatenate([G, [Gb]]), 1e-300))
        dt0 = min(tau, 1e-3 * min(times))
    lower = np.concatenate([[0.0], -G])        # K's off-diagonals
    upper = np.concatenate([-G, [0.0]])
    KGdiag = np.concatenate([[0.0], G]) + np.concatenate([G, [Gb]])
    solid_area = math.pi * R * R

    def KT(T):
        """K T: net heat flow out of each cell (W/m), in flux form."""
        q = G * (T[:-1] - T[1:])
        out = np.zeros_like(T)
        out[:-1] += q
        out[1:] -= q
        if outer is not None:
            out[-1] += Gb * (T[-1] - Tb)
        return out

    hist_t = [0.0]
    hist_mean = [float(np.dot(volume[:n1], T[:n1]) / solid_area)]
    hist_E = [float(np.dot(C, T))]
    want = set(times)
    saved = {}
    t, T_old, h_old = 0.0, None, None
    for t_new in time_points(times, dt0, dt_over_t):
        h = t_new - t
        if T_old is None:                  # backward Euler start
            a0, a2 = 1.0, 0.0
        else:                              # variable-step BDF2, w = h/h_old
            w = h / h_old
            a0, a2 = (1.0 + 2.0 * w) / (1.0 + w), w * w / (1.0 + w)
        # a0 C (T+ - T) - a2 C (T - T_old) = -h K T+ (+ boundary), for dT = T+ - T
        rhs = -h * KT(T)
        if a2:
            rhs += a2 * C * (T - T_old)
        dT = thomas((h * lower).tolist(), (a0 * C + h * KGdiag).tolist(), (h * upper).tolist(), rhs.tolist())
        T_old, T, t, h_old = T, T + np.array(dT), t_new, h
        hist_t.append(t)
        hist_mean.append(float(np.dot(volume[:n1], T[:n1]) / solid_area))
        hist_E.append(float(np.dot(C, T)))
        if t in want:
            saved[t] = (T.copy(), hist_mean[-1], hist_E[-1])
    res = {"faces": faces, "r": r, "volume": volume, "n_solid": n1, "R": R, "R_out": R_out,
           "solid": solid, "fluid": fluid, "outer": outer, "stretch": stretch,
           "dt_over_t": dt_over_t, "dt0": dt0, "times": times, "steps": len(hist_t) - 1,
           "T": [saved[t][0] for t in times],
           "mean_solid": np.array([saved[t][1] for t in times]),
           "energy": np.array([saved[t][2] for t in times]),
           "history": {"t": np.array(hist_t), "mean_solid": np.array(hist_mean),
                       "energy": np.array(hist_E)}}
    res["interface"] = np.array([_interface(res, T) for T in res["T"]])
    return res


def _interface(res, T):
    """T at r = R from flux continuity through the two half-cells."""
    n1, r, R = res["n_solid"], res["r"], res["R"]
    g1 = res["solid"].k / math.log(R / r[n1 - 1])
    g2 = res["fluid"].k / math.log(r[n1] / R)
    return (g1 * T[n1 - 1] + g2 * T[n1]) / (g1 + g2)


def nodes(res, index):
    """Radii and temperatures of one output: the axis (zero gradient), the
    solid's centres, the interface, the fluid's centres and the outer wall."""
    T, r, n1 = res["T"][index], res["r"], res["n_solid"]
    Tw = T[-1] if res["outer"] is None else res["outer"]
    rr = np.concatenate([[0.0], r[:n1], [res["R"]], r[n1:], [res["R_out"]]])
    TT = np.concatenate([[T[0]], T[:n1], [res["interface"][index]], T[n1:], [Tw]])
    return rr, TT


def temperature_at(res, radii, index):
    """T at the given radii at output `index`, linear between the nodes()
    (second order); never across the interface, which is itself a node."""
    rr, TT = nodes(res, index)
    return np.interp(np.asarray(radii, dtype=float), rr, TT)


def reference_error(res):
    """Own error of a solve() result: the difference to a run on twice the
    cells (each cell split in two: stretch -> sqrt(stretch)) and half the
    time step (dt0 / 2, dt_over_t / 2). Returns, per output time, the
    largest difference of T over the nodes() and the difference of the
    solid's mean temperature. For second-order convergence the error of
    `res` is 4/3 of these and that of the finer run 1/3."""
    n1 = res["n_solid"]
    n2 = len(res["r"]) - n1
    fine = solve(res["R"], res["R_out"], res["solid"], res["fluid"], res["times"],
                 (2 * n1, 2 * n2), res["outer"], math.sqrt(res["stretch"]),
                 res["dt_over_t"] / 2.0, res["dt0"] / 2.0)
    d_profile, d_mean = [], []
    for i in range(len(res["times"])):
        rr, TT = nodes(res, i)
        d_profile.append(float(np.max(np.abs(temperature_at(fine, rr, i) - TT))))
        d_mean.append(abs(float(fine["mean_solid"][i] - res["mean_solid"][i])))
    return np.array(d_profile), np.array(d_mean)


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--R", type=float, required=True, help="radius of the solid (m)")
    p.add_argument("--Rout", type=float, required=True, help="radius of the outer wall (m)")
    p.add_argument("--solid", required=True, help="rho,cv,k,T0 of the solid")
    p.add_argument("--fluid", required=True, help="rho,cv,k,T0 of the fluid")
    p.add_argument("--outer", default="adiabatic", help="'adiabatic' or the temperature held at R_out")
    p.add_argument("--cells", type=int, default=2000, help="radial cells in all (default 2000)")
    p.add_argument("--stretch", type=float, default=1.0,
                   help="growth factor of the fluid cells outwards (default 1: uniform)")
    p.add_argument("--dt-over-t", type=float, default=0.02, help="time step / time once it grows (default 0.02)")
    p.add_argument("--times", required=True, help="comma-separated output times (s)")
    p.add_argument("--radii", help="comma-separated radii to print (default 0, R/2, R, then up to R_out)")
    p.add_argument("--profile", help="write the nodes' r and T, one column per time, to this file")
    p.add_argument("--no-error", action="store_true",
                   help="skip reference_error() (it costs about 4 times the run)")
    a = p.parse_args()
    solid, fluid = Material.parse(a.solid), Material.parse(a.fluid)
    outer = None if a.outer == "adiabatic" else float(a.outer)
    times = [float(t) for t in a.times.split(",")]
    if a.radii:
        radii = [float(v) for v in a.radii.split(",")]
    else:
        radii = [0.0, 0.5 * a.R, a.R] + [x for x in (1.5 * a.R, 2.0 * a.R) if x < a.Rout] + [a.Rout]
    res = solve(a.R, a.Rout, solid, fluid, times, a.cells, outer, a.stretch, a.dt_over_t)
    n1 = res["n_solid"]
    print(f"# conjugate_cylinder: {n1} solid + {len(res['r']) - n1} fluid cells, stretch {a.stretch:g}, "
          f"{res['steps']} BDF2 steps (dt0 {res['dt0']:.3g} s, dt/t {a.dt_over_t:g}), "
          f"outer wall {'adiabatic' if outer is None else f'held at {outer:g}'}")
    E0 = res["history"]["energy"][0]
    print(f"# energy at t = 0: {E0:.10g} J/m")
    if not a.no_error:
        d_profile, d_mean = reference_error(res)
        print(f"# estimated error: difference to {2 * n1} + {2 * (len(res['r']) - n1)} cells and half the step")
    print("# t mean_solid " + " ".join(f"T(r={x:g})" for x in radii) + " energy/E0-1"
          + ("" if a.no_error else " err_mean_solid err_T_max"))
    for i, t in enumerate(times):
        line = f"{t:g} {res['mean_solid'][i]:.6f} " + " ".join(
            f"{v:.6f}" for v in temperature_at(res, radii, i)) + f" {res['energy'][i] / E0 - 1:.2e}"
        if not a.no_error:
            line += f" {d_mean[i]:.2e} {d_profile[i]:.2e}"
        print(line)
    if a.profile:
        with open(a.profile, "w") as out:
            out.write("# r " + " ".join(f"T(t={t:g})" for t in times) + "\n")
            cols = [nodes(res, i)[1] for i in range(len(times))]
            for j, x in enumerate(nodes(res, 0)[0]):
                out.write(f"{x:.10g} " + " ".join(f"{c[j]:.10g}" for c in cols) + "\n")
    return 0


if __name__ == "__main__":
    sys.exit(main())
