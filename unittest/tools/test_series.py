"""sphthermal_tools.series: time averages and steady state against signals
whose answers are known in closed form, and the series-file reader.

  y = 1 - exp(-t / tau): the time average over [a, b] is
  1 - tau (exp(-a/tau) - exp(-b/tau)) / (b - a), and the signal stays within
  rtol of its final value 1 from t_s = tau ln(1 / rtol)."""

import math
import os
import tempfile

import numpy as np

from checks import finish, that
from sphthermal_tools.series import read_columns, read_table, steady_state, time_average


def main():
    # a known average: sin over whole periods, uneven sampling
    t = np.sort(np.concatenate([np.linspace(0.0, 4.0 * math.pi, 2001),
                                np.random.default_rng(1).uniform(0.0, 4.0 * math.pi, 500)]))
    t = np.unique(t)
    avg = time_average(t, 2.0 + np.sin(t))
    that(abs(avg - 2.0) < 1e-5, "average of 2 + sin(t) over two periods, uneven samples", f"{avg!r}")
    # the average of a linear ramp over a window inside the series (ends interpolated)
    t = np.linspace(0.0, 10.0, 11)
    avg = time_average(t, 3.0 * t, 2.5, 7.5)
    that(abs(avg - 15.0) < 1e-12, "average of 3 t over [2.5, 7.5] is 15", f"{avg!r}")

    # exponential approach
    tau, rtol = 0.7, 1e-3
    t = np.linspace(0.0, 20.0, 20001)
    y = 1.0 - np.exp(-t / tau)
    a, b = 0.5, 3.0
    exact = 1.0 - tau * (math.exp(-a / tau) - math.exp(-b / tau)) / (b - a)
    avg = time_average(t, y, a, b)
    that(abs(avg - exact) < 1e-7, "average of 1 - exp(-t/tau) over [0.5, 3]",
         f"{avg:.9f} against {exact:.9f}")
    t_s, final = steady_state(t, y, rtol=rtol)
    expected = tau * math.log(1.0 / rtol)   # 4.835 for tau = 0.7
    that(abs(final - 1.0) < 1e-9, "steady value 1", f"{final!r}")
    that(t_s is not None and abs(t_s - expected) < 0.01,
         f"steady from tau ln(1/rtol) = {expected:.4f}", f"{t_s}")
    # not settled: a ramp never stays within 1e-3 of its last-window mean
    t_s, _ = steady_state(t, t, rtol=rtol)
    that(t_s is None, "a ramp is not steady", f"{t_s}")
    # a noisy plateau with atol: settled once the approach is within the noise band
    rng = np.random.default_rng(2)
    noisy = y + 1e-4 * rng.standard_normal(len(t))
    t_s, final = steady_state(t, noisy, rtol=0.0, atol=1e-2)
    expected = tau * math.log(1.0 / 1e-2)
    that(t_s is not None and abs(t_s - expected) < 0.05 and abs(final - 1.0) < 1e-4,
         "noisy plateau: steady from tau ln(100) within the absolute band", f"{t_s}, {final}")

    # the reader: header names, numbers, no data
    with tempfile.TemporaryDirectory() as tmp:
        path = os.path.join(tmp, "tavg.txt")
        with open(path, "w") as f:
            f.write("# Time-averaged data for fix tavg\n# TimeStep c_T v_flux\n0 1 2\n10 3 4\n")
        names, data = read_table(path)
        that(names == ["TimeStep", "c_T", "v_flux"] and data.shape == (2, 3), "read_table names",
             f"{names} {data.shape}")
        that(list(read_columns(path)["v_flux"]) == [2.0, 4.0], "read_columns by name")
        empty = os.path.join(tmp, "empty.txt")
        with open(empty, "w") as f:
            f.write("# TimeStep c_T\n")
        try:
            read_table(empty)
            that(False, "no data refused")
        except ValueError as e:
            that("no data" in str(e), "no data refused", str(e))
    finish(passed="all passed")


if __name__ == "__main__":
    main()
