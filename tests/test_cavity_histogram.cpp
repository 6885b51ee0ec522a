// The cavity-size histogram (algorithms/cavity_histogram.hpp): its buckets'
// edges, and, on real runs of bowyer-watson and george, its agreement with the
// counters kept apart from it (cavity_simplices: the sum; max_cavity_simplices).
#include <catch2/catch.hpp>
#include <cstdint>
#include <string>

#include "algorithms/cavity_histogram.hpp"
#include "fuzz/generators.hpp"
#include "tests/run_readout.hpp"
#include "variants/run.hpp"

using namespace dlab;
using dlab::test::counter;

namespace {

std::uint64_t count_of(const CavityHistogram& h, int bucket) {
  Counters c;
  h.append_to(c);
  return c.at(static_cast<std::size_t>(bucket)).second;
}

}  // namespace

TEST_CASE("cavity histogram: power-of-two buckets", "[cavity_histogram]") {
  CHECK(CavityHistogram::name(0) == "cavity_size_1");
  CHECK(CavityHistogram::name(1) == "cavity_size_2_3");
  CHECK(CavityHistogram::name(5) == "cavity_size_32_63");
  CHECK(CavityHistogram::name(6) == "cavity_size_64_up");
  // Each size lands in the bucket [2^b, 2^(b+1)), the last one open above.
  const struct {
    std::uint64_t size;
    int bucket;
  } cases[] = {{1, 0}, {2, 1}, {3, 1}, {4, 2}, {7, 2}, {8, 3}, {31, 4}, {32, 5}, {63, 5}, {64, 6}, {1000000, 6}};
  for (const auto& c : cases) {
    CavityHistogram h;
    h.add(c.size);
    h.add(0);  // no cavity: not counted
    INFO("size " << c.size);
    for (int b = 0; b < CavityHistogram::kBuckets; ++b) CHECK(count_of(h, b) == (b == c.bucket ? 1u : 0u));
  }
}

TEST_CASE("cavity histogram agrees with the cavity counters", "[cavity_histogram]") {
  for (const char* algo : {"bowyer-watson", "george"})
    for (int dim : {2, 3})
      for (const char* g : {"uniform", "cospherical", "lattice"}) {
        gen::GenOptions go;
        go.name = g;
        go.n = 400;
        go.dim = dim;
        go.seed = 5;
        RunOptions o;
        o.algorithm = algo;
        const RunResult r = run(gen::generate(go), o);
        INFO(algo << " " << dim << "D " << g);
        REQUIRE(r.outcome == RunResult::Outcome::ok);
        // Every insertion after the first simplex has a cavity, duplicates none.
        std::uint64_t insertions = 0, lo_sum = 0, hi_sum = 0;
        int top = -1;
        for (int b = 0; b < CavityHistogram::kBuckets; ++b) {
          const std::uint64_t k = counter(r.counters, CavityHistogram::name(b));
          insertions += k;
          lo_sum += k << b;
          hi_sum += b + 1 < CavityHistogram::kBuckets ? k * ((std::uint64_t{2} << b) - 1) : k * 1000000;
          if (k) top = b;
        }
        CHECK(insertions == r.distinct_points - static_cast<std::uint64_t>(dim + 1));
        const std::uint64_t total = counter(r.counters, "cavity_simplices");
        CHECK(lo_sum <= total);
        CHECK(total <= hi_sum);
        const std::uint64_t largest = counter(r.counters, "max_cavity_simplices");
        REQUIRE(top >= 0);
        CHECK(largest >= (std::uint64_t{1} << top));
        if (top + 1 < CavityHistogram::kBuckets) CHECK(largest < (std::uint64_t{2} << top));
      }
}
