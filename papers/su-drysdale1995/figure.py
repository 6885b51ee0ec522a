"""Su & Drysdale's counts for incremental insertion, from the study of study.json:
in-circle tests and flips per point (the work of the update) and orientation
tests per point (the work of locating) for each order and location scheme.

    /usr/bin/python3 papers/su-drysdale1995/figure.py STUDY_DIR

Writes STUDY_DIR/su_drysdale.{png,svg} and STUDY_DIR/counts.md (the table at the
largest n), and prints the table.
"""
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
import paper_plot as pp  # noqa: E402

study = sys.argv[1]
rows = pp.read_runs(os.path.join(study, "runs.csv"))
generators = []
for r in rows:
    if r["generator"] not in generators:
        generators.append(r["generator"])
ORDERS = ["input", "random", "brio", "hilbert"]
COLOUR = {"input": "tab:gray", "random": "tab:blue", "brio": "tab:orange", "hilbert": "tab:green"}
ALGO_STYLE = {"lawson": ("-", "o"), "bowyer-watson": ("--", "s")}
LOC_STYLE = {"walk": ("-", "o"), "scan": (":", "x")}


def per_point(rs, f):
    return [f(r) / r["input_points"] for r in rs]


def select(**kw):
    out = [r for r in rows if all(r[k] == v for k, v in kw.items())]
    return sorted(out, key=lambda r: r["n"])


fig, axes = pp.plt.subplots(3, len(generators), figsize=(4 * len(generators) + 2.5, 10), squeeze=False)
for col, gen in enumerate(generators):
    for order in ORDERS:
        for algo, (ls, mk) in ALGO_STYLE.items():
            rs = select(generator=gen, order=order, algorithm=algo, location="walk")
            ns = [r["n"] for r in rs]
            axes[0][col].plot(ns, per_point(rs, lambda r: r["pred.incircle"]), ls, marker=mk,
                              color=COLOUR[order], label="%s, %s" % (algo, order))
            if algo == "lawson":
                axes[1][col].plot(ns, per_point(rs, lambda r: pp.counter(r, "flips_2_2")), ls, marker=mk,
                                  color=COLOUR[order], label="lawson, %s" % order)
        for loc, (ls, mk) in LOC_STYLE.items():
            rs = select(generator=gen, order=order, algorithm="lawson", location=loc)
            axes[2][col].plot([r["n"] for r in rs], per_point(rs, lambda r: r["pred.orient2d"]), ls, marker=mk,
                              color=COLOUR[order], label="lawson, %s, %s" % (order, loc))
    for row, what in enumerate(["in-circle tests per point", "flips per point (Lawson)",
                                "orientation tests per point (Lawson: location + split)"]):
        ax = axes[row][col]
        ax.set_xscale("log")
        if row == 2:
            ax.set_yscale("log")
        ax.set_xlabel("n (%s points, 2D)" % gen)
        ax.set_ylabel(what)
        ax.set_title("%s: %s" % (gen, what.split(" (")[0]))
        ax.grid(True, which="both", alpha=0.3)
        if row < 2:
            ax.set_ylim(bottom=0)
        if col == len(generators) - 1:  # one legend per row, outside the panels
            ax.legend(loc="center left", bbox_to_anchor=(1.02, 0.5))
fig.suptitle("Su & Drysdale 1995: incremental insertion, work per point, by insertion order and location scheme\n"
             "(in-circle tests and flips are the same with the scan; orientation tests are where the schemes differ)")
fig.tight_layout()
png = pp.save(fig, study, "su_drysdale")

nmax = max(r["n"] for r in rows)
table = ["| generator | order | algorithm | in-circle / pt | flips / pt | orient2d / pt, walk | orient2d / pt, scan |",
         "|---|---|---|---:|---:|---:|---:|"]
for gen in generators:
    for order in ORDERS:
        for algo in ALGO_STYLE:
            w = select(generator=gen, order=order, algorithm=algo, location="walk", n=nmax)[0]
            s = select(generator=gen, order=order, algorithm=algo, location="scan", n=nmax)[0]
            n = w["input_points"]
            flips = "%.2f" % (pp.counter(w, "flips_2_2") / n) if algo == "lawson" else "-"
            table.append("| %s | %s | %s | %.2f | %s | %.1f | %.0f |" % (
                gen, order, algo, w["pred.incircle"] / n, flips, w["pred.orient2d"] / n, s["pred.orient2d"] / n))
with open(os.path.join(study, "counts.md"), "w") as f:
    f.write("n = %d\n\n" % nmax + "\n".join(table) + "\n")
print("n = %d" % nmax)
print("\n".join(table))
print(png)
