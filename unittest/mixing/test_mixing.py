"""Tests of compute sph/mixing against values computed here independently
(plain numpy: kernel sums, the affine map of a pure shear, the measures'
definitions of Reece et al. 2024, Table 4).

  segregated  two layers: F is 0 or 1 away from the interface, Robinson's
              measure 0 there; every per-particle value and global measure
              equals this script's, S* = 0 at the reference
  uniform     a checkerboard of the two components (mixed at the smallest
              scale): F and Robinson's measure against this script's
  shear       the layers in a pure shear x += gamma y t (fix nve/noforce): the FTLE
              equals ln(max_j |A r_j0| / |r_j0|) / T with A the shear's map,
              neighbours across the periodic boundary included; the VF-FTLE
              measure, entropies, fix ave/time and thermo agree
  ranks       the shear on 1, 2 and 4 ranks (atoms migrate): the same values
  restart     the shear stopped half-way, written, read and continued: the
              same values as without the restart
  renumber    the shear with the bottom row (outside the group) deleted
              half-way by delete_atoms, which renumbers the atom IDs: the
              same values as without it (the reference names each
              neighbour by its ID at the reference, which its atom keeps)
"""

import argparse
import math
import os
import shutil
import tempfile

import numpy as np

from lammps_checks import lammps_arguments, read_frames, run_lammps
from checks import below, finish, that

DX = 0.001
NX, NY = 16, 12
CUT = 4.0 * DX
GAMMA = 0.5     # shear rate, 1/s
STEPS = 200     # of 0.01 s: the top row moves 0.5 * 0.0115 * 2 = 11.5 mm, 0.7 box widths

COLUMNS = ["F", "ftle", "robinson", "vf_ftle"]
GLOBALS = ["mean_F", "f_all", "S_A", "S_B", "vf_ftle_mean", "robinson_mean", "ftle_max", "ftle_mean"]


def script(plugin, pattern="layers", steps=0, shear=True, part="whole", restart_file="mix.restart"):
    """The test's input. pattern: layers (type 2 above y = NY/2) or checker;
    part: whole, first (write a restart half-way) or second (read it)."""
    head = f"""plugin load {plugin}
units si
dimension 2
atom_style sph
"""
    build = f"""boundary p f p
lattice sq {DX} origin 0.5 0.5 0
region box block 0 {NX} 0 {NY} -0.5 0.5
create_box 3 box
create_atoms 1 box
"""
    if pattern == "layers":
        build += f"region upper block INF INF {NY // 2} INF INF INF\nset region upper type 2\n"
    else:
        build += "variable odd atom (round(x/1e-3-0.5)+round(y/1e-3-0.5))%2==1\n" \
                 "group odd variable odd\nset group odd type 2\n"
    materials = "fix materials all sph/materials type * conductivity constant 0.02587 cv 1006 " \
                "viscosity constant 1e-4 eos linear 1.0 rho0 1.2\n"
    # a row of a third type at the bottom and top: outside the group, ignored
    build += f"region rows block INF INF INF 1 INF INF\nregion rows2 block INF INF {NY - 1} INF INF INF\n" \
             "set region rows type 3\nset region rows2 type 3\n"
    build += materials + f"""sph/set all materials spacing {DX} temperature 283
# volumes that differ from particle to particle
variable rho atom 1.2*(1.0+0.05*sin(700*x+1300*y))
set group all sph/rho v_rho
"""
    common = f"""group top type 2
group fluid type 1 2
pair_style sph/harmonic/visc wendland {CUT}
pair_coeff * *
neighbor {0.2 * DX} bin
neigh_modify every 1 delay 0 check yes
timestep 0.01
"""
    if shear:
        # x = x0 + gamma y t: constant velocities, forces ignored
        if part != "second":
            build += f"variable shear atom {GAMMA}*y\nvelocity all set v_shear 0.0 0.0\n"
        common += "fix move all nve/noforce\n"
    common += f"""compute mix fluid sph/mixing top
fix average all ave/time 1 1 {max(steps, 1)} c_mix[*] file mix.ave
thermo_style custom step time c_mix c_mix[*]
thermo_modify format float %.15g
thermo {max(steps, 1)}
dump measures all custom {max(steps, 1)} mix.dump id type x y xu yu c_mix[*]
dump_modify measures format float %.16g
"""
    if part == "whole":
        return head + build + common + f"run {steps}\n"
    if part == "first":
        return head + build + common + f"run {steps // 2}\nwrite_restart {restart_file}\n"
    return head + f"read_restart {restart_file}\n" + materials + common + f"run {steps // 2}\n"


def run(args, text, workdir, np_=1):
    out = run_lammps(args.lmp, text, workdir, np_=np_, mpirun=args.mpirun)
    frames = read_frames(os.path.join(workdir, "mix.dump"))
    return out, frames


def thermo_globals(out):
    """The last thermo row: step, time, c_mix and c_mix[1..8]."""
    rows = [line.split() for line in out.splitlines()]
    rows = [r for r in rows if len(r) == 11 and all(_is_number(v) for v in r)]
    return np.array([float(v) for v in rows[-1]])


def _is_number(text):
    try:
        float(text)
        return True
    except ValueError:
        return False


# ------------------------------------------------------------ the oracle

def wendland_2d(r, cut):
    h = cut / 2.0
    q = r / h
    return np.where(q < 2.0, 7.0 / (4.0 * math.pi * h * h) * (1.0 - q / 2.0) ** 4 * (1.0 + 2.0 * q), 0.0)


def pair_vectors(x, y, box_x):
    """r_j - r_i for all pairs, x periodic (minimum image)."""
    dx = x[None, :] - x[:, None]
    dx -= box_x * np.round(dx / box_x)
    dy = y[None, :] - y[:, None]
    return dx, dy


def fractions(x, y, volume, in_a, box_x):
    dx, dy = pair_vectors(x, y, box_x)
    w = wendland_2d(np.hypot(dx, dy), CUT) * volume[None, :]
    return (w * in_a[None, :]).sum(axis=1) / w.sum(axis=1)


def robinson(f, f_all):
    a, b = f / f_all, (1 - f) / (1 - f_all)
    return (math.sqrt(2) + 1) * ((a + b) / np.hypot(a, b) - 1)


def composition(f, f_all):
    return np.where(f <= f_all, f / f_all, (1 - f) / (1 - f_all))


def entropy(f):
    with np.errstate(divide="ignore", invalid="ignore"):
        return float(np.where(f > 0, -f * np.log(f), 0.0).sum())


def expected(initial, now, elapsed, box_x):
    """Every measure from the initial frame (neighbourhoods, S_0) and the
    frame now; the FTLE from the exact map of the shear."""
    group = now["type"] != 3
    initial = {name: column[group] for name, column in initial.items()}
    now = {name: column[group] for name, column in now.items()}
    mass = 1.2 * DX * DX    # sph/set: rho0 dx^2 per unit depth
    in_a = now["type"] == 2
    volume = mass / (1.2 * (1.0 + 0.05 * np.sin(700 * initial["x"] + 1300 * initial["y"])))
    f_all = volume[in_a].sum() / volume.sum()
    f0 = fractions(initial["x"], initial["y"], volume, in_a, box_x)
    f = fractions(now["x"], now["y"], volume, in_a, box_x)
    dx0, dy0 = pair_vectors(initial["x"], initial["y"], box_x)
    r0 = np.hypot(dx0, dy0)
    neighbour = (r0 > 0) & (r0 < CUT)
    r_t = np.hypot(dx0 + GAMMA * elapsed * dy0, dy0)
    stretch = np.where(neighbour, r_t / np.where(neighbour, r0, 1.0), 0.0).max(axis=1)
    ftle = np.log(stretch) / elapsed if elapsed > 0 else np.zeros_like(stretch)
    ftle_max = ftle.max()
    vf = (ftle / ftle_max if ftle_max > 0 else 0 * ftle) * composition(f, f_all)
    n = len(f)

    def normalised(s, s0, s_max):
        return (s - s0) / (s_max - s0)
    s_max_a, s_max_b = n * -f_all * math.log(f_all), n * -(1 - f_all) * math.log(1 - f_all)
    per_atom = {}
    for name, values in {"F": f, "ftle": ftle, "robinson": robinson(f, f_all), "vf_ftle": vf}.items():
        per_atom[name] = np.zeros(len(group))    # 0 outside the group
        per_atom[name][group] = values
    globals_ = [f.mean(), f_all, normalised(entropy(f), entropy(f0), s_max_a),
                normalised(entropy(1 - f), entropy(1 - f0), s_max_b), vf.mean(),
                robinson(f, f_all).mean(), ftle_max, ftle.mean()]
    return per_atom, np.array(globals_)


def measured(frame):
    return {name: frame[f"c_mix[{k + 1}]"] for k, name in enumerate(COLUMNS)}


def compare(frame_initial, frame_now, elapsed, out, what, tolerance=1e-11):
    per_atom, globals_ = expected(frame_initial, frame_now, elapsed, NX * DX)
    got = measured(frame_now)
    for name in COLUMNS:
        scale = max(1.0, np.abs(per_atom[name]).max())
        below(np.abs(got[name] - per_atom[name]).max() / scale, tolerance, f"{what}: per-particle {name}")
    row = thermo_globals(out)
    below(abs(row[2] - globals_[4]), tolerance, f"{what}: scalar (the VF-FTLE mean)")
    for k, name in enumerate(GLOBALS):
        below(abs(row[3 + k] - globals_[k]) / max(1.0, abs(globals_[k])), tolerance, f"{what}: global {name}")
    return per_atom, globals_, row


# ----------------------------------------------------------------- checks

def check_segregated(args, workdir):
    out, frames = run(args, script(args.plugin, steps=0, shear=False), workdir)
    frame = frames[-1][1]
    compare(frame, frame, 0.0, out, "layers at t = 0")
    got = measured(frame)
    # rows half a spacing off the lattice: the other component is within reach of
    # rows up to 3.5 spacings from the interface, at exactly the cutoff from the next
    far = np.abs(frame["y"] - NY / 2 * DX) > CUT - DX
    that(np.all(got["F"][far] == (frame["type"][far] == 2)), "F is exactly 0 or 1 from the kernel support from the interface on",
         f"{far.sum()} particles")
    that(np.all(got["robinson"][far] == 0.0), "Robinson's measure is exactly 0 there")
    near_interface = ~far & (frame["type"] != 3)
    that(np.all((got["F"][near_interface] > 0) & (got["F"][near_interface] < 1)),
         "F strictly between 0 and 1 closer to the interface")
    row = thermo_globals(out)
    that(row[5] == 0.0 and row[6] == 0.0, "S*_A = S*_B = 0 at the reference", f"{row[5]:g}, {row[6]:g}")
    that(row[9] == 0.0 and row[2] == 0.0, "FTLE and VF-FTLE 0 at the reference (T = 0)")


def check_uniform(args, workdir):
    out, frames = run(args, script(args.plugin, pattern="checker", steps=0, shear=False), workdir)
    frame = frames[-1][1]
    compare(frame, frame, 0.0, out, "checkerboard")
    got = measured(frame)
    interior = (frame["y"] > CUT) & (frame["y"] < NY * DX - CUT)
    below(np.abs(got["F"][interior] - 0.5).max(), 0.1, "checkerboard: F within 0.1 of the composition 1/2")
    that(got["robinson"][interior].min() > 0.97, "checkerboard: Robinson's measure near 1 (mixed)",
         f"min {got['robinson'][interior].min():.4f}")


def check_shear(args, workdir):
    out, frames = run(args, script(args.plugin, steps=STEPS), workdir)
    initial, now = frames[0][1], frames[-1][1]
    elapsed = STEPS * 0.01
    per_atom, globals_, row = compare(initial, now, elapsed, out, f"shear to T = {elapsed:g} s")
    moved = now["xu"] - initial["xu"]
    that(np.abs(moved).max() > 0.5 * NX * DX, "atoms crossed the periodic boundary",
         f"largest move {np.abs(moved).max() / (NX * DX):.2f} box widths")
    # away from the walls every particle sees the same lattice: the continuum's stretch
    s = GAMMA * elapsed
    sigma = math.sqrt(1 + s * s / 2 + s * math.sqrt(1 + s * s / 4))
    interior = (initial["y"] > CUT) & (initial["y"] < NY * DX - CUT)
    below(abs(per_atom["ftle"][interior].max() * elapsed / math.log(sigma) - 1), 0.05,
          "largest FTLE within 5 % of the continuum's ln(sigma_max) / T")
    ave = np.loadtxt(os.path.join(workdir, "mix.ave"), comments="#", ndmin=2)
    # the file has 6 digits
    below(np.abs(ave[-1, 1:] / row[3:] - 1).max(), 1e-5, "fix ave/time reads the global vector")


def check_ranks(args, workdir):
    reference = None
    for ranks in (1, 2, 4):
        sub = os.path.join(workdir, f"np{ranks}")
        os.makedirs(sub)
        out, frames = run(args, script(args.plugin, steps=STEPS), sub, np_=ranks)
        # create_atoms numbers the atoms by rank: match them by their initial positions
        order = np.lexsort((frames[0][1]["x"], frames[0][1]["y"]))
        values = np.column_stack([frames[-1][1][f"c_mix[{k + 1}]"][order] for k in range(4)])
        row = thermo_globals(out)
        if reference is None:
            reference = (values, row)
            continue
        below(np.abs(values - reference[0]).max(), 1e-12, f"{ranks} ranks: per-particle measures as on 1")
        below(np.abs(row[2:] - reference[1][2:]).max(), 1e-12, f"{ranks} ranks: global measures as on 1")


def check_restart(args, workdir):
    whole = os.path.join(workdir, "whole")
    split = os.path.join(workdir, "split")
    os.makedirs(whole)
    os.makedirs(split)
    out_whole, frames_whole = run(args, script(args.plugin, steps=STEPS), whole, np_=2)
    run_lammps(args.lmp, script(args.plugin, steps=STEPS, part="first"), split, np_=2, mpirun=args.mpirun)
    out_split, frames_split = run(args, script(args.plugin, steps=STEPS, part="second"), split, np_=2)
    a = np.column_stack([frames_whole[-1][1][f"c_mix[{k + 1}]"] for k in range(4)])
    b = np.column_stack([frames_split[-1][1][f"c_mix[{k + 1}]"] for k in range(4)])
    that(frames_split[-1][0] == frames_whole[-1][0], "the continued run ends at the same step")
    below(np.abs(a - b).max(), 1e-12, "per-particle measures across the restart as without it")
    below(np.abs(thermo_globals(out_whole)[2:] - thermo_globals(out_split)[2:]).max(), 1e-12,
          "global measures across the restart as without it")
    that(thermo_globals(out_split)[9] > 0.04, "the continued run's FTLE is that of the sheared reference")


def check_renumber(args, workdir):
    whole = os.path.join(workdir, "whole")
    renumbered = os.path.join(workdir, "renumbered")
    os.makedirs(whole)
    os.makedirs(renumbered)
    out_whole, frames_whole = run(args, script(args.plugin, steps=STEPS), whole, np_=2)
    text = script(args.plugin, steps=STEPS)
    half = f"run {STEPS // 2}\n"
    text = text.replace(f"run {STEPS}\n", half + "delete_atoms region rows compress yes\n" + half)
    out_renumbered, frames_renumbered = run(args, text, renumbered, np_=2)
    a, b = frames_whole[-1][1], frames_renumbered[-1][1]
    that(frames_renumbered[-1][0] == frames_whole[-1][0], "the run with deleted atoms ends at the same step")
    that(len(b["id"]) == len(a["id"]) - NX and b["id"].max() == len(b["id"]),
         "delete_atoms removed the bottom row and renumbered the IDs", f"largest ID {b['id'].max():.0f}")
    # the same atoms, matched by their positions (in the group: the rest is 0)
    in_a, in_b = a["type"] != 3, b["type"] != 3
    order_a = np.lexsort((a["xu"][in_a], a["yu"][in_a]))
    order_b = np.lexsort((b["xu"][in_b], b["yu"][in_b]))
    pos = np.abs(a["xu"][in_a][order_a] - b["xu"][in_b][order_b]).max() + \
        np.abs(a["yu"][in_a][order_a] - b["yu"][in_b][order_b]).max()
    below(pos, 1e-15, "the group's atoms at the same positions")
    va = np.column_stack([a[f"c_mix[{k + 1}]"][in_a][order_a] for k in range(4)])
    vb = np.column_stack([b[f"c_mix[{k + 1}]"][in_b][order_b] for k in range(4)])
    below(np.abs(va - vb).max(), 1e-12, "per-particle measures (FTLE too) after the IDs changed as without it")
    below(np.abs(thermo_globals(out_whole)[2:] - thermo_globals(out_renumbered)[2:]).max(), 1e-12,
          "global measures after the IDs changed as without it")
    that(thermo_globals(out_renumbered)[9] > 0.04, "the FTLE is that of the sheared reference",
         f"{thermo_globals(out_renumbered)[9]:.4f}")


CHECKS = {"segregated": check_segregated, "uniform": check_uniform, "shear": check_shear,
          "ranks": check_ranks, "restart": check_restart, "renumber": check_renumber}


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("check", choices=sorted(CHECKS))
    lammps_arguments(parser)
    args = parser.parse_args()
    workdir = tempfile.mkdtemp(prefix="mixing-")
    try:
        CHECKS[args.check](args, workdir)
    finally:
        shutil.rmtree(workdir, ignore_errors=True)
    finish()


if __name__ == "__main__":
    main()
