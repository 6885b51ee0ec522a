#!/bin/bash
# Validity and distance from Delaunay on every generator (section 1 of README.md).
# usage: validity_sweep.sh ALGO KERNEL [extra flags], e.g. validity_sweep.sh george integer [--exact-sphere]
D=${DLAB:-build/cli/dlab}
A=$1; K=$2; shift 2
for dim in 2 3; do
for g in uniform gaussian clustered lattice rotated-lattice cocircular collinear near-degenerate near-duplicates huge tiny coplanar kettner-grid kettner-hull; do
  [ $g = coplanar ] && [ $dim = 2 ] && continue
  [ $g = kettner-grid ] && [ $dim = 3 ] && continue
  [ $g = kettner-hull ] && [ $dim = 3 ] && continue
  n=3000; [ $dim = 3 ] && n=1500
  extra=""; [ $g = kettner-grid ] && extra="--side 64"
  $D gen $g --n $n --dim $dim --seed 3 $extra > ./in.txt 2>/dev/null || { echo "$dim $g gen-fail"; continue; }
  timeout 120 $D triangulate ./in.txt --algo $A --kernel $K "$@" -o ./out.tri --stats ./st.json --points-out ./pts.txt 2>./err.txt; rc=$?
  chk=$($D check ./pts.txt ./out.tri 2>&1 | tr '\n' ' ' | cut -c1-100)
  c=$(python3 -c "import json;d=json.load(open('./st.json'));c=d['counters'];print(d['simplices'],' '.join(f'{k}={c[k]}' for k in ['corrected_insertions','removed_for_visibility','added_for_zero_volume','zero_volume_not_addable','removed_for_connectivity','removed_for_enclosed_vertex','non_delaunay_facets','valid'] if k in c))" 2>/dev/null)
  echo "$dim $g rc=$rc [$chk] $c $(head -c 150 ./err.txt)"
done; done
