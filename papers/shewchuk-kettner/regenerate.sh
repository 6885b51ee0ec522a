#!/usr/bin/env bash
# Regenerates papers/shewchuk-kettner: the sign maps (pictures + counts) and the
# cost table. Usage: papers/shewchuk-kettner/regenerate.sh [DLAB]  (default: build/cli/dlab)
# Needs /usr/bin/python3 with matplotlib (Debian: python3-matplotlib). About 5 minutes on 2 cores.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
dlab=$(realpath "${1:-$here/../../build/cli/dlab}")
python=/usr/bin/python3
[[ -x $python ]] || python=python3
"$python" "$here/sign_maps.py" "$dlab" "$here"      # sign_map_*.png, sign_maps.png, sign_maps.md
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
"$dlab" study "$here/costs_study.json" --out "$work/costs"        # float, adaptive, epsilon, integer
"$dlab" study "$here/costs_study_mp.json" --out "$work/costs-mp"  # mp, n = 10^4 only
"$python" "$here/costs.py" "$here" "$work/costs" "$work/costs-mp"  # costs.md, costs.json
"$python" "$here/quick_check.py" "$dlab" "$(mktemp -d)"
