"""Read the thermo tables of a LAMMPS log or screen output, the loop times
of its runs, and the final Nusselt numbers the cavity inputs print."""

import re

import numpy as np


def loop_runs(text):
    """(loop seconds, steps, atoms) of every run in text, in order (runs of
    0 steps too)."""
    return [(float(t), int(n), int(a)) for t, n, a in re.findall(
        r"Loop time of ([0-9.eE+-]+) on \d+ procs for (\d+) steps with (\d+) atoms", text)]


def thermo_tables(text):
    """Every thermo table in text (a table starts at a header line whose
    first word is 'Step'), as {column name: numpy array}, in order."""
    tables, header, rows = [], None, None

    def close():
        if header and rows:
            data = np.array(rows)
            tables.append({name: data[:, k] for k, name in enumerate(header)})

    for line in text.splitlines():
        words = line.split()
        if words[:1] == ["Step"]:
            close()
            header, rows = words, []
            continue
        if header is None:
            continue
        try:
            values = [float(w) for w in words]
        except ValueError:
            values = None
        if values is not None and len(values) == len(header):
            rows.append(values)
        else:
            close()
            header, rows = None, None
    close()
    return tables


def longest_thermo_table(text):
    """The thermo table with the most rows (that of the main run), or None."""
    tables = thermo_tables(text)
    return max(tables, key=lambda t: len(next(iter(t.values())))) if tables else None



def late_rows(table, fraction=2.0 / 3.0):
    """The rows at Time >= fraction of the last row's Time (the steady end
    of a run), as a boolean mask."""
    return table["Time"] >= fraction * table["Time"][-1]


def final_nusselt(text):
    """The last Nusselt numbers the cavity inputs (in.cavity, in.air) print
    at their end: {"heat": (hot, cold), "time": t, "gradient": (hot, cold),
    or None when the run printed no gradient estimate}; None when there is
    no 'final:' line. Anchored at line starts: a log also echoes the print
    commands."""
    heat = re.findall(r"^final: Nu_hot = (\S+) Nu_cold = (\S+) at t = (\S+)", text, re.M)
    gradient = re.findall(r"^final, from the wall gradient: Nu_hot = (\S+) Nu_cold = (\S+)",
                          text, re.M)
    if not heat:
        return None
    hot, cold, time = (float(v) for v in heat[-1])
    return {"heat": (hot, cold), "time": time,
            "gradient": tuple(float(v) for v in gradient[-1]) if gradient else None}
