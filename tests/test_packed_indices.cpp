// PackedIndices (variants/packed_indices.hpp): the driver's insertion order in
// ceil(log2 n) bits per index. Round trips at the widths' edges (n = 2^k and
// 2^k + 1, values up to n - 1, indices straddling two words), and the
// reordering of points through a packed order equals the one through the
// plain order.
#include <catch2/catch.hpp>

#include <cstdint>
#include <numeric>
#include <random>
#include <vector>

#include "variants/insertion_order.hpp"
#include "variants/packed_indices.hpp"

using namespace dlab;

TEST_CASE("packed indices: the width is ceil(log2 n)", "[packed_indices]") {
  CHECK(PackedIndices::width_for(1) == 1);
  CHECK(PackedIndices::width_for(2) == 1);
  CHECK(PackedIndices::width_for(3) == 2);
  CHECK(PackedIndices::width_for(4) == 2);
  CHECK(PackedIndices::width_for(5) == 3);
  CHECK(PackedIndices::width_for(1u << 20) == 20);
  CHECK(PackedIndices::width_for((1u << 20) + 1) == 21);
  CHECK(PackedIndices::width_for(1000000) == 20);
  CHECK(PackedIndices::width_for(std::uint64_t(1) << 32) == 32);
}

TEST_CASE("packed indices: every value comes back, at every width's edge", "[packed_indices]") {
  std::mt19937_64 rng(5);
  for (std::uint64_t n : {1ull, 2ull, 3ull, 4ull, 5ull, 63ull, 64ull, 65ull, 1000ull, 4096ull, 4097ull, 70001ull}) {
    // A permutation, its largest value (n - 1) in every position modulo 64 bits.
    std::vector<std::uint32_t> v(n);
    std::iota(v.begin(), v.end(), 0u);
    std::shuffle(v.begin(), v.end(), rng);
    const PackedIndices p(v, n);
    REQUIRE(p.size() == n);
    bool all = true;
    for (std::size_t i = 0; i < n; ++i) all = all && p[i] == v[i];
    CHECK(all);
    CHECK(p.bytes() * 8 <= n * PackedIndices::width_for(n) + 128);
  }
  // All ones at 32 bits: values up to 2^32 - 1.
  const std::vector<std::uint32_t> high{0xFFFFFFFFu, 0u, 0xFFFFFFFEu, 0x80000000u, 0xFFFFFFFFu};
  const PackedIndices p(high, std::uint64_t(1) << 32);
  CHECK(p.width() == 32);
  for (std::size_t i = 0; i < high.size(); ++i) CHECK(p[i] == high[i]);
  // Odd widths straddle words: 31 bits, values 2^31 - 1.
  const std::vector<std::uint32_t> ones(9, 0x7FFFFFFFu);
  const PackedIndices q(ones, 0x80000000u);
  CHECK(q.width() == 31);
  for (std::size_t i = 0; i < ones.size(); ++i) CHECK(q[i] == 0x7FFFFFFFu);
}

TEST_CASE("packed indices: apply_order through a packed order is the plain one's", "[packed_indices]") {
  std::mt19937_64 rng(9);
  const std::size_t n = 5000;
  std::vector<std::uint32_t> order(n);
  std::iota(order.begin(), order.end(), 0u);
  std::shuffle(order.begin(), order.end(), rng);
  std::vector<double> values(n);
  for (std::size_t i = 0; i < n; ++i) values[i] = double(i) * 1.5;
  const PackedIndices packed(order, n);
  for (bool in_place : {false, true}) {
    std::vector<double> a = values, b = values;
    std::vector<bool> done;
    apply_order(a, order, false, done, in_place);
    apply_order(b, packed, false, done, in_place);
    CHECK(a == b);
    CHECK(b[0] == values[order[0]]);
    apply_order(b, packed, true, done, in_place);
    CHECK(b == values);
  }
}
