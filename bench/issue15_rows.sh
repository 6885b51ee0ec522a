#!/usr/bin/env bash
# Every row of issue 15's table measured on one machine in one run: CGAL and
# dlab on the same points in the same process (bench/bench_triangulation.cpp),
# the peak memory and the end-to-end time of `dlab triangulate`, and the
# parallel algorithm's scaling curve, two cores first (bench/parallel_scaling.sh).
#
#   bench/issue15_rows.sh [-n N] [-r REPEAT] BENCH DLAB
#
# BENCH is build/bench/dlab_bench_triangulation, DLAB build/cli/dlab.  N is the
# size of the 10^6 rows (default 1000000); the kernel rows use N/10.  Output:
# the benches' own tables under a heading per row, then the rest as markdown.
set -euo pipefail
n=1000000 repeat=3
usage="usage: $0 [-n N] [-r REPEAT] BENCH DLAB"
while getopts "n:r:" o; do
  case $o in
    n) n=$OPTARG ;; r) repeat=$OPTARG ;; *) echo "$usage" >&2; exit 2 ;;
  esac
done
shift $((OPTIND - 1))
[ $# -eq 2 ] || { echo "$usage" >&2; exit 2; }
bench=$1 dlab=$2
here=$(cd "$(dirname "$0")" && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

echo "# issue 15's rows, $(date -u +%FT%TZ), $("$dlab" --version | sed -n 2p)"
echo "# $(nproc) CPUs: $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2-)"
row() {
  local title=$1; shift
  echo; echo "## $title"
  "$bench" "$@"
}
row "Bowyer-Watson, 3D uniform" --dim 3 --n "$n" --repeat "$repeat"
row "Bowyer-Watson, 2D uniform" --dim 2 --n "$n" --repeat "$repeat"
row "Bowyer-Watson, 3D grid" --dim 3 --n "$n" --set grid --repeat "$repeat"
row "Bowyer-Watson, 2D grid" --dim 2 --n "$n" --set grid --repeat "$repeat"
row "Lawson, 3D uniform" --dim 3 --n "$n" --algo lawson --repeat "$repeat"
row "George, 3D uniform" --dim 3 --n "$n" --algo george --repeat "$repeat"
row "George, 3D uniform, N/10" --dim 3 --n $((n / 10)) --algo george --repeat "$repeat"
row "Tanemura-Ogawa-Ogita, 2D uniform" --dim 2 --n "$n" --algo tanemura --repeat 1
row "Tanemura-Ogawa-Ogita, 3D uniform" --dim 3 --n "$n" --algo tanemura --repeat 1
row "kernels, 3D uniform, N/10" --dim 3 --n $((n / 10)) --kernels adaptive,integer,mp --repeat "$repeat"
row "kernels, 3D grid, N/10" --dim 3 --n $((n / 10)) --set grid --kernels adaptive,integer,mp --repeat "$repeat"

echo; echo "## dlab triangulate: peak memory and end to end"
echo "| input | stats seconds | end-to-end seconds | end to end / stats | peak RSS bytes per point |"
echo "|---|---:|---:|---:|---:|"
for d in 3 2; do
  "$dlab" gen uniform --dim "$d" --n "$n" --seed 1 -o "$work/u$d.txt"
  t0=$(date +%s.%N)
  "$dlab" triangulate "$work/u$d.txt" -o "$work/u$d.tri" --stats "$work/u$d.json"
  t1=$(date +%s.%N)
  s=$(grep -o '"seconds": [0-9.e+-]*' "$work/u$d.json" | cut -d' ' -f2)
  rss=$(grep -o '"peak_rss_bytes": [0-9]*' "$work/u$d.json" | cut -d' ' -f2)
  awk -v d="$d" -v n="$n" -v s="$s" -v t0="$t0" -v t1="$t1" -v rss="$rss" \
    'BEGIN {printf "| %dD uniform %d | %.3f | %.3f | %.2f | %.0f |\n", d, n, s, t1 - t0, (t1 - t0) / s, rss / n}'
done

# Two threads on two distinct physical cores (not two hyperthreads of one).
two=$(for c in /sys/devices/system/cpu/cpu[0-9]*; do
        [ -r "$c/topology/core_id" ] && echo "$(cat "$c/topology/physical_package_id"):$(cat "$c/topology/core_id") ${c##*cpu}"
      done | sort -t' ' -k2,2n | sort -u -t' ' -k1,1 | sort -t' ' -k2,2n | head -2 | cut -d' ' -f2 | paste -sd,)
for d in 3 2; do
  echo; echo "## parallel Bowyer-Watson, ${d}D, pinned to CPUs $two"
  taskset -c "$two" "$here/parallel_scaling.sh" -d "$d" -n "$n" -r "$repeat" -t "1 2" "$dlab"
  echo; echo "## parallel Bowyer-Watson, ${d}D, all CPUs"
  "$here/parallel_scaling.sh" -d "$d" -n "$n" -r "$repeat" -t "2 4 8 16" "$dlab"
done
