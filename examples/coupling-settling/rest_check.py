"""How far a neutrally buoyant disc of in.tank moves after its release:
the largest distance of its centre from where it was released, from the
series file (in.tank's <out>.series) and the log (its "released at t =").

    rest_check.py tank_rest.series --log log.tank_rest [--dx 0.002] [--max-move 0.1]

Prints the largest distance and speed after the release; exits 1 when the
distance exceeds --max-move spacings dx.
"""

import argparse
import math
import re


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("series")
    ap.add_argument("--log", required=True)
    ap.add_argument("--dx", type=float, default=0.002)
    ap.add_argument("--max-move", type=float, help="in spacings dx")
    args = ap.parse_args()
    with open(args.log) as f:
        found = re.findall(r"^released at t = (\S+) s", f.read(), re.M)
    if not found:
        print(f"FAIL: no 'released at t =' line in {args.log}")
        return 1
    released = float(found[-1])
    # columns: step, t, x and y of the centre, its velocity (x, y), spin
    rows = []
    with open(args.series) as f:
        for line in f:
            if not line.startswith("#") and line.strip():
                rows.append([float(v) for v in line.split()])
    held = [r for r in rows if r[1] <= released]
    free = [r for r in rows if r[1] > released]
    if not held or not free:
        print(f"FAIL: {args.series} has no rows before and after the release at t = {released}")
        return 1
    x0, y0 = held[-1][2], held[-1][3]
    move = max(math.hypot(r[2] - x0, r[3] - y0) for r in free)
    speed = max(math.hypot(r[4], r[5]) for r in free)
    spin = max(abs(r[6]) for r in free)
    print(f"after the release at t = {released:.4g} s, for {free[-1][1] - released:.3g} s: the "
          f"centre moved at most {move:.3e} m ({move / args.dx:.3f} dx), largest speed "
          f"{speed:.3e} m/s, largest spin {spin:.3e} 1/s")
    if args.max_move is not None and move > args.max_move * args.dx:
        print(f"FAIL: the neutral disc moved {move / args.dx:.3f} dx (more than {args.max_move} dx)")
        return 1
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
