"""Shewchuk, "Adaptive precision floating-point arithmetic and fast robust geometric
predicates", DCG 18 (1997): on random input the adaptive predicates cost about as much
as plain floating point, because the first, floating-point stage settles almost
every call. Measured here at the level of a whole Delaunay triangulation.

Usage: costs.py OUT_DIR STUDY_DIR... -- the runs.csv of `dlab study costs_study.json`
and `costs_study_mp.json` (bowyer-watson, every kernel, uniform points in 2D and 3D,
seeds 1-3, n = 10^4 and 10^5, mp at 10^4 only, 3 repeats). The time is wall_seconds
(the triangulation alone), best of the 3 repeats per seed, then the median over the
seeds. Writes OUT_DIR/costs.md and costs.json.
"""
import csv
import json
import pathlib
import statistics
import sys

KERNELS = ["float", "adaptive", "epsilon", "integer", "mp"]
PREDICATES = ["orient2d", "incircle", "orient3d", "insphere"]
FLOATING_STAGES = ("static", "filter", "A")


def read_rows(study_dirs):
    rows = []
    for d in study_dirs:
        with open(pathlib.Path(d) / "runs.csv", newline="") as f:
            rows += list(csv.DictReader(f))
    bad = [r for r in rows if r["outcome"] != "ok"]
    if bad:
        raise SystemExit("costs.py: run %s is %s, not ok" % (bad[0]["run"], bad[0]["outcome"]))
    return rows


def main(out_dir, study_dirs):
    out_dir = pathlib.Path(out_dir)
    rows = read_rows(study_dirs)
    results = []
    for dim, n in sorted({(int(r["dimension"]), int(r["n"])) for r in rows}):
        cell = {}
        for kernel in KERNELS:
            runs = [r for r in rows if int(r["dimension"]) == dim and int(r["n"]) == n
                    and r["kernel"] == kernel]
            if not runs:
                continue
            seeds = sorted({int(r["seed"]) for r in runs})
            per_seed = [min(float(r["wall_seconds"]) for r in runs if int(r["seed"]) == s) / n * 1e6
                        for s in seeds]
            # Calls and stages of one repeat per seed (the repeats make the same calls).
            first = [r for r in runs if r["repeat"] == "0"]
            calls = sum(int(r["pred." + p]) for r in first for p in PREDICATES)
            past = sum(int(r[c]) for r in first for c in r
                       if c.startswith("pred.") and c.count(".") == 2 and r[c]
                       and c.split(".")[1] in PREDICATES and c.split(".")[2] not in FLOATING_STAGES)
            cell[kernel] = dict(us_per_point=statistics.median(per_seed), seeds=per_seed,
                                calls=calls, past_filters=past if kernel == "adaptive" else None)
        results.append(dict(dimension=dim, n=n, kernels=cell))
    (out_dir / "costs.json").write_text(json.dumps(results, indent=1, sort_keys=True) + "\n")
    with open(out_dir / "costs.md", "w", encoding="utf-8") as f:
        f.write("Microseconds per point of a bowyer-watson triangulation of uniform points (median "
                "over seeds 1-3 of the best of 3 runs), and adaptive / float:\n\n")
        f.write("| dim | n | %s | adaptive / float | adaptive calls past the filters |\n"
                % " | ".join(KERNELS))
        f.write("|---|---:|%s---:|---:|\n" % ("---:|" * len(KERNELS)))
        for r in results:
            k = r["kernels"]
            cells = ["%.3f" % k[name]["us_per_point"] if name in k else "–" for name in KERNELS]
            a = k["adaptive"]
            f.write("| %dD | %d | %s | %.2f | %d of %d |\n"
                    % (r["dimension"], r["n"], " | ".join(cells),
                       a["us_per_point"] / k["float"]["us_per_point"], a["past_filters"], a["calls"]))


if __name__ == "__main__":
    if len(sys.argv) < 3:
        raise SystemExit("usage: costs.py OUT_DIR STUDY_DIR...")
    main(sys.argv[1], sys.argv[2:])
