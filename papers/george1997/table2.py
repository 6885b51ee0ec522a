"""George 1997, Table 2 beside dlab's enumeration (shell_triangulations.cpp).

    DLAB_SHELL=build/papers/dlab_shell_triangulations
    $DLAB_SHELL 13 > OUT/table2.csv && /usr/bin/python3 papers/george1997/table2.py OUT/table2.csv

Writes OUT/table2.{png,svg} beside the CSV and prints the comparison as a markdown table.
"""
import csv
import math
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
import paper_plot as pp  # noqa: E402

# Table 2 as printed (n = 3..13), from the seed's text of the paper.
GEORGE = {3: 1, 4: 2, 5: 5, 6: 14, 7: 42, 8: 132, 9: 429, 10: 1430, 11: 4862, 12: 16796, 13: 587786}

path = sys.argv[1]
rows = [(int(r["n"]), int(r["triangulations"]), int(r["flip_graph_edges"])) for r in csv.DictReader(open(path))]
print("| n | George's Table 2 | dlab: triangulations reached by flips | flip-graph edges | C(n-2) = (2m)!/(m!(m+1)!) |")
print("|---:|---:|---:|---:|---:|")
for n, t, e in rows:
    m = n - 2
    catalan = math.comb(2 * m, m) // (m + 1)
    g = GEORGE.get(n)
    mark = " (misprint)" if g is not None and g != catalan else ""
    print("| %d | %s%s | %d | %d | %d |" % (n, g if g is not None else "-", mark, t, e, catalan))

fig, ax = pp.plt.subplots(figsize=(6.5, 4.5))
ns = [n for n, _, _ in rows]
ax.plot(ns, [t for _, t, _ in rows], "-o", color="tab:blue", label="dlab: triangulations reached by 2-2 flips")
gn = sorted(GEORGE)
ax.plot(gn, [GEORGE[n] for n in gn], "x", color="tab:red", markersize=9, mew=2,
        label="George 1997, Table 2 (as printed)")
bad = [n for n in gn if GEORGE[n] != math.comb(2 * (n - 2), n - 2) // (n - 1)]
for n in bad:
    ax.annotate("n = %d: printed %d,\nC(%d) = %d" % (n, GEORGE[n], n - 2, math.comb(2 * (n - 2), n - 2) // (n - 1)),
                (n, GEORGE[n]), textcoords="offset points", xytext=(-150, -5), fontsize=8,
                arrowprops={"arrowstyle": "->"})
ax.set_yscale("log")
ax.set_xlabel("n (tetrahedra in the shell = vertices of its polygon)")
ax.set_ylabel("ways to re-mesh the shell (triangulations of the n-gon)")
ax.set_title("George 1997, Table 2: shell re-meshings are the Catalan numbers C(n-2)")
ax.grid(True, which="both", alpha=0.3)
ax.legend(loc="upper left")
fig.tight_layout()
print(pp.save(fig, os.path.dirname(os.path.abspath(path)), "table2"))
