"""tools/sphplot.py on synthetic files: a dump custom file of 2 frames with a
temperature linear in x, and a fix ave/time-like file. Each subcommand must
write valid PNGs, bin_means must give the exact bin means of the linear field,
and bad input (missing column, file or data) must fail with a one-line message.
A dump with moving fluid (type 1, T from 1 to 3) between wall dummies (types
2 and 3, at rest, T = 100 and -50): the colour range of 'field' must be the
fluid's with --types 1, --exclude-types 2,3 and by default (the moving types),
the walls' with --types 1,2; --arrows draws a subsample of the velocities.

  python test_sphplot.py --python /usr/bin/python3

This script needs only the standard library: everything that needs numpy and
matplotlib runs in subprocesses of --python (default: this interpreter)."""

import argparse
import json
import os
import subprocess
import sys
import tempfile

from checks import finish, that

TOOLS = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "tools")
SPHPLOT = os.path.join(TOOLS, "sphplot.py")
PNG_MAGIC = b"\x89PNG\r\n\x1a\n"
NX, NY = 20, 4  # particles at cell centres of [0, 1] x [0, 0.2]


def temperature(x, step):
    """The synthetic field: linear in x, a different slope per frame."""
    return 1.0 + (2.0 if step == 0 else -3.0) * x


def write_dump(path):
    with open(path, "w") as f:
        for step in (0, 100):
            f.write(f"ITEM: TIMESTEP\n{step}\nITEM: NUMBER OF ATOMS\n{NX * NY}\n"
                    "ITEM: BOX BOUNDS pp pp pp\n0 1\n0 0.2\n-0.025 0.025\n"
                    "ITEM: ATOMS id x y c_T\n")
            for j in range(NY):
                for i in range(NX):
                    x, y = (i + 0.5) / NX, (j + 0.5) * 0.05
                    f.write(f"{j * NX + i + 1} {x!r} {y!r} {temperature(x, step)!r}\n")


def write_walls_dump(path):
    """Fluid rows (type 1, moving, T in [1, 3]) between a bottom wall row
    (type 2, T = 100) and a top one (type 3, T = -50), both at rest."""
    with open(path, "w") as f:
        f.write(f"ITEM: TIMESTEP\n0\nITEM: NUMBER OF ATOMS\n{NX * (NY + 2)}\n"
                "ITEM: BOX BOUNDS pp ff pp\n0 1\n-0.05 0.25\n-0.025 0.025\n"
                "ITEM: ATOMS id type x y vx vy c_T\n")
        for j in range(-1, NY + 1):
            for i in range(NX):
                x, y = (i + 0.5) / NX, (j + 0.5) * 0.05
                kind = 2 if j < 0 else 3 if j == NY else 1
                vx, vy = (0.0, 0.0) if kind != 1 else (0.1 * (j + 1), 0.01 * x)
                T = {1: 1.0 + 2.0 * x, 2: 100.0, 3: -50.0}[kind]
                f.write(f"{(j + 1) * NX + i + 1} {kind} {x!r} {y!r} {vx!r} {vy!r} {T!r}\n")


def colour_range(result):
    """(vmin, vmax, what) of sphplot's 'c_T from A to B over WHAT' line, or None."""
    for line in result.stderr.splitlines():
        words = line.split()
        if words[:4] == ["sphplot:", "c_T", "from", words[3]] and len(words) > 7 and words[4] == "to":
            return float(words[3]), float(words[5]), " ".join(words[7:])
    return None


def check_types_and_arrows(python, tmp):
    dump = os.path.join(tmp, "walls.dump")
    write_walls_dump(dump)
    out = lambda name: os.path.join(tmp, name)  # noqa: E731
    fluid = (1.0 + 2.0 * 0.5 / NX, 1.0 + 2.0 * (NX - 0.5) / NX)
    for options, expected, what in (
            (["--types", "1"], fluid, "--types 1: the fluid's range"),
            (["--exclude-types", "2,3"], fluid, "--exclude-types 2,3: the fluid's range"),
            ([], fluid, "default: the moving types' range (walls at rest left out)"),
            (["--types", "1,2"], (fluid[0], 100.0), "--types 1,2: up to the bottom wall's 100"),
            (["--exclude-types", "2"], (-50.0, fluid[1]), "--exclude-types 2: down to the top wall's -50")):
        name = "walls-" + ("-".join(options).replace(",", "_").replace("--", "") or "default")
        result = run(python, "field", dump, "--color", "c_T", "--out", out(name), *options)
        check_pngs(result, [out(name + "-0.png")], f"field {' '.join(options) or '(default types)'}")
        found = colour_range(result)
        that(found is not None and abs(found[0] - expected[0]) < 1e-9 and abs(found[1] - expected[1]) < 1e-9,
             what, f"{found} against {expected}")
    # the same frame without velocities: no default filter, every type
    plain = run(python, "field", dump, "--color", "c_T", "--types", "1,2,3", "--out", out("walls-all"))
    found = colour_range(plain)
    that(found is not None and found[:2] == (-50.0, 100.0), "--types 1,2,3: the whole range", f"{found}")
    # arrows: a subsample of the fluid's velocities, and a different picture
    result = run(python, "field", dump, "--color", "c_T", "--types", "1", "--arrows", "--arrow-every", "3",
                 "--out", out("walls-arrows"))
    check_pngs(result, [out("walls-arrows-0.png")], "field --arrows")
    counts = [line.split() for line in result.stderr.splitlines() if "arrows of" in line]
    n_fluid = NX * NY
    that(len(counts) == 1 and int(counts[0][3]) == -(-n_fluid // 3) and int(counts[0][6]) == n_fluid,
         "--arrow-every 3: every third fluid particle has an arrow", str(counts))
    with open(out("walls-arrows-0.png"), "rb") as f, open(out("walls-types-1-0.png"), "rb") as g:
        that(f.read() != g.read(), "--arrows changes the picture")
    result = run(python, "field", dump, "--color", "c_T", "--types", "1", "--arrows", "--out", out("walls-auto"))
    counts = [line.split() for line in result.stderr.splitlines() if "arrows of" in line]
    that(len(counts) == 1 and int(counts[0][3]) == n_fluid, "--arrows: all of 80 particles (below 400)",
         str(counts))
    # bad choices
    check_fails(run(python, "field", dump, "--color", "c_T", "--types", "7"), ["7", "1 2 3"],
                "--types: a type not in the dump")
    check_fails(run(python, "field", dump, "--color", "c_T", "--types", "a"), ["--types", "a"],
                "--types: not a type")
    linear = os.path.join(tmp, "linear.dump")
    check_fails(run(python, "field", linear, "--color", "c_T", "--arrows"), ["vx"],
                "--arrows without vx, vy")
    check_fails(run(python, "field", linear, "--color", "c_T", "--types", "1"), ["type"],
                "--types without a type column")


def write_ave_time(path):
    with open(path, "w") as f:
        f.write("# Time-averaged data for fix tavg\n# TimeStep c_T v_flux\n")
        for step in range(0, 1001, 100):
            f.write(f"{step} {1.0 + step / 1000} {2.0 ** (-step / 100)}\n")


def run(python, *args):
    return subprocess.run([python, SPHPLOT, *args], capture_output=True, text=True)


def check_pngs(result, expected, what):
    """The command succeeded and printed exactly the expected, valid PNGs."""
    printed = result.stdout.split()
    that(result.returncode == 0, f"{what} exits 0", result.stderr.strip())
    that(printed == expected, f"{what} prints its PNGs", " ".join(printed))
    for path in expected:
        size, magic = 0, b""
        if os.path.isfile(path):
            size = os.path.getsize(path)
            with open(path, "rb") as f:
                magic = f.read(8)
        that(magic == PNG_MAGIC and size > 5000, f"{what} writes a PNG {os.path.basename(path)}",
             f"{size} bytes")


def check_fails(result, words, what):
    """Non-zero exit with a one-line message naming each of words."""
    message = result.stderr.strip()
    ok = result.returncode != 0 and "\n" not in message and all(w in message for w in words)
    that(ok, what, f"exit {result.returncode}, {message!r}")


def check_bin_means(python):
    """bin_means against the linear field, whose bin means are its values at
    the bin centres when the particles sit symmetrically in each bin."""
    code = f"""
import json
import numpy as np
from sphplot import bin_means, bins_for
x = np.repeat((np.arange({NX}) + 0.5) / {NX}, {NY})
out = {{}}
c, m = bin_means(x, 1.0 + 2.0 * x, 10, 0.0, 1.0)   # 2 columns per bin
out["centres"], out["means"] = c.tolist(), m.tolist()
# bins of 0.5 over [0, 2]: 2 points, 1, none, 2 with one at hi; 2.5 is outside
c, m = bin_means([0.0, 0.2, 0.5, 1.9, 2.0, 2.5], [1.0, 3.0, 5.0, 7.0, 9.0, 100.0], 4, 0.0, 2.0)
out["edges"] = [None if v != v else v for v in m]
out["auto"] = list(bins_for(x))
print(json.dumps(out))
"""
    result = subprocess.run([python, "-c", code], capture_output=True, text=True)
    that(result.returncode == 0, "bin_means runs", result.stderr.strip()[-300:])
    if result.returncode:
        return
    out = json.loads(result.stdout)
    centres = [(k + 0.5) / 10 for k in range(10)]
    error = max(abs(m - (1.0 + 2.0 * c)) for m, c in zip(out["means"], centres))
    that(max(abs(a - b) for a, b in zip(out["centres"], centres)) < 1e-12, "bin centres")
    that(error < 1e-12, "bin means of a linear field", f"max error {error:.1e}")
    that(out["edges"] == [2.0, 5.0, None, 8.0], "point at hi in the last bin, outside ignored, empty NaN",
         str(out["edges"]))
    nbins, lo, hi = out["auto"]
    that(nbins == NX and abs(lo) < 1e-12 and abs(hi - 1.0) < 1e-12,
         "default bins: one per lattice column", str(out["auto"]))


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--python", default=sys.executable, help="a python with numpy and matplotlib")
    python = p.parse_args().python

    check_bin_means(python)
    with tempfile.TemporaryDirectory() as tmp:
        dump, ave = os.path.join(tmp, "linear.dump"), os.path.join(tmp, "tavg.txt")
        write_dump(dump)
        write_ave_time(ave)
        out = lambda name: os.path.join(tmp, name)  # noqa: E731

        check_pngs(run(python, "field", dump, "--color", "c_T", "--frames", "all", "--out", out("T")),
                   [out("T-0.png"), out("T-100.png")], "field --frames all")
        check_pngs(run(python, "field", dump, "--color", "c_T", "--frames", "100", "--cmap", "coolwarm",
                       "--vmin", "0", "--vmax", "3", "--size", "30"), [out("linear-c_T-100.png")],
                   "field, one frame, default prefix")
        check_pngs(run(python, "profile", dump, "--along", "x", "--value", "c_T", "--bins", "10",
                       "--out", out("profile.png")), [out("profile.png")], "profile along x")
        check_pngs(run(python, "profile", dump, "--along", "y", "--value", "c_T", "--frames", "last"),
                   [out("linear-profile-c_T.png")], "profile along y, default name")
        check_pngs(run(python, "series", ave, "--x", "TimeStep", "--y", "c_T,3", "--logy",
                       "--out", out("series.png")), [out("series.png")], "series by name and index")

        check_fails(run(python, "field", dump, "--color", "c_Q"), ["c_Q", dump, "c_T"],
                    "field: missing column named with the columns there are")
        check_fails(run(python, "profile", dump, "--along", "x", "--value", "v_rho"), ["v_rho"],
                    "profile: missing column")
        check_fails(run(python, "field", dump, "--color", "c_T", "--frames", "50"), ["50", "0 100"],
                    "field: missing timestep")
        check_fails(run(python, "series", ave, "--x", "TimeStep", "--y", "c_Q"), ["c_Q", "v_flux"],
                    "series: missing column")
        check_fails(run(python, "series", out("absent.txt"), "--x", "1", "--y", "2"), ["absent.txt"],
                    "series: missing file")
        with open(out("empty.txt"), "w") as f:
            f.write("# TimeStep c_T\n")
        check_fails(run(python, "series", out("empty.txt"), "--x", "1", "--y", "2"), ["no data"],
                    "series: no data")
        check_fails(run(python, "field", ave, "--color", "c_T"), ["no frames"], "field: not a dump")

        check_types_and_arrows(python, tmp)

        # without a header the columns are 1, 2, 3, ...
        with open(out("bare.txt"), "w") as f:
            f.write("0 1 2\n1 2 4\n2 3 8\n")
        check_pngs(run(python, "series", out("bare.txt"), "--x", "1", "--y", "2,3", "--out", out("bare.png")),
                   [out("bare.png")], "series without a header")

    finish(passed="all passed")


if __name__ == "__main__":
    main()
