#!/usr/bin/env bash
# ctest papers.liu-snoeyink: the quick study (400 PDB-like points, fine and
# coarse spacing) through every dlab pair and the installed baselines, then
# summarize.py --check: exact pairs and CGAL always valid Delaunay, George with
# floating spheres always valid. Usage: quick_check.sh DLAB
set -euo pipefail
dlab=$1
here=$(cd "$(dirname "$0")" && pwd)
python=/usr/bin/python3
[[ -x $python ]] || python=python3
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
"$dlab" study "$here/quick.json" --out "$out/study"
"$python" "$here/summarize.py" "$out/study/runs.csv" --check
# The coarse input must trip the inexact kernels somewhere, or it tests nothing.
grep -q ',pdb 0.004,.*,\(float\|epsilon\),.*,\(reported\|invalid\|not-delaunay\),' "$out/study/runs.csv" || {
  echo "no inexact failure on the coarse PDB-like input: the input lost its near-degeneracies" >&2
  exit 1
}
