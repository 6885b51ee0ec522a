#!/bin/bash
# papers/george1997, Table 2, quick version (ctest papers.george1997_shell), run as
#   test_papers_george_shell.sh DLAB_SHELL_TRIANGULATIONS
# The triangulations of a convex n-gon that dlab's flips enumerate
# (papers/george1997/shell_triangulations.cpp) are the Catalan numbers
# C(n-2) = (2m)! / (m! (m+1)!), m = n - 2, computed here by the closed formula
# (the product of (m+k)/k over k = 2..m); the flip graph (the associahedron)
# is (n-3)-regular: C(n-2) (n-3) / 2 edges. George's Table 2, n = 3..12, is
# checked against the same formula (its n = 13 entry is the misprint noted in
# papers/george1997/README.md).
set -u
TOOL=$1
HERE=$(cd "$(dirname "$0")" && pwd)
. "$HERE/test_papers_lib.sh"
catalan() { awk -v m="$1" 'BEGIN { c = 1; for (k = 2; k <= m; ++k) c = c * (m + k) / k; printf "%.0f", c }'; }

out=$("$TOOL" 11) || fail "dlab_shell_triangulations 11: exit $?"
rows=0
while IFS=, read -r n count edges; do
  [ "$n" = n ] && continue
  rows=$((rows + 1))
  c=$(catalan $((n - 2)))
  [ "$count" = "$c" ] || fail "n=$n: $count triangulations enumerated, Catalan C($((n - 2))) = $c"
  [ "$edges" = $((c * (n - 3) / 2)) ] || fail "n=$n: $edges flip-graph edges, expected $((c * (n - 3) / 2))"
done <<< "$out"
[ "$rows" = 9 ] || fail "expected rows for n = 3..11, got $rows"

george_table2=(1 2 5 14 42 132 429 1430 4862 16796)  # n = 3..12 (the seed's text)
for i in "${!george_table2[@]}"; do
  [ "${george_table2[$i]}" = "$(catalan $((i + 1)))" ] || fail "George's Table 2, n=$((i + 3)): ${george_table2[$i]}"
done
"$TOOL" 2 > /dev/null 2>&1 && fail "NMAX 2 accepted"
"$TOOL" 15 > /dev/null 2>&1 && fail "NMAX 15 accepted"
finish
