// voronoi::round_quotient (voronoi/circumcentre.hpp): num / den * 2^exp2
// rounded once to the nearest double, ties to even. Independent checks: IEEE
// division of two doubles is itself correctly rounded (IEEE 754 §5.4), and
// in the subnormal range hand-computed quotients whose 53-bit rounding would
// land on a tie, so that rounding twice (to 53 bits, then by ldexp to the
// subnormal grid) gives the other neighbour.
#include <catch2/catch.hpp>
#include <rapidcheck.h>
#include <rapidcheck/catch.h>

#include <cmath>
#include <cstdint>
#include <limits>

#include "voronoi/circumcentre.hpp"

namespace {

struct Z {
  mpz_t v;
  Z() { mpz_init(v); }
  explicit Z(double x) { mpz_init_set_d(v, x); }
  ~Z() { mpz_clear(v); }
  Z(const Z&) = delete;
  Z& operator=(const Z&) = delete;
};

double rq(const Z& num, const Z& den, long exp2) { return dlab::voronoi::round_quotient(num.v, den.v, exp2); }

// (a 2^s + b) as an mpz.
void set_shifted(Z& z, long a, unsigned s, long b) {
  mpz_set_si(z.v, a);
  mpz_mul_2exp(z.v, z.v, s);
  if (b >= 0)
    mpz_add_ui(z.v, z.v, static_cast<unsigned long>(b));
  else
    mpz_sub_ui(z.v, z.v, static_cast<unsigned long>(-b));
}

const double kTiny = std::numeric_limits<double>::denorm_min();  // 2^-1074

}  // namespace

TEST_CASE("round_quotient equals IEEE division on integer-valued doubles", "[voronoi]") {
  rc::prop("a / b", [] {
    const auto a = static_cast<double>(*rc::gen::inRange<std::int64_t>(-(std::int64_t{1} << 53), std::int64_t{1} << 53));
    auto b = static_cast<double>(*rc::gen::inRange<std::int64_t>(1, std::int64_t{1} << 53));
    if (*rc::gen::arbitrary<bool>()) b = -b;
    Z na(a), nb(b);
    const double want = a / b;
    const double got = rq(na, nb, 0);
    RC_ASSERT(got == want);
    RC_ASSERT(std::signbit(got) == std::signbit(want) || want == 0);
  });
  Z one(1.0), three(3.0), ten(10.0);
  CHECK(rq(one, three, 0) == 1.0 / 3.0);
  CHECK(rq(one, ten, 0) == 0.1);
  CHECK(rq(one, three, -1000) == std::ldexp(1.0 / 3.0, -1000));  // still normal: scaling is exact
}

TEST_CASE("round_quotient rounds once in the subnormal range", "[voronoi]") {
  Z num, den(1.0);
  // (2.5 + 2^-60) 2^-1074 = (5 2^59 + 1) 2^-1134: just above the tie between
  // 2 and 3 subnormal units -> 3 units. Rounded to 53 bits first, the 2^-60
  // vanishes, the tie remains and goes to even: 2 units.
  set_shifted(num, 5, 59, 1);
  CHECK(rq(num, den, -1134) == 3 * kTiny);
  // (2.5 - 2^-60) units: just below -> 2 units (53 bits first: tie -> 2 as well).
  set_shifted(num, 5, 59, -1);
  CHECK(rq(num, den, -1134) == 2 * kTiny);
  // (4.5 + 2^-60) units: 5 units (twice rounded: the tie goes to even 4).
  set_shifted(num, 9, 59, 1);
  CHECK(rq(num, den, -1134) == 5 * kTiny);
  // Negative: -(2.5 + 2^-60) units -> -3 units.
  set_shifted(num, -5, 59, -1);
  CHECK(rq(num, den, -1134) == -3 * kTiny);
  // Exact ties: 2.5 -> 2, 3.5 -> 4 units; half a unit -> +0 (even), 1.5 -> 2.
  Z two(2.0);
  mpz_set_ui(num.v, 5);
  CHECK(rq(num, two, -1074) == 2 * kTiny);
  mpz_set_ui(num.v, 7);
  CHECK(rq(num, two, -1074) == 4 * kTiny);
  mpz_set_ui(num.v, 1);
  const double half = rq(num, two, -1074);
  CHECK(half == 0.0);
  CHECK_FALSE(std::signbit(half));
  mpz_set_ui(num.v, 3);
  CHECK(rq(num, two, -1074) == 2 * kTiny);
  // Not dyadic: 2/3 unit -> 1 unit; 1/3 unit -> 0; (2^52 - 1/3) units, the
  // top of the subnormal range -> 2^52 units = the smallest normal 2^-1022.
  Z three(3.0);
  mpz_set_ui(num.v, 2);
  CHECK(rq(num, three, -1074) == kTiny);
  mpz_set_ui(num.v, 1);
  CHECK(rq(num, three, -1074) == 0.0);
  set_shifted(num, 3, 52, -1);
  CHECK(rq(num, three, -1074) == std::numeric_limits<double>::min());
  // Beyond the largest double: infinity; just below its rounding boundary
  // (2^1024 - 2^970, the midpoint to 2^1024): the largest double.
  set_shifted(num, 1, 54, -2);  // (2^54 - 2) 2^970 = 2^1024 - 2^971
  CHECK(rq(num, den, 970) == std::numeric_limits<double>::max());
  set_shifted(num, 1, 54, -1);  // 2^1024 - 2^970: a tie with 2^1024, odd -> up: infinity
  CHECK(std::isinf(rq(num, den, 970)));
}
