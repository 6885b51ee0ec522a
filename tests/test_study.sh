#!/bin/bash
# `dlab study` end to end (ctest `study`, label studies): the same rows on any
# --jobs; three shards run by GNU parallel and merged equal the unsharded
# runs.csv (measured columns cut out); resume after a cut file and after a
# kill; a config mismatch, bad configs (exit 2, the key named) and bad merges;
# inexact kernels' failures, a timeout and an out-of-memory are outcomes.
# Usage: test_study.sh DLAB WORKDIR [SANITIZED=ON|OFF] (ON: no memory limit is
# enforced, fuzz/child_limits.hpp, so the out-of-memory check is left out, and
# ASan's own SEGV handler ends the crashing run, so its message is not checked).
# Exit 77 (skipped) without GNU parallel.
set -u
DLAB=$1
WORK=$2
SANITIZED=${3:-OFF}
command -v parallel >/dev/null || { echo "GNU parallel not installed: skipped"; exit 77; }
rm -rf "$WORK" && mkdir -p "$WORK" && cd "$WORK" || exit 1
fails=0
fail() { echo "FAIL: $*"; fails=$((fails + 1)); }

# runs.csv without wall_seconds, cpu_seconds, peak_rss_bytes (by name; quoted fields kept intact).
cut_measured() {
  python3 - "$1" <<'EOF'
import csv, sys
rows = list(csv.reader(open(sys.argv[1], newline='')))
drop = {rows[0].index(c) for c in ('wall_seconds', 'cpu_seconds', 'peak_rss_bytes')}
w = csv.writer(sys.stdout, lineterminator='\n')
for r in rows:
    w.writerow([x for i, x in enumerate(r) if i not in drop])
EOF
}
# The value of column $2 in the row of run $3.
cell() {
  python3 - "$1" "$2" "$3" <<'EOF'
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1], newline='')))
print(next(r[sys.argv[2]] for r in rows if r['run'] == sys.argv[3]))
EOF
}
# Exit status $1 and a stderr line containing $2 for: dlab study ARGS...
expect_error() {
  local status=$1 text=$2
  shift 2
  "$DLAB" study "$@" >out.txt 2>err.txt
  local rc=$?
  [ $rc -eq "$status" ] || fail "dlab study $*: exit $rc, expected $status ($(cat err.txt))"
  grep -qF -- "$text" err.txt || fail "dlab study $*: stderr lacks '$text': $(cat err.txt)"
}

"$DLAB" gen uniform --n 60 --dim 2 --seed 9 -o pts.txt || exit 1
cat >small.json <<'EOF'
{
  "name": "test-small",
  "algorithms": ["bowyer-watson", "lawson", "tanemura"],
  "kernels": ["adaptive", "float"],
  "inputs": [
    {"generator": "uniform", "dimension": 2, "n": [100, 300], "seeds": [1, 2]},
    {"generator": "near-degenerate", "dimension": 3, "n": 40, "seeds": [3], "label": "near-3d"},
    {"file": "pts.txt", "seeds": [4]}
  ],
  "timeout_seconds": 20
}
EOF

# --- unsharded, and the same rows with --jobs 2 --------------------------------
"$DLAB" study small.json --out A >A.out 2>A.err || fail "unsharded study: exit $? ($(cat A.err))"
rows=$(($(wc -l <A/runs.csv) - 1))
[ "$rows" -eq 36 ] || fail "unsharded study: $rows rows, expected 3 x 2 x 6 = 36"
grep -q '"complete": true' A/meta.json || fail "meta.json not complete"
for key in git_commit compiler compile_flags cpu_model started_utc hostname '"config"'; do
  grep -q "$key" A/meta.json || fail "meta.json lacks $key"
done
"$DLAB" study small.json --out B --jobs 2 >/dev/null 2>B.err || fail "--jobs 2: exit $?"
cmp -s <(cut_measured A/runs.csv) <(cut_measured B/runs.csv) || fail "--jobs 2 gives other rows than --jobs 1"

# Every run is measured: wall seconds > 0 and a peak resident size for ok runs.
python3 - A/runs.csv <<'EOF' || fail "measured columns"
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1], newline='')))
ok = [r for r in rows if r['outcome'] == 'ok']
assert ok and all(float(r['wall_seconds']) > 0 and int(r['peak_rss_bytes']) > 1e6 for r in ok), 'measure'
assert all(r['pred.orient2d'] != '' for r in rows if r['dimension'] == '2' and r['outcome'] == 'ok'), 'counters'
assert all(r['ctr.walk_steps'] == '' for r in rows if r['algorithm'] == 'tanemura'), 'empty where absent'
assert {r['location'] for r in rows if r['algorithm'] == 'tanemura'} == {'-'}, 'location'
# The float kernel fails on the near-degenerate 3D set: an outcome, not a dead study.
bad = [r for r in rows if r['input'] == 'near-3d' and r['kernel'] == 'float' and r['outcome'] != 'ok']
assert bad and all(r['outcome'] in ('reported', 'invalid', 'not-delaunay') and r['message'] for r in bad), bad
assert all(r['outcome'] == 'ok' for r in rows if r['kernel'] == 'adaptive'), 'exact'
assert {r['input'] for r in rows} == {'uniform', 'near-3d', 'pts.txt'} and \
    {r['n'] for r in rows if r['input'] == 'pts.txt'} == {'60'}, 'inputs'
EOF

# --- three shards through GNU parallel, merged --------------------------------
parallel --halt now,fail=1 "$DLAB" study small.json --shard {}/3 --out S{} ::: 1 2 3 >/dev/null 2>P.err ||
  fail "parallel shards: $(cat P.err)"
"$DLAB" study merge S1 S2 S3 --out M >/dev/null 2>M.err || fail "merge: exit $? ($(cat M.err))"
cmp -s <(cut_measured A/runs.csv) <(cut_measured M/runs.csv) || fail "merged shards differ from the unsharded study"
expect_error 2 "2 of 3 shards given" merge S1 S3 --out M2
expect_error 2 "shard 1/3 is given twice" merge S1 S1 S3 --out M3
expect_error 2 "already holds a study" merge S1 S2 S3 --out M

# --- resume: a cut file, then a kill -------------------------------------------
mkdir R && cp A/meta.json R/ && sed -i 's/"complete": true/"complete": false/' R/meta.json
{ head -n 6 A/runs.csv; sed -n 7p A/runs.csv | head -c 25; } >R/runs.csv  # 5 rows and a cut line
"$DLAB" study small.json --out R >/dev/null 2>R.err || fail "resume: exit $?"
grep -q "resuming after 5 rows (a cut last line dropped)" R.err || fail "resume notice: $(cat R.err)"
grep -q "dlab study: 31 runs" R.err || fail "resume ran other than the 31 missing runs: $(cat R.err)"
cmp -s <(cut_measured A/runs.csv) <(cut_measured R/runs.csv) || fail "resumed study differs"
[ "$(cell R/runs.csv wall_seconds 3)" = "$(cell A/runs.csv wall_seconds 3)" ] || fail "a kept row was run again"

"$DLAB" study small.json --out K >/dev/null 2>&1 &
pid=$!
for _ in $(seq 200); do [ "$(wc -l 2>/dev/null <K/runs.csv || echo 0)" -ge 4 ] && break; sleep 0.02; done
kill -9 $pid 2>/dev/null
wait $pid 2>/dev/null
"$DLAB" study small.json --out K >/dev/null 2>K.err || fail "resume after kill: exit $? ($(cat K.err))"
cmp -s <(cut_measured A/runs.csv) <(cut_measured K/runs.csv) || fail "study resumed after a kill differs"

sed 's/"timeout_seconds": 20/"timeout_seconds": 21/' small.json >other.json
expect_error 2 "holds a study of another configuration" other.json --out A
expect_error 2 "holds shard 1/1 of this study, not 2/3" small.json --out A --shard 2/3

# --- a timeout and an out-of-memory are outcomes -------------------------------
# (run 0: the scan location's O(n^2) tests outlast one CPU second long before 40 000
# points fill 16 MiB; run 1: a million points cannot fit)
cat >limits.json <<'EOF'
{"algorithms": ["bowyer-watson"], "kernels": ["mp"], "locations": ["scan"], "timeout_seconds": 0.01, "memory_limit_mib": 16,
 "inputs": [{"generator": "uniform", "dimension": 3, "n": 40000, "seeds": [1]},
            {"generator": "uniform", "dimension": 2, "n": 1000000, "seeds": [1]}]}
EOF
"$DLAB" study limits.json --out L >/dev/null 2>L.err
[ $? -eq 1 ] || fail "an exact pair's timeout should exit 1"
[ "$(cell L/runs.csv outcome 0)" = timeout ] || fail "run 0: $(cell L/runs.csv outcome 0), expected timeout"
[ "$SANITIZED" = ON ] || [ "$(cell L/runs.csv outcome 1)" = out-of-memory ] || fail "run 1: $(cell L/runs.csv outcome 1), expected out-of-memory"

# A run that dies of a signal is outcome crash; the study goes on (test hook of studies/run_child.cpp).
DLAB_STUDY_CRASH_RUN=3 "$DLAB" study small.json --out C >/dev/null 2>C.err || fail "crash: exit $? ($(cat C.err))"
[ "$(cell C/runs.csv outcome 3)" = crash ] || fail "run 3: $(cell C/runs.csv outcome 3), expected crash"
[ "$SANITIZED" = ON ] || [ "$(cell C/runs.csv message 3)" = "killed by SIGSEGV" ] || fail "run 3: message $(cell C/runs.csv message 3)"
[ "$(cell C/runs.csv input_points 3)" = 100 ] || fail "run 3: input_points of a crash"
[ $(($(wc -l <C/runs.csv) - 1)) -eq 36 ] || fail "crash: not every run has its row"

# --- bad configs: exit 2, the file and the key named ---------------------------
bad() {  # NAME JSON EXPECTED-TEXT
  printf '%s\n' "$2" >"$1.json"
  expect_error 2 "$3" "$1.json" --out "X-$1"
  [ ! -e "X-$1/runs.csv" ] || fail "$1: a bad config left a runs.csv"
}
base='"algorithms": ["lawson"], "kernels": ["mp"]'
inputs='"inputs": [{"generator": "uniform", "n": 10}]'
bad unknown "{$base, $inputs, \"repeat\": 2}" "unknown.json: /repeat: unknown key 'repeat'"
bad type "{\"algorithms\": \"lawson\", \"kernels\": [\"mp\"], $inputs}" "type.json: /algorithms: must be an array"
bad algo "{\"algorithms\": [\"lawson\", \"flip\"], \"kernels\": [\"mp\"], $inputs}" "algo.json: /algorithms/1: unknown algorithm 'flip'"
bad kernel "{\"algorithms\": [\"lawson\"], \"kernels\": [\"exact\"], $inputs}" "kernel.json: /kernels/0: unknown kernel 'exact'"
bad gen "{$base, \"inputs\": [{\"generator\": \"random\", \"n\": 10}]}" "gen.json: /inputs/0/generator: unknown generator"
bad noinputs "{$base}" "noinputs.json: (top level): missing \"inputs\""
bad n "{$base, \"inputs\": [{\"generator\": \"uniform\", \"n\": 10}, {\"generator\": \"uniform\", \"n\": -3}]}" \
  "n.json: /inputs/1/n: must be an integer in 1.."
bad dim "{$base, \"inputs\": [{\"generator\": \"coplanar\", \"dimension\": 2, \"n\": 10}]}" \
  "dim.json: /inputs/0/dimension: coplanar has no dimension 2"
bad file "{$base, \"inputs\": [{\"file\": \"no-such.pts\"}]}" "file.json: /inputs/0/file: no-such.pts"
bad refused "{$base, \"inputs\": [{\"generator\": \"cospherical\", \"dimension\": 3, \"n\": 60000}]}" \
  "refused.json: /inputs/0: the generator refuses n = 60000"
bad syntax "{$base,
  $inputs,,
}" "syntax.json:2:49: JSON syntax error: "
expect_error 2 "cannot read the study configuration" missing.json --out X
expect_error 2 "--shard: '4/3' is not k/n" small.json --out X --shard 4/3
expect_error 2 "missing --out" small.json

# --- the built-in default matrix parses; its first run (shard 1 of 10^5) works --
"$DLAB" study --default --shard 1/100000 --out D >/dev/null 2>D.err || fail "--default: exit $? ($(cat D.err))"
[ "$(cell D/runs.csv algorithm 0)" = bowyer-watson ] || fail "--default: run 0"
"$DLAB" study --help | grep -q "dlab study merge" || fail "--help"

[ $fails -eq 0 ] && echo "all study checks passed"
exit $((fails > 0))
