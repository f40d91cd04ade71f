#!/usr/bin/env python3
"""The package's styles find each other by C++ type (SPHHub), never by style
name or through a void* extract(): a look-up of that kind anywhere but the
hub (sph_hub.*) fails this test, naming the file and line.

Allowed outside the hub: extract("gvec") (LAMMPS's fix gravity states its
acceleration only so) and the package's own extract() overrides that serve
LAMMPS's library interface (fix sph/materials' per-type arrays).
"""
import argparse
import os
import re
import sys

FORBIDDEN = [
    (re.compile(r"\bpair_match\s*\("), "a pair style looked up by name (Force::pair_match)"),
    (re.compile(r"\bfixes_of_style\b"), "fixes looked up by style name"),
    (re.compile(r"\bfind_fix_by_style\b|\bget_fix_by_style\b"), "fixes looked up by style name"),
    (re.compile(r"(strcmp|strncmp|strmatch)\s*\([^;]*->\s*style\b"), "a style name compared"),
    (re.compile(r"(strcmp|strncmp|strmatch)\s*\(\s*style\b"), "a style name compared"),
    (re.compile(r"->\s*extract\s*\(\s*\"(?!gvec\")"), "a package-internal extract() key (void*)"),
    (re.compile(r"\(\s*(Pair|Fix|Compute)SPH\w*\s*\*\s*\)"), "a C cast to a package style"),
]
# the one place that may look LAMMPS's own styles up by name
HUB = {"sph_hub.h", "sph_hub.cpp"}


def offences(path):
    found = []
    with open(path, encoding="utf-8") as f:
        for number, line in enumerate(f, 1):
            code = line.split("//", 1)[0]
            for pattern, what in FORBIDDEN:
                if pattern.search(code):
                    found.append((number, what, line.strip()))
    return found


def main():
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("src", help="the package's source directory")
    parser.add_argument("--expect-offence", metavar="FILE",
                        help="self-test: this file must be reported")
    args = parser.parse_args()
    files = sorted(f for f in os.listdir(args.src) if f.endswith((".cpp", ".h")))
    if args.expect_offence:
        # every line marked '// offence' must be reported, and no other
        with open(args.expect_offence, encoding="utf-8") as f:
            marked = {n for n, line in enumerate(f, 1) if "// offence" in line}
        hits = offences(args.expect_offence)
        for number, what, line in hits:
            print(f"  {number}: {what}: {line}")
        reported = {number for number, _, _ in hits}
        print(f"{args.expect_offence}: {len(marked)} marked, {len(reported)} reported")
        return 0 if reported == marked and marked else 1
    total = 0
    for name in files:
        if name in HUB:
            continue
        for number, what, line in offences(os.path.join(args.src, name)):
            print(f"{name}:{number}: {what}: {line}")
            total += 1
    print(f"{len(files)} files, {total} by-name or void* couplings outside the hub")
    return 1 if total else 0


if __name__ == "__main__":
    sys.exit(main())
