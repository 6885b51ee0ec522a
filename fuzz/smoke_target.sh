#!/usr/bin/env bash
# One bounded libFuzzer run (ctest -L libfuzzer, fuzz/targets.cmake):
#   smoke_target.sh TARGET WORKDIR SECONDS SEED_DIR...
# Fuzzes TARGET for SECONDS starting from the seed directories (read only: new
# inputs go to WORKDIR/corpus, crash files to WORKDIR/). Exit 0 when nothing
# was found; otherwise libFuzzer's status, after the crash file's decoded
# points (DLAB_FUZZ_PRINT_POINTS) for the triangulation targets.
set -uo pipefail
[[ $# -ge 4 ]] || { echo "usage: $0 TARGET WORKDIR SECONDS SEED_DIR..." >&2; exit 2; }
target=$1 work=$2 seconds=$3
shift 3
rm -rf "$work" && mkdir -p "$work/corpus" || exit 2
# -timeout: one input taking over 10 s is a hang (a few ms is the norm);
# -rss_limit_mb: runaway allocation; -max_len: the decoders read at most a few
# hundred bytes. Leak detection stays on (ASan's default).
ASAN_OPTIONS=${ASAN_OPTIONS:-malloc_context_size=2} "$target" "$work/corpus" "$@" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 -max_len=1024 \
  -artifact_prefix="$work/" -print_final_stats=1
status=$?
if [[ $status -ne 0 ]]; then
  for f in "$work"/crash-* "$work"/timeout-* "$work"/oom-* "$work"/leak-*; do
    [[ -e $f ]] || continue
    echo "== found: $f"
    [[ $(basename "$target") == fuzz_triangulate_* ]] && DLAB_FUZZ_PRINT_POINTS=1 "$target" -runs=1 "$f" 2>/dev/null | grep -v '^INFO\|^Running\|^Executed\|^\*\*\*'
  done
fi
exit $status
