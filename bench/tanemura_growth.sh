#!/usr/bin/env bash
# Growth of Tanemura-Ogawa-Ogita's cost with n on one generator
# (papers/triangulation_costs.md, issue 17 section 3):
#
#   bench/tanemura_growth.sh DLAB KERNEL "GEN ARGS" N1 N2 ...
#
# e.g. bench/tanemura_growth.sh build/cli/dlab adaptive "cospherical --dim 3 --seed 1" 500 1000 2000
# For each n: `dlab triangulate --stats` seconds (triangulating only) and the
# counters points_examined and candidates_outer (inside-sphere tests: exact
# counts, unaffected by a shared machine); last line: the least-squares slope of
# log(value) on log(n) for each column (the growth exponent).
set -euo pipefail
[ $# -ge 4 ] || { echo "usage: $0 DLAB KERNEL \"GEN ARGS\" N1 N2 ..." >&2; exit 2; }
dlab=$1 kernel=$2 gen=$3
shift 3
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
field() { sed -n "s/^ *\"$1\": *\\([0-9.eE+-]*\\),*\$/\\1/p" "$work/s.json"; }
echo "| n | seconds | points_examined | candidates_outer |"
echo "|---:|---:|---:|---:|"
for n in "$@"; do
  # shellcheck disable=SC2086
  "$dlab" gen $gen --n "$n" -o "$work/p.txt"
  "$dlab" triangulate "$work/p.txt" --algo tanemura --kernel "$kernel" -o /dev/null --stats "$work/s.json"
  echo "| $n | $(field seconds) | $(field points_examined) | $(field candidates_outer) |"
done | tee "$work/rows"
awk -F'|' '{ x = log($2); for (c = 3; c <= 5; ++c) { y[c] = log($c); sx[c] += x; sy[c] += y[c];
             sxx[c] += x * x; sxy[c] += x * y[c] } ++m }
     END { printf "| slope |"; for (c = 3; c <= 5; ++c)
             printf " %.2f |", (m * sxy[c] - sx[c] * sy[c]) / (m * sxx[c] - sx[c] * sx[c]); print "" }' \
  "$work/rows"
