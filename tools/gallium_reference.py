"""Melting of gallium in a cavity heated from one side: the published data
that examples/phase-gallium and the phase.gallium tests compare with, and
the measures taken from a snapshot of the particles.

The scene (Gau and Viskanta, J. Heat Transfer 108 (1986) 174-181; the
properties and temperatures as Brent, Voller and Reid, Numer. Heat Transfer
13 (1988) 297-318, Table 1, set it up): a cavity W = 88.9 mm wide and
H = 63.5 mm high, solid gallium at 28.3 C, the left wall at 38 C from t = 0.

Experiment (Gau and Viskanta 1986, their figures of the melt front at the
top, middle and bottom of the cavity and of the melted volume, against
Fo Ste): the points as read off those figures by the Lethe project
(chaos-polymtl/lethe, examples/multiphysics/melting-cavity). The figures'
abscissa is proportional to time; we take the points at 2, 3, 4.5, 6, 8,
10, 12.5 and 15 min (the melted volume also at 17 and 19 min), the times
whose ratios their abscissae have (to the spread abscissa_ratio_spread()
prints), the first at 2 min. The front positions are fractions of W: at
2 min the measured melt is then 10.2 mm deep against 11.3 mm of pure
conduction (as fractions of H it would be 7.3 mm). Read off a printed figure, each point
carries about 0.005 (front) and 0.01 (volume) of reading error besides the
experiment's own: the experiment is three-dimensional (a cell 38 mm deep),
the computations two-dimensional, which melt faster at the top.

Computation (Blais and Ilinca, Comput. Fluids 172 (2018), doi
10.1016/j.compfluid.2018.03.037: a stabilised finite-element computation
of the same scene):
the melted volume fraction read off their figure by the same project, on
the same abscissa as the experiment's melted volume.
"""

import numpy as np

import stefan
from sphthermal_tools import phase

WIDTH, HEIGHT = 0.0889, 0.0635  # m
T_HOT, T_INITIAL, T_MELT = 273.15 + 38.0, 273.15 + 28.3, 273.15 + 29.78  # K
RHO, CP, K, LATENT = 6093.0, 381.5, 32.0, 80160.0  # SI
ALPHA = K / (RHO * CP)

# the experiment: times (s) and the melt front (fraction of W) at the top,
# middle and bottom of the cavity
FRONT_TIMES = 60.0 * np.array([2.0, 3.0, 4.5, 6.0, 8.0, 10.0, 12.5, 15.0])
FRONT_TOP = np.array([0.11508, 0.18212, 0.28603, 0.31508, 0.38994, 0.50391, 0.61117, 0.72514])
FRONT_MIDDLE = np.array([0.11508, 0.16313, 0.20894, 0.23911, 0.29609, 0.36089, 0.45475, 0.52961])
FRONT_BOTTOM = np.array([0.1095, 0.12849, 0.14078, 0.16425, 0.21117, 0.22346, 0.26592, 0.26592])
FRONT_ABSCISSA = np.array([0.00853, 0.01279, 0.01931, 0.02575, 0.03428, 0.04298, 0.0536, 0.06438])

# the experiment: times (s) and the melted volume fraction
MELT_TIMES = 60.0 * np.array([2.0, 3.0, 4.5, 6.0, 8.0, 10.0, 12.5, 15.0, 17.0, 19.0])
MELT_FRACTION = np.array([0.11972, 0.16112, 0.20476, 0.22713, 0.2786, 0.34014, 0.43077, 0.5035,
                          0.56392, 0.61664])
MELT_ABSCISSA = np.array([0.00946, 0.01433, 0.02113, 0.02877, 0.03774, 0.04739, 0.05956, 0.07164,
                          0.08104, 0.09069])

# Blais and Ilinca (2018): melted volume fraction on the experiment's abscissa
_BLAIS_ABSCISSA = np.array([0.000941, 0.002621, 0.004570, 0.006855, 0.011156, 0.018011, 0.024731,
                            0.029637, 0.034005, 0.038911, 0.043683, 0.048118, 0.053226, 0.057594,
                            0.064516, 0.074328, 0.082661, 0.089315, 0.095968, 0.098992])
_BLAIS_FRACTION = np.array([0.03721, 0.06698, 0.08558, 0.10791, 0.14233, 0.18977, 0.23442, 0.26140,
                            0.28744, 0.31628, 0.34419, 0.37209, 0.40000, 0.42419, 0.46512, 0.51535,
                            0.56000, 0.59349, 0.62791, 0.64372])
BLAIS_TIMES = _BLAIS_ABSCISSA * (MELT_TIMES[0] / MELT_ABSCISSA[0])
BLAIS_FRACTION = _BLAIS_FRACTION


def abscissa_ratio_spread():
    """How far the experiment's abscissae are from the stated times'
    ratios (the largest relative difference, both figures)."""
    spread = 0.0
    for times, abscissa in ((FRONT_TIMES, FRONT_ABSCISSA), (MELT_TIMES, MELT_ABSCISSA)):
        scaled = abscissa / abscissa[0] * times[0]
        spread = max(spread, float(np.abs(scaled / times - 1.0).max()))
    return spread


def conduction_melt_fraction(t):
    """The melted volume fraction of pure conduction from the hot wall, the
    two-phase Neumann solution (tools/stefan.py) over the cavity's width:
    the scene's limit while the melt is too thin to convect."""
    st_l = CP * (T_HOT - T_MELT) / LATENT
    st_s = CP * (T_MELT - T_INITIAL) / LATENT
    lam = stefan.neumann_lambda(st_l, st_s, 1.0)
    return stefan.front(t, lam, ALPHA) / WIDTH


def melted_fraction(frame):
    """The melted volume fraction of a snapshot."""
    return phase.liquid_fraction(frame)


def front_positions(frame, spacing):
    """The melt front (fraction of W) in the rows of particles at the top,
    middle and bottom of the cavity (sphthermal_tools.phase)."""
    return phase.front_positions(frame, spacing, WIDTH, HEIGHT, "liquid")


def experiment_at(times, values, t):
    """The experiment's value at time t, linear between its times."""
    return float(np.interp(t, times, values))


if __name__ == "__main__":
    print(f"abscissae against the stated times: within {100 * abscissa_ratio_spread():.2f} %")
    for t in (60.0, 120.0):
        print(f"conduction's melted fraction at {t:g} s: {conduction_melt_fraction(t):.5f}")
    print(f"conduction's melt depth at 120 s: {1e3 * WIDTH * conduction_melt_fraction(120.0):.2f} mm")
