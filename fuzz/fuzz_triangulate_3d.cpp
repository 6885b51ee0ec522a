// libFuzzer / AFL++ target: bytes -> a 3D point set with likely degeneracies
// -> every algorithm x kernel pair (fuzz/triangulate_target.hpp).
#include <cstddef>
#include <cstdint>

#include "fuzz/triangulate_target.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return dlab::fuzz::fuzz_triangulate(data, size, 3, "fuzz_triangulate_3d");
}
