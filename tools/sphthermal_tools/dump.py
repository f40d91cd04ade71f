"""Read LAMMPS 'dump custom' text files (the format OVITO and ParaView read)."""

import numpy as np


def read_frames(path):
    """Return a list of (timestep, {column: numpy array}) sorted by atom id."""
    frames = []
    with open(path) as f:
        lines = f.read().splitlines()
    i = 0
    while i < len(lines):
        if lines[i].startswith("ITEM: TIMESTEP"):
            step = int(lines[i + 1])
            natoms = int(lines[i + 3])
            while not lines[i].startswith("ITEM: ATOMS"):
                i += 1
            names = lines[i].split()[2:]
            data = np.loadtxt(lines[i + 1:i + 1 + natoms], ndmin=2)
            columns = {name: data[:, c] for c, name in enumerate(names)}
            if "id" in columns:
                order = np.argsort(columns["id"])
                columns = {name: col[order] for name, col in columns.items()}
            frames.append((step, columns))
            i += 1 + natoms
        else:
            i += 1
    return frames


def frame_times(path):
    """The simulation time of each frame (ITEM: TIME, written with dump_modify
    time yes, before its ITEM: TIMESTEP), None for a frame without one."""
    times, pending = [], None
    with open(path) as f:
        lines = iter(f)
        for line in lines:
            if line.strip() == "ITEM: TIME":
                pending = float(next(lines))
            elif line.startswith("ITEM: TIMESTEP"):
                times.append(pending)
                pending = None
    return times
