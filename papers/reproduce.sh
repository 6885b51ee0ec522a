#!/usr/bin/env bash
# Regenerates every paper folder from its study configs and scripts, into OUT
# (each folder's README says which of its files come from where).
#
#   papers/reproduce.sh BUILD_DIR OUT     all of them: about 1 h on 2 cores
#   papers/reproduce.sh --quick BUILD_DIR the quick versions (ctest -L papers):
#                                          small sizes, each claim's direction asserted
#
# BUILD_DIR: a Release build of this tree (cmake -S . -B build -DCMAKE_BUILD_TYPE=Release).
# papers/robustness/ is not rerun here: its campaigns take hours; its README gives
# the `dlab fuzz` commands and tabulate.py recomputes its tables from their results.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
if [[ ${1:-} == --quick ]]; then
  build=${2:?usage: reproduce.sh --quick BUILD_DIR}
  exec ctest --test-dir "$build" -L papers --output-on-failure
fi
[[ $# -eq 2 ]] || { echo "usage: reproduce.sh BUILD_DIR OUT | reproduce.sh --quick BUILD_DIR" >&2; exit 2; }
build=$(realpath "$1")
out=$(realpath -m "$2")
dlab=$build/cli/dlab
python=/usr/bin/python3
[[ -x $python ]] || python=python3
[[ -x $dlab ]] || { echo "reproduce.sh: no $dlab (build the tree first)" >&2; exit 2; }
mkdir -p "$out"
step() { printf '\n== %s\n' "$*" >&2; }

step "Shewchuk 1997 / Kettner et al. 2008: sign maps and predicate costs"
"$here/shewchuk-kettner/regenerate.sh" "$dlab"

step "Baker ch. 16: Bowyer-Watson with and without location, Tanemura's growth"
"$here/baker-ch16/reproduce.sh" "$dlab" "$out/baker-ch16"

step "Su & Drysdale 1995: in-circle tests and flips per point"
"$dlab" study "$here/su-drysdale1995/study.json" --out "$out/su-drysdale1995"
"$dlab" plot "$out/su-drysdale1995"
"$python" "$here/su-drysdale1995/figure.py" "$out/su-drysdale1995"

step "George 1997: Table 1 (study), Table 2 (flips), validity with floating spheres, Baker's tolerance"
"$dlab" study "$here/george1997/table1.json" --out "$out/george1997/table1"
"$build/papers/dlab_shell_triangulations" 13 > "$out/george1997/table2.csv"
"$python" "$here/george1997/table2.py" "$out/george1997/table2.csv"
DLAB=$dlab "$here/george1997/validity_sweep.sh" george integer > "$out/george1997/validity.txt"
DLAB=$dlab "$here/george1997/eps_study.sh" > "$out/george1997/eps.txt"

step "Liu & Snoeyink 2005: PDB-like inputs through every code"
"$here/liu-snoeyink2005/regenerate.sh" "$dlab" "$out/liu-snoeyink2005"

step "done: $out"
