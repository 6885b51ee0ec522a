"""ctest `plot` (label studies): `dlab plot` on the hand-written study fixture
tests/data/study_fixture/runs.csv. Usage: test_plot.py DLAB WORK_DIR.

The plotted values (plots/figures.json) are checked against numbers worked out by
hand from the fixture's rows; reruns must give identical files; absent columns
skip figures; bad input exits 2 naming file and line. Exit 77 (skipped) when
the python3 that dlab plot runs has no matplotlib.
"""
import csv
import json
import os
import pathlib
import shutil
import subprocess
import sys

DLAB, WORK = sys.argv[1], pathlib.Path(sys.argv[2])
FIXTURE = pathlib.Path(__file__).resolve().parent / "data" / "study_fixture"
STEMS = ["time_per_point", "predicate_calls", "stage_shares", "flips_per_point", "cavity_sizes",
         "cavity_histogram", "outcomes"]
failures = []


def check(cond, what):
    if not cond:
        failures.append(what)
        print("FAIL:", what)


def plot(study, out=None, env=None):
    cmd = [DLAB, "plot", str(study)] + (["--out", str(out)] if out else [])
    return subprocess.run(cmd, capture_output=True, text=True,
                          env=dict(os.environ, **(env or {})), timeout=300)


def close(a, b):
    return abs(a - b) <= 1e-9 * max(1.0, abs(b))


python = "/usr/bin/python3" if os.access("/usr/bin/python3", os.X_OK) else "python3"
if subprocess.run([python, "-c", "import matplotlib, numpy"], capture_output=True).returncode:
    print("skipped: %s has no matplotlib (Debian: python3-matplotlib)" % python)
    sys.exit(77)
shutil.rmtree(WORK, ignore_errors=True)
WORK.mkdir(parents=True)

r = subprocess.run([DLAB, "plot", "--help"], capture_output=True, text=True)
check(r.returncode == 0 and "STUDY_DIR" in r.stdout, "dlab plot --help")

# 1. Every figure, as SVG and PNG, from the fixture.
study = WORK / "study"
shutil.copytree(FIXTURE, study)
r = plot(study)
check(r.returncode == 0, "dlab plot on the fixture exits 0: " + r.stderr)
plots = study / "plots"
for stem in STEMS:
    for ext, magic in (("svg", b"<?xml"), ("png", b"\x89PNG")):
        f = plots / (stem + "." + ext)
        check(f.is_file() and f.read_bytes().startswith(magic), "%s is a %s file" % (f, ext))
figs = json.loads((plots / "figures.json").read_text())["figures"]
check(sorted(figs) == sorted(STEMS), "figures.json lists every figure: %s" % sorted(figs))

# 2. Values worked out by hand from runs.csv.
# Time: bowyer-watson x adaptive, uniform 2D, n = 1000: seeds 1 and 2 ran 0.0012 s and
# 0.0014 s for 1000 points: 1.2 and 1.4 us per point, median 1.3.
t = figs["time_per_point"]["panels"]["uniform 2D"]["bowyer-watson × adaptive"]
check([p[0] for p in t] == [100, 1000] and close(t[1][1], 1.3) and t[1][2] == 2,
      "time per point, uniform 2D, bowyer-watson x adaptive, n=1000: 1.3 us over 2 runs: %s" % t)
# qhull on near-degenerate 2D: its n = 1000 run lost points (not ok): only n = 100, 0.5 us.
q = figs["time_per_point"]["panels"]["near-degenerate 2D"]["qhull"]
check(len(q) == 1 and q[0][0] == 100 and close(q[0][1], 0.5), "qhull's failed run left out: %s" % q)
# Calls: lawson x float, uniform 2D, n = 100: 1500 orient2d + 800 incircle = 23 per point.
c = figs["predicate_calls"]["panels"]["uniform 2D"]["lawson × float"]
check(close(c[0][1], 23.0), "predicate calls per point, lawson x float: 23: %s" % c)
# Stages: adaptive incircle on near-degenerate 2D, both algorithms, n = 100 and 1000:
# filter 2 x (200 + 2000) = 4400 of 2 x (800 + 8000) = 17600 calls = 0.25; B 2 x (399 + 3999)
# = 8796; perturbation 4; past the filters (B + perturbation) 8800 / 17600 = 0.5.
s = figs["stage_shares"]["panels"]["near-degenerate 2D"]["adaptive incircle"]
check(s["calls"] == 17600 and close(s["shares"]["filter"], 0.25)
      and close(s["shares"]["B"], 8796 / 17600) and close(s["shares"]["perturbation"], 4 / 17600)
      and close(s["past_filters"], 0.5), "stage shares, adaptive incircle: %s" % s)
check("float orient2d" not in figs["stage_shares"]["panels"]["uniform 2D"],
      "float (no stages) has no bar")
# Flips: lawson, uniform 3D, n = 100: 400 2-3 flips, 200 3-2 flips.
f = figs["flips_per_point"]["panels"]
check(close(f["uniform 3D · 2–3 flips"]["lawson × adaptive"][0][1], 4.0)
      and close(f["uniform 3D · 3–2 flips"]["lawson × float"][0][1], 2.0),
      "flips per point, uniform 3D: %s" % {k: v for k, v in f.items() if "3D" in k})
# Cavities: bowyer-watson, uniform 2D: 4n simplices over n points; largest 12 at n = 1000.
v = figs["cavity_sizes"]["panels"]
check(close(v["uniform 2D · mean cavity"]["bowyer-watson × adaptive"][1][1], 4.0)
      and v["uniform 2D · largest cavity"]["bowyer-watson × adaptive"][1][1] == 12,
      "cavity sizes: %s" % v.get("uniform 2D · largest cavity"))
# Cavity histogram: uniform 2D at its largest n (1000), bowyer-watson x adaptive,
# seeds 1 and 2: buckets 10+20, 300+290, 600+610, 87+77 of 1994 insertions.
h = figs["cavity_histogram"]["panels"]["uniform 2D"]
shares = h["series"]["bowyer-watson × adaptive"]["shares_percent"]
check(h["n"] == 1000 and h["series"]["bowyer-watson × adaptive"]["insertions"] == 1994
      and close(shares[0], 100 * 30 / 1994) and close(shares[2], 100 * 1210 / 1994)
      and shares[4:] == [0, 0, 0],
      "cavity histogram, uniform 2D: %s" % h)
# Outcomes: bowyer-watson x float failed both near-degenerate runs, lawson x float one,
# qhull one; nothing else failed.
o = figs["outcomes"]
cells = {(row, col): (o["not_ok"][i][j], o["runs"][i][j])
         for i, row in enumerate(o["rows"]) for j, col in enumerate(o["columns"])}
expected_bad = {("bowyer-watson × float", "near-degenerate 2D"): (2, 2),
                ("lawson × float", "near-degenerate 2D"): (1, 2),
                ("qhull", "near-degenerate 2D"): (1, 2)}
check(all(cells[k] == v for k, v in expected_bad.items())
      and all(bad == 0 for k, (bad, _) in cells.items() if k not in expected_bad)
      and cells[("lawson × adaptive", "uniform 2D")] == (0, 4),
      "outcome heatmap cells: %s" % cells)

# 3. Reruns give identical files (SVG hash salt, no dates).
r = plot(study, WORK / "again")
for f in sorted(plots.iterdir()):
    check((WORK / "again" / f.name).read_bytes() == f.read_bytes(), "rerun identical: " + f.name)

# 4. Absent counters: the per-point figures without them are skipped, with a notice.
bare = WORK / "bare"
bare.mkdir()
lines = (FIXTURE / "runs.csv").read_text().splitlines()
rows = list(csv.reader(lines))
keep = [i for i, c in enumerate(rows[0]) if not c.startswith(("pred.", "ctr."))]
with open(bare / "runs.csv", "w", newline="") as out:
    csv.writer(out, lineterminator="\n").writerows([[row[i] for i in keep] for row in rows])
r = plot(bare)
skipped = json.loads((bare / "plots" / "figures.json").read_text())["skipped"]
check(r.returncode == 0 and sorted(skipped) == sorted(STEMS[1:6])
      and all("skipped " + s in r.stderr for s in STEMS[1:6])
      and (bare / "plots" / "time_per_point.png").is_file(),
      "figures without their columns are skipped with a notice: %s / %s" % (skipped, r.stderr))

# 5. Bad input: exit 2, file and line named.
def bad(name, text, expect):
    d = WORK / name
    d.mkdir()
    (d / "runs.csv").write_text(text)
    r = plot(d)
    check(r.returncode == 2 and expect in r.stderr, "%s: exit 2 and '%s': %d %s"
          % (name, expect, r.returncode, r.stderr))


bad("short-row", lines[0] + "\n" + lines[1] + "\n1,2,3\n", "runs.csv:3: 3 fields")
bad("no-outcome", lines[0].replace(",outcome,", ",result,") + "\n", "runs.csv:1: header lacks column 'outcome'")
bad("bad-n", lines[0] + "\n" + lines[1].replace(",100,1,0,", ",1e2x,1,0,", 1) + "\n",
    "runs.csv:2: column n: '1e2x' is not an integer")
bad("bad-time", lines[0] + "\n" + lines[1].replace(",0.0001,", ",nan,", 1) + "\n",
    "runs.csv:2: column wall_seconds: 'nan' is not finite")
bad("empty", "", "runs.csv:1: empty file")
r = plot(WORK / "no-such-study")
check(r.returncode == 2 and "cannot read" in r.stderr, "missing study: exit 2: " + r.stderr)
r = plot(study, env={"DLAB_PLOT_SCRIPT": str(WORK / "none.py")})
check(r.returncode == 2 and "none.py: no such file" in r.stderr, "missing script: " + r.stderr)
# matplotlib missing: a package of that name that fails to import.
fake = WORK / "fake-site" / "matplotlib"
fake.mkdir(parents=True)
(fake / "__init__.py").write_text("raise ImportError('no matplotlib here', name='matplotlib')\n")
r = plot(study, WORK / "nompl", env={"PYTHONPATH": str(WORK / "fake-site")})
check(r.returncode == 2 and "python3-matplotlib" in r.stderr, "no matplotlib: exit 2: " + r.stderr)
r = subprocess.run([DLAB, "plot"], capture_output=True, text=True)
check(r.returncode == 2 and "missing STUDY_DIR" in r.stderr, "no argument: exit 2")

print("%d failure(s)" % len(failures))
sys.exit(1 if failures else 0)
