"""Shewchuk, "Adaptive precision floating-point arithmetic and fast robust geometric
predicates", DCG 18 (1997): on random input the adaptive predicates cost about as much
as plain floating point, because the first, floating-point stage settles almost
every call. Measured here at the level of a whole Delaunay triangulation.

Usage: costs.py DLAB OUT_DIR. For uniform points in 2D and 3D (dlab gen, seeds 1-3),
n = 10^4 and 10^5 (mp: 10^4 only), every kernel triangulates with bowyer-watson; the
time is dlab's own `seconds` (the triangulation alone), best of 3 repeats per seed,
then the median over the seeds. Writes OUT_DIR/costs.md and costs.json.
"""
import json
import pathlib
import statistics
import subprocess
import sys

KERNELS = ["float", "adaptive", "epsilon", "integer", "mp"]
SIZES = [10_000, 100_000]
SEEDS = [1, 2, 3]
REPEATS = 3
FLOATING_STAGES = ("static", "filter", "A")


def run(dlab, pts, kernel, stats):
    subprocess.run([dlab, "triangulate", str(pts), "--kernel", kernel, "--stats", str(stats),
                    "-o", "/dev/null"], check=True)
    return json.loads(stats.read_text())


def main(dlab, out_dir):
    out_dir = pathlib.Path(out_dir)
    work = out_dir / "work"
    work.mkdir(parents=True, exist_ok=True)
    results = []
    for dim in (2, 3):
        for n in SIZES:
            cell = {}
            for kernel in KERNELS:
                if kernel == "mp" and n > SIZES[0]:
                    continue
                per_seed, past, calls = [], 0, 0
                for seed in SEEDS:
                    pts = work / ("u%d_%d_%d.txt" % (dim, n, seed))
                    if not pts.exists():
                        subprocess.run([dlab, "gen", "uniform", "--dim", str(dim), "--n", str(n),
                                        "--seed", str(seed), "-o", str(pts)], check=True)
                    best = None
                    for _ in range(REPEATS):
                        s = run(dlab, pts, kernel, work / "stats.json")
                        best = s["seconds"] if best is None else min(best, s["seconds"])
                    per_seed.append(best / n * 1e6)
                    pred = s["predicates"]
                    calls += sum(v for k, v in pred.items() if "." not in k)
                    past += sum(v for k, v in pred.items()
                                if "." in k and k.split(".", 1)[1] not in FLOATING_STAGES)
                cell[kernel] = dict(us_per_point=statistics.median(per_seed), seeds=per_seed,
                                    calls=calls, past_filters=past if kernel == "adaptive" else None)
                print("uniform %dD n=%d %s: %.3f us/point" % (dim, n, kernel, cell[kernel]["us_per_point"]),
                      file=sys.stderr)
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
    if len(sys.argv) != 3:
        raise SystemExit("usage: costs.py DLAB OUT_DIR")
    main(sys.argv[1], sys.argv[2])
