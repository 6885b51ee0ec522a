#!/usr/bin/env python3
"""The README's benchmark table from a `dlab study` of papers/benchmark/study.json.

Usage: table.py STUDY_DIR/runs.csv

Prints two Markdown tables (studies/README.md gives the columns read here):
1. for each dlab pair (algorithm x kernel) and each input, the CPU time of the
   triangulation divided by CGAL Epick's on the same points (the cgal-epick
   baseline row of the same input, seed and n), then the run's peak resident
   bytes per input point; CGAL's own row gives its seconds and bytes per point;
2. for each algorithm and input, the integer and mp kernels' CPU time divided by
   the adaptive kernel's.
With several repeats, each time is the median of the repeats. A run whose outcome
is not `ok` shows its outcome instead of a number. Exit 2 on a missing or empty file.
"""
import csv
import statistics
import sys
from collections import defaultdict


def key_of(row):
    return (row["input"], row["seed"], row["n"])


def code_of(row):
    if row["tool"] != "dlab":
        return row["tool"]
    return f'{row["algorithm"]} × {row["kernel"]}'


def summarize(rows):
    """(code, input key) -> (median cpu seconds, median bytes per point) or the outcome."""
    groups = defaultdict(list)
    for r in rows:
        groups[(code_of(r), key_of(r))].append(r)
    out = {}
    for k, runs in groups.items():
        bad = [r["outcome"] for r in runs if r["outcome"] != "ok"]
        if bad:
            out[k] = bad[0]
            continue
        cpu = statistics.median(float(r["cpu_seconds"]) for r in runs)
        bpp = statistics.median(float(r["peak_rss_bytes"]) / int(r["input_points"]) for r in runs)
        out[k] = (cpu, bpp)
    return out


def ratio_cell(value, reference):
    if isinstance(value, str):
        return value
    if not isinstance(reference, tuple) or reference[0] <= 0:
        return "–"
    return f"{value[0] / reference[0]:.2f}"


def print_table(header, lines):
    print("| " + " | ".join(header) + " |")
    print("|" + "---|" + "---:|" * (len(header) - 1))
    for cells in lines:
        print("| " + " | ".join(cells) + " |")


def main(argv):
    if len(argv) != 1:
        print("usage: table.py STUDY_DIR/runs.csv", file=sys.stderr)
        return 2
    try:
        with open(argv[0], newline="") as f:
            rows = list(csv.DictReader(f))
    except OSError as e:
        print(f"{argv[0]}: {e.strerror}", file=sys.stderr)
        return 2
    if not rows:
        print(f"{argv[0]}: no runs", file=sys.stderr)
        return 2
    stats = summarize(rows)
    inputs = list(dict.fromkeys(key_of(r) for r in rows))  # in the study's order
    cgal = {k: stats.get(("cgal-epick", k), "–") for k in inputs}
    names = [f"{label} (n = {n})" for label, _, n in inputs]

    pairs = sorted({(r["algorithm"], r["kernel"]) for r in rows if r["tool"] == "dlab"})
    lines = [["CGAL Epick: seconds, B/pt"] +
             [f"{c[0]:.2f} s, {c[1]:.0f}" if isinstance(c, tuple) else c for c in cgal.values()]]
    for algo, kernel in pairs:
        cells = [f"{algo} × {kernel}"]
        for k in inputs:
            v = stats.get((f"{algo} × {kernel}", k), "–")
            cell = ratio_cell(v, cgal[k])
            cells.append(f"{cell}, {v[1]:.0f}" if isinstance(v, tuple) else cell)
        lines.append(cells)
    print_table(["dlab / CGAL (CPU), B/pt"] + names, lines)

    print()
    lines = []
    for algo in sorted({a for a, _ in pairs}):
        for kernel in ("integer", "mp"):
            if (algo, kernel) not in pairs:
                continue
            cells = [f"{algo}: {kernel} / adaptive"]
            for k in inputs:
                cells.append(ratio_cell(stats.get((f"{algo} × {kernel}", k), "–"),
                                        stats.get((f"{algo} × adaptive", k), "–")))
            lines.append(cells)
    print_table(["kernel / adaptive (CPU)"] + names, lines)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
