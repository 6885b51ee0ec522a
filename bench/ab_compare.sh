#!/usr/bin/env bash
# Wall-time comparison of two builds of bench/bench_triangulation.cpp on one
# machine: R rounds, the two binaries in alternating order (A B, B A, ...), so
# that a drift of the machine's speed falls on both alike.  Each run is the
# bench's own best of its --repeat; the script prints, per binary, every
# round's dlab seconds (the first dlab row: the first of --kernels), their
# minimum and median, and the minimum and median of the ratio to CGAL when the
# bench timed CGAL in the same run (--cgal 1, the bench's default).
#
#   bench/ab_compare.sh [-r ROUNDS] BENCH_A BENCH_B [bench options...]
#   e.g. bench/ab_compare.sh -r 6 /tmp/base/dlab_bench_triangulation \
#          build/bench/dlab_bench_triangulation --dim 3 --n 200000 --algo lawson --repeat 5 --cgal 0
#
# Run it once with the same binary as A and B first: the spread of that A/A
# comparison is the noise floor of the machine.  On the 2-vCPU VM of
# papers/triangulation_costs.md, session 33, two A/A runs of 6 rounds put the
# minima 0.1 % and 5 % apart and the medians 7 % and 0 %; a change there with
# 1.4 % fewer instructions (callgrind) read +2.6 % (minimum) and +13 % (median),
# so instruction counts alone do not decide.
set -euo pipefail
rounds=6
usage="usage: $0 [-r ROUNDS] BENCH_A BENCH_B [bench options...]"
while getopts "r:" o; do
  case $o in
    r) rounds=$OPTARG ;; *) echo "$usage" >&2; exit 2 ;;
  esac
done
shift $((OPTIND - 1))
[ $# -ge 2 ] || { echo "$usage" >&2; exit 2; }
a=$1 b=$2
shift 2
for x in "$a" "$b"; do [ -x "$x" ] || { echo "$0: $x: not an executable" >&2; exit 2; }; done
case $rounds in '' | *[!0-9]* | 0) echo "$0: -r needs a positive integer" >&2; exit 2 ;; esac

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
# One run of BIN: appends "seconds ratio" of its dlab row to FILE (ratio "-"
# when the bench did not time CGAL).
measure() {
  local bin=$1 file=$2 out rc=0
  shift 2
  out=$("$bin" "$@" 2>&1) || rc=$?
  # The bench's status passes on: 2 for a bad option, 1 for a failed run.
  if [ "$rc" -ne 0 ]; then echo "$0: $bin exited with $rc:" >&2; echo "$out" >&2; exit "$rc"; fi
  local cgal dl
  cgal=$(echo "$out" | awk '$1 ~ /^cgal/ {print $2; exit}')
  dl=$(echo "$out" | awk '$1 ~ /^dlab/ {print $2; exit}')
  [ -n "$dl" ] || { echo "$0: no dlab row in the output of $bin:" >&2; echo "$out" >&2; exit 1; }
  if [ -n "$cgal" ]; then
    awk -v d="$dl" -v c="$cgal" 'BEGIN {printf "%s %.4f\n", d, d / c}' >> "$file"
  else
    echo "$dl -" >> "$file"
  fi
}
for ((r = 1; r <= rounds; r++)); do
  if ((r % 2)); then order="A B"; else order="B A"; fi
  for which in $order; do
    if [ "$which" = A ]; then measure "$a" "$work/A" "$@"; else measure "$b" "$work/B" "$@"; fi
  done
  [ -t 2 ] && printf '\rround %d of %d' "$r" "$rounds" >&2
done
[ -t 2 ] && printf '\n' >&2

# "LABEL min X median Y" of column COLUMN of FILE.
min_median() {
  local label=$1 column=$2 file=$3
  cut -d' ' -f"$column" "$file" | sort -g |
    awk -v label="$label" '{s[NR] = $1}
      END {printf "  %s min %.3f median %.3f\n", label, s[1], NR % 2 ? s[(NR + 1) / 2] : (s[NR / 2] + s[NR / 2 + 1]) / 2}'
}
summary() {
  local name=$1 bin=$2 file=$3
  echo "$name $bin"
  echo "  seconds: $(cut -d' ' -f1 "$file" | paste -sd' ')"
  min_median seconds 1 "$file"
  if [ "$(cut -d' ' -f2 "$file" | head -1)" != - ]; then min_median "dlab / CGAL" 2 "$file"; fi
}
echo "# $rounds rounds, alternating order; bench options: $*"
summary A "$a" "$work/A"
summary B "$b" "$work/B"
