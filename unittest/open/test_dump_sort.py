"""A dump sorted by atom ID stays right while fix sph/open creates and
deletes atoms in balance. LAMMPS's Dump::sort places each atom at index
ID - lowest ID when the IDs were 1..N at the run's start and the count is
unchanged; the open boundaries keep the count but not the IDs, which wrote
past the dump's index (a corrupted heap and wrong frames) until the fix
turned that shortcut off. unittest/open/in.open, a uniform stream (as many
atoms in as out), every atom dumped every 100 steps sorted and unsorted:
each sorted frame must be the unsorted one ordered by ID.
usage: test_dump_sort.py --lmp LMP --plugin PLUGIN"""

import argparse
import os
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
from checks import finish, that
from lammps_checks import lammps_arguments, run_input


def frames(path):
    """{step: [row tuples in file order]} of a dump custom file."""
    out, lines, i = {}, open(path).read().splitlines(), 0
    while i < len(lines):
        if lines[i].startswith("ITEM: TIMESTEP"):
            step, natoms = int(lines[i + 1]), int(lines[i + 3])
            while not lines[i].startswith("ITEM: ATOMS"):
                i += 1
            out[step] = [tuple(line.split()) for line in lines[i + 1:i + 1 + natoms]]
            i += natoms
        i += 1
    return out


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    lammps_arguments(parser, ranks=False)
    args = parser.parse_args()
    workdir = tempfile.mkdtemp(prefix="sph-dump-sort-")
    run_input(args.lmp, os.path.join(HERE, "in.open"),
              {"plugin": os.path.abspath(args.plugin), "check": "uniform", "scene": "stream",
               "inflow": "uniform", "dumps": "yes"}, workdir)
    sorted_frames = frames(os.path.join(workdir, "sorted.dump"))
    plain_frames = frames(os.path.join(workdir, "plain.dump"))
    steps = sorted(sorted_frames)
    that(len(steps) > 10 and steps == sorted(plain_frames), "both dumps have the run's frames",
         f"{len(steps)} frames")
    first_ids = {row[0] for row in plain_frames[steps[0]]}
    last_ids = {row[0] for row in plain_frames[steps[-1]]}
    # the case of the shortcut: the same count, other IDs
    that(len(first_ids) == len(last_ids) and first_ids != last_ids,
         "the stream replaced atoms and kept their count",
         f"{len(first_ids)} atoms, {len(first_ids - last_ids)} replaced")
    wrong = [step for step in steps
             if sorted_frames[step] != sorted(plain_frames[step], key=lambda row: int(row[0]))]
    that(not wrong, "every sorted frame is the unsorted one ordered by ID",
         f"{len(wrong)} of {len(steps)} frames differ" + (f", the first at step {wrong[0]}" if wrong else ""))
    finish()


if __name__ == "__main__":
    main()
