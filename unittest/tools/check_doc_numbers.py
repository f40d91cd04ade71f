#!/usr/bin/env python3
"""Measured numbers the docs quote are those of the results files the
benchmarks and reference solvers write (bench/*/*.md, tools/*.md).

The quotes checked are listed in a table (unittest/tools/doc_numbers.txt):
a measurement is one or more `doc:` lines followed by the `res:` line of
the results file that holds it,

  doc: README.md: error of the mean Nu from the heat (time average): [[+0.84]] %
  doc: doc/src/Validation_convection.rst: - 1e4 - 40 x 40 - [[+0.84]] %
  res: bench/convection/results.md: | 1e4 | 40 x 40 | 23780 | 191 | [[+0.84]] % |

Each line is a path (relative to REPO) and an excerpt of that file with
the number in [[ ]]; excerpts match with every run of whitespace as one
space (so a wrapped sentence or an rst list-table row is one line here).
A quote passes when its excerpt is in the doc, the results excerpt is in
the results file, and the two numbers agree to the doc's precision (the
doc may round, not add digits; a doc number without a sign states the
measured one's magnitude). A changed doc, a rewritten results file
or a wrong number fails, naming the table line.

  check_doc_numbers.py REPO [--table FILE]
  check_doc_numbers.py REPO --table FILE --expect-fail   (self-test: every
                                                         quote of FILE must fail)
"""
import argparse
import os
import re
import sys
from decimal import Decimal, InvalidOperation

MARK = re.compile(r"\[\[([^\]]*)\]\]")


def squash(text):
    return " ".join(text.split())


def number(text):
    """The Decimal of a quoted number ('+0.84', '2,989', '1.2e5')."""
    try:
        return Decimal(text.strip().replace(",", "").lstrip("+"))
    except InvalidOperation:
        return None


def parse(path):
    """[(line number, [doc quotes], results quote)], a quote being
    (table line, file, excerpt)."""
    groups, docs = [], []
    with open(path, encoding="utf-8") as f:
        for number_, line in enumerate(f, 1):
            line = line.strip()
            if not line or line.startswith("#"):
                continue
            kind, _, rest = line.partition(": ")
            file_, _, excerpt = rest.partition(": ")
            if kind not in ("doc", "res") or not excerpt:
                raise SystemExit(f"{path}:{number_}: not 'doc: FILE: EXCERPT' or 'res: FILE: EXCERPT'")
            if kind == "doc":
                docs.append((number_, file_, excerpt))
            elif not docs:
                raise SystemExit(f"{path}:{number_}: a res: line without doc: lines before it")
            else:
                groups.append((docs, (number_, file_, excerpt)))
                docs = []
    if docs:
        raise SystemExit(f"{path}:{docs[-1][0]}: doc: lines without a res: line after them")
    return groups


class Texts:
    """The files' texts, whitespace squashed, read once."""
    def __init__(self, repo):
        self.repo, self.cache = repo, {}

    def __getitem__(self, file_):
        if file_ not in self.cache:
            path = os.path.join(self.repo, file_)
            if not os.path.isfile(path):
                self.cache[file_] = None
            else:
                with open(path, encoding="utf-8") as f:
                    self.cache[file_] = squash(f.read())
        return self.cache[file_]


def quoted(texts, quote):
    """(the quote's number as written, problem or None)."""
    _, file_, excerpt = quote
    marks = MARK.findall(excerpt)
    if len(marks) != 1 or number(marks[0]) is None:
        return None, "the excerpt needs one number in [[ ]]"
    text = texts[file_]
    if text is None:
        return None, f"no file {file_}"
    plain = squash(MARK.sub(r"\1", excerpt))
    if plain not in text:
        return None, f"{file_} no longer has: {plain}"
    return marks[0], None


def problems(groups, texts):
    """[(table line, problem)] over every doc quote."""
    found = []
    for docs, res in groups:
        measured, problem = quoted(texts, res)
        if problem:
            found += [(number_, problem) for number_, _, _ in docs + [res]]
            continue
        for doc in docs:
            value = number(measured)
            said, problem = quoted(texts, doc)
            if problem:
                found.append((doc[0], problem))
                continue
            q = number(said)
            if not said.strip().startswith(("+", "-")):
                value = abs(value)
            # the doc's last digit fixes the precision; the doc may not
            # quote a finer digit than the results file measured
            if q.as_tuple().exponent < value.as_tuple().exponent:
                found.append((doc[0], f"{doc[1]} quotes {said}, finer than {res[1]}'s {measured}"))
            elif abs(value - q) > Decimal(5).scaleb(q.as_tuple().exponent - 1):
                found.append((doc[0], f"{doc[1]} quotes {said}, {res[1]} has {measured}"))
    return found


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    parser = argparse.ArgumentParser()
    parser.add_argument("repo")
    parser.add_argument("--table", default=os.path.join(here, "doc_numbers.txt"))
    parser.add_argument("--expect-fail", action="store_true")
    args = parser.parse_args()
    groups = parse(args.table)
    found = problems(groups, Texts(args.repo))
    for number_, problem in found:
        print(f"{args.table}:{number_}: {problem}")
    quotes = sum(len(docs) for docs, _ in groups)
    print(f"{quotes} quotes of {len(groups)} measurements, {len(found)} problems")
    if args.expect_fail:
        failed = {number_ for number_, _ in found}
        missed = [doc[0] for docs, _ in groups for doc in docs if doc[0] not in failed]
        for number_ in missed:
            print(f"{args.table}:{number_}: passed, but the self-test wants it to fail")
        return 1 if missed or not quotes else 0
    return 1 if found or not quotes else 0


if __name__ == "__main__":
    sys.exit(main())
