"""The checks of the test scripts in unittest/tools: each prints one line,
"ok" or "FAIL", what was checked and the value against its limit; finish()
exits 1 if any failed. Plain Python, no numpy.

  from checks import below, finish
  below(err, 1e-8, "Nu - 1")
  finish()"""

import sys

failures = 0


def that(ok, what, detail=""):
    """Count ok as a check and print "ok|FAIL what[: detail]"."""
    global failures
    failures += not ok
    print(f"{'ok' if ok else 'FAIL'} {what}{': ' + detail if detail else ''}")


def fail(what):
    """Count a failed check that prints nothing when it passes: "FAIL what"."""
    that(False, what)


def below(value, limit, what, fmt=".2e"):
    """value <= limit."""
    that(value <= limit, what, f"{value:{fmt}} (limit {limit:.0e})")


def near(value, target, tolerance, what, fmt=".8g"):
    """|value - target| <= tolerance."""
    that(abs(value - target) <= tolerance, what, f"{value:{fmt}} (expected {target:{fmt}} +- {tolerance:.2g})")


def inside(value, lo, hi, what, fmt=".4g"):
    """lo <= value <= hi."""
    that(lo <= value <= hi, what, f"{value:{fmt}} (expected in [{lo:g}, {hi:g}])")


def finish(passed=""):
    """Print the number of failed checks (or passed, if given and none failed) and exit 1 if any failed."""
    if failures:
        print(f"{failures} check(s) failed")
    elif passed:
        print(passed)
    sys.exit(1 if failures else 0)
