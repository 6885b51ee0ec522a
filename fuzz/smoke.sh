#!/usr/bin/env bash
# CI smoke of the coverage-guided fuzz targets (fuzz/README.md): configure with
# clang and -DDLAB_FUZZ=ON into build-libfuzzer (or $1, with any further
# arguments passed on to cmake), build the three targets, and run each for
# DLAB_FUZZ_SMOKE_SECONDS (default 20) on its seeds (ctest -L libfuzzer,
# fuzz/smoke_target.sh). Exit status: ctest's.
#   fuzz/smoke.sh [BUILD [CMAKE_ARG...]]
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build-libfuzzer}
shift $(( $# > 0 ? 1 : 0 ))
seconds=${DLAB_FUZZ_SMOKE_SECONDS:-20}
launcher=()
command -v ccache > /dev/null && launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
# -O1 -g1: the sanitizers' usual level, about half the compile time of -O2 -g;
# assertions stay on.
cmake -S . -B "$build" -DCMAKE_CXX_COMPILER=clang++ -DDLAB_FUZZ=ON -DDLAB_BUILD_TESTS=OFF \
  -DDLAB_BUILD_BENCH=OFF -DCMAKE_BUILD_TYPE=RelWithDebInfo "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-O1 -g1" \
  -DDLAB_FUZZ_SMOKE_SECONDS="$seconds" "${launcher[@]}" "$@"
cmake --build "$build" -j2 --target fuzz_point_reader fuzz_triangulate_2d fuzz_triangulate_3d
# Two targets at a time, one per core.
ctest --test-dir "$build" -L libfuzzer -j2 --output-on-failure
