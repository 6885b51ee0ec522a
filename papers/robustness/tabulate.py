#!/usr/bin/env python3
"""Failure-rate tables for papers/robustness from dlab fuzz campaign directories.

usage: tabulate.py CAMPAIGN_DIR... > tables.md

Reads each DIR/results.jsonl (one line per case x pair) and writes, per dimension
and kernel, a Markdown table: generators as rows, algorithms as columns, each
cell the failure rate (outcome not ok / lower-dimensional) with its 95 % Wilson
score interval (Wilson, JASA 22, 1927). It recomputes the rates from the records
alone, so it is also an independent check of the campaign's own summary.txt.
Then the exact pairs' run and failure counts.
"""
import collections
import json
import math
import sys

NOT_FAILURES = {"ok", "lower-dimensional"}


def wilson(k, n, z=1.959963984540054):
    if n == 0:
        return (0.0, 1.0)
    if k == 0:
        return (0.0, z * z / (n + z * z))
    if k == n:
        return (n / (n + z * z), 1.0)
    p = k / n
    d = 1 + z * z / n
    c = (p + z * z / (2 * n)) / d
    h = z * math.sqrt(p * (1 - p) / n + z * z / (4 * n * n)) / d
    return (max(0.0, c - h), min(1.0, c + h))


def pct(x):
    return f"{100 * x:.3g}"


def main(dirs):
    runs = collections.Counter()
    fails = collections.Counter()
    classes = collections.defaultdict(collections.Counter)
    exact_runs = exact_fails = 0
    order_algo, order_gen = [], []
    for d in dirs:
        # The generators in the order the campaign's summary lists them.
        try:
            with open(f"{d}/summary.txt") as f:
                for line in list(f)[1:]:
                    cols = line.split()
                    if len(cols) > 2 and cols[2] not in order_gen:
                        order_gen.append(cols[2])
        except OSError:
            pass
        with open(f"{d}/results.jsonl") as f:
            for line in f:
                r = json.loads(line)
                key = (r["dim"], r["kernel"], r["algo"], r["gen"])
                failed = r["outcome"] not in NOT_FAILURES
                if r["exact"]:
                    exact_runs += 1
                    exact_fails += failed
                    continue
                if r["algo"] not in order_algo:
                    order_algo.append(r["algo"])
                if r["gen"] not in order_gen:
                    order_gen.append(r["gen"])
                runs[key] += 1
                fails[key] += failed
                if failed:
                    classes[key][r["outcome"]] += 1
    for dim in sorted({k[0] for k in runs}):
        for kernel in sorted({k[1] for k in runs if k[0] == dim}):
            gens = [g for g in order_gen if any(k[0] == dim and k[3] == g for k in runs)]
            algos = [a for a in order_algo if any(k[0] == dim and k[1] == kernel and k[2] == a for k in runs)]
            print(f"\n### {dim}D, kernel `{kernel}`: failure rate in % [95 % Wilson interval]\n")
            print("| generator | runs | " + " | ".join(algos) + " |")
            print("|---|---:|" + "---|" * len(algos))
            for g in gens:
                cells = []
                for a in algos:
                    key = (dim, kernel, a, g)
                    lo, hi = wilson(fails[key], runs[key])
                    cells.append(f"{pct(fails[key] / runs[key])} [{pct(lo)}, {pct(hi)}]" if runs[key] else "")
                n = min(runs[(dim, kernel, a, g)] for a in algos)
                print(f"| {g} | {n} | " + " | ".join(cells) + " |")
            print("\nOver all generators (each drawn with equal probability): failures, and how they"
                  " showed -- silently (a mesh returned as a result: invalid or not-delaunay) or"
                  " reported by the algorithm's own checks; crash, timeout, out-of-memory counted apart.\n")
            print("| algorithm | runs | failed % | silent % | reported % | crash / timeout / out-of-memory |")
            print("|---|---:|---:|---:|---:|---|")
            for a in algos:
                keys = [(dim, kernel, a, g) for g in gens]
                n = sum(runs[k] for k in keys)
                cls = collections.Counter()
                for k in keys:
                    cls.update(classes[k])
                failed = sum(cls.values())
                silent = cls["invalid"] + cls["not-delaunay"]
                died = " / ".join(str(cls[c]) for c in ("crash", "timeout", "out-of-memory"))
                print(f"| {a} | {n} | {100 * failed / n:.2f} | {100 * silent / n:.2f} | "
                      f"{100 * cls['reported'] / n:.2f} | {died} |")
            print("\nMost fragile algorithm per generator (highest rate; ties listed):\n")
            for g in gens:
                rates = {a: fails[(dim, kernel, a, g)] / runs[(dim, kernel, a, g)]
                         for a in order_algo if runs[(dim, kernel, a, g)]}
                top = max(rates.values())
                if top == 0:
                    continue
                worst = [a for a, r in rates.items() if r == top]
                cls = collections.Counter()
                for a in worst:
                    cls.update(classes[(dim, kernel, a, g)])
                print(f"- {g}: {', '.join(worst)} ({pct(top)} %; "
                      + ", ".join(f"{c} {n}" for c, n in cls.most_common()) + ")")
    print(f"\nExact pairs: {exact_runs} runs, {exact_fails} failures.")


if __name__ == "__main__":
    if len(sys.argv) < 2:
        sys.exit(__doc__)
    main(sys.argv[1:])
