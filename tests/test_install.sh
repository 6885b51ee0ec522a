#!/usr/bin/env bash
# ctest `install` (label install): `cmake --install` of this build into a fresh
# prefix, then tests/install_consumer/ -- another project -- configured with
# find_package(dlab) against that prefix only, built (it links the installed
# static libraries; nothing of this build is rebuilt) and run; its output must
# equal tests/install_consumer/expected.txt, written by hand. Also: the
# installed `dlab` runs, and the installed Python module (when this build has
# one) imports from the prefix and triangulates the square and its centre.
# Usage: test_install.sh BUILD_DIR WORK_DIR [PYTHON3 (given when the build has the Python module)]
set -euo pipefail
build=$1 work=$2 python=${3:-}
src=$(cd "$(dirname "$0")/.." && pwd)
rm -rf "$work"
mkdir -p "$work"
prefix=$work/prefix

cmake --install "$build" --prefix "$prefix" > "$work/install.log"
[[ -x $prefix/bin/dlab ]] || { echo "FAIL: no $prefix/bin/dlab" >&2; exit 1; }
"$prefix/bin/dlab" --version > /dev/null

# The installed `dlab plot` runs the script installed beside it, not this tree's.
grep -qF "script: $prefix/share/dlab/plot/dlab_plot.py" <("$prefix/bin/dlab" plot --help) ||
  { echo "FAIL: the installed dlab plot does not use $prefix/share/dlab/plot/dlab_plot.py" >&2; exit 1; }

# The consumer sees the prefix only: no package registry, no path of this tree.
cmake -S "$src/tests/install_consumer" -B "$work/consumer" -DCMAKE_BUILD_TYPE=Release \
  -DCMAKE_PREFIX_PATH="$prefix" -DCMAKE_FIND_USE_PACKAGE_REGISTRY=OFF > "$work/configure.log" ||
  { cat "$work/configure.log" >&2; exit 1; }
cmake --build "$work/consumer" -j2 > "$work/build.log" 2>&1 || { cat "$work/build.log" >&2; exit 1; }
# (WORK may lie inside this tree: its own paths are taken out before looking.)
if cat "$work/consumer/CMakeFiles/consumer.dir/flags.make" "$work/consumer/CMakeFiles/consumer.dir/link.txt" |
   sed "s|$work/||g" | grep -F -- "$src/"; then
  echo "FAIL: the consumer compiles or links against this source tree, not the prefix" >&2
  exit 1
fi
"$work/consumer/consumer" > "$work/consumer.out"
diff -u "$src/tests/install_consumer/expected.txt" "$work/consumer.out"

# The Python module, installed only with -DDLAB_PYTHON=ON (then PYTHON3 is given),
# where the interpreter's own modules go: lib/python3.X/dist-packages on Debian.
if [[ -n $python ]]; then
  modules=("$prefix"/lib/python3*/*-packages/dlab.*.so)
  [[ -e ${modules[0]} ]] || { echo "FAIL: no Python module dlab under $prefix/lib/python3*/*-packages" >&2; exit 1; }
  out=$(cd "$work" && PYTHONPATH=$(dirname "${modules[0]}") "$python" -c '
import numpy as np, dlab
assert dlab.__file__.startswith("'"$prefix"'"), dlab.__file__
s, stats = dlab.triangulate(np.array([[0, 0], [1, 0], [1, 1], [0, 1], [0.5, 0.5]], dtype=np.float64))
print(sorted(sorted(int(v) for v in t) for t in s), stats["simplices"])')
  [[ $out == "[[0, 1, 4], [0, 3, 4], [1, 2, 4], [2, 3, 4]] 4" ]] || { echo "FAIL: python module: $out" >&2; exit 1; }
  echo "python module: $out"
fi
echo "install: ok"
