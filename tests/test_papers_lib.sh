# Shared by tests/test_papers_*.sh (sourced): failure counting, a stats reader,
# ratio checks. The quick versions of the paper folders' claims (ctest -L papers).
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }
# field FILE KEY: the number on KEY's line of a --stats JSON file (one key a line).
field() { sed -n "s/^ *\"$2\": *\\([0-9.eE+-]*\\),*\$/\\1/p" "$1" | head -1; }
# calls FILE: predicate calls of the four predicates together.
calls() { echo $(( $(field "$1" orient2d) + $(field "$1" incircle) + $(field "$1" orient3d) + $(field "$1" insphere) )); }
# within NAME X LO HI: fails unless LO <= X <= HI (decimals).
within() {
  awk -v x="$2" -v lo="$3" -v hi="$4" 'BEGIN { exit !(x >= lo && x <= hi) }' || fail "$1 = $2, expected in [$3, $4]"
}
# per_point_ratio CALLS_A N_A CALLS_B N_B: (CALLS_B / N_B) / (CALLS_A / N_A).
per_point_ratio() { awk -v a="$1" -v na="$2" -v b="$3" -v nb="$4" 'BEGIN { printf "%.4f", (b / nb) / (a / na) }'; }
# run NAME ARGS...: dlab triangulate ARGS --validate --stats NAME.json; an exact
# pair must end valid Delaunay (exit 0).
run() {
  local name=$1
  shift
  "$DLAB" triangulate "$@" --validate -o /dev/null --stats "$name.json" 2> "$name.err" ||
    fail "$name: exit $? ($(head -c 300 "$name.err"))"
}
finish() {
  [ "$failures" = 0 ] && echo "all checks passed" && exit 0
  echo "$failures failures"
  exit 1
}
