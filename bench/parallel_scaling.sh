#!/usr/bin/env bash
# The parallel Bowyer–Watson's scaling curve (issue 15): `dlab triangulate
# --threads T` against the serial algorithm (`--canonical`, so that both sort
# their output the same way) on the same points, in the same run.
#
#   bench/parallel_scaling.sh [-d DIM] [-n N] [-g GENERATOR] [-r REPEAT] [-t "1 2 4"] [-k KERNEL] DLAB
#
# Seconds are `--stats`'s "seconds" (triangulating, ordering and sorting the
# output; not reading or writing), the median of REPEAT runs, alternating the
# configurations so that a change in the machine's load hits all of them.
# Output: one markdown row per configuration: threads, median seconds, speed-up
# over serial, and the deferred insertions (points put back after meeting
# another worker) of the last run. Every output is compared with the serial one
# byte for byte; a difference stops the script with exit 1.
set -euo pipefail
dim=3 n=1000000 gen=uniform repeat=3 threads="1 2" kernel=adaptive
usage="usage: $0 [-d DIM] [-n N] [-g GENERATOR] [-r REPEAT] [-t \"T1 T2 ...\"] [-k KERNEL] DLAB"
while getopts "d:n:g:r:t:k:" o; do
  case $o in
    d) dim=$OPTARG ;; n) n=$OPTARG ;; g) gen=$OPTARG ;; r) repeat=$OPTARG ;; t) threads=$OPTARG ;;
    k) kernel=$OPTARG ;; *) echo "$usage" >&2; exit 2 ;;
  esac
done
shift $((OPTIND - 1))
[ $# -eq 1 ] || { echo "$usage" >&2; exit 2; }
dlab=$1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

"$dlab" gen "$gen" --dim "$dim" --n "$n" --seed 1 -o "$work/p.txt"
configs=(serial $threads)
for ((r = 0; r < repeat; ++r)); do
  for c in "${configs[@]}"; do
    if [ "$c" = serial ]; then opt=(--canonical); else opt=(--threads "$c"); fi
    "$dlab" triangulate "$work/p.txt" --kernel "$kernel" "${opt[@]}" -o "$work/$c.tri" --stats "$work/$c.json"
    grep -o '"seconds": [0-9.e+-]*' "$work/$c.json" | cut -d' ' -f2 >> "$work/$c.sec"
    [ -t 2 ] && printf '\rrun %d/%d: %-6s' $((r + 1)) "$repeat" "$c" >&2
  done
done
[ -t 2 ] && printf '\r%40s\r' '' >&2
median() { sort -g "$1" | awk '{a[NR] = $1} END {print (NR % 2) ? a[(NR + 1) / 2] : (a[NR / 2] + a[NR / 2 + 1]) / 2}'; }
base=$(median "$work/serial.sec")
echo "| $gen ${dim}D n=$n $kernel | threads | seconds | speed-up over serial | deferred insertions |"
echo "|---|---:|---:|---:|---:|"
for c in "${configs[@]}"; do
  cmp -s "$work/serial.tri" "$work/$c.tri" || { echo "$c: output differs from the serial one" >&2; exit 1; }
  s=$(median "$work/$c.sec")
  d=$(grep -o '"deferred_insertions": [0-9]*' "$work/$c.json" | cut -d' ' -f2 || true)
  awk -v c="$c" -v s="$s" -v b="$base" -v d="${d:--}" \
    'BEGIN {printf "| | %s | %.3f | %.2f | %s |\n", c, s, b / s, d}'
done
