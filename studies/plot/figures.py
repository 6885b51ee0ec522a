"""The figures of `dlab plot` (issue 13). Each function takes the study and returns
the data it plotted (for figures.json) or raises Skip with the reason.

Per-point figures (time, predicate calls, flips, cavities) use the runs whose
outcome is `ok` and plot, per series and n, the median over seeds and repeats.
"""
import math
import textwrap

import matplotlib.pyplot as plt
import matplotlib.ticker as ticker

import runs_table as rt
import style


class Skip(Exception):
    pass


class Study:
    def __init__(self, name, header, rows, out_dir):
        self.name, self.header, self.rows, self.out_dir = name, header, rows, out_dir
        self.ok = [r for r in rows if r["outcome"] == "ok"]
        self.vary = rt.varying_columns(rows)
        self.algorithms = sorted({r["algorithm"] for r in rows if r["tool"] == "dlab"})
        self.variants = sorted({rt.variant_of(r, self.vary) for r in rows if r["tool"] == "dlab"})
        self.kernels = [k for k in style.KERNEL_STYLE] + sorted(
            {r["kernel"] for r in rows if r["tool"] == "dlab"} - set(style.KERNEL_STYLE))

    def series_key(self, series):
        return rt.series_sort_key(series, style.ALGORITHM_ORDER, self.kernels)

    def style(self, series):
        return style.series_style(series, self.algorithms, self.variants)

    def counter_columns(self, prefix):
        return [c for c in self.header if c.startswith(prefix)]


_plain = ticker.FuncFormatter(lambda v, _: "%g" % v)


def _n_range(ns):
    ns = sorted(set(ns))
    if not ns:
        return "n = –"
    return "n = %d" % ns[0] if len(ns) == 1 else "n = %d–%d" % (ns[0], ns[-1])


def _panel_sort_key(panel):
    return (panel.dimension, panel.source)


def _caption(fig, text, width_inches):
    wrapped = "\n".join(textwrap.wrap(text, max(60, int(width_inches * 17))))
    fig.text(0.0, 0.0, wrapped, ha="left", va="top", fontsize=7.5, color="#333333",
             transform=fig.transFigure)


def _json_curves(curves):
    return {rt.panel_label(p): {rt.series_label(s): [list(t) for t in pts]
                                for s, pts in sorted(series.items())}
            for p, series in sorted(curves.items())}


def _json_titled(curves, titles):
    return {titles[k][1]: {rt.series_label(s): [list(t) for t in pts] for s, pts in sorted(v.items())}
            for k, v in sorted(curves.items(), key=lambda kv: titles[kv[0]][0])}


def _line_figure(study, curves, stem, title, ylabel, logy, caption, panel_titles=None, ncols=None):
    """One panel per key of curves: a Panel, or any key of panel_titles, whose values are
    (sort key, panel title[, y label])."""
    panels = sorted(curves, key=lambda p: panel_titles[p][0] if panel_titles else _panel_sort_key(p))
    ncols = ncols or (2 if len(panels) == 4 else min(3, len(panels)))
    nrows = math.ceil(len(panels) / ncols)
    fig, axes = plt.subplots(nrows, ncols, figsize=(4.4 * ncols, 3.3 * nrows), squeeze=False)
    all_series = sorted({s for p in panels for s in curves[p]}, key=study.series_key)
    handles = {}
    for ax, panel in zip(axes.flat, panels):
        ns, runs = [], 0
        for series in sorted(curves[panel], key=study.series_key):
            pts = curves[panel][series]
            (line,) = ax.plot([p[0] for p in pts], [p[1] for p in pts], **study.style(series))
            handles.setdefault(series, line)
            ns += [p[0] for p in pts]
            runs += sum(p[2] for p in pts)
        ax.set_xscale("log")
        ax.set_xticks(sorted(set(ns)))  # the sizes the study ran
        ax.xaxis.set_major_formatter(_plain)
        ax.xaxis.set_minor_formatter(ticker.NullFormatter())
        if logy:
            ax.set_yscale("log")
            ax.yaxis.set_major_locator(ticker.LogLocator(subs=(1.0, 2.0, 5.0)))
            ax.yaxis.set_major_formatter(_plain)
            ax.yaxis.set_minor_formatter(ticker.NullFormatter())
        else:
            ax.set_ylim(bottom=0)
        head = panel_titles[panel][1] if panel_titles else rt.panel_label(panel)
        ax.set_title("%s · %s · %d runs" % (head, _n_range(ns), runs))
        ax.set_xlabel("n (input points)")
        ax.set_ylabel(panel_titles[panel][2] if panel_titles and len(panel_titles[panel]) > 2
                      else ylabel)
        ax.grid(True, which="major", alpha=0.3)
    for ax in list(axes.flat)[len(panels):]:
        ax.set_visible(False)
    fig.suptitle("%s — %s" % (study.name, title), y=1.0)
    fig.tight_layout()
    fig.legend([handles[s] for s in all_series], [rt.series_label(s) for s in all_series],
               loc="upper left", bbox_to_anchor=(1.0, 0.97), frameon=False)
    _caption(fig, caption, 4.4 * ncols)
    return style.save(fig, study.out_dir, stem)


def _per_point(value, row):
    return None if value is None or not row["input_points"] else value / row["input_points"]


def time_per_point(study):
    curves = rt.median_curves(
        study.ok, lambda r: None if r["wall_seconds"] is None else
        _per_point(r["wall_seconds"] * 1e6, r), study.vary)
    if not curves:
        raise Skip("no ok run with wall_seconds")
    files = _line_figure(
        study, curves, "time_per_point", "triangulation time per point", "time per point (µs)", True,
        "Wall time of the triangulation alone (wall_seconds: no process start, file reading or "
        "validation) divided by the input points; median over seeds and repeats of the runs whose "
        "outcome is ok. Baselines: the time the tool reports itself.")
    return dict(files=files, unit="microseconds per input point", panels=_json_curves(curves))


def _predicate_names(study):
    return [c[5:] for c in study.counter_columns("pred.") if "." not in c[5:]]


def predicate_calls(study):
    names = _predicate_names(study)

    def calls(row):
        values = [row["pred." + p] for p in names if row["pred." + p] is not None]
        return _per_point(sum(values), row) if values else None

    curves = rt.median_curves([r for r in study.ok if r["tool"] == "dlab"], calls, study.vary)
    if not names or not curves:
        raise Skip("no pred.* column with values in ok runs")
    files = _line_figure(
        study, curves, "predicate_calls", "predicate calls per point", "predicate calls per point",
        False, "Calls of all predicates (%s) per input point, whatever stage answered them; "
        "median over seeds and repeats of the ok runs." % ", ".join(names))
    return dict(files=files, unit="calls per input point", predicates=names,
                panels=_json_curves(curves))


def stage_shares(study):
    """Stacked bars: per generator x dimension, per kernel x predicate, the share of
    calls answered by each stage (pred.X.S / pred.X), summed over all dlab runs."""
    names = _predicate_names(study)
    stages = sorted({c.split(".", 2)[2] for c in study.counter_columns("pred.") if c.count(".") == 2},
                    key=style.stage_rank)
    totals = {}  # panel -> (kernel, predicate) -> {stage: calls}
    ns = {}
    for row in study.rows:
        if row["tool"] != "dlab":
            continue
        for p in names:
            parts = {s: row.get("pred.%s.%s" % (p, s)) for s in stages}
            if not any(parts.values()):
                continue
            bar = totals.setdefault(rt.panel_of(row), {}).setdefault((row["kernel"], p), {})
            for s, v in parts.items():
                bar[s] = bar.get(s, 0) + (v or 0)
            ns.setdefault(rt.panel_of(row), []).append(rt.n_of(row))
    if not totals:
        raise Skip("no pred.<predicate>.<stage> column with values")
    panels = sorted(totals, key=_panel_sort_key)
    used = [s for s in stages if any(b.get(s) for p in panels for b in totals[p].values())]
    width = max(3.2, 0.75 * max(len(totals[p]) for p in panels) + 1.2)
    ncols = min(3, len(panels))
    nrows = math.ceil(len(panels) / ncols)
    fig, axes = plt.subplots(nrows, ncols, figsize=(width * ncols, 3.6 * nrows), squeeze=False)
    data = {}
    for ax, panel in zip(axes.flat, panels):
        bars = sorted(totals[panel], key=lambda kp: (study.kernels.index(kp[0]), names.index(kp[1])))
        panel_data = {}
        for x, (kernel, pred) in enumerate(bars):
            counts = totals[panel][(kernel, pred)]
            calls = sum(counts.values())
            shares = {s: counts[s] / calls for s in used if counts.get(s)}
            bottom = 0.0
            for s in used:
                share = shares.get(s, 0.0)
                if share:
                    ax.bar(x, 100 * share, bottom=100 * bottom, width=0.7,
                           color=style.stage_colour(s, used), edgecolor="white", linewidth=0.5)
                    if share >= 0.06:
                        ax.text(x, 100 * (bottom + share / 2), "%s\n%.1f%%" % (s, 100 * share),
                                ha="center", va="center", fontsize=6.5, color="white")
                bottom += share
            past = sum(v for s, v in shares.items() if s not in style.FLOATING_STAGES)
            ax.text(x, 101.5, "%d calls\npast the\nfilters: %.3g%%" % (calls, 100 * past),
                    ha="center", va="bottom", fontsize=6)
            panel_data["%s %s" % (kernel, pred)] = dict(calls=calls, shares=shares,
                                                        past_filters=past)
        data[rt.panel_label(panel)] = panel_data
        ax.set_xticks(range(len(bars)))
        ax.set_xticklabels(["%s\n%s" % kp for kp in bars], fontsize=7.5)
        ax.set_xlim(-0.6, len(bars) - 0.4)
        ax.set_ylim(0, 125)
        ax.set_yticks(range(0, 101, 20))
        ax.set_ylabel("share of calls (%)")
        ax.set_title("%s · %s · all algorithms" % (rt.panel_label(panel), _n_range(ns[panel])))
    for ax in list(axes.flat)[len(panels):]:
        ax.set_visible(False)
    fig.suptitle("%s — which stage answers a predicate call" % study.name, y=1.0)
    fig.tight_layout()
    handles = [plt.Rectangle((0, 0), 1, 1, color=style.stage_colour(s, used)) for s in used]
    fig.legend(handles, used, title="stage", loc="upper left", bbox_to_anchor=(1.0, 0.95),
               frameon=False)
    _caption(fig, "Share of the calls of each predicate answered by each stage "
             "(pred.X.stage / pred.X), summed over all dlab runs of the generator (every "
             "algorithm, n, seed and outcome). Above each bar: its calls and the share "
             "answered past the floating-point filters (any stage but static, filter and A). Stages: predicates/adaptive_kernel.hpp "
             "(static, filter, A–D, mp), integer and mp kernels (one stage each), "
             "perturbation = exact zero decided symbolically.", width * ncols)
    return dict(files=style.save(fig, study.out_dir, "stage_shares"), panels=data)


def flips_per_point(study):
    columns = [c for c in study.counter_columns("ctr.flips_") if c != "ctr.flips_total"]
    if not any(r[c] for r in study.ok for c in columns):
        columns = ["ctr.flips_total"] if "ctr.flips_total" in study.header else []
    curves, titles = {}, {}
    for column in columns:
        kind = column[len("ctr.flips_"):].replace("_", "–")
        part = rt.median_curves(study.ok, lambda r: _per_point(r[column], r), study.vary)
        for panel, series in part.items():
            if any(v for pts in series.values() for _, v, _ in pts):
                curves[(panel, kind)] = series
                titles[(panel, kind)] = ((_panel_sort_key(panel), kind),
                                         "%s · %s flips" % (rt.panel_label(panel), kind))
    if not curves:
        raise Skip("no ctr.flips_* column with values in ok runs")
    files = _line_figure(
        study, curves, "flips_per_point", "flips per point", "flips per point", False,
        "Flips of each type (ctr.flips_<in>_<out>: a flip replacing <in> simplices by <out>) per "
        "input point; median over seeds and repeats of the ok runs. Only algorithms that flip "
        "have these counters.", panel_titles=titles)
    return dict(files=files, unit="flips per input point",
                panels=_json_titled(curves, titles))


def cavity_sizes(study):
    curves, titles = {}, {}
    measures = [("ctr.cavity_simplices", "simplices per inserted point",
                 lambda r: None if r["ctr.cavity_simplices"] is None or not r["distinct_points"]
                 else r["ctr.cavity_simplices"] / r["distinct_points"]),
                ("ctr.max_cavity_simplices", "simplices",
                 lambda r: r["ctr.max_cavity_simplices"])]
    present = []
    for order, (column, ylabel, metric) in enumerate(measures):
        if column not in study.header:
            continue
        part = rt.median_curves(study.ok, metric, study.vary)
        if part:
            present.append(column)
        for panel, series in part.items():
            curves[(panel, column)] = series
            titles[(panel, column)] = ((_panel_sort_key(panel), order),
                                       "%s · %s cavity" % (rt.panel_label(panel),
                                                           "mean" if order == 0 else "largest"),
                                       ylabel)
    if not curves:
        raise Skip("no ctr.cavity_simplices / ctr.max_cavity_simplices values in ok runs")
    files = _line_figure(
        study, curves, "cavity_sizes", "cavity sizes", "simplices", False,
        "The distribution is the figure cavity_histogram. "
        "'mean' = ctr.cavity_simplices / distinct points (simplices removed per inserted point), "
        "'largest' = ctr.max_cavity_simplices; median over seeds and repeats of the ok runs. "
        "Only cavity-based algorithms have these counters.", panel_titles=titles,
        ncols=2 if len(present) == 2 else None)
    return dict(files=files, columns=present,
                panels=_json_titled(curves, titles))


def cavity_histogram(study):
    """Per panel, at its largest n: the share of insertions whose cavity removed
    1, 2-3, 4-7, ... simplices (ctr.cavity_size_* columns), summed over the ok runs."""
    columns = study.counter_columns("ctr.cavity_size_")
    rows = [r for r in study.ok if columns and any(r[c] for c in columns)]
    if not rows:
        raise Skip("no ctr.cavity_size_* values in ok runs")
    largest = {}
    for r in rows:
        panel = rt.panel_of(r)
        largest[panel] = max(largest.get(panel, 0), rt.n_of(r))
    counts, runs = {}, {}
    for r in rows:
        panel = rt.panel_of(r)
        if rt.n_of(r) != largest[panel]:
            continue
        series = rt.series_of(r, study.vary)
        bucket = counts.setdefault(panel, {}).setdefault(series, [0] * len(columns))
        for i, c in enumerate(columns):
            bucket[i] += r[c] or 0
        runs[panel] = runs.get(panel, 0) + 1
    labels = [c[len("ctr.cavity_size_"):].replace("_up", "+").replace("_", "–") for c in columns]
    panels = sorted(counts, key=_panel_sort_key)
    ncols = min(3, len(panels))
    nrows = math.ceil(len(panels) / ncols)
    fig, axes = plt.subplots(nrows, ncols, figsize=(4.4 * ncols, 3.3 * nrows), squeeze=False)
    all_series = sorted({s for p in panels for s in counts[p]}, key=study.series_key)
    handles, data = {}, {}
    for ax, panel in zip(axes.flat, panels):
        panel_data = {}
        for series in sorted(counts[panel], key=study.series_key):
            total = sum(counts[panel][series])
            shares = [100.0 * k / total for k in counts[panel][series]]
            (line,) = ax.plot(range(len(columns)), shares, **study.style(series))
            handles.setdefault(series, line)
            panel_data[rt.series_label(series)] = dict(insertions=total, shares_percent=shares)
        data[rt.panel_label(panel)] = dict(n=largest[panel], series=panel_data)
        ax.set_xticks(range(len(columns)))
        ax.set_xticklabels(labels)
        ax.set_ylim(bottom=0)
        ax.set_xlabel("simplices removed by one insertion")
        ax.set_ylabel("share of insertions (%)")
        ax.set_title("%s · n = %d · %d runs" % (rt.panel_label(panel), largest[panel], runs[panel]))
        ax.grid(True, alpha=0.3)
    for ax in list(axes.flat)[len(panels):]:
        ax.set_visible(False)
    fig.suptitle("%s — cavity-size distribution" % study.name, y=1.0)
    fig.tight_layout()
    fig.legend([handles[s] for s in all_series], [rt.series_label(s) for s in all_series],
               loc="upper left", bbox_to_anchor=(1.0, 0.97), frameon=False)
    _caption(fig, "Insertions by the number of simplices their cavity removed, in power-of-two "
             "buckets (ctr.cavity_size_*; algorithms/cavity_histogram.hpp), as a share of all "
             "insertions with a cavity, summed over the seeds and repeats of the ok runs at each "
             "panel's largest n. Only cavity-based algorithms (bowyer-watson, george) have them.",
             4.4 * ncols)
    return dict(files=style.save(fig, study.out_dir, "cavity_histogram"), buckets=labels,
                panels=data)


def outcomes(study):
    """Heatmap: series x (generator, dimension), the share of runs not ok."""
    if not study.rows:
        raise Skip("no runs")
    cells, ns = {}, {}
    for row in study.rows:
        key = (rt.series_of(row, study.vary), rt.panel_of(row))
        total, bad = cells.get(key, (0, 0))
        cells[key] = (total + 1, bad + (row["outcome"] != "ok"))
        ns.setdefault(rt.panel_of(row), []).append(rt.n_of(row))
    series = sorted({s for s, _ in cells}, key=study.series_key)
    panels = sorted({p for _, p in cells}, key=_panel_sort_key)
    fig, ax = plt.subplots(figsize=(2.6 + 1.25 * len(panels), 1.3 + 0.32 * len(series)))
    shares = [[(cells[(s, p)][1] / cells[(s, p)][0]) if (s, p) in cells else float("nan")
               for p in panels] for s in series]
    cmap = plt.get_cmap("Reds").copy()
    cmap.set_bad("#dddddd")
    image = ax.imshow(shares, cmap=cmap, vmin=0, vmax=1, aspect="auto")
    for i, s in enumerate(series):
        for j, p in enumerate(panels):
            if (s, p) in cells:
                total, bad = cells[(s, p)]
                ax.text(j, i, "%d/%d" % (bad, total), ha="center", va="center", fontsize=7,
                        color="white" if bad / total > 0.55 else "black")
            else:
                ax.text(j, i, "–", ha="center", va="center", fontsize=7, color="#666666")
    ax.set_xticks(range(len(panels)))
    ax.set_xticklabels(["%s\n%s" % (rt.panel_label(p), _n_range(ns[p])) for p in panels],
                       fontsize=7.5)
    ax.xaxis.tick_top()
    ax.set_yticks(range(len(series)))
    ax.set_yticklabels([rt.series_label(s) for s in series], fontsize=7.5)
    ax.set_xticks([x - 0.5 for x in range(1, len(panels))], minor=True)
    ax.set_yticks([y - 0.5 for y in range(1, len(series))], minor=True)
    ax.grid(which="minor", color="white", linewidth=1.5)
    ax.tick_params(which="minor", length=0)
    bar = fig.colorbar(image, ax=ax, fraction=0.05, pad=0.02)
    bar.set_label("share of runs not ok")
    ax.set_title("%s — runs whose outcome is not ok (not ok / runs)" % study.name, pad=12)
    fig.tight_layout()
    _caption(fig, "Not ok: any outcome but ok (lower-dimensional, reported, invalid, "
             "not-delaunay, missing-points, crash, timeout, out-of-memory); every seed, "
             "repeat and n of the generator counted. Grey: no run.", 2.6 + 1.25 * len(panels))
    return dict(files=style.save(fig, study.out_dir, "outcomes"),
                rows=[rt.series_label(s) for s in series],
                columns=[rt.panel_label(p) for p in panels],
                not_ok=[[cells[(s, p)][1] if (s, p) in cells else None for p in panels]
                        for s in series],
                runs=[[cells[(s, p)][0] if (s, p) in cells else None for p in panels]
                      for s in series])


ALL = [("time_per_point", time_per_point), ("predicate_calls", predicate_calls),
       ("stage_shares", stage_shares), ("flips_per_point", flips_per_point),
       ("cavity_sizes", cavity_sizes), ("cavity_histogram", cavity_histogram),
       ("outcomes", outcomes)]
