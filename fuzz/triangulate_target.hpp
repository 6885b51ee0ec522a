// The body of the coverage-guided targets fuzz_triangulate_2d / _3d: decode
// the bytes into points (fuzz/byte_decoder.hpp), run every pair on them
// (fuzz/all_pairs_check.hpp), and abort with a message naming the pair and
// the points when an exact pair broke its promise. Shared by the libFuzzer /
// AFL++ builds and the standalone replayer (fuzz/replay_main.cpp).
//
// With DLAB_FUZZ_PRINT_POINTS=1 in the environment, each input's decoded
// points are printed on stdout first, as hexadecimal floats that `dlab
// triangulate` reads (turn a crash file into a point file:
// `DLAB_FUZZ_PRINT_POINTS=1 ./fuzz_triangulate_2d crash-... > case.pts`).
#pragma once
#include <cstddef>
#include <cstdint>

namespace dlab::fuzz {

// Returns 0 (libFuzzer's convention) or does not return.
int fuzz_triangulate(const std::uint8_t* data, std::size_t size, int dim, const char* target);

}  // namespace dlab::fuzz
