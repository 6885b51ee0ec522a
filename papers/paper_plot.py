"""What the paper folders' figure scripts share: reading a study's runs.csv
(studies/README.md), predicate totals, least-squares growth exponents, and
deterministic matplotlib output (the same bytes on a rerun, as `dlab plot`).

Run with /usr/bin/python3 (Debian's python3-matplotlib).
"""
import csv
import math
import os

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

plt.rcParams.update({
    "svg.hashsalt": "dlab-papers",
    "svg.fonttype": "path",
    "font.family": "DejaVu Sans",
    "font.size": 9,
    "legend.fontsize": 7,
    "savefig.dpi": 130,
})

PREDICATES = ("orient2d", "incircle", "orient3d", "insphere")


def read_runs(path):
    """The rows of runs.csv, numbers converted; refuses a study with a failed exact run."""
    rows = []
    with open(path, newline="") as f:
        for line, r in enumerate(csv.DictReader(f), start=2):
            for key in ("n", "dimension", "input_points"):
                r[key] = int(r[key])
            for key in ("wall_seconds", "cpu_seconds"):
                r[key] = float(r[key]) if r[key] else float("nan")
            for key in list(r):
                if key.startswith(("pred.", "ctr.")):
                    r[key] = int(r[key]) if r[key] else None
            if r["outcome"] not in ("ok", "lower-dimensional"):
                raise SystemExit("%s:%d: run %s ended %s (%s)" % (path, line, r["run"], r["outcome"], r["message"]))
            rows.append(r)
    return rows


def predicate_calls(row):
    """Calls of the four predicates together (each counted once, whatever stage answered)."""
    return sum(row["pred." + p] or 0 for p in PREDICATES)


def counter(row, name):
    v = row.get("ctr." + name)
    return 0 if v is None else v


def slope(xs, ys):
    """Least-squares slope of log(y) on log(x): the growth exponent."""
    lx = [math.log(x) for x in xs]
    ly = [math.log(y) for y in ys]
    m = len(lx)
    sx, sy = sum(lx), sum(ly)
    sxx = sum(x * x for x in lx)
    sxy = sum(x * y for x, y in zip(lx, ly))
    return (m * sxy - sx * sy) / (m * sxx - sx * sx)


def save(fig, out_dir, name):
    """name.png and name.svg in out_dir; returns the PNG's path."""
    os.makedirs(out_dir, exist_ok=True)
    base = os.path.join(out_dir, name)
    fig.savefig(base + ".svg", metadata={"Date": None})
    fig.savefig(base + ".png", metadata={"Software": None})
    plt.close(fig)
    return base + ".png"
