"""Baker ch. 16 figure: Bowyer-Watson with the walk from the last insertion against
the scan of every simplex (no location structure), and Tanemura-Ogawa-Ogita,
from the two studies of reproduce.sh.

    /usr/bin/python3 papers/baker-ch16/figure.py OUT    (OUT/walk, OUT/scan: study dirs)

Writes OUT/baker_ch16.{png,svg} (CPU seconds and predicate calls per point
against n, log-log, 2D and 3D) and OUT/slopes.md (the growth exponent of the
totals, least squares over every n measured), and prints the table.
"""
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
import paper_plot as pp  # noqa: E402

out = sys.argv[1]
rows = pp.read_runs(os.path.join(out, "walk", "runs.csv")) + pp.read_runs(os.path.join(out, "scan", "runs.csv"))


def label(r):
    if r["algorithm"] == "tanemura":
        return "Tanemura-Ogawa-Ogita, %s" % r["order"]
    return "Bowyer-Watson, %s, %s order" % (r["location"], r["order"])


STYLE = {  # colour by method, marker by order
    ("bowyer-watson", "walk"): "tab:blue",
    ("bowyer-watson", "scan"): "tab:red",
    ("tanemura", "-"): "tab:green",
}
MARKER = {"brio": "o", "random": "s"}

series = {}
for r in rows:
    series.setdefault((r["dimension"], label(r)), []).append(r)

fig, axes = pp.plt.subplots(2, 2, figsize=(10, 8))
table = ["| dim | run | n | exponent of CPU time | exponent of predicate calls | calls per point at largest n |",
         "|---|---|---|---:|---:|---:|"]
for (dim, name), rs in sorted(series.items()):
    rs.sort(key=lambda r: r["n"])
    ns = [r["n"] for r in rs]
    cpu = [r["cpu_seconds"] for r in rs]
    calls = [pp.predicate_calls(r) for r in rs]
    s_cpu, s_calls = pp.slope(ns, cpu), pp.slope(ns, calls)
    r0 = rs[0]
    colour = STYLE[(r0["algorithm"], r0["location"])]
    marker = MARKER[r0["order"]]
    style = "-" if r0["order"] == "brio" else "--"
    row = dim - 2
    axes[row][0].plot(ns, [c / n * 1e6 for c, n in zip(cpu, ns)], style, color=colour, marker=marker,
                      label="%s (slope %.2f)" % (name, s_cpu))
    axes[row][1].plot(ns, [c / n for c, n in zip(calls, ns)], style, color=colour, marker=marker,
                      label="%s (slope %.2f)" % (name, s_calls))
    table.append("| %dD | %s | %d..%d | %.2f | %.2f | %.0f |" % (dim, name, ns[0], ns[-1], s_cpu, s_calls,
                                                             calls[-1] / ns[-1]))
for row in range(2):
    for col, what in enumerate(["CPU time per point (microseconds)", "predicate calls per point"]):
        ax = axes[row][col]
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.set_xlabel("n (uniform points in the unit %s)" % ("square" if row == 0 else "cube"))
        ax.set_ylabel(what)
        ax.set_title("%dD: %s" % (row + 2, what))
        ax.grid(True, which="both", alpha=0.3)
        ax.legend(loc="best")
fig.suptitle("Baker ch. 16: Bowyer-Watson located by a walk from the last insertion vs a scan of every simplex\n"
             "(slope: growth exponent of the total, least squares; N log N ~ 1, N^2 = 2)")
fig.tight_layout()
png = pp.save(fig, out, "baker_ch16")
with open(os.path.join(out, "slopes.md"), "w") as f:
    f.write("\n".join(table) + "\n")
print("\n".join(table))
print(png)
