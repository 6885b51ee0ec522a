"""runs.csv of a study (studies/README.md, "runs.csv"): reading, series, panels, medians.

Standard library only, so that the tests can use it without matplotlib.
"""
import csv
import statistics
from collections import namedtuple

FIXED_COLUMNS = [
    "run", "input", "generator", "dimension", "n", "seed", "repeat", "tool", "algorithm", "kernel",
    "order", "policy", "location", "input_points", "distinct_points", "simplices", "outcome",
    "message", "wall_seconds", "cpu_seconds", "peak_rss_bytes",
]
INTEGER_COLUMNS = ["run", "dimension", "input_points", "distinct_points"]
REAL_COLUMNS = ["wall_seconds", "cpu_seconds"]


class BadInput(Exception):
    """A problem with the study directory: the message names file and line."""


# One line of a figure: a dlab pair (algorithm x kernel, with the order / policy /
# location `variant` when the study varies them) or an external baseline (tool).
Series = namedtuple("Series", "tool algorithm kernel variant")
# One panel: a generator (or a file input's label) in one dimension.
Panel = namedtuple("Panel", "source dimension")


def _number(text, path, line, column, kind):
    try:
        value = kind(text)
    except ValueError:
        raise BadInput("%s:%d: column %s: '%s' is not a%s number"
                       % (path, line, column, text, "n integer" if kind is int else ""))
    if kind is float and not (value == value and abs(value) != float("inf")):
        raise BadInput("%s:%d: column %s: '%s' is not finite" % (path, line, column, text))
    return value


def read_runs(path):
    """The rows of runs.csv as dicts; counters (pred.*, ctr.*) are int or None when empty."""
    try:
        handle = open(path, newline="", encoding="utf-8")
    except OSError as e:
        raise BadInput("%s: cannot read: %s" % (path, e.strerror))
    with handle:
        reader = csv.reader(handle)
        header = next(reader, None)
        if header is None:
            raise BadInput("%s:1: empty file (expected the runs.csv header)" % path)
        for column in FIXED_COLUMNS:
            if column not in header:
                raise BadInput("%s:1: header lacks column '%s'" % (path, column))
        counters = [c for c in header if c.startswith(("pred.", "ctr."))]
        rows = []
        for cells in reader:
            line = reader.line_num
            if cells == []:
                continue
            if len(cells) != len(header):
                raise BadInput("%s:%d: %d fields, the header has %d"
                               % (path, line, len(cells), len(header)))
            row = dict(zip(header, cells))
            for column in INTEGER_COLUMNS:
                row[column] = _number(row[column], path, line, column, int)
            row["n"] = _number(row["n"], path, line, "n", int) if row["n"] not in ("", "-") else None
            for column in REAL_COLUMNS:
                row[column] = (_number(row[column], path, line, column, float)
                               if row[column] != "" else None)
            for column in counters:
                row[column] = (_number(row[column], path, line, column, int)
                               if row[column] != "" else None)
            row["_line"] = line
            rows.append(row)
    return header, rows


VARIANT_COLUMNS = ["order", "policy", "location"]


def varying_columns(rows):
    """The columns of VARIANT_COLUMNS that take more than one value within one
    algorithm x kernel pair (policy `default` follows the kernel: not a variant)."""
    seen = {}
    for r in rows:
        if r["tool"] == "dlab":
            for c in VARIANT_COLUMNS:
                seen.setdefault((r["algorithm"], r["kernel"], c), set()).add(r[c])
    return [c for c in VARIANT_COLUMNS if any(len(v) > 1 for k, v in seen.items() if k[2] == c)]


def variant_of(row, columns):
    return "/".join(row[c] for c in columns)


def series_of(row, vary_columns):
    if row["tool"] != "dlab":
        return Series(row["tool"], row["tool"], "-", "-")
    return Series("dlab", row["algorithm"], row["kernel"], variant_of(row, vary_columns))


def series_label(series):
    if series.tool != "dlab":
        return series.tool
    label = "%s × %s" % (series.algorithm, series.kernel)
    return label + (" (%s)" % series.variant if series.variant else "")


def panel_of(row):
    # The input's label: the generator's name unless the config labels it (two
    # inputs of one generator with different options are two panels).
    source = row["input"] or row["generator"]
    return Panel(source, row["dimension"])


def panel_label(panel):
    return "%s %dD" % (panel.source, panel.dimension)


def n_of(row):
    """The size plotted on the x axis: the generator's n, else the points read."""
    return row["n"] if row["n"] is not None else row["input_points"]


def series_sort_key(series, algorithm_order, kernel_order):
    a = series.algorithm
    return (series.tool != "dlab",
            algorithm_order.index(a) if a in algorithm_order else len(algorithm_order), a,
            kernel_order.index(series.kernel) if series.kernel in kernel_order else len(kernel_order),
            series.kernel, series.variant)


def median_curves(rows, metric, vary_columns):
    """{panel: {series: [(n, median of metric over the runs at n, runs)]}}.

    metric(row) is a number or None (the row does not count)."""
    cells = {}
    for row in rows:
        value = metric(row)
        if value is None:
            continue
        key = (panel_of(row), series_of(row, vary_columns), n_of(row))
        cells.setdefault(key, []).append(value)
    curves = {}
    for (panel, series, n), values in cells.items():
        curves.setdefault(panel, {}).setdefault(series, []).append(
            (n, statistics.median(values), len(values)))
    for panel in curves.values():
        for points in panel.values():
            points.sort()
    return curves
