"""`dlab plot STUDY_DIR [--out DIR]`: the figures of a study (issue 13).

Reads STUDY_DIR/runs.csv (contract: studies/README.md) and writes, as SVG and
PNG, into DIR (default STUDY_DIR/plots): time per point, predicate calls per
point, the share of calls answered by each predicate stage, flips per point,
cavity sizes and the outcome heatmap, plus figures.json with every plotted
value. A figure whose columns are absent or empty is skipped with a notice.
Exit status: 0 done, 2 bad input or matplotlib missing.
"""
import argparse
import json
import pathlib
import sys

import runs_table


def study_name(study_dir):
    """The config's name from meta.json when there is one, else the folder's name."""
    meta = study_dir / "meta.json"
    try:
        with open(meta, encoding="utf-8") as f:
            name = json.load(f).get("config", {}).get("name")
            if isinstance(name, str) and name:
                return name
    except (OSError, ValueError, AttributeError):
        pass
    return study_dir.resolve().name


def main(argv):
    parser = argparse.ArgumentParser(prog="dlab plot", add_help=True)
    parser.add_argument("study_dir")
    parser.add_argument("--out")
    args = parser.parse_args(argv)
    study_dir = pathlib.Path(args.study_dir)
    out_dir = pathlib.Path(args.out) if args.out else study_dir / "plots"
    try:
        header, rows = runs_table.read_runs(study_dir / "runs.csv")
    except runs_table.BadInput as e:
        print("dlab plot: %s" % e, file=sys.stderr)
        return 2
    try:
        import matplotlib  # noqa: F401
        import numpy  # noqa: F401
    except ImportError as e:
        print("dlab plot: %s cannot import %s: install Debian's python3-matplotlib "
              "(apt-get install python3-matplotlib)" % (sys.executable, e.name), file=sys.stderr)
        return 2
    import figures  # after the check: it imports matplotlib

    try:
        out_dir.mkdir(parents=True, exist_ok=True)
    except OSError as e:
        print("dlab plot: %s: cannot create: %s" % (out_dir, e.strerror), file=sys.stderr)
        return 2
    study = figures.Study(study_name(study_dir), header, rows, out_dir)
    summary = dict(study=study.name, runs=len(rows), figures={}, skipped={})
    for name, draw in figures.ALL:
        try:
            summary["figures"][name] = draw(study)
            print("dlab plot: %s" % ", ".join(str(out_dir / f)
                                              for f in summary["figures"][name]["files"]))
        except figures.Skip as e:
            summary["skipped"][name] = str(e)
            print("dlab plot: skipped %s: %s" % (name, e), file=sys.stderr)
    with open(out_dir / "figures.json", "w", encoding="utf-8") as f:
        json.dump(summary, f, indent=1, sort_keys=True, ensure_ascii=False)
        f.write("\n")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
