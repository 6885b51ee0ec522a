"""ctest `papers.benchmark_table` (label papers): papers/benchmark/table.py on the
hand-written fixture tests/data/benchmark_fixture/runs.csv. Expected cells are worked
out by hand from the fixture: u2's adaptive CPU times 1.0, 3.0, 1.5 have median 1.5,
CGAL's is 2.0, so 0.75; their bytes 50000, 70000, 60000 over 1000 points have median 60;
mp 30.0 / 2.0 = 15.00 (80 B/pt) and 30.0 / 1.5 = 20.00 against adaptive; the integer
run timed out; l3 has no CGAL row, and integer 0.25 / 0.5 = 0.50, mp 1.0 / 0.5 = 2.00.
"""
import pathlib
import subprocess
import sys

ROOT = pathlib.Path(__file__).resolve().parent.parent
TABLE = ROOT / "papers" / "benchmark" / "table.py"
FIXTURE = ROOT / "tests" / "data" / "benchmark_fixture" / "runs.csv"
failures = []


def run(*args):
    return subprocess.run([sys.executable, str(TABLE), *map(str, args)], capture_output=True,
                          text=True, timeout=60)


def check(cond, what):
    if not cond:
        failures.append(what)
        print("FAIL:", what)


r = run(FIXTURE)
check(r.returncode == 0, f"exit {r.returncode}: {r.stderr}")
lines = r.stdout.splitlines()
expected = [
    "| dlab / CGAL (CPU), B/pt | u2 (n = 1000) | l3 (n = 8) |",
    "| CGAL Epick: seconds, B/pt | 2.00 s, 100 | – |",
    "| bowyer-watson × adaptive | 0.75, 60 | –, 100 |",
    "| bowyer-watson × integer | timeout | –, 50 |",
    "| bowyer-watson × mp | 15.00, 80 | –, 200 |",
    "| bowyer-watson: integer / adaptive | timeout | 0.50 |",
    "| bowyer-watson: mp / adaptive | 20.00 | 2.00 |",
]
for line in expected:
    check(line in lines, f"missing line {line!r}")
check(run(FIXTURE).stdout == r.stdout, "two runs differ")

empty = pathlib.Path(sys.argv[1]) / "empty.csv" if len(sys.argv) > 1 else None
if empty:
    empty.parent.mkdir(parents=True, exist_ok=True)
    empty.write_text("run,input\n")
    e = run(empty)
    check(e.returncode == 2 and "no runs" in e.stderr, f"empty file: exit {e.returncode}")
m = run("/nonexistent/runs.csv")
check(m.returncode == 2 and "/nonexistent/runs.csv" in m.stderr, f"missing file: exit {m.returncode}")

print(r.stdout)
sys.exit(1 if failures else 0)
