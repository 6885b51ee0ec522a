"""What the Python tests of the `dlab` command share (test_formats.py,
test_voronoi.py): the command and a fresh work directory from argv, failures
collected rather than raised (every check runs), `dlab ...` with its exit
status checked.

usage in a test:  from cli_checks import check, dlab, path, finish
                  ... finish("formats")   # prints the verdict and exits 1 on failure
"""
import os
import shutil
import subprocess
import sys

DLAB, WORK = os.path.abspath(sys.argv[1]), os.path.abspath(sys.argv[2])
failures = []


def check(cond, what):
    if not cond:
        failures.append(what)
        print("FAIL:", what)


def dlab(*args, expect=0):
    r = subprocess.run([DLAB, *args], cwd=WORK, capture_output=True, text=True, timeout=120)
    check(r.returncode == expect, f"dlab {' '.join(args)}: exit {r.returncode}, expected {expect}\n{r.stderr}")
    return r


def path(name):
    return os.path.join(WORK, name)


def fresh_work_dir():
    shutil.rmtree(WORK, ignore_errors=True)
    os.makedirs(WORK)


def finish(name):
    print(f"{len(failures)} failure(s)" if failures else f"{name}: all checks passed")
    sys.exit(1 if failures else 0)
