"""The restart data of the package's styles carry a version head: the
settings of the pairs and the global state of the fixes. A file whose head
is missing (written before heads existed) or of another version is refused
with an error naming the style, not misread.

usage: test_restart_head.py --lmp LMP --plugin PLUGIN [--scene grains]

A restart of pair hybrid/overlay sph/harmonic/visc + sph/cleary/heat and of
every fix of the package that keeps a global state is written once; each
head (tag "SPTH", then the version) is found in the file by its tag and its
owner read from the style name written in front of it. Checked, for each:
- the file as written reads back, the fixes defined again (the control);
- the version raised by one, and lowered by one where the layout has been
  raised (a file of the older layout): the error names the style and both
  versions;
- the head cut out (the layout of a file from before heads; for a fix the
  size of its block shrunk with it): the error names the style and says the
  file has no version head.
"""

import argparse
import os
import struct
import sys
import tempfile

from sphtest import finish, lammps_arguments, record_site, run_script

# the fixes, defined alike before write_restart and after read_restart (the
# fix's restart() reads its state when it is defined again); the materials'
# speed of sound from 'auto' is such a state
FIXES = """fix materials all sph/materials type 1 conductivity constant 1.0 cv 1.0 &
    viscosity constant 1e-3 eos linear auto speed 0.1 rho0 1000
fix integrate moving sph
fix volume moving sph/hold/volume
fix held right sph/stationary
fix adami wall sph/wall/adami
fix hot wall sph/wall/dirichlet 1.0
fix dt moving sph/dt/reset 1
fix into right sph/heatflow wall
fix flux right sph/surface/flux flux 1.0 spacing 0.01
fix shift moving sph/shift skillen 2.0
fix inlet moving sph/inlet/temperature 1.0
fix open opening sph/open inlet -y 0.02 fluid moving velocity 0.01
fix drive moving sph/flowrate x 0.01
compute mix moving sph/mixing top
"""

WRITE = """plugin load {plugin}
units si
dimension 2
atom_style sph
boundary p m p
lattice sq 0.01
region box block 0 8 0 6 -0.5 0.5
create_box 1 box
create_atoms 1 box
mass * 0.1
region left block INF 0.5 INF INF INF INF
region right block 6.5 INF INF INF INF INF
region upper block INF INF 1 INF INF INF
region opening block 0.5 6.5 2 INF INF INF
group wall region left
group right region right
group top region upper
group opening region opening
group fixed union wall right
group moving subtract all fixed opening
""" + FIXES + """sph/set all materials spacing 0.01 temperature 1.0
pair_style hybrid/overlay sph/harmonic/visc wendland 0.03 sph/cleary/heat wendland 0.03
pair_coeff * * sph/harmonic/visc
pair_coeff * * sph/cleary/heat
thermo_style custom step c_mix
run 2
write_restart {path}
"""

READ = """plugin load {plugin}
read_restart {path}
""" + FIXES + """print "READ BACK"
"""

# the style names whose data carry a head, as the file spells them
STYLES = ["sph/harmonic/visc", "sph/cleary/heat", "sph/wall/adami", "sph/wall/dirichlet",
          "sph/dt/reset", "sph/heatflow", "sph/surface/flux", "sph/shift",
          "sph/inlet/temperature", "SPH/MIXING/REFERENCE", "sph/materials", "sph/hold/volume",
          "sph/open", "sph/flowrate"]
# fix sph/grains, which needs a 3-d scene of atom style hybrid sph sphere
# (its state: whether the fluid filled the pores)
GRAINS_FIXES = """fix materials all sph/materials type 1 rho0 1000.0 cv 4000.0 viscosity constant 0.05 &
    eos linear 0.1 type 2 rho0 2500.0 cv 800.0
fix integrate fluid sph
fix couple grains sph/grains fluid fluid heat none fill yes
"""

GRAINS_WRITE = """plugin load {plugin}
units si
dimension 3
atom_style hybrid sph sphere
boundary p p p
comm_modify vel yes
lattice sc 0.001
region box block 0 6 0 6 0 6
create_box 2 box
create_atoms 1 box
create_atoms 2 single 0.0031 0.0029 0.0033 units box
group fluid type 1
group grains type 2
set group fluid diameter 0.0
set group grains diameter 0.0004 density 2500.0
set group grains sph/rho 2500.0
set group grains sph/cv 800.0
""" + GRAINS_FIXES + """sph/set fluid materials spacing 0.001 temperature 300.0
pair_style hybrid/overlay sph/harmonic/visc wendland 0.003 granular
pair_coeff 1 1 sph/harmonic/visc
pair_coeff 1 2 none
pair_coeff 2 2 granular hooke 1e3 0.5 tangential linear_nohistory 1.0 0.0
timestep 1e-4
run 2
write_restart {path}
"""

GRAINS_READ = """plugin load {plugin}
read_restart {path}
comm_modify vel yes
""" + GRAINS_FIXES + """print "READ BACK"
"""

SCENES = {"styles": (WRITE, READ, STYLES, "flow.restart_head"),
          "grains": (GRAINS_WRITE, GRAINS_READ, ["sph/harmonic/visc", "sph/grains"],
                     "granular.restart_head")}
TAG = struct.pack("i", 0x53505448)


def string_before(data, end):
    """The string LAMMPS wrote (length with its NUL, then the characters)
    that ends just before 'end', and where its length starts."""
    for length in range(2, 100):
        start = end - length
        if start >= 4 and data[end - 1] == 0 and struct.unpack_from("i", data, start - 4)[0] == length:
            return data[start:end - 1].decode(), start - 4
    return None, None


def owner(data, at):
    """'pair STYLE' for a pair's settings (its style name just in front), or
    'Fix STYLE ID' for a fix's state (id, style, then the block's size)."""
    style, start = string_before(data, at - 4)
    if style is not None:
        fix_id, _ = string_before(data, start)
        return f"Fix {style} {fix_id}", True
    style, _ = string_before(data, at)
    return ("pair " + style if style else None), False


def main():
    p = lammps_arguments(argparse.ArgumentParser(description=__doc__), mpi=False)
    p.add_argument("--record", help="directory for the sites of the messages (robust.error_branches)")
    p.add_argument("--scene", choices=sorted(SCENES), default="styles",
                   help="styles: the package's pairs and fixes in 2-d; grains: fix sph/grains in 3-d")
    a = p.parse_args()
    write_script, read_script, styles, site_prefix = SCENES[a.scene]
    failures = []
    with tempfile.TemporaryDirectory() as tmp:
        written = os.path.join(tmp, "written.restart")
        code, out = run_script(a.lmp, write_script.format(plugin=a.plugin, path=written))
        if code != 0:
            sys.exit("FAIL: writing the restart:\n" + out[-2000:])
        data = open(written, "rb").read()
        heads = []
        at = data.find(TAG)
        while at >= 0:
            heads.append(at)
            at = data.find(TAG, at + 1)
        owners = [owner(data, at) for at in heads]
        named = sorted(who.split()[1] if who else "?" for who, _ in owners)
        if named != sorted(styles):
            sys.exit(f"FAIL: heads in the restart file for {named}, expected {sorted(styles)}")

        def reads(name, content, expect):
            path = os.path.join(tmp, name)
            with open(path, "wb") as f:
                f.write(content)
            code, out = run_script(a.lmp, read_script.format(plugin=a.plugin, path=path))
            if expect is None:
                ok = code == 0 and "READ BACK" in out
            else:
                ok = code != 0 and all(e in out for e in expect)
                if ok and a.record:
                    record_site(os.path.join(a.record, f"{site_prefix}.{name}.site"), a.plugin,
                                out, expect[0])
            print(f"{name}: exit {code}, {'as expected' if ok else 'NOT as expected'}")
            if not ok:
                print(out[-1500:])
                failures.append(name)

        reads("unchanged.restart", data, None)
        for (who, is_fix), at in zip(owners, heads):
            short = who.split()[1].replace("/", "_").lower()
            what = "state data" if is_fix else "settings"
            # each style's own layout version
            version = struct.unpack_from("i", data, at + 4)[0]
            raised = data[:at + 4] + struct.pack("i", version + 1) + data[at + 8:]
            reads(f"version_{short}.restart", raised,
                  [f"{who}: the restart file's {what} are of version {version + 1}, "
                   f"this build reads version {version}"])
            # a layout this build has raised since (the head of a file of then)
            if version > 1:
                older = data[:at + 4] + struct.pack("i", version - 1) + data[at + 8:]
                reads(f"older_{short}.restart", older,
                      [f"{who}: the restart file's {what} are of version {version - 1}, "
                       f"this build reads version {version}"])
            if is_fix:
                # the block's size, in front of the head, shrinks with it
                size = struct.unpack_from("i", data, at - 4)[0]
                headless = data[:at - 4] + struct.pack("i", size - 8) + data[at + 8:]
            else:
                headless = data[:at] + data[at + 8:]
            reads(f"headless_{short}.restart", headless,
                  [f"{who}: the restart file's {what} have no version head"])
    finish(failures)


if __name__ == "__main__":
    main()
