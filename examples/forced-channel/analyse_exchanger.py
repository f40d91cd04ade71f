#!/usr/bin/env python3
"""Analyse the heat exchangers (in.exchanger): the last frame of the
parallel-flow and counter-flow dumps against tools/channel_fv.py.

Per arrangement: the bulk (mixing-cup) temperature of each stream along x
(per lattice column) against the reference, the outlet temperatures (the
column at each stream's outlet end), the effectiveness
eps = (T_cold,out - T_cold,in) / (T_hot,in - T_cold,in) (the cold stream
has the smaller heat capacity rate), and the centre-line temperatures
T* = (T - T_C) / (T_H - T_C) of both streams (Ng et al. 2020, Fig 23) in a
PNG. Checks that the counter-flow cold outlet is the warmer.

  analyse_exchanger.py exchanger-parallel.dump exchanger-counter.dump [--n 10]
                       [--png exchanger.png] [--max-outlet-error PCT] [--history]

--history prints the outlet temperatures of every frame, to show whether the
run has reached its steady state.
"""
import argparse
import sys

import numpy as np

import channel_fv
from sphthermal_tools.dump import frame_times, read_frames

W, LENGTH, T_C, T_H = 0.1, 2.0, 300.0, 800.0


def streams(frame, n):
    """Bulk temperature per column of the cold (type 1) and hot (type 2)
    streams, and their centre-line temperatures (the row nearest y = W/2,
    5 W/2), of one dump frame (step, columns)."""
    step, d = frame
    dx = W / n
    ncol = int(round(LENGTH / dx))
    x = np.mod(d["x"], LENGTH)
    index = np.clip((x / dx).astype(int), 0, ncol - 1)
    out = {"step": step, "x": (np.arange(ncol) + 0.5) * dx}
    for name, kind, centre in (("cold", 1, 0.5 * W), ("hot", 2, 2.5 * W)):
        s = d["type"] == kind
        u = np.abs(d["vx"][s])
        out[name] = np.bincount(index[s], u * d["c_T"][s], ncol) / np.bincount(index[s], u, ncol)
        row = s & (np.abs(d["y"] - centre) < 0.5 * dx)
        order = np.argsort(x[row])
        out[name + "_line"] = (x[row][order], d["c_T"][row][order])
    return out


def when(t):
    """A frame's time, or that its dump has none (no dump_modify time yes)."""
    return f"t = {t:7.2f} s" if t is not None else "no time"


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawTextHelpFormatter)
    p.add_argument("parallel")
    p.add_argument("counter")
    p.add_argument("--n", type=int, default=10)
    p.add_argument("--png", default="exchanger.png")
    p.add_argument("--max-outlet-error", type=float,
                   help="fail if an outlet temperature is off the reference by more than PCT %% of T_H - T_C")
    p.add_argument("--history", action="store_true", help="the outlet temperatures of every frame")
    a = p.parse_args()
    dT = T_H - T_C
    ok = True
    results = {}
    for arrangement, dump in (("parallel", a.parallel), ("counter", a.counter)):
        ref = channel_fv.solve(channel_fv.preset("exchanger", counter=arrangement == "counter"))
        frames = read_frames(dump)
        s = streams(frames[-1], a.n)
        if a.history:
            # the frames' times (ITEM: TIME, dump_modify time yes)
            for frame, t in list(zip(frames, frame_times(dump)))[1:]:
                f = streams(frame, a.n)
                cold = f["cold"][-1] if arrangement == "parallel" else f["cold"][0]
                print(f"{arrangement} {when(t)}: cold outlet {cold:.2f} K, "
                      f"hot outlet {f['hot'][-1]:.2f} K")
        ref_cold = channel_fv.bulk_at(ref, "cold", s["x"])
        ref_hot = channel_fv.bulk_at(ref, "hot", s["x"])
        # outlets: the hot stream leaves at x = L; the cold one at x = L
        # (parallel) or x = 0 (counter)
        cold_out, ref_cold_out = (s["cold"][-1], ref_cold[-1]) if arrangement == "parallel" \
            else (s["cold"][0], ref_cold[0])
        hot_out, ref_hot_out = s["hot"][-1], ref_hot[-1]
        eps, ref_eps = (cold_out - T_C) / dT, (ref_cold_out - T_C) / dT
        err_bulk = 100.0 * max(np.abs(s["cold"] - ref_cold).max(), np.abs(s["hot"] - ref_hot).max()) / dT
        err_out = 100.0 * max(abs(cold_out - ref_cold_out), abs(hot_out - ref_hot_out)) / dT
        print(f"{arrangement} (step {s['step']}, {when(frame_times(dump)[-1])}): cold outlet {cold_out:.2f} K (reference "
              f"{ref_cold_out:.2f} K), hot outlet {hot_out:.2f} K ({ref_hot_out:.2f} K); "
              f"effectiveness {eps:.4f} ({ref_eps:.4f}); largest bulk error {err_bulk:.2f} %, "
              f"outlets {err_out:.2f} % of T_H - T_C")
        if a.max_outlet_error is not None and not err_out <= a.max_outlet_error:
            print(f"FAIL: {arrangement} outlet error above {a.max_outlet_error} %")
            ok = False
        results[arrangement] = (s, ref, cold_out)
    warmer = results["counter"][2] > results["parallel"][2]
    print(f"{'ok' if warmer else 'FAIL'}: the counter-flow cold outlet is "
          f"{results['counter'][2] - results['parallel'][2]:+.2f} K warmer than the parallel-flow one")
    ok &= warmer

    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        fig, ax = plt.subplots(figsize=(7, 4.5))
        for arrangement, style in (("parallel", "-"), ("counter", "--")):
            s, ref, _ = results[arrangement]
            for name, centre, colour in (("cold", 0.5 * W, "tab:blue"), ("hot", 2.5 * W, "tab:red")):
                xs = np.linspace(0.0, LENGTH, 201)
                t_ref = np.array([channel_fv.profile_at(ref, xv, [centre])[1][0] for xv in xs])
                ax.plot(xs, (t_ref - T_C) / dT, style, color=colour, lw=1,
                        label=f"{arrangement}, {name}: finite volume")
                lx, lt = s[name + "_line"]
                ax.plot(lx, (lt - T_C) / dT, "o" if arrangement == "parallel" else "s", ms=2,
                        color=colour, label=f"{arrangement}, {name}: SPH")
        ax.set_xlabel("x (m)")
        ax.set_ylabel("centre-line T* = (T - T_C) / (T_H - T_C)")
        ax.set_title("Heat exchangers (Ng et al. 2020, section 4.5)")
        ax.legend(fontsize=7, ncol=2)
        fig.tight_layout()
        fig.savefig(a.png, dpi=110)
        print(f"wrote {a.png}")
    except ImportError:
        print("no matplotlib: no PNG")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
