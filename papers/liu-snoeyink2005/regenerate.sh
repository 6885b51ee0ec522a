#!/usr/bin/env bash
# Regenerates this folder: the study (study.json, about 5 minutes on 2 cores),
# its table (results.md) and figures (plots/, by dlab plot).
# Usage: papers/liu-snoeyink2005/regenerate.sh DLAB [WORK_DIR]   (--quick: quick.json)
set -euo pipefail
quick=false
[[ ${1:-} == --quick ]] && { quick=true; shift; }
dlab=${1:?usage: regenerate.sh [--quick] DLAB [WORK_DIR]}
here=$(cd "$(dirname "$0")" && pwd)
work=${2:-$here/work}
python=/usr/bin/python3
[[ -x $python ]] || python=python3
config=$here/study.json
$quick && config=$here/quick.json
"$dlab" study "$config" --out "$work/study"
"$python" "$here/summarize.py" "$work/study/runs.csv" --check > "$work/results.md"
"$dlab" plot "$work/study" --out "$work/plots"
if ! $quick; then
  cp "$work/results.md" "$here/results.md"
  cp "$work/plots/time_per_point.png" "$here/time_per_point.png"
  cp "$work/plots/outcomes.png" "$here/outcomes.png"
fi
echo "results: $work/results.md, figures: $work/plots/"
