#!/bin/bash
# papers/baker-ch16, quick version (ctest papers.baker_ch16), run as
#   test_papers_baker.sh DLAB WORKDIR
# Bowyer-Watson (and Lawson) located by a scan of every simplex are quadratic,
# by a walk from the last insertion (brio order) linear: predicate calls per
# point grow about 4x from n to 4n with the scan and stay about constant with
# the walk; with Bowyer-Watson the scan changes nothing but the orientation
# tests (the in-circle / in-sphere tests are the walk's, to the call); exact kernels never fail with
# either scheme, degenerate input included (--validate: the exact validator).
set -u
DLAB=$(realpath "$1")
WORK=$2
HERE=$(cd "$(dirname "$0")" && pwd)
rm -rf "$WORK" && mkdir -p "$WORK" && cd "$WORK" || exit 1
. "$HERE/test_papers_lib.sh"

for dim in 2 3; do
  if [ $dim = 2 ]; then small=1000; else small=500; fi
  large=$((4 * small))
  "$DLAB" gen uniform --dim $dim --n $small --seed 1 -o u$small.txt
  "$DLAB" gen uniform --dim $dim --n $large --seed 1 -o u$large.txt
  for algo in bowyer-watson lawson; do
    for loc in walk scan; do
      for n in $small $large; do run $dim-$algo-$loc-$n u$n.txt --algo $algo --location $loc --order brio; done
      a=$(calls $dim-$algo-$loc-$small.json) b=$(calls $dim-$algo-$loc-$large.json)
      r=$(per_point_ratio "$a" $small "$b" $large)
      if [ $loc = scan ]; then
        within "${dim}D $algo scan: calls per point, n=$large over n=$small" "$r" 3.2 5.0
        [ "$(field $dim-$algo-$loc-$large.json scan_tests)" -gt $((large * large / 8)) ] ||
          fail "${dim}D $algo scan: scan_tests $(field $dim-$algo-$loc-$large.json scan_tests) at n=$large"
      else
        within "${dim}D $algo walk: calls per point, n=$large over n=$small" "$r" 0.8 1.25
      fi
    done
  done
  # Bowyer-Watson's cavity is the same set whichever conflicting simplex it
  # grows from, so its in-sphere tests are the walk's to the call. (Lawson's
  # are not: outside the hull the ghost found first orders the flips.)
  for n in $small $large; do
    for p in incircle insphere; do
      [ "$(field $dim-bowyer-watson-walk-$n.json $p)" = "$(field $dim-bowyer-watson-scan-$n.json $p)" ] ||
        fail "${dim}D bowyer-watson n=$n: $p calls differ between walk and scan"
    done
  done
done

# Exact kernels never fail, with either location, on exactly degenerate sets.
"$DLAB" gen cocircular --dim 2 --n 200 --seed 2 -o c2.txt
"$DLAB" gen cospherical --dim 3 --n 120 --seed 2 -o c3.txt
for f in c2 c3; do
  for kernel in adaptive integer mp; do
    for algo in bowyer-watson lawson; do
      run $f-$kernel-$algo-scan $f.txt --algo $algo --kernel $kernel --location scan --order random
    done
  done
done
finish
