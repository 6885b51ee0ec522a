#!/bin/bash
# papers/su-drysdale1995, quick version (ctest papers.su_drysdale1995), run as
#   test_papers_su_drysdale.sh DLAB WORKDIR
# Incremental insertion in 2D does O(1) in-circle tests and flips per point:
# from n to 4n uniform points the per-point counts stay within 10 %, for every
# order and both location schemes. In random order they stay under the
# randomized-incremental expectation (Guibas, Knuth, Sharir 1992; de Berg et
# al., Computational Geometry, ch. 9): the new vertex has expected degree
# below 6 (backwards analysis), so Lawson makes fewer than 3 flips per point
# in expectation and, testing 3 + 2 x flips edges, fewer than 9 in-circle tests.
# The sample means of 1000 and 4000 points are a few standard errors (~0.05)
# from those bounds; the lower limits catch tests or flips skipped.
set -u
DLAB=$(realpath "$1")
WORK=$2
HERE=$(cd "$(dirname "$0")" && pwd)
rm -rf "$WORK" && mkdir -p "$WORK" && cd "$WORK" || exit 1
. "$HERE/test_papers_lib.sh"

"$DLAB" gen uniform --n 1000 --seed 1 -o u1000.txt
"$DLAB" gen uniform --n 4000 --seed 1 -o u4000.txt
for order in random brio hilbert; do
  for loc in walk scan; do
    for n in 1000 4000; do run lawson-$order-$loc-$n u$n.txt --algo lawson --order $order --location $loc; done
    a=$(field lawson-$order-$loc-1000.json incircle) b=$(field lawson-$order-$loc-4000.json incircle)
    within "$order $loc: in-circle tests per point, n=4000 over n=1000" "$(per_point_ratio "$a" 1000 "$b" 4000)" 0.95 1.1
    a=$(field lawson-$order-$loc-1000.json flips_2_2) b=$(field lawson-$order-$loc-4000.json flips_2_2)
    within "$order $loc: flips per point, n=4000 over n=1000" "$(per_point_ratio "$a" 1000 "$b" 4000)" 0.95 1.1
  done
done
for n in 1000 4000; do
  within "random order, n=$n: in-circle tests per point" \
    "$(awk -v c="$(field lawson-random-walk-$n.json incircle)" -v n=$n 'BEGIN { print c / n }')" 8.0 9.0
  within "random order, n=$n: flips per point" \
    "$(awk -v c="$(field lawson-random-walk-$n.json flips_2_2)" -v n=$n 'BEGIN { print c / n }')" 2.5 3.0
done
finish
