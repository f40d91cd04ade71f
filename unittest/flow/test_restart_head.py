"""The pairs' restart settings carry a version head, and a file whose head
is missing (written before heads existed) or of another version is refused
with an error naming the pair, not misread.

usage: test_restart_head.py --lmp LMP --plugin PLUGIN

A restart of pair hybrid/overlay sph/harmonic/visc + sph/cleary/heat is
written once; the head of each pair (tag "SPTH", then the version) is found
in the file by its tag. Checked, for each pair:
- the file as written reads back (the control);
- the version raised by one: the error names the pair and both versions;
- the head cut out (the layout of a file from before heads): the error names
  the pair and says the file has no version head.
"""

import argparse
import os
import struct
import sys
import tempfile

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "tools"))
from sphtest import finish, lammps_arguments, run_script  # noqa: E402

WRITE = """plugin load {plugin}
units si
dimension 2
atom_style sph
boundary p p p
lattice sq 0.01
region box block 0 4 0 4 -0.5 0.5
create_box 1 box
create_atoms 1 box
mass * 0.1
fix materials all sph/materials type 1 conductivity constant 1.0 cv 1.0 &
    viscosity constant 1e-3 eos linear 1.0 rho0 1000
sph/set all materials spacing 0.01 temperature 1.0
pair_style hybrid/overlay sph/harmonic/visc wendland 0.03 sph/cleary/heat wendland 0.03
pair_coeff * * sph/harmonic/visc
pair_coeff * * sph/cleary/heat
write_restart {path}
"""

READ = """plugin load {plugin}
read_restart {path}
print "READ BACK"
"""

PAIRS = ["pair sph/harmonic/visc", "pair sph/cleary/heat"]
TAG = struct.pack("i", 0x53505448)


def main():
    a = lammps_arguments(argparse.ArgumentParser(description=__doc__), mpi=False).parse_args()
    failures = []
    with tempfile.TemporaryDirectory() as tmp:
        written = os.path.join(tmp, "written.restart")
        code, out = run_script(a.lmp, WRITE.format(plugin=a.plugin, path=written))
        if code != 0:
            sys.exit("FAIL: writing the restart:\n" + out[-2000:])
        data = open(written, "rb").read()
        heads = []
        at = data.find(TAG)
        while at >= 0:
            heads.append(at)
            at = data.find(TAG, at + 1)
        if len(heads) != len(PAIRS):
            sys.exit(f"FAIL: {len(heads)} heads in the restart file, expected {len(PAIRS)}")
        version = struct.unpack_from("i", data, heads[0] + 4)[0]

        def reads(name, content, expect):
            path = os.path.join(tmp, name)
            with open(path, "wb") as f:
                f.write(content)
            code, out = run_script(a.lmp, READ.format(plugin=a.plugin, path=path))
            if expect is None:
                ok = code == 0 and "READ BACK" in out
            else:
                ok = code != 0 and all(e in out for e in expect)
            print(f"{name}: exit {code}, {'as expected' if ok else 'NOT as expected'}")
            if not ok:
                print(out[-1500:])
                failures.append(name)

        reads("unchanged.restart", data, None)
        for pair, at in zip(PAIRS, heads):
            short = pair.split("/")[-1]
            raised = data[:at + 4] + struct.pack("i", version + 1) + data[at + 8:]
            reads(f"version_{short}.restart", raised,
                  [f"{pair}: the restart file's settings are of version {version + 1}, "
                   f"this build reads version {version}"])
            headless = data[:at] + data[at + 8:]
            reads(f"headless_{short}.restart", headless,
                  [f"{pair}: the restart file's settings have no version head"])
    finish(failures)


if __name__ == "__main__":
    main()
