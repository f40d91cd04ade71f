"""Time series: the columns of a 'fix ave/time' or 'fix print' file, the
time average of a signal over a window, and when it reaches steady state."""

import numpy as np


class SeriesError(ValueError):
    """A series file that cannot be read as a table (one-line message)."""


def read_table(path):
    """Columns of a fix ave/time or fix print file as ([names], 2-D array).

    Columns are named by the last '#' line before the data (e.g.
    '# TimeStep c_T v_q'), or 1, 2, 3, ... without one; later comments (a
    restarted run's title) do not rename them."""
    header, rows = None, []
    with open(path) as f:
        for line in f:
            words = line.split()
            if not words:
                continue
            if words[0].startswith("#"):
                if not rows:
                    header = line.lstrip("#").split()
                continue
            try:
                rows.append([float(w) for w in words])
            except ValueError:
                raise SeriesError(f"non-numeric data in {path}: {line.strip()}")
    if not rows:
        raise SeriesError(f"no data in {path}")
    if len({len(r) for r in rows}) > 1:
        # fix ave/time in vector mode interleaves 'step nrows' lines with rows
        raise SeriesError(f"rows of different lengths in {path} (fix ave/time mode vector is not supported)")
    ncols = len(rows[0])
    if not header or len(header) != ncols:
        header = [str(i + 1) for i in range(ncols)]
    return header, np.array(rows)


def read_columns(path):
    """The columns of a series file as {name: numpy array}."""
    names, data = read_table(path)
    return {name: data[:, k] for k, name in enumerate(names)}


def time_average(t, y, start=None, end=None):
    """The time average of y(t) over [start, end] (default: the whole
    series), by the trapezoidal rule on the samples, so that unevenly spaced
    samples (fix sph/dt/reset) are weighted by the time they stand for; the
    ends of the window are interpolated linearly."""
    t, y = np.asarray(t, float), np.asarray(y, float)
    if t.ndim != 1 or t.shape != y.shape or len(t) < 2:
        raise ValueError("time_average: t and y must be 1-D of the same length, at least 2")
    if np.any(np.diff(t) <= 0):
        raise ValueError("time_average: t must increase")
    start = t[0] if start is None else max(float(start), t[0])
    end = t[-1] if end is None else min(float(end), t[-1])
    if not end > start:
        raise ValueError(f"time_average: empty window [{start:g}, {end:g}] in [{t[0]:g}, {t[-1]:g}]")
    inside = (t > start) & (t < end)
    tw = np.concatenate([[start], t[inside], [end]])
    yw = np.concatenate([[np.interp(start, t, y)], y[inside], [np.interp(end, t, y)]])
    return float(np.sum(0.5 * (yw[1:] + yw[:-1]) * np.diff(tw)) / (end - start))


def steady_state(t, y, rtol=1e-3, atol=0.0, window=None):
    """When y(t) has settled: the first time t_s from which every later
    sample stays within rtol * |y_final| + atol of the final value (the mean
    over the last 'window' of time, default a tenth of the series). Returns
    (t_s, y_final); t_s is None when the last sample is itself outside the band
    (the series has not settled)."""
    t, y = np.asarray(t, float), np.asarray(y, float)
    if t.ndim != 1 or t.shape != y.shape or len(t) < 2:
        raise ValueError("steady_state: t and y must be 1-D of the same length, at least 2")
    span = t[-1] - t[0]
    window = 0.1 * span if window is None else float(window)
    final = time_average(t, y, t[-1] - window, t[-1]) if window > 0 else float(y[-1])
    band = rtol * abs(final) + atol
    outside = np.abs(y - final) > band
    if outside[-1]:
        return None, final
    if not outside.any():
        return float(t[0]), final
    last_out = np.nonzero(outside)[0][-1]
    return float(t[last_out + 1]), final
