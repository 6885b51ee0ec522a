"""Deterministic matplotlib set-up and the look of a series (dlab plot).

Reruns must give byte-identical files: a fixed SVG hash salt, no date in the
metadata, glyphs drawn as paths in matplotlib's bundled DejaVu Sans, and every
series drawn in a sorted order.
"""
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

plt.rcParams.update({
    "svg.hashsalt": "dlab-plot",
    "svg.fonttype": "path",
    "font.family": "DejaVu Sans",
    "font.size": 9,
    "axes.titlesize": 9,
    "axes.labelsize": 9,
    "legend.fontsize": 8,
    "figure.dpi": 100,
    "savefig.dpi": 130,
    "path.simplify": False,
})

# Colour per algorithm (tab10 order), line style and marker per kernel.
ALGORITHM_ORDER = ["bowyer-watson", "lawson", "tanemura", "george"]
KERNEL_STYLE = {
    "adaptive": ("-", "o"),
    "integer": ("--", "s"),
    "mp": (":", "D"),
    "float": ("-.", "x"),
    "epsilon": ((0, (5, 1, 1, 1, 1, 1)), "^"),
}
BASELINE_STYLE = {
    "cgal-epick": ("#000000", "P"),
    "cgal-epeck": ("#555555", "*"),
    "tetgen": ("#8c564b", "v"),
    "qhull": ("#7f7f7f", "X"),
    "scipy": ("#bcbd22", "h"),
}
VARIANT_MARKERS = ["o", "s", "^", "D", "v", "P", "X", "*", "h", "<", ">"]
# Stages of predicates/*: the order in which a call can reach them.
# Stages that answer in floating point (the adaptive kernel's first ones, and the
# single stage of the inexact kernels); the others compute exactly.
FLOATING_STAGES = {"static", "filter", "A", "float", "epsilon"}
STAGE_ORDER = ["float", "epsilon", "static", "filter", "A", "B", "C", "D", "integer", "exact", "mp",
               "perturbation"]


def algorithm_colour(algorithm, algorithms):
    """tab10 colour of an algorithm: the known four first, then others sorted."""
    known = [a for a in ALGORITHM_ORDER if a in algorithms]
    rest = sorted(a for a in algorithms if a not in ALGORITHM_ORDER)
    names = known + rest
    base = algorithm.split("+")[0]
    index = names.index(algorithm) if algorithm in names else names.index(base)
    return plt.get_cmap("tab10")(index % 10)


def series_style(series, algorithms, variants):
    """matplotlib keyword arguments for one series (see runs_table.Series)."""
    if series.tool != "dlab":
        colour, marker = BASELINE_STYLE.get(series.tool, ("#333333", "p"))
        return dict(color=colour, linestyle="-", marker=marker, linewidth=1.0, markersize=5)
    linestyle, marker = KERNEL_STYLE.get(series.kernel, ("-", "p"))
    if len(variants) > 1:
        marker = VARIANT_MARKERS[variants.index(series.variant) % len(VARIANT_MARKERS)]
    return dict(color=algorithm_colour(series.algorithm, algorithms), linestyle=linestyle,
                marker=marker, linewidth=1.3, markersize=4.5,
                markerfacecolor="none" if series.kernel in ("float", "epsilon") else None)


def stage_colour(stage, stages):
    ordered = sorted(stages, key=stage_rank)
    return plt.get_cmap("viridis" if len(ordered) > 10 else "tab10")(ordered.index(stage) % 10)


def stage_rank(stage):
    return (STAGE_ORDER.index(stage) if stage in STAGE_ORDER else len(STAGE_ORDER), stage)


def save(fig, out_dir, stem):
    """STEM.svg and STEM.png in out_dir, without dates or version stamps."""
    paths = []
    for ext, meta in (("svg", {"Date": None, "Creator": None}),
                      ("png", {"Software": None})):
        path = out_dir / (stem + "." + ext)
        fig.savefig(path, format=ext, metadata=meta, bbox_inches="tight")
        paths.append(path.name)
    plt.close(fig)
    return paths
