#!/bin/bash
# `dlab corpus replay` and `dlab corpus add` (issue 12), run by ctest as
#   test_corpus_tools.sh DLAB WORKDIR CORPUS_DIR
# on temporary copies of three issue 17 cases: a changed expect line is a
# change in either direction (exit 1, one line naming it), the same whatever
# --jobs; a malformed header exits 2 naming FILE:LINE; an exact pair that
# stops giving the perturbed triangulation (DLAB_FUZZ_SELFTEST=unperturbed)
# is a change to `differs`; `add` rewrites a case byte for byte, takes a
# campaign failure file's provenance and order seed, refuses an exact
# failure, a timeout and an existing case without --replace.
set -u
DLAB=$1
WORK=$2
CORPUS=$3
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
SQUARE=issue17-half-integer-square
LATTICE=issue17-binade-lattice-minus-2p51
CUBE=issue17-half-integer-cube
mkdir base
for c in $SQUARE $LATTICE $CUBE; do cp "$CORPUS/$c.pts" base/ || exit 1; done

# ---- replay: no change, then changes in both directions ---------------------
expect_rc 0 base "$DLAB" corpus replay base
grep -qx 'corpus replay: 3 cases, 90 pairs, 0 changes' base.out || fail "base: $(cat base.out)"
cp -r base changed
# An inexact pair that passes, recorded as failing: "now passes" is a change.
sed -i 's/^# expect: lawson float ok$/# expect: lawson float not-delaunay/' changed/$SQUARE.pts
# An inexact pair that fails, recorded as passing.
cube_failing=$(grep -m1 -E '^# expect: [a-z+-]+ (float|epsilon) not-delaunay$' changed/$CUBE.pts | cut -d' ' -f3,4)
[ -n "$cube_failing" ] || fail "changed: no inexact not-delaunay expect line in $CUBE"
sed -i "s/^# expect: $cube_failing not-delaunay\$/# expect: $cube_failing ok/" changed/$CUBE.pts
expect_rc 1 changed "$DLAB" corpus replay changed --jobs 1
grep -qx "$SQUARE: lawson float expected not-delaunay, got ok" changed.out || fail "changed: $(cat changed.out)"
grep -qx "$CUBE: $cube_failing expected ok, got not-delaunay (.*)" changed.out || fail "changed: $(cat changed.out)"
grep -qx 'corpus replay: 3 cases, 90 pairs, 2 changes' changed.out || fail "changed: $(tail -1 changed.out)"
expect_rc 1 changed-jobs "$DLAB" corpus replay changed --jobs 3
cmp -s changed.out changed-jobs.out || fail "changed: output differs with --jobs 3"
# --algo / --kernel restrict the pairs run.
expect_rc 0 subset "$DLAB" corpus replay changed --algo bowyer-watson,tanemura --kernel adaptive,mp,epsilon
grep -qx 'corpus replay: 3 cases, 18 pairs, 0 changes' subset.out || fail "subset: $(cat subset.out)"

# ---- replay: an exact pair that is valid Delaunay but not the perturbed one -
expect_rc 1 differs env DLAB_FUZZ_SELFTEST=unperturbed@0:mp "$DLAB" corpus replay base/$LATTICE.pts
grep -qx "$LATTICE: bowyer-watson mp expected ok, got differs (.*perturbed reference.*)" differs.out ||
  fail "differs: $(cat differs.out)"
grep -q 'deliberate failures are injected' differs.err || fail "differs: no warning about DLAB_FUZZ_SELFTEST"

# ---- order-seed: every pair runs with the case's brio seed ------------------
# (brio shuffles only from 64 points on; on this set lawson x float leaves a
# number of non-Delaunay facets that depends on the seed.)
"$DLAB" gen near-degenerate --dim 2 --n 100 --seed 2 --base lattice --ulps 1 > nd.txt
facets() {
  "$DLAB" triangulate nd.txt --algo lawson --kernel float --seed "$1" --validate 2>&1 > /dev/null |
    sed -n 's/.*not-delaunay: \([0-9]*\) facets\{0,1\} not locally.*/\1/p'
}
f0=$(facets 0)
f1=$(facets 1)
[ -n "$f1" ] && [ "$f0" != "$f1" ] || fail "order-seed: precondition: lawson x float leaves '$f0' and '$f1' facets"
mkdir seeded
{ printf '# case: seeded\n# source: dlab gen\n# exercises: order-seed\n# dimension: 2\n# order-seed: 1\n'; cat nd.txt; } \
  > seeded/seeded.pts
expect_rc 0 seeded-add "$DLAB" corpus add seeded/seeded.pts --to seeded --replace
grep -qx '# order-seed: 1' seeded/seeded.pts || fail "seeded-add: order-seed not kept"
sed -i 's/^# expect: lawson float not-delaunay$/# expect: lawson float ok/' seeded/seeded.pts
expect_rc 1 seeded "$DLAB" corpus replay seeded
grep -qx "seeded: lawson float expected ok, got not-delaunay ($f1 facets\{0,1\} not locally Delaunay .*)" seeded.out ||
  fail "seeded: not the $f1 facets of --seed 1: $(cat seeded.out)"

# ---- replay: bad input -> FILE:LINE: problem, exit 2 -------------------------
# bad_header NAME LINE REGEX SED-SCRIPT: a copy of the square edited by SED-SCRIPT.
bad_header() {
  local name=$1 line=$2 regex=$3
  mkdir -p "bad-$name"
  sed "$4" base/$SQUARE.pts > "bad-$name/$SQUARE.pts"
  expect_rc 2 "bad-$name" "$DLAB" corpus replay "bad-$name"
  grep -qE "^dlab corpus: bad-$name/$SQUARE.pts:$line: $regex" "bad-$name.err" ||
    fail "bad-$name: $(cat "bad-$name.err")"
}
bad_header unknown-key 2 "unknown key 'origin'" 's/^# source:/# origin:/'
bad_header short-expect 12 "expect needs ALGO KERNEL OUTCOME" 's/^# expect: lawson mp ok$/# expect: lawson mp/'
bad_header unknown-algo 12 "unknown algorithm 'lawsn'" 's/^# expect: lawson mp ok$/# expect: lawsn mp ok/'
bad_header unknown-kernel 12 "unknown kernel 'gmp'" 's/^# expect: lawson mp ok$/# expect: lawson gmp ok/'
bad_header unknown-outcome 13 "unknown outcome 'broken'" 's/^# expect: lawson float ok$/# expect: lawson float broken/'
bad_header timeout 13 "timeout depends on the machine" 's/^# expect: lawson float ok$/# expect: lawson float timeout/'
bad_header exact-failure 12 "lawson mp is an exact pair" 's/^# expect: lawson mp ok$/# expect: lawson mp reported/'
bad_header duplicate-expect 13 "duplicate expect for lawson mp \(first on line 12\)" \
  's/^# expect: lawson mp ok$/&\n&/'
bad_header missing-expect 34 "no expect line for lawson mp" '/^# expect: lawson mp ok$/d'
bad_header missing-dimension 34 'missing `# dimension:`' '/^# dimension:/d'
bad_header wrong-dimension 4 "dimension 3 but the points have 2 coordinates" 's/^# dimension: 2$/# dimension: 3/'
bad_header duplicate-key 5 "duplicate key 'dimension'" 's/^# dimension: 2$/&\n&/'
bad_header not-a-key 1 'not a `# key: value` header line' '1i # a note'
bad_header comment-after 39 "a comment after the points" '$a # a note'
bad_header wrong-name 1 "case 'other' but the file is named $SQUARE.pts" 's/^# case: .*/# case: other/'
bad_header bad-point 39 "wrong number of coordinates" '$a 1 2 3'
expect_rc 2 no-dir "$DLAB" corpus replay "$WORK/no-such-dir"
mkdir empty
expect_rc 2 empty-dir "$DLAB" corpus replay empty
grep -q "no cases" empty-dir.err || fail "empty-dir: $(cat empty-dir.err)"
expect_rc 2 twice "$DLAB" corpus replay base base/$SQUARE.pts
expect_rc 2 bad-algo "$DLAB" corpus replay base --algo lawsn

# ---- add: a case rewritten from itself is the same file ---------------------
cp -r base readd
for c in $SQUARE $LATTICE $CUBE; do
  expect_rc 0 readd-$c "$DLAB" corpus add readd/$c.pts --to readd --replace
  cmp -s readd/$c.pts base/$c.pts || fail "readd: $c.pts is not rewritten byte for byte"
done
expect_rc 2 readd-exists "$DLAB" corpus add base/$SQUARE.pts --to readd
grep -q "exists (--replace" readd-exists.err || fail "readd-exists: $(cat readd-exists.err)"
# Without its expect lines (a new case), add fills them: the same file again.
mkdir fill
grep -v '^# expect:' base/$CUBE.pts > fill/$CUBE.pts
expect_rc 2 fill-replay "$DLAB" corpus replay fill
expect_rc 0 fill "$DLAB" corpus add fill/$CUBE.pts --to fill --replace
cmp -s fill/$CUBE.pts base/$CUBE.pts || fail "fill: $CUBE.pts differs from the corpus's"

# ---- add: a campaign's failure file -----------------------------------------
expect_rc 0 campaign "$DLAB" fuzz --algo lawson --kernel float --gen near-degenerate --n 8..16 --seed 4 \
  --cases 20 --no-timing --out c
failure=$(ls c/failures/lawson.float.2d.*.txt 2>/dev/null | head -1)
if [ -z "$failure" ]; then
  fail "campaign: lawson x float never failed"
else
  stem=$(basename "$failure" .txt)
  outcome=$(echo "$stem" | cut -d. -f4)
  mkdir found
  expect_rc 0 add-failure "$DLAB" corpus add "$failure" --to found
  grep -qx "# case: $stem" "found/$stem.pts" || fail "add-failure: case key: $(head -1 "found/$stem.pts")"
  grep -qx "# source: dlab fuzz, first seen in case [0-9]* (case seed [0-9]*, campaign seed 4), .*; replay: dlab gen .*" \
    "found/$stem.pts" || fail "add-failure: source: $(grep '^# source' "found/$stem.pts")"
  seed=$(sed -n 's/^# replay: .* --seed \([0-9]*\) --validate$/\1/p' "$failure")
  grep -qx "# order-seed: $seed" "found/$stem.pts" || fail "add-failure: order-seed is not the replay's $seed"
  grep -qx "# expect: lawson float $outcome" "found/$stem.pts" || fail "add-failure: does not record lawson float $outcome"
  cmp -s <(grep -v '^#' "$failure") <(grep -v '^#' "found/$stem.pts") || fail "add-failure: points differ"
  expect_rc 0 replay-failure "$DLAB" corpus replay found
  cp "found/$stem.pts" first.pts
  expect_rc 2 add-failure-again "$DLAB" corpus add "$failure" --to found
  expect_rc 0 add-failure-replace "$DLAB" corpus add "$failure" --to found --replace --jobs 2
  cmp -s first.pts "found/$stem.pts" || fail "add-failure: --replace wrote another file"
fi

# `dlab shrink`'s output keeps its input's comments, the campaign's replay as
# "unshrunk replay:"; the order seed is its own replay's (here 2^64 - 1).
{
  echo "# dlab shrink: lawson x float, 2D: not-delaunay"
  echo "# shrunk: yes: 9 points -> 4 points; 20 tests"
  echo "# replay: dlab triangulate s.txt --algo lawson --kernel float --seed 18446744073709551615 --validate"
  echo "# dlab fuzz failure: lawson x float, 2D: not-delaunay"
  echo "# first seen in case 3 (case seed 5, campaign seed 7), lattice n=9"
  echo "# unshrunk replay: dlab gen lattice --dim 2 --n 9 --seed 1 | dlab triangulate - --algo lawson --kernel float --seed 18446744073709551615 --validate"
  grep -v '^#' base/$SQUARE.pts
} > shrunk.txt
mkdir shrunk
expect_rc 0 add-shrunk "$DLAB" corpus add shrunk.txt --to shrunk
grep -qx '# order-seed: 18446744073709551615' shrunk/shrunk.pts || fail "add-shrunk: order-seed: $(grep '^# order' shrunk/shrunk.pts)"
grep -qx '# source: dlab fuzz, first seen in case 3 (case seed 5, campaign seed 7), lattice n=9; replay: dlab gen lattice .*; then dlab shrink' \
  shrunk/shrunk.pts || fail "add-shrunk: source: $(grep '^# source' shrunk/shrunk.pts)"
grep -qx '# exercises: the lawson x float, 2D: not-delaunay failure found by dlab fuzz, shrunk (9 points -> 4 points; 20 tests)' \
  shrunk/shrunk.pts || fail "add-shrunk: exercises: $(grep '^# exercises' shrunk/shrunk.pts)"

# ---- add: other inputs, refusals, bad usage ----------------------------------
grep -v '^#' base/$SQUARE.pts > plain.txt
mkdir new
expect_rc 2 add-no-source "$DLAB" corpus add plain.txt --to new
grep -q -- "--source" add-no-source.err || fail "add-no-source: $(cat add-no-source.err)"
expect_rc 0 add-plain "$DLAB" corpus add plain.txt --to new --name square --source "a test" --exercises "the tools"
grep -qx '# source: a test' new/square.pts && grep -qx '# exercises: the tools' new/square.pts ||
  fail "add-plain: $(head -3 new/square.pts)"
expect_rc 2 add-stdin-no-name "$DLAB" corpus add - --to new --source s --exercises e < plain.txt
expect_rc 2 add-bad-name "$DLAB" corpus add plain.txt --to new --name "a/b" --source s --exercises e
expect_rc 2 add-no-dir "$DLAB" corpus add plain.txt --to "$WORK/no-such-dir" --source s --exercises e
expect_rc 2 add-bad-input "$DLAB" corpus add bad-unknown-key/$SQUARE.pts --to new --name x
grep -q "bad-unknown-key/$SQUARE.pts:2: unknown key" add-bad-input.err || fail "add-bad-input: $(cat add-bad-input.err)"
# An exact pair that is not the perturbed triangulation is a bug: refused, nothing written.
expect_rc 1 add-differs env DLAB_FUZZ_SELFTEST=unperturbed@0:integer "$DLAB" corpus add base/$LATTICE.pts --to new
grep -q "bowyer-watson integer gave differs .*a bug to fix, not to record" add-differs.err ||
  fail "add-differs: $(cat add-differs.err)"
[ -e new/$LATTICE.pts ] && fail "add-differs: wrote the case"
# A timeout is never recorded.
expect_rc 1 add-timeout env DLAB_FUZZ_SELFTEST=hang@0:lawson/epsilon "$DLAB" corpus add base/$SQUARE.pts --to new \
  --timeout 1
grep -q "lawson epsilon timed out" add-timeout.err || fail "add-timeout: $(cat add-timeout.err)"
[ "$(grep -c 'timed out' add-timeout.err)" = 1 ] || fail "add-timeout: not only lawson x epsilon: $(cat add-timeout.err)"
[ -e new/$SQUARE.pts ] && fail "add-timeout: wrote the case"

echo "$failures failures"
[ $failures = 0 ]
