#!/usr/bin/env python3
"""Every page of doc/src parses as reStructuredText without a warning or an
error (docutils, with Sphinx's roles and directives accepted as they are):
an unclosed literal, an undefined substitution such as |v| in prose, a
broken table. Fails listing each problem with its file and line.

  check_rst.py doc/src/*.rst
  check_rst.py --expect-problems FILE   (self-test: FILE must give some)
"""
import sys, io
from docutils.core import publish_doctree
from docutils.parsers.rst import roles, directives, Directive
from docutils import nodes
# Sphinx roles/directives the plain parser lacks: accept them
for r in ['doc', 'ref', 'math', 'cite', 'file', 'program', 'envvar']:
    roles.register_generic_role(r, nodes.literal)
class Pass(Directive):
    has_content=True; optional_arguments=10; final_argument_whitespace=True
    option_spec=None
    def run(self): return []


class AnyOptions(dict):
    def __getitem__(self, key):
        return directives.unchanged

    def __contains__(self, key):
        return True


Pass.option_spec = AnyOptions()
# Sphinx's directives (docutils knows the others)
for d in ['toctree', 'index', 'only', 'versionadded', 'versionchanged', 'deprecated', 'literalinclude',
          'code-block']:
    directives.register_directive(d, Pass)
expect = len(sys.argv) > 2 and sys.argv[1] == '--expect-problems'
files = sys.argv[2:] if expect else sys.argv[1:]
bad = 0
for f in files:
    err=io.StringIO()
    publish_doctree(open(f).read(), source_path=f, settings_overrides={'warning_stream':err,'report_level':2,'halt_level':5})
    out=[l for l in err.getvalue().splitlines() if ('ERROR' in l or 'WARNING' in l) and 'Unknown interpreted text role' not in l and 'Unknown directive' not in l]
    for l in out: print(l)
    bad+=len(out)
print(f'{len(files)} pages, {bad} problems')
sys.exit((0 if bad else 1) if expect else (1 if bad else 0))
