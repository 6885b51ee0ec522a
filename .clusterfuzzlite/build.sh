#!/bin/bash -eu
# ClusterFuzzLite / OSS-Fuzz build script (.clusterfuzzlite/Dockerfile): the
# fuzz targets of fuzz/targets.cmake into $OUT, with their seed corpora.
# The engine's instrumentation and sanitizer flags come in $CXXFLAGS (read by
# CMake) and $LIB_FUZZING_ENGINE, so the project adds none of its own
# (DLAB_FUZZ_FLAGS empty) and no build type's flags (-O1 from $CXXFLAGS;
# assertions stay on).
cmake -S "$SRC/delaunay-lab" -B "$WORK/build" \
  -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_FLAGS_RELWITHDEBINFO= \
  -DDLAB_FUZZ=ON -DDLAB_FUZZ_FLAGS= -DDLAB_FUZZ_ENGINE="$LIB_FUZZING_ENGINE" \
  -DDLAB_BUILD_TESTS=OFF -DDLAB_BUILD_BENCH=OFF \
  -DBOOST_ROOT=/opt/boost_1_83_0 -DGMP_LIBRARY=/usr/lib/x86_64-linux-gnu/libgmp.a
targets="fuzz_point_reader fuzz_triangulate_2d fuzz_triangulate_3d"
cmake --build "$WORK/build" -j"$(nproc)" --target $targets

seeds=$SRC/delaunay-lab/fuzz/seeds
for t in $targets; do
  cp "$WORK/build/fuzz/$t" "$OUT/"
  zip -q -j "$OUT/${t}_seed_corpus.zip" "$seeds/${t#fuzz_}"/*
done
# The reader also starts from the regression corpus's point files.
zip -q -j "$OUT/fuzz_point_reader_seed_corpus.zip" "$SRC"/delaunay-lab/tests/corpus/*.pts
