#!/bin/bash
# `dlab fuzz` end to end (issue 12), run by ctest as
#   test_fuzz_campaign.sh DLAB WORKDIR SANITIZED(ON|OFF)
# Small campaigns (seconds) whose outcomes are checked against what is known
# of the inputs: exact pairs only ever ok, float fails on near-degenerate sets;
# a failure file replays its failure, shrunk; --case re-runs a case byte for byte;
# resume after a torn line and after kill -9 equals the uninterrupted run;
# shards run with GNU parallel and merged equal the unsharded run byte for byte
# (records' seconds are 0 under --no-timing, the comparison is exact); bad
# input exits 2; deliberate crash / hang / allocation of an inexact pair
# (DLAB_FUZZ_SELFTEST) never takes the campaign down, of an exact pair exits 1.
# Exits 77 (ctest: skipped) after all other checks pass if GNU parallel is missing.
set -u
DLAB=$1
WORK=$2
SANITIZED=${3:-OFF}
rm -rf "$WORK" && mkdir -p "$WORK" && cd "$WORK" || exit 1
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }
# expect_rc RC NAME CMD...: runs CMD, checks its exit status.
expect_rc() {
  local want=$1 name=$2
  shift 2
  "$@" > "$name.out" 2> "$name.err"
  local rc=$?
  [ "$rc" = "$want" ] || fail "$name: exit $rc, expected $want ($(head -c 300 "$name.err"))"
}

# ---- a 2D campaign: every algorithm x exact kernel ok, float fails ---------
ALGOS=bowyer-watson,lawson,tanemura,george+exact-sphere
CAMPAIGN=(--algo $ALGOS --kernel adaptive,integer,mp,float --gen near-degenerate,lattice,cocircular,kettner-grid,uniform
          --dim 2 --n 4..24 --seed 12 --no-timing)
expect_rc 0 full "$DLAB" fuzz "${CAMPAIGN[@]}" --cases 40 --out full
[ "$(wc -l < full/results.jsonl)" = $((40 * 16)) ] || fail "full: $(wc -l < full/results.jsonl) records, expected 640"
grep -q '^40 cases, 640 case x pairs, .*exact pairs: 480 runs, 0 failures$' full.out || fail "full: summary totals: $(tail -1 full.out)"
bad_exact=$(grep '"exact":true' full/results.jsonl | grep -v -c -E '"outcome":"(ok|lower-dimensional)"')
[ "$bad_exact" = 0 ] || fail "full: $bad_exact exact-pair records not ok"
float_failures=$(grep '"kernel":"float"' full/results.jsonl | grep -c -E '"outcome":"(not-delaunay|invalid|reported)"')
[ "$float_failures" -gt 0 ] || fail "full: float never failed on near-degenerate input"
grep -q '"gen":"near-degenerate"' full/results.jsonl || fail "full: no near-degenerate case drawn"
# Float on near-degenerate sets (exact degenerate sets moved by a few ulps) fails,
# and the summary reports it with a Wilson interval; adaptive never does.
expect_rc 0 near "$DLAB" fuzz --algo bowyer-watson,lawson --kernel adaptive,float --gen near-degenerate \
  --n 8..30 --seed 4 --cases 30 --out near
grep -E '^bowyer-watson +float +near-degenerate +30 +[1-9][0-9]* +[0-9.]+% +\[[0-9.]+%, [0-9.]+%\] +[a-z]' near.out > /dev/null ||
  fail "near: no failing float row in the summary"
grep -E '^lawson +adaptive +near-degenerate +30 +0 +0% +\[0%, 11.4%\] +-$' near.out > /dev/null ||
  fail "near: adaptive row is not 30 runs without failure, Wilson [0%, 11.4%]"
cmp -s full.out full/summary.txt || fail "full: summary.txt differs from the printed summary"
# One failure file per signature (algo, kernel, dim, outcome, kind) of the failures.
signatures=$(grep -v -E '"outcome":"(ok|lower-dimensional)"' full/results.jsonl |
  sed -E 's/.*"algo":"([^"]*)","kernel":"([^"]*)".*"outcome":"([^"]*)","kind":"((\\.|[^"\\])*)".*/\1 \2 \3 \4/' | sort -u | wc -l)
[ "$(ls full/failures/*.txt | wc -l)" = "$signatures" ] || fail "full: $(ls full/failures/*.txt | wc -l) failure files for $signatures signatures"

# A failure file replays its failure: its case from `dlab gen` fails (exit 1 from
# triangulate), and the file's own points, shrunk by dlab shrink's algorithm, are
# no more (in some file fewer) and fail with the same outcome class, re-run here
# by dlab triangulate.
ls full/failures/bowyer-watson.float.* full/failures/lawson.float.* > /dev/null 2>&1 || fail "replay: no float failure file"
fewer=0
for f in full/failures/*.txt; do
  replay=$(sed -n 's/^# replay: //p' "$f")
  gen_part=${replay%% | *}
  tri_part=${replay#* | }
  outcome=$(sed -n 's/^# dlab fuzz failure: [^,]*, [23]D: \([a-z-]*\).*/\1/p' "$f")
  $DLAB ${gen_part#dlab } > replay.pts || fail "replay: dlab gen failed ($f)"
  $DLAB ${tri_part#dlab } < replay.pts > /dev/null 2> replay.err
  [ $? = 1 ] || fail "replay: '$tri_part' did not fail again ($f)"
  grep -q '^# shrunk: yes: ' "$f" || fail "replay: not shrunk ($f)"
  $DLAB ${tri_part#dlab } < "$f" > /dev/null 2> shrunk.err
  [ $? = 1 ] && grep -q "^dlab triangulate: $outcome: " shrunk.err ||
    fail "replay: the shrunk points do not give $outcome ($f: $(cat shrunk.err))"
  [ "$(grep -vc '^#' "$f")" -le "$(wc -l < replay.pts)" ] || fail "replay: more points than the case ($f)"
  [ "$(grep -vc '^#' "$f")" -lt "$(wc -l < replay.pts)" ] && fewer=$((fewer + 1))
done
[ "$fewer" -gt 0 ] || fail "replay: no failure file has fewer points than its case"

# ---- --case i re-runs one case alone, byte for byte -------------------------
"$DLAB" fuzz "${CAMPAIGN[@]}" --case 23 > case23.jsonl 2> /dev/null
grep '^{"case":23,' full/results.jsonl | cmp -s - case23.jsonl || fail "--case 23 differs from the campaign's records"

# ---- 3D, exact kernels and float ------------------------------------------
expect_rc 0 three "$DLAB" fuzz --algo bowyer-watson,lawson,tanemura --kernel adaptive,integer,mp,float \
  --gen cospherical,lattice,near-degenerate,coplanar --dim 3 --n 5..16 --seed 5 --cases 12 --out three
grep -q 'exact pairs: 108 runs, 0 failures$' three.out || fail "three: $(tail -1 three.out)"

# Each not-delaunay or invalid failure comes with a picture of the pair's mesh
# of the file's points (2D: .svg), named in the file; it marks as many
# non-Delaunay edges as `dlab check` counts non-locally-Delaunay facets in the
# mesh `dlab triangulate` makes of the same points (an independent rerun).
pictures=0
for f in full/failures/*.txt near/failures/*.txt three/failures/*.txt; do
  outcome=$(sed -n 's/^# dlab fuzz failure: [^,]*, [23]D: \([a-z-]*\).*/\1/p' "$f")
  pic=$(sed -n 's/^# picture of their mesh, faults marked by the exact validator: failures\///p' "$f")
  case $outcome in
    not-delaunay | invalid) ;;
    *) [ -z "$pic" ] || fail "picture: $f ($outcome) names a picture"; continue ;;
  esac
  [ -n "$pic" ] && [ -f "$(dirname "$f")/$pic" ] || { fail "picture: none for $f"; continue; }
  pictures=$((pictures + 1))
  tri_part=$(sed -n 's/^# replay the points below: dlab triangulate failures\/[^ ]* \(.*\)   (from DIR)$/\1/p' "$f")
  $DLAB triangulate "$f" $tri_part -o mesh.txt > /dev/null 2>&1
  want=$($DLAB check "$f" mesh.txt | sed -n 's/^not_delaunay: \([0-9]*\).*/\1/p')
  case $pic in
    *.svg)
      got=$(grep -c 'class="edge-bad non-delaunay"' "$(dirname "$f")/$pic") ;;
    *.vtu)  # each non-Delaunay facet counted once from each of its two cells
      got=$(awk '/Name="non_delaunay_facets"/ { on = 1; next } /<\/DataArray>/ { on = 0 } on { s += $1 }
                 END { print s / 2 }' "$(dirname "$f")/$pic") ;;
  esac
  [ "$got" = "${want:-0}" ] || fail "picture: $pic marks $got non-Delaunay facets, dlab check counts ${want:-0}"
done
ls near/failures/*.svg > /dev/null 2>&1 || fail "picture: no 2D picture"
ls three/failures/*.vtu > /dev/null 2>&1 || fail "picture: no 3D picture"

# ---- resume after a torn last line, and after kill -9 ----------------------
mkdir torn && cp full/campaign.json torn/ && head -c 100000 full/results.jsonl > torn/results.jsonl
expect_rc 0 torn "$DLAB" fuzz "${CAMPAIGN[@]}" --cases 40 --out torn
grep -q 'resuming after [0-9]* complete cases (.* dropped' torn.err || fail "torn: no resume message"
cmp -s full/results.jsonl torn/results.jsonl || fail "torn: resumed results differ from the uninterrupted run"
cmp -s full/summary.txt torn/summary.txt || fail "torn: summaries differ"
BIG=(--algo bowyer-watson,lawson --kernel adaptive,float --gen mix --n 10..40 --seed 9 --no-timing --cases 800)
expect_rc 0 whole "$DLAB" fuzz "${BIG[@]}" --out whole
"$DLAB" fuzz "${BIG[@]}" --jobs 2 --out killed > /dev/null 2>&1 &
sleep 0.3
kill -9 $! 2> /dev/null
wait $! 2> /dev/null
expect_rc 0 killed "$DLAB" fuzz "${BIG[@]}" --out killed
cmp -s whole/results.jsonl killed/results.jsonl || fail "kill -9: resumed results differ from the uninterrupted run"
cmp -s whole/summary.txt killed/summary.txt || fail "kill -9: summaries differ"

# ---- shards with GNU parallel, merged: exactly the unsharded run ------------
have_parallel=1
command -v parallel > /dev/null || have_parallel=0
if [ $have_parallel = 1 ]; then
  expect_rc 0 unsharded "$DLAB" fuzz "${CAMPAIGN[@]}" --cases 40 --jobs 2 --out unsharded
  cmp -s full/results.jsonl unsharded/results.jsonl || fail "--jobs 2 changed the results"
  parallel --will-cite -j 2 "$DLAB" fuzz "${CAMPAIGN[@]}" --cases 40 --shard {}/3 --out shard{} '>' /dev/null ::: 1 2 3 ||
    fail "parallel: a shard failed"
  expect_rc 0 merged "$DLAB" fuzz merge shard1 shard2 shard3 --out merged
  for file in results.jsonl summary.txt campaign.json; do
    cmp -s unsharded/$file merged/$file || fail "merge: $file differs from the unsharded run"
  done
  diff -r unsharded/failures merged/failures > /dev/null || fail "merge: failures/ differs from the unsharded run"
  cmp -s unsharded.out merged.out || fail "merge: printed summary differs"
  expect_rc 2 merge-missing "$DLAB" fuzz merge shard1 shard3 --out merged2
  grep -q 'shard 2/3 is missing' merge-missing.err || fail "merge-missing: $(cat merge-missing.err)"
fi

# ---- bad input: a clear message, exit 2 -------------------------------------
touch afile
expect_rc 2 shard32 "$DLAB" fuzz --cases 2 --shard 3/2 --out x
expect_rc 2 shard02 "$DLAB" fuzz --cases 2 --shard 0/2 --out x
expect_rc 2 nrange "$DLAB" fuzz --cases 2 --n 5..2 --out x
expect_rc 2 nzero "$DLAB" fuzz --cases 2 --n 0 --out x
expect_rc 2 gen "$DLAB" fuzz --cases 2 --gen nosuch --out x
grep -q "unknown generator 'nosuch'" gen.err || fail "gen: $(cat gen.err)"
expect_rc 2 gendim "$DLAB" fuzz --cases 2 --gen coplanar --dim 2 --out x
expect_rc 2 algo "$DLAB" fuzz --cases 2 --algo quickhull --out x
expect_rc 2 kernel "$DLAB" fuzz --cases 2 --kernel exact --out x
expect_rc 2 both "$DLAB" fuzz --cases 2 --budget 5s --out x
expect_rc 2 neither "$DLAB" fuzz --out x
expect_rc 2 budget "$DLAB" fuzz --budget 0s --out x
expect_rc 2 dirfile "$DLAB" fuzz --cases 2 --out afile
expect_rc 2 dirunder "$DLAB" fuzz --cases 2 --out afile/sub
grep -q "afile/sub" dirunder.err || fail "dirunder: $(cat dirunder.err)"
expect_rc 2 another "$DLAB" fuzz --cases 2 --seed 13 --algo $ALGOS --kernel adaptive --out full
grep -q 'holds another campaign' another.err || fail "another: $(cat another.err)"
mkdir corrupt && cp full/campaign.json corrupt/ &&
  { head -n 3 full/results.jsonl; echo 'garbage'; tail -n +5 full/results.jsonl; } > corrupt/results.jsonl
expect_rc 2 corrupt "$DLAB" fuzz "${CAMPAIGN[@]}" --cases 40 --out corrupt
grep -q 'results.jsonl:4:' corrupt.err || fail "corrupt: no file:line in '$(cat corrupt.err)'"
expect_rc 2 selftest-bad env DLAB_FUZZ_SELFTEST=explode@1:float "$DLAB" fuzz --cases 2 --out y

# ---- isolation: deliberate crash, hang, allocation in an inexact pair -------
ST="crash@1:float,hang@3:float"
[ "$SANITIZED" = ON ] || ST="$ST,allocate@4:float"
expect_rc 0 isolated env DLAB_FUZZ_SELFTEST=$ST "$DLAB" fuzz --algo bowyer-watson --kernel adaptive,float \
  --gen uniform --n 12 --seed 2 --cases 6 --timeout 1 --memory 256 --out isolated
[ "$(wc -l < isolated/results.jsonl)" = 12 ] || fail "isolated: $(wc -l < isolated/results.jsonl) records, expected 12"
grep -q '^{"case":1,.*"kernel":"float",.*"outcome":"crash","kind":"SIGABRT"' isolated/results.jsonl || fail "isolated: no crash record"
grep -q '^{"case":3,.*"kernel":"float",.*"outcome":"timeout","kind":"cpu"' isolated/results.jsonl || fail "isolated: no timeout record"
if [ "$SANITIZED" != ON ]; then
  grep -q '^{"case":4,.*"kernel":"float",.*"outcome":"out-of-memory"' isolated/results.jsonl || fail "isolated: no out-of-memory record"
fi
# Every other case x pair ran normally: the adaptive ones all ok.
[ "$(grep -c '"kernel":"adaptive".*"outcome":"ok"' isolated/results.jsonl)" = 6 ] || fail "isolated: adaptive records not all ok"
grep -q 'deliberate failures are injected' isolated.err || fail "isolated: no warning about DLAB_FUZZ_SELFTEST"
ls isolated/failures | grep -q 'crash' || fail "isolated: no failure file for the crash"
# A deliberate crash does not show again in the shrinker's fresh child: written as generated.
grep -q '^# shrunk: no: in a fresh child the case gave ok, not crash (SIGABRT)$' isolated/failures/*crash* ||
  fail "isolated: the crash file's shrunk line: $(grep '^# shrunk' isolated/failures/*crash*)"
# A crash of an exact pair is a bug: exit 1.
expect_rc 1 exact-crash env DLAB_FUZZ_SELFTEST=crash@2:adaptive "$DLAB" fuzz --algo bowyer-watson \
  --kernel adaptive --gen uniform --n 12 --seed 2 --cases 4 --out exact-crash
grep -q 'exact pairs: 4 runs, 1 failures (bugs)$' exact-crash.out || fail "exact-crash: $(tail -1 exact-crash.out)"
# The selftest campaign cannot be resumed as an ordinary one.
expect_rc 2 selftest-resume "$DLAB" fuzz --algo bowyer-watson --kernel adaptive --gen uniform --n 12 --seed 2 \
  --cases 4 --out exact-crash

# ---- budget -----------------------------------------------------------------
expect_rc 0 budget2 "$DLAB" fuzz --algo bowyer-watson --kernel adaptive,float --gen mix --n 20 --budget 1s --out budget
lines=$(wc -l < budget/results.jsonl)
[ "$lines" -gt 0 ] && [ $((lines % 2)) = 0 ] || fail "budget: $lines records"
grep -q $'\r' budget2.err && fail "budget: a progress line on a non-terminal"

echo "$failures failures"
[ $failures = 0 ] || exit 1
[ $have_parallel = 1 ] || { echo "GNU parallel not found: shard + merge not tested (skipped)"; exit 77; }
exit 0
