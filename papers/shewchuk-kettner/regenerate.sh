#!/usr/bin/env bash
# Regenerates papers/shewchuk-kettner: the sign maps (pictures + counts) and the
# cost table. Usage: papers/shewchuk-kettner/regenerate.sh [DLAB]  (default: build/cli/dlab)
# Needs /usr/bin/python3 with matplotlib (Debian: python3-matplotlib). About 2 minutes on 2 cores.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
dlab=$(realpath "${1:-$here/../../build/cli/dlab}")
python=/usr/bin/python3
[[ -x $python ]] || python=python3
"$python" "$here/sign_maps.py" "$dlab" "$here"      # sign_map_*.png, sign_maps.png, sign_maps.md
"$python" "$here/costs.py" "$dlab" "$here"          # costs.md, costs.json
rm -rf "$here/work"                                  # the generated point sets
"$python" "$here/quick_check.py" "$dlab" "$(mktemp -d)"
