"""Plot LAMMPS output of the SPH examples as PNG files.

  field    particles at (x, y) coloured by a dump column, one PNG per frame;
           --types/--exclude-types keep some particle types only (default:
           the moving types when the dump has type, vx and vy and some types
           never move, e.g. wall dummies, else all), --arrows draws the
           velocity (vx, vy) of a subsample
  profile  a dump column averaged in bins along x or y, one curve per frame
  series   columns of a 'fix ave/time' or 'fix print' file against another

Run it with a python that has numpy and matplotlib (tools/find-python.sh
prints one). Frames are chosen by timestep: all, last, or a list such as
0,1000. Columns of a series file are named by its last '#' line before the
data (e.g. '# TimeStep c_T v_q'), or 1, 2, 3, ... without one; either the
name or the 1-based index selects a column. Each PNG written is printed.

Examples:
  PY=$(tools/find-python.sh)
  $PY tools/sphplot.py field out/erf.dump --color c_T --frames 0,2000
  $PY tools/sphplot.py field out/erf.dump --color c_T --vmin 0 --vmax 1 --out erf-T
  $PY tools/sphplot.py field out/cavity.dump --color c_T --exclude-types 2 --arrows
  $PY tools/sphplot.py profile out/erf.dump --along x --value c_T --out erf-profile.png
  $PY tools/sphplot.py series out/correct.flux --x time --y q_energy,q_direct --logy
  $PY tools/sphplot.py series tavg.txt --x 1 --y 2,3
"""

import argparse
import os
import re
import sys

import numpy as np

from sphthermal_tools import series
from sphthermal_tools.dump import read_frames


class InputError(Exception):
    """Bad input: reported as one line, exit status 1."""


def bin_means(coord, values, nbins, lo, hi):
    """Mean of values in nbins equal bins over [lo, hi] of coord.

    Returns (bin centres, means); empty bins are NaN, points outside [lo, hi]
    are ignored and a point at hi belongs to the last bin."""
    coord, values = np.asarray(coord, float), np.asarray(values, float)
    inside = (coord >= lo) & (coord <= hi)
    index = np.floor((coord[inside] - lo) / (hi - lo) * nbins).astype(int)
    index = np.minimum(index, nbins - 1)
    sums = np.bincount(index, weights=values[inside], minlength=nbins)
    counts = np.bincount(index, minlength=nbins)
    with np.errstate(invalid="ignore", divide="ignore"):
        means = np.where(counts > 0, sums / counts, np.nan)
    edges = np.linspace(lo, hi, nbins + 1)
    return 0.5 * (edges[:-1] + edges[1:]), means


def bins_for(coord, nbins=None):
    """Bin count and range for a profile along coord.

    Without nbins, one bin per distinct coordinate (a lattice's columns) up to
    200, else 50. The range is padded by half a bin so that the outermost
    particles sit at bin centres rather than on edges."""
    distinct = np.unique(np.round(coord, 9))
    if nbins is None:
        nbins = len(distinct) if len(distinct) <= 200 else 50
    a, b = distinct[0], distinct[-1]
    width = (b - a) / max(nbins - 1, 1) if b > a else 1.0
    return nbins, a - width / 2, b + width / 2


# ------------------------------------------------------------------ input

def require_file(path):
    if not os.path.isfile(path):
        raise InputError(f"no such file: {path}")


def load_dump(path):
    require_file(path)
    try:
        frames = read_frames(path)
    except (ValueError, IndexError) as e:
        raise InputError(f"cannot read {path} as a LAMMPS dump custom file: {e}")
    if not frames:
        raise InputError(f"no frames in {path} (not a LAMMPS dump custom file?)")
    return frames


def require_columns(path, columns, names):
    for name in names:
        if name not in columns:
            raise InputError(f"no column '{name}' in {path} (columns: {' '.join(columns)})")


def choose_frames(path, frames, spec):
    """Frames for 'all', 'last' or a comma-separated list of timesteps."""
    if spec == "all":
        return frames
    if spec == "last":
        return frames[-1:]
    by_step = {step: (step, columns) for step, columns in frames}
    chosen = []
    for word in spec.split(","):
        try:
            step = int(word)
        except ValueError:
            raise InputError(f"--frames takes all, last or timesteps like 0,1000, not '{spec}'")
        if step not in by_step:
            raise InputError(f"no timestep {step} in {path} (timesteps: {' '.join(map(str, by_step))})")
        chosen.append(by_step[step])
    return chosen


def read_table(path):
    """Columns of a fix ave/time or fix print file as ([names], 2-D array)."""
    require_file(path)
    try:
        return series.read_table(path)
    except series.SeriesError as e:
        raise InputError(str(e))


def table_column(path, names, key):
    """A column by name, or by 1-based index when no column has that name."""
    if key in names:
        return names.index(key)
    if key.isdigit() and 1 <= int(key) <= len(names):
        return int(key) - 1
    listing = " ".join(f"{i + 1}:{n}" for i, n in enumerate(names))
    raise InputError(f"no column '{key}' in {path} (columns: {listing})")


def stem(path):
    return os.path.splitext(path)[0]


def safe(name):
    """A column name usable in a file name (c_f[1] -> c_f_1_)."""
    return re.sub(r"[^\w.-]", "_", name)


# --------------------------------------------------------------- plotting

def pyplot():
    # imported here so that bin_means etc. need only numpy, and never a display
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    return plt


def make_axes_locatable(ax):
    from mpl_toolkits.axes_grid1 import make_axes_locatable as locatable
    return locatable(ax)


def type_list(text, option):
    try:
        return sorted({int(w) for w in text.split(",")})
    except ValueError:
        raise InputError(f"{option} takes atom types like 1 or 2,3, not '{text}'")


def moving_types(chosen):
    """The types with a non-zero velocity in any of the frames, when the dump
    has type, vx and vy and some types never move (wall dummies); else None."""
    if not all(all(k in c for k in ("type", "vx", "vy")) for _, c in chosen):
        return None
    types = np.unique(np.concatenate([c["type"] for _, c in chosen])).astype(int)
    moving = [t for t in types
              if any(np.any((c["type"] == t) & ((c["vx"] != 0) | (c["vy"] != 0))) for _, c in chosen)]
    return moving if 0 < len(moving) < len(types) else None


def select_types(path, chosen, types, exclude):
    """The frames with only the particles of the chosen types, and a
    description of the choice (None: all)."""
    if types is None and exclude is None:
        keep = moving_types(chosen)
        how = None if keep is None else f"moving types {','.join(map(str, keep))}"
    else:
        keep = None
        if any("type" not in c for _, c in chosen):
            raise InputError(f"no column 'type' in {path}: --types and --exclude-types need it")
        present = np.unique(np.concatenate([c["type"] for _, c in chosen])).astype(int).tolist()
        keep = type_list(types, "--types") if types is not None else present
        if exclude is not None:
            keep = [t for t in keep if t not in type_list(exclude, "--exclude-types")]
        if not any(t in present for t in keep):
            raise InputError(f"no particles of types {','.join(map(str, keep)) or '(none)'} in {path} "
                             f"(types: {' '.join(map(str, present))})")
        how = f"types {','.join(map(str, keep))}"
    if keep is None:
        return chosen, None
    out = []
    for step, columns in chosen:
        mask = np.isin(columns["type"].astype(int), keep)
        out.append((step, {name: col[mask] for name, col in columns.items()}))
    return out, how


def arrow_subsample(n, every=None, most=400):
    """Indices of the particles that get an arrow: every 'every'-th, or
    evenly spread, at most 'most' of them."""
    step = every if every else max(1, int(np.ceil(n / most)))
    return np.arange(0, n, step)


def plot_field(args):
    frames = load_dump(args.dump)
    chosen = choose_frames(args.dump, frames, args.frames)
    for _, columns in chosen:
        require_columns(args.dump, columns, ["x", "y", args.color] + (["vx", "vy"] if args.arrows else []))
    chosen, how = select_types(args.dump, chosen, args.types, args.exclude_types)
    # one colour scale for all frames so that they can be compared
    vmin = args.vmin if args.vmin is not None else min(np.nanmin(c[args.color]) for _, c in chosen)
    vmax = args.vmax if args.vmax is not None else max(np.nanmax(c[args.color]) for _, c in chosen)
    prefix = args.out or f"{stem(args.dump)}-{safe(args.color)}"
    print(f"sphplot: {args.color} from {vmin:.6g} to {vmax:.6g} over {how or 'all particles'}",
          file=sys.stderr)
    plt = pyplot()
    for step, columns in chosen:
        x, y, value = columns["x"], columns["y"], columns[args.color]
        xr, yr = np.ptp(x), np.ptp(y)
        height = 7 * yr / xr if xr > 0 else 7
        fig, ax = plt.subplots(figsize=(7, min(max(height + 1.5, 3), 8)))
        dots = ax.scatter(x, y, c=value, s=20, cmap=args.cmap, vmin=vmin, vmax=vmax, linewidths=0)
        if args.arrows:
            pick = arrow_subsample(len(x), args.arrow_every)
            ax.quiver(x[pick], y[pick], columns["vx"][pick], columns["vy"][pick], color="k",
                      angles="xy", width=0.003)
            print(f"sphplot: step {step}: {len(pick)} arrows of {len(x)} particles", file=sys.stderr)
        ax.set_aspect("equal")
        ax.margins(0.02)
        # a colorbar as tall as the (possibly flat) axes
        bar_axes = make_axes_locatable(ax).append_axes("right", size=0.15, pad=0.1)
        fig.colorbar(dots, cax=bar_axes, label=args.color)
        ax.set_xlabel("x")
        ax.set_ylabel("y")
        ax.set_title(f"{args.color}, step {step}")
        if args.size is not None:
            dots.set_sizes([args.size])
        elif xr > 0 and yr > 0:
            # markers 0.9 of the mean particle spacing wide: the particles tile the plot
            # yet stay distinguishable; measured after layout, in points
            fig.canvas.draw()
            points_per_unit = ax.get_window_extent().width / np.diff(ax.get_xlim())[0] * 72 / fig.dpi
            spacing = np.sqrt(xr * yr / len(x))
            dots.set_sizes([(0.9 * spacing * points_per_unit) ** 2])
        path = f"{prefix}-{step}.png"
        fig.savefig(path, dpi=120, bbox_inches="tight")
        plt.close(fig)
        print(path)


def plot_profile(args):
    frames = load_dump(args.dump)
    chosen = choose_frames(args.dump, frames, args.frames)
    for _, columns in chosen:
        require_columns(args.dump, columns, [args.along, args.value])
    # the same bins for every frame, over all of their particles
    nbins, lo, hi = bins_for(np.concatenate([c[args.along] for _, c in chosen]), args.bins)
    plt = pyplot()
    fig, ax = plt.subplots(figsize=(7, 4.5))
    for step, columns in chosen:
        centres, means = bin_means(columns[args.along], columns[args.value], nbins, lo, hi)
        filled = np.isfinite(means)
        ax.plot(centres[filled], means[filled], ".-", label=f"step {step}")
    ax.set_xlabel(args.along)
    ax.set_ylabel(f"{args.value}, mean over {'y' if args.along == 'x' else 'x'}")
    ax.set_title(f"{os.path.basename(args.dump)}: {args.value} along {args.along}, {nbins} bins")
    if len(chosen) <= 20:
        ax.legend(fontsize="small")
    ax.grid(alpha=0.3)
    path = args.out or f"{stem(args.dump)}-profile-{safe(args.value)}.png"
    fig.savefig(path, dpi=120, bbox_inches="tight")
    plt.close(fig)
    print(path)


def plot_series(args):
    names, data = read_table(args.file)
    xi = table_column(args.file, names, args.x)
    yis = [table_column(args.file, names, key) for key in args.y.split(",")]
    plt = pyplot()
    fig, ax = plt.subplots(figsize=(7, 4.5))
    for yi in yis:
        ax.plot(data[:, xi], data[:, yi], label=names[yi])
    if args.logy:
        ax.set_yscale("log")
    ax.set_xlabel(names[xi])
    if len(yis) == 1:
        ax.set_ylabel(names[yis[0]])
    else:
        ax.legend()
    ax.set_title(os.path.basename(args.file))
    ax.grid(alpha=0.3)
    path = args.out or f"{stem(args.file)}-series.png"
    fig.savefig(path, dpi=120, bbox_inches="tight")
    plt.close(fig)
    print(path)


def main(argv=None):
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    sub = p.add_subparsers(dest="command", required=True)

    f = sub.add_parser("field", help="particles coloured by a column, one PNG per frame")
    f.add_argument("dump")
    f.add_argument("--color", required=True, help="dump column, e.g. c_T")
    f.add_argument("--frames", default="last", help="all, last (default) or timesteps like 0,1000")
    f.add_argument("--out", help="PNG prefix: writes PREFIX-<step>.png (default: DUMP-COLUMN)")
    f.add_argument("--size", type=float, help="marker size in points^2 (default: the particle spacing)")
    f.add_argument("--cmap", default="viridis")
    f.add_argument("--vmin", type=float, help="colour scale (default: over the chosen frames)")
    f.add_argument("--vmax", type=float)
    f.add_argument("--types", help="atom types to show, e.g. 1 or 1,3 (default: the moving types "
                                   "if the dump has type, vx, vy and some types never move, else all)")
    f.add_argument("--exclude-types", help="atom types to leave out, e.g. 2,3 (wall dummies)")
    f.add_argument("--arrows", action="store_true", help="velocity arrows from the vx, vy columns")
    f.add_argument("--arrow-every", type=int, help="an arrow on every N-th particle (default: at most 400)")
    f.set_defaults(run=plot_field)

    r = sub.add_parser("profile", help="a column averaged in bins along x or y")
    r.add_argument("dump")
    r.add_argument("--along", choices=["x", "y"], required=True)
    r.add_argument("--value", required=True, help="dump column, e.g. c_T")
    r.add_argument("--frames", default="all", help="all (default), last or timesteps like 0,1000")
    r.add_argument("--bins", type=int, help="default: one per lattice column, up to 200, else 50")
    r.add_argument("--out", help="PNG file (default: DUMP-profile-VALUE.png)")
    r.set_defaults(run=plot_profile)

    s = sub.add_parser("series", help="columns of a fix ave/time or fix print file")
    s.add_argument("file")
    s.add_argument("--x", required=True, help="column name or 1-based index")
    s.add_argument("--y", required=True, help="column names or indices, comma-separated")
    s.add_argument("--out", help="PNG file (default: FILE-series.png)")
    s.add_argument("--logy", action="store_true")
    s.set_defaults(run=plot_series)

    args = p.parse_args(argv)
    if getattr(args, "bins", None) is not None and args.bins < 1:
        p.error("--bins must be at least 1")
    if getattr(args, "arrow_every", None) is not None and args.arrow_every < 1:
        p.error("--arrow-every must be at least 1")
    try:
        args.run(args)
    except (InputError, OSError) as e:  # OSError: e.g. --out in a missing directory
        sys.exit(f"sphplot: {e}")


if __name__ == "__main__":
    main()
