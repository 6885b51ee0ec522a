#!/bin/bash
# Baker's tolerance variant (bowyer-watson x epsilon, strict policy: a zero within mu
# is outside the cavity) beside float and beside george (integer volumes, floating spheres;
# and float volumes: is George's exactness needed?).
# 5 seeds per row; columns: runs that ended valid Delaunay / valid but not Delaunay /
# invalid (caught by the validator) / failed (reported by the algorithm), and the
# locally non-Delaunay facets summed over the not-Delaunay runs.
D=${DLAB:-build/cli/dlab}
printf "%-3s %-34s %-22s %4s %6s %6s %7s %6s %9s\n" dim set variant runs ok_del notdel invalid failed nd_facets
for dim in 2 3; do
for spec in "near-degenerate --ulps 1" "near-degenerate --ulps 16" "near-degenerate --base lattice --ulps 1" "near-duplicates --ulps 1" "kettner-grid --side 64"; do
  set -- $spec; g=$1; shift
  [ $g = kettner-grid ] && [ $dim = 3 ] && continue
  n=2000; [ $dim = 3 ] && n=800
  for v in "bowyer-watson epsilon" "bowyer-watson float" "george integer" "george float"; do
    set -- $v; A=$1; K=$2
    runs=0; okd=0; nd=0; inv=0; fl=0; ndf=0
    for seed in 1 2 3 4 5; do
      $D gen $g --n $n --dim $dim --seed $seed ${spec#* } > e.txt 2>/dev/null || $D gen $g --n $n --dim $dim --seed $seed > e.txt
      timeout 60 $D triangulate e.txt --algo $A --kernel $K --policy strict -o e.tri --points-out e.pts --stats e.json 2>/dev/null
      o=$(python3 -c "import json;print(json.load(open('e.json'))['outcome'])" 2>/dev/null || echo failed)
      runs=$((runs+1))
      if [ $A = george ] && [ "$o" = failed ]; then fl=$((fl+1)); continue; fi
      if [ $A = george ]; then  # its own exact counters (validator run after the triangulation)
        read o c < <(python3 -c "import json;c=json.load(open('e.json'))['counters'];print('ok' if c['valid'] and not c['non_delaunay_facets'] else ('not_delaunay' if c['valid'] else 'invalid'), c['non_delaunay_facets'])")
        [ $o = not_delaunay ] && ndf=$((ndf+c))
        case $o in ok) okd=$((okd+1));; not_delaunay) nd=$((nd+1));; *) inv=$((inv+1));; esac
        continue
      fi
      case $o in ok) okd=$((okd+1));; not_delaunay) nd=$((nd+1)); c=$($D check e.pts e.tri 2>&1 | grep -o 'not_delaunay: [0-9]*' | grep -o '[0-9]*'); ndf=$((ndf+${c:-0}));; invalid) inv=$((inv+1));; *) fl=$((fl+1));; esac
    done
    printf "%-3s %-34s %-22s %4d %6d %6d %7d %6d %9d\n" $dim "$spec" "$A $K" $runs $okd $nd $inv $fl $ndf
  done
done; done
