#!/usr/bin/env python3
"""No source file of the package above a line budget (800): a file past it
holds more than one component. Fails naming each file and its length."""
import argparse
import os
import sys


def main():
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("src", help="the package's source directory")
    parser.add_argument("--limit", type=int, default=800)
    args = parser.parse_args()
    over = []
    names = sorted(f for f in os.listdir(args.src) if f.endswith((".cpp", ".h")))
    for name in names:
        with open(os.path.join(args.src, name), encoding="utf-8") as f:
            lines = sum(1 for _ in f)
        if lines > args.limit:
            over.append((name, lines))
    for name, lines in over:
        print(f"{name}: {lines} lines (limit {args.limit})")
    print(f"{len(names)} files, {len(over)} above {args.limit} lines")
    return 1 if over else 0


if __name__ == "__main__":
    sys.exit(main())
