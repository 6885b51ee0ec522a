#!/usr/bin/env bash
# Regenerates papers/baker-ch16: the two studies (walk: n up to 256 000; scan:
# up to 16 000 in 2D and 8 000 in 3D, it is quadratic), dlab plot's figures of
# each, and the paper's figure with the fitted exponents (figure.py).
#
#   papers/baker-ch16/reproduce.sh DLAB OUT      (about 6 minutes on one core)
set -euo pipefail
[ $# -eq 2 ] || { echo "usage: $0 DLAB OUT" >&2; exit 2; }
dlab=$1 out=$2 here=$(dirname "$0")
"$dlab" study "$here/walk.json" --out "$out/walk"
"$dlab" study "$here/scan.json" --out "$out/scan"
"$dlab" plot "$out/walk"
"$dlab" plot "$out/scan"
/usr/bin/python3 "$here/figure.py" "$out"
