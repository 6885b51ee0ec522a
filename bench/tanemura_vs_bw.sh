#!/usr/bin/env bash
# Tanemura-Ogawa-Ogita against Bowyer-Watson on the same points, same kernel,
# in the same run (papers/triangulation_costs.md, issue 17 section 3).
#
#   bench/tanemura_vs_bw.sh [-k KERNEL] [-r REPEAT] [-t TIMEOUT_S] [-c CASES] [-i] DLAB [DLAB2 ...]
#
# For each case (one `dlab gen` invocation), the points are generated once and
# each binary runs Tanemura and Bowyer-Watson on them alternately, REPEAT times;
# the seconds are `dlab triangulate --stats`'s "seconds" (triangulating only),
# the median of the repeats, and the ratio is Tanemura / Bowyer-Watson of those
# medians. A run that exceeds TIMEOUT_S is shown as ">T". Several binaries (a
# build before and after a change) are compared on the same files in one run.
# CASES: a file with one line per case, "LABEL | gen arguments"; the default is
# every generator at 65 536 points in 2D and 20 000 in 3D, plus the two cases
# of issue 17. Output: one markdown table row per case on stdout.
# -i: instead of seconds, the instructions executed by the triangulation
# (valgrind callgrind's Ir, collected only inside the driver's run_kernel: the
# insertion order, the algorithm and the mapping of its output; not reading,
# writing or validating). Deterministic and unaffected by other load on the
# machine; one run each (REPEAT is ignored); callgrind runs about 50x slower,
# so TIMEOUT_S applies to the run under valgrind. Shown in millions (M).
set -euo pipefail
kernel=adaptive repeat=3 timeout_s=300 cases="" instr=""
usage="usage: $0 [-k KERNEL] [-r REPEAT] [-t TIMEOUT_S] [-c CASES] [-i] DLAB [DLAB2 ...]"
while getopts "k:r:t:c:i" o; do
  case $o in
    k) kernel=$OPTARG ;; r) repeat=$OPTARG ;; t) timeout_s=$OPTARG ;; c) cases=$OPTARG ;;
    i) instr=1 repeat=1 ;;
    *) echo "$usage" >&2; exit 2 ;;
  esac
done
shift $((OPTIND - 1))
[ $# -ge 1 ] || { echo "$usage" >&2; exit 2; }
bins=("$@")
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

default_cases() {
  for g in uniform gaussian clustered lattice rotated-lattice cocircular collinear near-degenerate \
           near-duplicates huge tiny; do
    echo "2D $g 65536 | $g --dim 2 --n 65536 --seed 1"
  done
  echo "2D kettner-grid 65538 | kettner-grid"
  echo "2D kettner-hull A1 | kettner-hull --set A1"
  for g in uniform gaussian clustered lattice rotated-lattice cospherical collinear coplanar \
           near-degenerate near-duplicates huge tiny; do
    echo "3D $g 20000 | $g --dim 3 --n 20000 --seed 1"
  done
  echo "3D cospherical 2000 | cospherical --dim 3 --n 2000 --seed 1"
}

# seconds (-i: millions of instructions) of one run, or ">T" past the timeout, or "fail"
one_run() {  # bin algo points
  local rc=0
  if [ -n "$instr" ]; then
    timeout "$timeout_s" valgrind --tool=callgrind --callgrind-out-file="$work/cg.out" \
      "--toggle-collect=void dlab::driver_detail::run_kernel*" \
      "$1" triangulate "$3" --algo "$2" --kernel "$kernel" -o /dev/null >/dev/null 2>"$work/vg.txt" || rc=$?
    if [ $rc -eq 124 ]; then echo ">$timeout_s"; return; fi
    if [ $rc -ne 0 ]; then echo "fail"; return; fi
    sed -n 's/^==[0-9]*== Collected : \([0-9]*\)$/\1/p' "$work/vg.txt" | awk '{printf "%.4g", $1 / 1e6}'
    return
  fi
  timeout "$timeout_s" "$1" triangulate "$3" --algo "$2" --kernel "$kernel" -o /dev/null \
    --stats "$work/s.json" 2>/dev/null || rc=$?
  if [ $rc -eq 124 ]; then echo ">$timeout_s"; return; fi
  if [ $rc -ne 0 ]; then echo "fail"; return; fi
  sed -n 's/^ *"seconds": *\([0-9.eE+-]*\),*$/\1/p' "$work/s.json"
}
median() { tr ' ' '\n' | grep -v '^$' | sort -g | awk '{a[NR]=$1} END {printf "%.3g", a[int((NR+1)/2)]}'; }
ratio() { awk -v a="$1" -v b="$2" 'BEGIN { if (a ~ /^[0-9.eE+-]+$/ && b ~ /^[0-9.eE+-]+$/ && b > 0)
  printf "%.1f", a / b; else print "-" }'; }

header="| case | n |"
rule="|---|---:|"
for b in "${bins[@]}"; do
  unit=s; [ -n "$instr" ] && unit=MIr
  header+=" Tanemura $unit ($(basename "$b")) | BW $unit | ratio |"
  rule+="---:|---:|---:|"
done
what="median of $repeat"; [ -n "$instr" ] && what="callgrind instructions (millions), one run"
echo "kernel $kernel, $what, timeout ${timeout_s}s, $(nproc) cores, load $(cut -d' ' -f1-3 /proc/loadavg)"
echo "$header"
echo "$rule"
{ if [ -n "$cases" ]; then cat "$cases"; else default_cases; fi; } | while IFS='|' read -r label args; do
  label=$(echo "$label" | xargs)
  # shellcheck disable=SC2086
  "${bins[0]}" gen $args -o "$work/p.txt"
  n=$(grep -cv '^#' "$work/p.txt")
  row="| $label | $n |"
  for b in "${bins[@]}"; do
    tt="" tb="" skip_t="" skip_b=""
    for ((r = 0; r < repeat; r++)); do  # a timeout or failure is not repeated
      if [ -z "$skip_t" ]; then
        t=$(one_run "$b" tanemura "$work/p.txt"); tt+=" $t"
        case $t in ">"*|fail) skip_t=$t ;; esac
      fi
      if [ -z "$skip_b" ]; then
        t=$(one_run "$b" bowyer-watson "$work/p.txt"); tb+=" $t"
        case $t in ">"*|fail) skip_b=$t ;; esac
      fi
    done
    mt=${skip_t:-$(echo "$tt" | median)}
    mb=${skip_b:-$(echo "$tb" | median)}
    row+=" $mt | $mb | $(ratio "$mt" "$mb") |"
  done
  echo "$row"
done
