"""A heated packed bed of fix sph/grains (examples/grains-bed/in.heatbed)
against Schumann's solution (schumann.py): the grains' and the fluid's
temperatures along the bed at the run's end, from its dumps and its printed
line. The reference takes the run's own quantities: the fluid's pore
velocity (the mean of its particles'), h from the heat law at the grains'
mean slip and porosity (grain_exact.nusselt), the heat capacities per volume
of the bed from the masses (the fluid fills the pores: eps rho_f c_f).
compare(line, grains_dump, fluid_dump) -> the largest errors of the grains
and of the fluid (in units of T_in - T0) over the whole bed, the exchange
length L_f = eps rho_f c_f u / (h a) and the profiles."""

import math
import re

import numpy as np

from grain_exact import nusselt
from schumann import temperatures
from sphthermal_tools.dump import read_frames

# the scene of in.heatbed
RHO_F, CP_F, MU, RHO_S, CP_S = 1000.0, 4000.0, 1e-3, 2500.0, 800.0


def value(line, name):
    return float(re.search(rf"(?:: |, ){name} (-?[0-9.eE+-]+)", line).group(1))


def compare(line, grains_dump, fluid_dump, spacing=1e-3):
    law = re.search(r"heat law ([a-z-]+)", line).group(1)
    d, eps, eps_grain = value(line, "d"), value(line, "porosity"), value(line, "grain porosity")
    t, t0, t_in, slip = value(line, "time"), value(line, "t0"), value(line, "t_in"), value(line, "slip")
    k_f = value(line, "k")
    grains = read_frames(grains_dump)[-1][1]
    fluid = read_frames(fluid_dump)[-1][1]
    u = float(np.mean(fluid["vx"]))
    re_p = eps_grain * RHO_F * d * slip / MU
    h_a = nusselt(law, re_p, MU * CP_F / k_f, eps_grain) * k_f * math.pi * d / spacing ** 3
    fluid_capacity = eps * RHO_F * CP_F
    solid_capacity = RHO_S * math.pi * d ** 3 / 6.0 / spacing ** 3 * CP_S
    span = t_in - t0
    _, theta_s = temperatures(grains["x"], t, u, h_a, fluid_capacity, solid_capacity)
    theta_f, _ = temperatures(fluid["x"], t, u, h_a, fluid_capacity, solid_capacity)
    grain_theta = (grains["c_tgrain"] - t0) / span
    fluid_theta = (fluid["c_tfluid"] - t0) / span
    order = np.argsort(grains["x"])
    return {"grains": float(np.max(np.abs(grain_theta - theta_s))),
            "fluid": float(np.max(np.abs(fluid_theta - theta_f))),
            "fluid_min": float(np.min(fluid_theta)),
            "exchange_length": fluid_capacity * u / h_a, "u": u, "re": re_p, "time": t, "k": k_f,
            "x": grains["x"][order], "grain_theta": grain_theta[order], "schumann_s": theta_s[order]}
