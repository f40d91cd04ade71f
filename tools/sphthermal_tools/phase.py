"""Measures of a melting or freezing cavity from a snapshot of fix
sph/phase's particles (a dump with x, y and the liquid fraction f_phase):
the liquid fraction of the volume and the front's position in the rows of
particles at the top, middle and bottom, scanning from the wall at x = 0."""

import numpy as np


def liquid_fraction(frame):
    """The liquid fraction of the volume: every particle has the same mass,
    so the liquid mass fraction is the mean liquid fraction."""
    return float(frame["f_phase"].mean())


def front_positions(frame, spacing, width, height, grows_from_wall="liquid"):
    """The front (fraction of width) in the rows of particles at the top,
    middle and bottom: where the phase that grows from the wall at x = 0
    (grows_from_wall, 'liquid' for melting from a hot wall, 'solid' for
    freezing on a cold one) falls through a fraction 0.5 going away from
    the wall, linear between particles; the row's last particle when it
    does not."""
    x, y = frame["x"], frame["y"]
    f = frame["f_phase"] if grows_from_wall == "liquid" else 1.0 - frame["f_phase"]
    rows = {"top": height - 0.5 * spacing, "middle": None, "bottom": 0.5 * spacing}
    centres = np.unique(np.round(y / spacing - 0.5)) * spacing + 0.5 * spacing
    rows["middle"] = centres[np.argmin(np.abs(centres - 0.5 * height))]
    fronts = {}
    for name, level in rows.items():
        row = np.abs(y - level) < 0.5 * spacing
        order = np.argsort(x[row])
        xs, fs = x[row][order], f[row][order]
        front = xs[-1]
        for i in range(1, len(xs)):
            if fs[i] < 0.5 <= fs[i - 1]:
                front = xs[i - 1] + (fs[i - 1] - 0.5) / (fs[i - 1] - fs[i]) * (xs[i] - xs[i - 1])
                break
            if i == 1 and fs[0] < 0.5:
                front = xs[0] * fs[0] / 0.5
                break
        fronts[name] = front / width
    return fronts
