"""The collapse of a water column on a dry floor (a dam break): the
experiment examples/flow-dam-break and the flow.dam_break test compare
with, and the front read from a LAMMPS log.

Martin and Moyce (Phil. Trans. R. Soc. A 244 (1952) 312-324), a square-
based column a = 2.25 in wide and 2a high (n^2 = 2), its figure of the
front's position Z = x / a against T = t sqrt(2 g / a), as read off by the
PySPH project (pypr/pysph, pysph/examples/db_exp_data.py). The gate's
removal takes a finite time in the experiment, so that the measured front
lags a computation that releases the column at once by about 0.3 in T at
the start (computations of this experiment show the same offset).
"""

import re

# (T, Z) of Martin and Moyce's figure, a = 2.25 in, n^2 = 2
MARTIN_MOYCE = [
    (0.832, 1.217), (1.219, 1.474), (1.997, 2.292), (2.547, 2.995),
    (3.345, 4.134), (4.034, 4.944), (4.418, 5.881), (5.091, 6.980),
    (5.685, 7.945), (6.306, 8.966), (6.822, 9.986), (7.439, 10.963),
    (8.031, 11.977), (8.633, 13.005), (9.237, 13.970),
]


def front_series(log_text):
    """(T, Z, water atoms) of each thermo row of in.dam_break's log"""
    rows = []
    header = None
    for line in log_text.splitlines():
        words = line.split()
        if words[:2] == ["Step", "Time"]:
            header = words
            continue
        if header and len(words) == len(header) and re.match(r"^\d+$", words[0]):
            try:
                row = dict(zip(header, (float(w) for w in words)))
            except ValueError:
                continue
            rows.append((row["v_T"], row["v_Z"], row["v_nwater"]))
        elif header and not re.match(r"^\s*\d", line) and not line.startswith("WARNING"):
            header = None
    return rows


def front_at(rows, t_wanted):
    """Z at T = t_wanted, linear between the samples around it"""
    for (t0, z0, _), (t1, z1, _) in zip(rows, rows[1:]):
        if t0 <= t_wanted <= t1:
            return z0 + (z1 - z0) * (t_wanted - t0) / (t1 - t0)
    raise ValueError(f"T = {t_wanted} outside the run (T {rows[0][0]} to {rows[-1][0]})")


def time_at(rows, z_wanted):
    """the first T at which the front reaches Z = z_wanted"""
    for (t0, z0, _), (t1, z1, _) in zip(rows, rows[1:]):
        if z0 <= z_wanted <= z1 and z1 > z0:
            return t0 + (t1 - t0) * (z_wanted - z0) / (z1 - z0)
    raise ValueError(f"the front never reaches Z = {z_wanted}")
