"""The checks of the Python package's test scripts (TestPython*.py, run by python3 and pvpython):
each check prints "ok    ..." or "FAIL  ..." (ctest's FAIL_REGULAR_EXPRESSION), and finish()
ends the script with exit code 1 when any failed, else prints "all checks passed" (the pass
expression)."""

import sys

failures = []


def check(condition, what):
    print(("ok    " if condition else "FAIL  ") + what, flush=True)
    if not condition:
        failures.append(what)


def finish():
    if failures:
        print("%d check(s) failed" % len(failures))
        sys.exit(1)
    print("all checks passed")
