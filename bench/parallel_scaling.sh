#!/usr/bin/env bash
# The parallel Bowyer–Watson's scaling curve (issue 15): `dlab triangulate
# --threads T` against the serial algorithm (`--canonical`, so that both sort
# their output the same way) on the same points, in the same run.
#
#   bench/parallel_scaling.sh [-d DIM] [-n N] [-g GENERATOR] [-r REPEAT] [-t "1 2 4"] [-k KERNEL]
#                             [-c "0 1"] DLAB [DLAB...]
#
# Seconds are `--stats`'s "seconds" (triangulating, ordering and sorting the
# output; not reading or writing), the median of REPEAT runs, alternating the
# configurations (and the binaries, when several are given: a build before and
# after a change) so that a change in the machine's load hits all of them.
# Output: for each binary, one markdown row per configuration: threads, median
# seconds, speed-up over that binary's serial run, the medians of the three
# phase_seconds (order, triangulate, output), and the deferred insertions
# (points put back after meeting another worker) of the last run. Every output
# is compared with the first binary's serial one byte for byte; a difference
# stops the script with exit 1.
# -c "C1 C2 ...": also the serial run pinned to each of these CPUs (taskset),
# rows "cpuC" (their speed-up column: the unpinned serial's seconds over
# theirs). On a VM the CPUs need not be equal: session 46's 2-vCPU VM ran the
# serial 2D run in 0.51 s on one and 0.80 s on the other, which one changing
# within minutes (papers/triangulation_costs.md).
set -euo pipefail
dim=3 n=1000000 gen=uniform repeat=3 threads="1 2" kernel=adaptive cpus=""
usage="usage: $0 [-d DIM] [-n N] [-g GENERATOR] [-r REPEAT] [-t \"T1 T2 ...\"] [-k KERNEL] [-c \"C1 C2 ...\"] DLAB [DLAB...]"
while getopts "d:n:g:r:t:k:c:" o; do
  case $o in
    d) dim=$OPTARG ;; n) n=$OPTARG ;; g) gen=$OPTARG ;; r) repeat=$OPTARG ;; t) threads=$OPTARG ;;
    k) kernel=$OPTARG ;; c) cpus=$OPTARG ;; *) echo "$usage" >&2; exit 2 ;;
  esac
done
shift $((OPTIND - 1))
[ $# -ge 1 ] || { echo "$usage" >&2; exit 2; }
binaries=("$@")
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

"${binaries[0]}" gen "$gen" --dim "$dim" --n "$n" --seed 1 -o "$work/p.txt"
configs=(serial $threads)
for c in $cpus; do configs+=("cpu$c"); done
for ((r = 0; r < repeat; ++r)); do
  for ((b = 0; b < ${#binaries[@]}; ++b)); do
    for c in "${configs[@]}"; do
      pin=()
      case $c in
        serial) opt=(--canonical) ;;
        cpu*) opt=(--canonical) pin=(taskset -c "${c#cpu}") ;;
        *) opt=(--threads "$c") ;;
      esac
      "${pin[@]}" "${binaries[b]}" triangulate "$work/p.txt" --kernel "$kernel" "${opt[@]}" -o "$work/$b.$c.tri" \
        --stats "$work/$b.$c.json"
      python3 -c 'import json, sys
d = json.load(open(sys.argv[1])); p = d.get("phase_seconds", {})  # none before session 45
print(d["seconds"], *(p.get(k, "nan") for k in ("order", "triangulate", "output")))' "$work/$b.$c.json" >> "$work/$b.$c.sec"
      [ -t 2 ] && printf '\rrun %d/%d: binary %d, %-6s' $((r + 1)) "$repeat" $((b + 1)) "$c" >&2
    done
  done
done
[ -t 2 ] && printf '\r%40s\r' '' >&2
# median FILE COLUMN
median() { cut -d' ' -f"$2" "$1" | sort -g | awk '{a[NR] = $1} END {print (NR % 2) ? a[(NR + 1) / 2] : (a[NR / 2] + a[NR / 2 + 1]) / 2}'; }
for ((b = 0; b < ${#binaries[@]}; ++b)); do
  base=$(median "$work/$b.serial.sec" 1)
  [ $b -gt 0 ] && echo
  echo "| $gen ${dim}D n=$n $kernel, ${binaries[b]} | threads | seconds | speed-up over serial | order | triangulate | output | deferred insertions |"
  echo "|---|---:|---:|---:|---:|---:|---:|---:|"
  for c in "${configs[@]}"; do
    cmp -s "$work/0.serial.tri" "$work/$b.$c.tri" ||
      { echo "${binaries[b]} $c: output differs from ${binaries[0]}'s serial one" >&2; exit 1; }
    s=$(median "$work/$b.$c.sec" 1)
    phases=$(for k in 2 3 4; do median "$work/$b.$c.sec" $k; done | awk '{printf "%.3f | ", $1}')
    d=$(grep -o '"deferred_insertions": [0-9]*' "$work/$b.$c.json" | cut -d' ' -f2 || true)
    awk -v c="$c" -v s="$s" -v b="$base" -v p="$phases" -v d="${d:--}" \
      'BEGIN {printf "| | %s | %.3f | %.2f | %s%s |\n", c, s, b / s, p, d}'
  done
done
