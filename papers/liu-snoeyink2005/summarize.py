#!/usr/bin/env python3
"""Liu & Snoeyink 2005 beside dlab: speed and failures per code on PDB-like input.

Reads a study's runs.csv (studies/README.md) and prints a Markdown table: for each
code (dlab algorithm x kernel, or external tool), the runs, how many were valid
Delaunay triangulations, the other outcomes, and the median microseconds per point
at each n. With --check it exits 1 unless the claims' directions hold: every exact
dlab pair and CGAL produce a valid Delaunay triangulation on every input, and George's
corrected cavity with floating spheres a valid one.
"""
import csv
import statistics
import sys
from collections import defaultdict

EXACT_KERNELS = {"adaptive", "integer", "mp"}


def code_of(row):
    if row["tool"] != "dlab":
        return row["tool"]
    return f'{row["algorithm"]} x {row["kernel"]}'


def must_succeed(row):
    """Pairs whose contract is a valid Delaunay triangulation on any input."""
    if row["tool"] in ("cgal-epick", "cgal-epeck"):
        return True
    # George with floating spheres (and with the enclosing box) promises
    # validity only (George 1997, claim 1): checked apart, by must_be_valid.
    algo = row["algorithm"]
    exact_algo = not algo.startswith("george") or algo == "george+exact-sphere"
    return row["tool"] == "dlab" and row["kernel"] in EXACT_KERNELS and exact_algo


def must_be_valid(row):
    return row["tool"] == "dlab" and row["kernel"] in EXACT_KERNELS and row["algorithm"] == "george"


def main(argv):
    check = "--check" in argv
    paths = [a for a in argv if a != "--check"]
    if len(paths) != 1:
        print("usage: summarize.py STUDY_DIR/runs.csv [--check]", file=sys.stderr)
        return 2
    with open(paths[0], newline="") as f:
        rows = list(csv.DictReader(f))
    if not rows:
        print(f"{paths[0]}: no runs", file=sys.stderr)
        return 2
    sizes = sorted({int(r["n"]) for r in rows})
    per_code = defaultdict(list)
    for r in rows:
        per_code[code_of(r)].append(r)
    header = ["code", "runs", "ok", "other outcomes"] + [f"µs/point n={n}" for n in sizes]
    print("| " + " | ".join(header) + " |")
    print("|" + "---|" * len(header))
    broken = []
    for code in sorted(per_code):
        runs = per_code[code]
        outcomes = defaultdict(int)
        for r in runs:
            outcomes[r["outcome"]] += 1
            if (must_succeed(r) and r["outcome"] != "ok") or \
                    (must_be_valid(r) and r["outcome"] not in ("ok", "not-delaunay")):
                broken.append(f'run {r["run"]}: {code} -> {r["outcome"]} {r["message"]}')
        others = ", ".join(f"{k} {v}" for k, v in sorted(outcomes.items()) if k != "ok") or "–"
        cells = [code, str(len(runs)), str(outcomes.get("ok", 0)), others]
        for n in sizes:
            t = [float(r["wall_seconds"]) / int(r["input_points"]) * 1e6
                 for r in runs if int(r["n"]) == n and r["outcome"] == "ok" and r["wall_seconds"]]
            cells.append(f"{statistics.median(t):.2f}" if t else "–")
        print("| " + " | ".join(cells) + " |")
    if check and broken:
        print("\n".join(["claim broken:"] + broken), file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
