#!/usr/bin/env python3
"""The package's docs link only to what exists: every :doc: target is a page
of doc/src or of LAMMPS's own docs (--lammps-doc), every :ref: target an
anchor defined once, every relative link of the Markdown files (README,
examples, bench, tools) a file or directory of the repository. Fails naming
the file, line and target.

  check_doc_links.py REPO [--lammps-doc DIR]
  check_doc_links.py REPO --expect-broken FILE   (self-test: FILE's marked
                                                 lines must be reported)
"""
import argparse
import os
import re
import sys

DOC = re.compile(r":doc:`(?:[^`<]*<\s*([^>`]+?)\s*>|([^`<>]+?))`")
REF = re.compile(r":ref:`(?:[^`<]*<\s*([^>`]+?)\s*>|([^`<>]+?))`")
ANCHOR = re.compile(r"^\.\.\s+_([^:]+):\s*$")
MDLINK = re.compile(r"\]\(([^)#\s]+)(?:#[^)]*)?\)")


def anchors_of(paths):
    defined = {}
    for path in paths:
        with open(path, encoding="utf-8", errors="replace") as f:
            for line in f:
                m = ANCHOR.match(line.strip())
                if m:
                    defined.setdefault(m.group(1).strip().lower(), []).append(path)
    return defined


def rst_problems(path, pages, anchors, own_anchors):
    found = []
    with open(path, encoding="utf-8") as f:
        for number, line in enumerate(f, 1):
            for m in DOC.finditer(line):
                target = (m.group(1) or m.group(2)).strip()
                if os.path.basename(target) not in pages:
                    found.append((number, f"no page {target}"))
            for m in REF.finditer(line):
                target = (m.group(1) or m.group(2)).strip().lower()
                if target not in anchors:
                    found.append((number, f"no anchor {target}"))
                elif len(own_anchors.get(target, [])) > 1:
                    found.append((number, f"anchor {target} defined {len(own_anchors[target])} times"))
    return found


def md_problems(path):
    found = []
    base = os.path.dirname(path)
    with open(path, encoding="utf-8") as f:
        for number, line in enumerate(f, 1):
            for m in MDLINK.finditer(line):
                target = m.group(1)
                if re.match(r"^[a-z]+:", target):    # http:, https:, mailto:
                    continue
                if not os.path.exists(os.path.normpath(os.path.join(base, target))):
                    found.append((number, f"no file {target}"))
    return found


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("repo")
    p.add_argument("--lammps-doc", help="LAMMPS's doc/src (its pages and anchors count as targets)")
    p.add_argument("--expect-broken", metavar="FILE")
    args = p.parse_args()
    docdir = os.path.join(args.repo, "doc", "src")
    own = sorted(os.path.join(docdir, f) for f in os.listdir(docdir) if f.endswith(".rst"))
    pages = {os.path.basename(f)[:-4] for f in own}
    lammps = []
    if args.lammps_doc and os.path.isdir(args.lammps_doc):
        lammps = [os.path.join(args.lammps_doc, f) for f in os.listdir(args.lammps_doc) if f.endswith(".rst")]
        pages |= {os.path.basename(f)[:-4] for f in lammps}
    own_anchors = anchors_of(own)
    anchors = dict(anchors_of(lammps))
    anchors.update(own_anchors)

    if args.expect_broken:
        with open(args.expect_broken, encoding="utf-8") as f:
            marked = {n for n, line in enumerate(f, 1) if "broken" in line}
        got = {n for n, _ in rst_problems(args.expect_broken, pages, anchors, own_anchors)}
        print(f"{args.expect_broken}: {len(marked)} marked, {len(got)} reported")
        return 0 if got == marked and marked else 1

    total = 0
    for path in own:
        for number, what in rst_problems(path, pages, anchors, own_anchors):
            print(f"{os.path.relpath(path, args.repo)}:{number}: {what}")
            total += 1
    mds = [os.path.join(args.repo, "README.md")]
    for top in ("examples", "bench", "tools", "doc"):
        for dirpath, _, files in os.walk(os.path.join(args.repo, top)):
            mds += [os.path.join(dirpath, f) for f in files if f.endswith(".md")]
    for path in mds:
        for number, what in md_problems(path):
            print(f"{os.path.relpath(path, args.repo)}:{number}: {what}")
            total += 1
    print(f"{len(own)} rst pages, {len(mds)} Markdown files: {total} broken links")
    return 1 if total else 0


if __name__ == "__main__":
    sys.exit(main())
