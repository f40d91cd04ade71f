#!/usr/bin/env python3
"""Every page of doc/src parses as reStructuredText without a warning or an
error (docutils, with Sphinx's roles and directives accepted as they are):
an unclosed literal, an undefined substitution such as |v| in prose, a
broken table. Fails listing each problem with its file and line.

  check_rst.py doc/src/*.rst
  check_rst.py --expect-problems FILE   (self-test: FILE must give some)
"""
import io
import sys

from docutils import nodes
from docutils.core import publish_doctree
from docutils.parsers.rst import Directive, directives, roles

# Sphinx's roles, which plain docutils lacks, read as literals
for role in ["doc", "ref", "math", "cite", "file", "program", "envvar"]:
    roles.register_generic_role(role, nodes.literal)


class AnyOptions(dict):
    def __getitem__(self, key):
        return directives.unchanged

    def __contains__(self, key):
        return True


class Accepted(Directive):
    """A Sphinx directive, taken with any arguments, options and content."""
    has_content = True
    optional_arguments = 10
    final_argument_whitespace = True
    option_spec = AnyOptions()

    def run(self):
        return []


for name in ["toctree", "index", "only", "versionadded", "versionchanged", "deprecated",
             "literalinclude", "code-block"]:
    directives.register_directive(name, Accepted)


def problems(path):
    stream = io.StringIO()
    with open(path, encoding="utf-8") as f:
        publish_doctree(f.read(), source_path=path,
                        settings_overrides={"warning_stream": stream, "report_level": 2, "halt_level": 5})
    return [line for line in stream.getvalue().splitlines() if "ERROR" in line or "WARNING" in line]


def main():
    expect = len(sys.argv) > 2 and sys.argv[1] == "--expect-problems"
    files = sys.argv[2:] if expect else sys.argv[1:]
    bad = 0
    for path in files:
        for line in problems(path):
            print(line)
            bad += 1
    print(f"{len(files)} pages, {bad} problems")
    if expect:
        return 0 if bad else 1
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
