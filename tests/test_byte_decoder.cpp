// The fuzz targets' byte decoder (fuzz/byte_decoder.hpp): its degenerate
// constructions are exactly what the header says, checked with the mp kernel
// and in integers -- never with the decoder's own floating-point steps -- and
// every byte string decodes to at most kMaxPoints finite points,
// deterministically.
#include <catch2/catch.hpp>

#include <bit>
#include <cmath>
#include <cstdint>
#include <set>
#include <vector>

#include "fuzz/byte_decoder.hpp"
#include "fuzz/generators.hpp"
#include "predicates/mp_kernel.hpp"

using namespace dlab;
using namespace dlab::fuzz;

namespace {

using Bytes = std::vector<std::uint8_t>;

Bytes scale_op(int e) {  // instruction 6, two-byte form: e = -1074 + u
  const unsigned u = static_cast<unsigned>(e + 1074);
  return {0x86, static_cast<std::uint8_t>(u & 0xFF), static_cast<std::uint8_t>(u >> 8)};
}

Bytes cat(std::initializer_list<Bytes> parts) {
  Bytes out;
  for (const auto& p : parts) out.insert(out.end(), p.begin(), p.end());
  return out;
}

// Number of integer solutions of x^2 + y^2 = n: 4 (d_1(n) - d_3(n)), the
// divisors of n that are 1 and 3 mod 4 (Jacobi's two-square theorem).
std::int64_t r2(std::int64_t n) {
  std::int64_t d1 = 0, d3 = 0;
  for (std::int64_t d = 1; d <= n; ++d) {
    if (n % d != 0) continue;
    if (d % 4 == 1) ++d1;
    if (d % 4 == 3) ++d3;
  }
  return 4 * (d1 - d3);
}

// Integer solutions of x^2 + y^2 + z^2 = R^2, counted by brute force.
std::int64_t r3(std::int64_t R) {
  std::int64_t count = 0;
  for (std::int64_t x = -R; x <= R; ++x)
    for (std::int64_t y = -R; y <= R; ++y)
      for (std::int64_t z = -R; z <= R; ++z) count += x * x + y * y + z * z == R * R;
  return count;
}

}  // namespace

TEST_CASE("circle and sphere tables hold every lattice point of their radius, once", "[byte_decoder]") {
  for (int dim : {2, 3})
    for (std::size_t r = 0; r < circle_radius_count(dim); ++r) {
      const std::int64_t R = circle_radius(dim, r);
      const auto& pts = circle_points(dim, r);
      std::set<std::array<std::int64_t, 3>> seen;
      for (const auto& p : pts) {
        const std::array<std::int64_t, 3> q{std::int64_t(p[0]), std::int64_t(p[1]), std::int64_t(p[2])};
        CHECK(double(q[0]) == p[0]);
        CHECK(double(q[1]) == p[1]);
        CHECK(double(q[2]) == p[2]);
        if (dim == 2) CHECK(q[2] == 0);
        CHECK(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] == R * R);
        seen.insert(q);
      }
      CHECK(seen.size() == pts.size());
      CHECK(std::int64_t(pts.size()) == (dim == 2 ? r2(R * R) : r3(R)));
    }
  CHECK(circle_points(2, 1).size() == 12);  // 5^2: (+-5,0), (0,+-5), (+-3,+-4), (+-4,+-3)
}

TEST_CASE("cocircular and cospherical instructions give exactly cocircular points at every scale", "[byte_decoder]") {
  const MpKernel mp;
  for (int e : {-1074, -1060, -1022, -53, 0, 52, 1000})
    for (std::size_t r = 1; r < 6; ++r)
      for (bool shifted : {false, true}) {
        CAPTURE(e, r, shifted);
        // Optionally an origin on the grid first: lattice point (3, -7[, 5]) 2^e, origin := it;
        // then 18 consecutive points of radius r's circle / sphere (instruction 13, a = 15;
        // radius 5's 12 points wrap around: repeats).
        const Bytes circle{0xFD, static_cast<std::uint8_t>(r), 0};
        const Bytes origin2{0x00, 3, 0xF9, 0x17, 0}, origin3{0x00, 3, 0xF9, 5, 0x17, 0};
        const std::size_t first = shifted ? 1 : 0;
        const auto d2 = decode_points(cat({{0x00}, scale_op(e), shifted ? origin2 : Bytes{}, circle}), 2).points.p2;
        REQUIRE(d2.size() == first + 18);
        for (std::size_t k = first + 3; k < d2.size(); ++k)
          CHECK(mp.incircle(d2[first], d2[first + 1], d2[first + 2], d2[k]) == Sign::zero);
        const auto d3 = decode_points(cat({{0x00}, scale_op(e), shifted ? origin3 : Bytes{}, circle}), 3).points.p3;
        REQUIRE(d3.size() == first + 18);
        // Four points of the sphere that are not coplanar span it (no three
        // distinct points of a sphere are collinear).
        std::vector<std::size_t> base{first};
        for (std::size_t k = first + 1; k < d3.size() && base.size() < 4; ++k) {
          if (d3[k] == d3[first]) continue;
          if (base.size() == 3 && mp.orient3d(d3[base[0]], d3[base[1]], d3[base[2]], d3[k]) == Sign::zero) continue;
          base.push_back(k);
        }
        REQUIRE(base.size() == 4);
        for (std::size_t k = first; k < d3.size(); ++k)
          CHECK(mp.insphere(d3[base[0]], d3[base[1]], d3[base[2]], d3[base[3]], d3[k]) == Sign::zero);
      }
}

TEST_CASE("lattice lines are exactly collinear, ulp moves move by exactly k ulps", "[byte_decoder]") {
  const MpKernel mp;
  for (int e : {-1074, -30, 0, 900}) {
    CAPTURE(e);
    // 12 points base + t dir, base (3, -5), dir (7, 2).
    const auto line = decode_points(cat({{0x00}, scale_op(e), {0xA1, 3, 0xFB, 7, 2}}), 2).points.p2;
    REQUIRE(line.size() == 12);
    for (std::size_t k = 2; k < line.size(); ++k) CHECK(mp.orient2d(line[0], line[1], line[k]) == Sign::zero);
    CHECK(line[11][0] == std::ldexp(3.0 + 11 * 7, e));
  }
  // Raw point (0.1, -2^-1074), then the ulp moves of instruction 4: byte 5 -> -11 ulps, 0xF0 (-16) -> +1.
  Bytes prog{0x00, 0x08};
  for (double c : {0.1, -std::ldexp(1.0, -1074)})
    for (int i = 0; i < 8; ++i) prog.push_back(static_cast<std::uint8_t>(std::bit_cast<std::uint64_t>(c) >> (8 * i)));
  prog.insert(prog.end(), {0x04, 0, 5, 0x14, 0, 0xF0, 0x24, 0, 0xF0});
  const auto p = decode_points(prog, 2).points.p2;
  REQUIRE(p.size() == 4);
  CHECK(gen::ulp_distance(p[0][0], p[1][0]) == -11);
  CHECK(gen::ulp_distance(p[0][1], p[1][1]) == -11);
  CHECK(gen::ulp_distance(p[0][0], p[2][0]) == 1);  // a = 1: x only
  CHECK(p[2][1] == p[0][1]);
  CHECK(p[3][0] == p[0][0]);                         // a = 2: y only
  CHECK(p[3][1] == 0.0);  // -2^-1074 + 1 ulp = -0
}

TEST_CASE("every byte string decodes to at most 64 finite points, the same each time", "[byte_decoder]") {
  gen::SplitMix64 rng(20261123);
  for (int trial = 0; trial < 3000; ++trial) {
    Bytes b(rng.below(700));
    for (auto& x : b) x = static_cast<std::uint8_t>(rng.next());
    for (int dim : {2, 3}) {
      const DecodedInput a = decode_points(b, dim), again = decode_points(b, dim);
      REQUIRE(a.points.dimension == dim);
      REQUIRE(a.points.size() <= kMaxPoints);
      CHECK(a.points.p2 == again.points.p2);
      CHECK(a.points.p3 == again.points.p3);
      CHECK(a.order == again.order);
      for (const auto& p : a.points.p2)
        for (double c : p) REQUIRE(std::isfinite(c));
      for (const auto& p : a.points.p3)
        for (double c : p) REQUIRE(std::isfinite(c));
    }
  }
  CHECK(decode_points({}, 2).points.size() == 0);
  CHECK_THROWS_AS(decode_points({}, 4), std::invalid_argument);
}
