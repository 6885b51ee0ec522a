// The INPUT / SIMPLICES readers and the number formats of the `dlab` command:
// every bad-input path names the file, the line and the problem; hex and
// decimal floats parse exactly (checked against glibc's strtod and printf
// "%a", which are independent implementations); arbitrary bytes never crash.
#include <catch2/catch.hpp>
#include <rapidcheck/catch.h>

#include <bit>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <sstream>
#include <string>
#include <utility>

#include "cli/numbers.hpp"
#include "cli/point_reader.hpp"
#include "cli/point_writer.hpp"
#include "cli/simplex_io.hpp"
#include "cli/stats_json.hpp"

using namespace dlab;
using namespace dlab::io;

namespace {

bool same_bits(double a, double b) { return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b); }

double parsed(const std::string& s) {
  const ParsedDouble p = parse_double(s);
  REQUIRE(p.status == ParseStatus::ok);
  return p.value;
}

// The InputError message of parsing `text`, or "" if it parsed.
std::string error_of(const std::string& text, bool node = false, const std::string& name = "in.txt") {
  try {
    parse_points(text, name, node);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

double random_double(rc::Gen<std::uint64_t> g = rc::gen::arbitrary<std::uint64_t>()) {
  for (;;) {
    const double x = std::bit_cast<double>(*g);
    if (std::isfinite(x)) return x;
  }
}


// Decimal digit strings of big non-negative integers (most significant first),
// for literals that sit exactly on a rounding boundary.
std::string times(const std::string& a, int k) {
  std::string r(a.size(), '0');
  int carry = 0;
  for (std::size_t i = a.size(); i-- > 0;) {
    const int d = (a[i] - '0') * k + carry;
    r[i] = static_cast<char>('0' + d % 10);
    carry = d / 10;
  }
  for (; carry; carry /= 10) r.insert(r.begin(), static_cast<char>('0' + carry % 10));
  return r;
}
std::string power(int base, int n) {
  std::string r = "1";
  while (n-- > 0) r = times(r, base);
  return r;
}
std::string minus(std::string a, const std::string& b) {  // a >= b
  int borrow = 0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    const std::size_t ia = a.size() - 1 - i;
    int d = (a[ia] - '0') - borrow - (i < b.size() ? b[b.size() - 1 - i] - '0' : 0);
    borrow = d < 0;
    a[ia] = static_cast<char>('0' + (d + 10 * borrow));
  }
  const std::size_t nz = a.find_first_not_of('0');
  return nz == std::string::npos ? "0" : a.substr(nz);
}

// parse_double against glibc's strtod on the same text: the same double, or
// the refusal that strtod's infinity calls for (an overflow) or its zero
// from a literal that is not zero (an underflow).
void agrees_with_strtod(const std::string& text, bool nonzero_literal) {
  const double reference = std::strtod(text.c_str(), nullptr);
  const ParsedDouble p = parse_double(text);
  if (std::isinf(reference)) {
    RC_ASSERT(p.status == ParseStatus::out_of_range);
  } else if (reference == 0 && nonzero_literal) {
    RC_ASSERT(p.status == ParseStatus::underflow);
  } else {
    RC_ASSERT(p.status == ParseStatus::ok);
    RC_ASSERT(same_bits(p.value, reference));
  }
}

}  // namespace

TEST_CASE("parse_double reads decimal and C99 hexadecimal floats exactly", "[io]") {
  CHECK(parsed("0x1.8p-3") == 0.1875);
  CHECK(parsed("0X1P4") == 16);
  CHECK(parsed("-0x.8p1") == -1);
  CHECK(parsed("+0x10") == 16);
  CHECK(parsed("0x1.fffffffffffffp+1023") == std::numeric_limits<double>::max());
  CHECK(parsed("0x0.0000000000001p-1022") == std::numeric_limits<double>::denorm_min());
  CHECK(parsed("0x1p-1074") == std::numeric_limits<double>::denorm_min());
  CHECK(parsed("1.5") == 1.5);
  CHECK(parsed("+.5") == 0.5);
  CHECK(parsed("7.") == 7);
  CHECK(parsed("1e3") == 1000);
  CHECK(parsed("-2.5E-1") == -0.25);
  CHECK(parsed("0.1") == 0.1);
  CHECK(parsed("4e-324") == std::numeric_limits<double>::denorm_min());
  // Subnormal results are kept, correctly rounded.
  CHECK(parsed("0x1.8p-1074") == 2 * std::numeric_limits<double>::denorm_min());  // tie, to even
  CHECK(parsed("0x1.0000000000001p-1075") == std::numeric_limits<double>::denorm_min());
  CHECK(parsed("2.4703282292062328e-324") == std::numeric_limits<double>::denorm_min());
  // Zero literals give a signed zero, whatever their exponent.
  CHECK(same_bits(parsed("-0"), -0.0));
  CHECK(same_bits(parsed("0e99999"), 0.0));
  CHECK(same_bits(parsed("-0.000e-99999"), -0.0));
  CHECK(same_bits(parsed("-0x0.000p+99999"), -0.0));
}

TEST_CASE("parse_double's shortcut for normalised hex floats agrees with strtod", "[io][rc]") {
  // parse_double assembles "1.hhh...pE" (at most 13 digits, E in [-1022, 1023])
  // from its bits; strtod is the independent reference, on that form and
  // around each of its limits (digit count, exponent range and width, case).
  rc::prop("a mantissa of 0 to 14 digits and an exponent around the normal range", [] {
    const int digits = *rc::gen::inRange(0, 15);
    std::string t = *rc::gen::element(std::string("0x1"), std::string("0X1"), std::string("-0x1"),
                                      std::string("+0x1"));
    if (digits > 0 || *rc::gen::arbitrary<bool>()) t += '.';
    for (int d = 0; d < digits; ++d) t += "0123456789abcdefABCDEF"[*rc::gen::inRange(0, 22)];
    const int e = *rc::gen::element(-1075, -1074, -1023, -1022, -1021, -1, 0, 1, 1022, 1023, 1024,
                                    *rc::gen::inRange(-1100, 1100));
    t += *rc::gen::element('p', 'P');
    t += e < 0 ? "-" : *rc::gen::element(std::string("+"), std::string(""));
    t += *rc::gen::element(std::string(""), std::string("0")) + std::to_string(e < 0 ? -e : e);
    RC_TAG(digits > 13 ? "digits > 13" : "digits <= 13");
    agrees_with_strtod(t, true);  // a leading 1
  });
  // Every digit character at every fraction position.
  for (const char c : std::string("0123456789abcdefABCDEF"))
    for (int position = 0; position < 13; ++position) {
      const std::string t = "0x1." + std::string(static_cast<std::size_t>(position), '0') + c + "p-7";
      INFO(t);
      CHECK(same_bits(parsed(t), std::strtod(t.c_str(), nullptr)));
    }
}

TEST_CASE("read_normalised_hex reads exactly the normalised form, and stops where it ends", "[io]") {
  // {text, whether it is the normalised form}: each limit of the form, on both sides.
  const std::pair<const char*, bool> cases[] = {
      {"0x1p0", true},          {"-0X1P+0", true},         {"+0x1.p-1", true},
      {"0x1.fffffffffffffp1023", true},                    {"0x1.0000000000001p-1022", true},
      {"0x1.00000000000001p0", false},  // 14 fraction digits
      {"0x1p1024", false},      {"0x1p-1023", false},      // out of the normal range
      {"0x1p0001", true},       {"0x1p00001", false},      // 4, 5 exponent digits
      {"0x1p", false},          {"0x1p-", false},          {"0x1.8", false},  // no exponent
      {"0x2p0", false},         {"0x0.8p1", false},        {"1p0", false},    // not 0x1
      {"0x", false},            {"", false},               {"-", false}};
  for (const auto& [text, normalised] : cases)
    for (const std::string tail : {"", " 1", ",", "#c", "\t", "x", "g"}) {
      const std::string t = std::string(text) + tail;
      INFO(t);
      double v = -1;
      const char* end = read_normalised_hex(t.data(), t.data() + t.size(), v);
      if (!normalised) {
        CHECK(end == nullptr);
        continue;
      }
      REQUIRE(end == t.data() + std::strlen(text));
      CHECK(same_bits(v, std::strtod(text, nullptr)));
    }
}

TEST_CASE("a nonzero literal that rounds to zero is rejected as an overflow is", "[io]") {
  for (const char* tiny : {"1e-400", "-1e-400", "0x1p-1075", "-0x1p-1075", "0x1p-1076", "0x.8p-1074",
                           "-2.4703282292062327e-324", "0.00000000000000000000000001e-300",
                           "1e-99999", "0x0.0000000000000000001p-1022", "-0x0.00Ep-1070"}) {
    INFO(tiny);
    CHECK(parse_double(tiny).status == ParseStatus::underflow);
  }
  CHECK_THAT(describe(ParseStatus::underflow, "1e-400"),
             Catch::Equals("coordinate '1e-400' is not zero but rounds to zero (|x| <= 2^-1075)"));
  CHECK_THAT(error_of("1 2\n3 -0x1p-1080\n"),
             Catch::Contains("in.txt:2: coordinate '-0x1p-1080' is not zero but rounds to zero"));
}

TEST_CASE("parse_double classifies what it rejects", "[io]") {
  CHECK(parse_double("nan").status == ParseStatus::nan);
  CHECK(parse_double("-NaN").status == ParseStatus::nan);
  CHECK(parse_double("inf").status == ParseStatus::infinity);
  CHECK(parse_double("-Infinity").status == ParseStatus::infinity);
  CHECK(parse_double("1e400").status == ParseStatus::out_of_range);
  CHECK(parse_double("-0x1p1024").status == ParseStatus::out_of_range);
  for (const char* bad : {"", "+", "-", "--1", "+-1", "1.5.5", "1e", "1e+", "0x", "0xp1", "0x1p",
                          "1.8p-3", "0x-1", "0x+1", "0xinf", "1_000", "0x1.8p-3x", ".", "e5",
                          "1,5", "abc", "1 2", "0b101", "\x01", "1\xff"})
    CHECK(parse_double(bad).status == ParseStatus::malformed);
}

TEST_CASE("parse_double agrees with glibc strtod on random decimal and hex strings", "[io]") {
  rc::prop("decimal", [] {
    const double x = random_double();
    const int digits = *rc::gen::inRange(1, 25);
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.*e", digits, x);  // not necessarily the exact value
    agrees_with_strtod(buf, x != 0);
  });
  rc::prop("format_hex equals printf %a and reads back exactly", [] {
    const double x = random_double();
    char buf[64];
    std::snprintf(buf, sizeof buf, "%a", x);
    RC_ASSERT(format_hex(x) == std::string(buf));
    RC_ASSERT(same_bits(parsed(format_hex(x)), x));
    RC_ASSERT(same_bits(parsed(format_decimal(x)), x));
  });
}

TEST_CASE("parse_double on rounding boundaries agrees with strtod and with the exact values", "[io]") {
  constexpr double tiny = std::numeric_limits<double>::denorm_min();
  constexpr double big = std::numeric_limits<double>::max();
  const double inf = std::numeric_limits<double>::infinity();
  // Exact decimal literals: 2^-1075 = 5^1075 e-1075 (half the smallest
  // subnormal) and 2^1024 - 2^970 (halfway from the largest double to 2^1024).
  const std::string half_tiny = power(5, 1075);
  const std::string half_over = minus(power(2, 1024), power(2, 970));
  struct Edge {
    std::string literal;
    double exact;  // the correctly rounded value (infinity: overflow; 0 from a nonzero literal: underflow)
  };
  const std::vector<Edge> edges{
      {half_tiny + "e-1075", 0},                                 // tie, to even: 0
      {"-" + half_tiny + "e-1075", -0.0},
      {minus(half_tiny, "1") + "e-1075", 0},                     // below the tie
      {half_tiny + "1e-1076", tiny},                             // above the tie
      {times(half_tiny, 3) + "e-1075", 2 * tiny},                // 1.5 ulp: tie, to even
      {half_over, inf},                                          // tie, to even: 2^1024
      {minus(half_over, "1"), big},
      {"-" + minus(half_over, "1") + ".99999999999999999999", -big},
      {"1.7976931348623157e308", big},
      {"1.7976931348623159e308", inf},
      {"9007199254740993", 9007199254740992.0},                  // 2^53 + 1: tie, to even
      {"9007199254740993.00000000000000000000000001", 9007199254740994.0},
      {"9007199254740995", 9007199254740996.0},                  // 2^53 + 3: tie, to even
      {"9007199254740991", 9007199254740991.0},                  // 2^53 - 1: exact
      {"0.1", 0.1},
      {"0.1000000000000000055511151231257827021181583404541015625", 0.1},  // 0.1's exact value
      {"2.2250738585072011e-308", 0x0.fffffffffffffp-1022},      // largest subnormal
      {"2.2250738585072014e-308", 0x1p-1022},                    // smallest normal
      {"0x1.00000000000008p0", 1.0},                             // hex tie, to even
      {"0x1.00000000000018p0", 0x1.0000000000002p0},
      {"0x1.000000000000080000000001p0", 0x1.0000000000001p0},
      {"0x1.fffffffffffff8p1023", inf},
      {"0x1.fffffffffffff7ffffp1023", big},
      {"0x1p-1075", 0},
      {"0x1.0000000000001p-1075", tiny},
      {"0x3p-1076", tiny},                                       // 0.75 ulp
  };
  for (const Edge& e : edges) {
    INFO(e.literal.substr(0, 60) << " (" << e.literal.size() << " characters)");
    const ParsedDouble p = parse_double(e.literal);
    const double ref = std::strtod(e.literal.c_str(), nullptr);
    CHECK(same_bits(ref, e.exact));  // glibc agrees with the exact value ...
    if (std::isinf(e.exact)) {       // ... and so do we
      CHECK(p.status == ParseStatus::out_of_range);
    } else if (e.exact == 0) {
      CHECK(p.status == ParseStatus::underflow);
    } else {
      REQUIRE(p.status == ParseStatus::ok);
      CHECK(same_bits(p.value, e.exact));
    }
  }
}

TEST_CASE("format_decimal: the shortest decimal, read back bit for bit", "[io]") {
  // Expected strings: the shortest decimals that round to each value (known
  // values of IEEE binary64), in std::to_chars's plain or scientific form.
  const std::pair<double, const char*> cases[] = {
      {0.1, "0.1"},
      {-0.0, "-0"},
      {0.0, "0"},
      {std::numeric_limits<double>::denorm_min(), "5e-324"},
      {-2 * std::numeric_limits<double>::denorm_min(), "-1e-323"},
      {0x0.fffffffffffffp-1022, "2.225073858507201e-308"},
      {0x1p-1022, "2.2250738585072014e-308"},
      {std::numeric_limits<double>::max(), "1.7976931348623157e+308"},
      {-std::numeric_limits<double>::max(), "-1.7976931348623157e+308"},
      {9007199254740992.0, "9007199254740992"},  // 2^53
      {9007199254740994.0, "9007199254740994"},  // 2^53 + 2, the next double
      {9007199254740991.0, "9007199254740991"},  // 2^53 - 1, the previous one
      {0.30000000000000004, "0.30000000000000004"},
  };
  for (const auto& [x, text] : cases) {
    INFO(text);
    CHECK(format_decimal(x) == text);
    CHECK(same_bits(parsed(format_decimal(x)), x));
  }
}

TEST_CASE("format_hex on the special cases", "[io]") {
  CHECK(format_hex(0.0) == "0x0p+0");
  CHECK(format_hex(-0.0) == "-0x0p+0");
  CHECK(format_hex(0.1875) == "0x1.8p-3");
  CHECK(format_hex(std::numeric_limits<double>::denorm_min()) == "0x0.0000000000001p-1022");
  CHECK(format_hex(-std::numeric_limits<double>::max()) == "-0x1.fffffffffffffp+1023");
}

TEST_CASE("plain INPUT: blanks, commas, comments, blank lines, CRLF, hex", "[io]") {
  const PointSet ps = parse_points("# header\n\n 1 2\n3,4  # trailing comment\r\n0x1.8p-3 , -5e-1,\n\t\n", "f", false);
  REQUIRE(ps.dimension == 2);
  REQUIRE(ps.p2.size() == 3);
  CHECK(ps.p2[0] == Point2{1, 2});
  CHECK(ps.p2[1] == Point2{3, 4});
  CHECK(ps.p2[2] == Point2{0.1875, -0.5});
  const PointSet p3 = parse_points("1 2 3\n4 5 6", "f", false);  // no final newline
  REQUIRE(p3.dimension == 3);
  REQUIRE(p3.p3.size() == 2);
  CHECK(p3.p3[1] == Point3{4, 5, 6});
}

TEST_CASE("plain INPUT: the one-pass path for hex lines reads and refuses as the general one", "[io]") {
  // From the second data line on, lines of normalised hex floats skip the
  // tokens; everything else falls back to them, with the same messages.
  const PointSet ps = parse_points("0x1p0 0x1p1\n0x1p2,0x1p3 # c\n\t0x1p4\t-0x1p5,\n0x1.00000000000001p0 0x1p0\n",
                                   "f", false);
  REQUIRE(ps.p2.size() == 4);
  CHECK(ps.p2[1] == Point2{4, 8});
  CHECK(ps.p2[2] == Point2{16, -32});
  CHECK(same_bits(ps.p2[3][0], std::strtod("0x1.00000000000001p0", nullptr)));  // 14 digits: rounded
  const PointSet p3 = parse_points("1 2 3\n0x1p-3 0x1.8p0 -0x1p1\n", "f", false);
  REQUIRE(p3.p3.size() == 2);
  CHECK(p3.p3[1] == Point3{0.125, 1.5, -2});
  CHECK_THAT(error_of("0x1p0 0x1p1\n0x1p2 0x1p3x\n"), Catch::Contains("in.txt:2: unparsable number '0x1p3x'"));
  CHECK_THAT(error_of("0x1p0 0x1p1\n0x1p2 0x1p3,x\n"), Catch::Contains("in.txt:2: wrong number of coordinates"));
  CHECK_THAT(error_of("0x1p0 0x1p1\n0x1p2-0x1p3\n"), Catch::Contains("in.txt:2: wrong number of coordinates: expected 2 (as on line 1), found 1"));
  CHECK_THAT(error_of("0x1p0 0x1p1\n0x1p2#0x1p3\n"),
             Catch::Contains("in.txt:2: wrong number of coordinates: expected 2 (as on line 1), found 1"));
  CHECK_THAT(error_of("0x1p0 0x1p1\n\n0x1p2 0x1p3 0x1p4\n"),
             Catch::Contains("in.txt:3: wrong number of coordinates: expected 2 (as on line 1), found 3"));
  CHECK_THAT(error_of("0x1p0 0x1p1\n0x1p2 0x1p99999\n"), Catch::Contains("in.txt:2: coordinate '0x1p99999' overflows"));
}

TEST_CASE("plain INPUT errors name the file, the line and the problem", "[io]") {
  CHECK_THAT(error_of("1 2\n3 4\nnan 5\n"), Catch::Contains("in.txt:3: NaN coordinate 'nan'"));
  CHECK_THAT(error_of("1 2\n-inf 5\n"), Catch::Contains("in.txt:2: infinite coordinate '-inf'"));
  CHECK_THAT(error_of("1 2\n1e999 5\n"), Catch::Contains("in.txt:2: coordinate '1e999' overflows"));
  CHECK_THAT(error_of("1 2\n\n# c\n3 4 5\n"),
             Catch::Contains("in.txt:4: wrong number of coordinates: expected 2 (as on line 1), found 3"));
  CHECK_THAT(error_of("1 2 3\n4 5\n"), Catch::Contains("in.txt:2: wrong number of coordinates: expected 3"));
  CHECK_THAT(error_of("# only a comment\n1 2 3 4\n"),
             Catch::Contains("in.txt:2: expected 2 or 3 coordinates per point, found 4"));
  CHECK_THAT(error_of("7\n"), Catch::Contains("in.txt:1: expected 2 or 3 coordinates per point, found 1"));
  CHECK_THAT(error_of("1 2\n3 x4\n"), Catch::Contains("in.txt:2: unparsable number 'x4'"));
  CHECK_THAT(error_of("1 2\n3 4\x01\n"), Catch::Contains("in.txt:2: unparsable number '4\\x01'"));
  CHECK_THAT(error_of(""), Catch::Contains("in.txt:1: empty input"));
  CHECK_THAT(error_of("# nothing\n\n   \n"), Catch::Contains("in.txt:3: empty input"));
}

namespace {
// An input stream of `head`, then `long_bytes` bytes of "1 ", then "\n" and
// `tail`, generated on the fly; counts the bytes the reader pulled from it.
class LongLineBuf : public std::streambuf {
 public:
  LongLineBuf(std::string head, std::size_t long_bytes, std::string tail)
      : head_(std::move(head)), tail_("\n" + std::move(tail)), long_(long_bytes) {}
  std::size_t served() const { return served_; }

 protected:
  int_type underflow() override {
    chunk_.clear();
    const std::size_t total = head_.size() + long_ + tail_.size();
    for (; pos_ < total && chunk_.size() < 4096; ++pos_) {
      if (pos_ < head_.size()) chunk_ += head_[pos_];
      else if (pos_ < head_.size() + long_) chunk_ += (pos_ - head_.size()) % 2 ? ' ' : '1';
      else chunk_ += tail_[pos_ - head_.size() - long_];
    }
    if (chunk_.empty()) return traits_type::eof();
    served_ += chunk_.size();
    setg(chunk_.data(), chunk_.data(), chunk_.data() + chunk_.size());
    return traits_type::to_int_type(chunk_[0]);
  }

 private:
  std::string head_, tail_, chunk_;
  std::size_t long_, pos_ = 0, served_ = 0;
};

// A plain-text line of exactly `bytes` bytes holding the point (1, 2).
std::string padded_line(std::size_t bytes) { return "1" + std::string(bytes - 2, ' ') + "2"; }
}  // namespace

TEST_CASE("a line longer than kMaxLineBytes is refused before more of it is read", "[io]") {
  // An 8 MiB line (a 200 MB one behaves alike: the reader stops at the limit).
  LongLineBuf buf("0 0\n# comment\n", 8 * kMaxLineBytes, "1 1\n");
  std::istream in(&buf);
  try {
    read_points(in, "long.txt", false);
    FAIL("no error");
  } catch (const InputError& e) {
    CHECK_THAT(e.what(), Catch::Equals("long.txt:3: line longer than 1048576 bytes (a point needs a few "
                                       "dozen): not a point set?"));
  }
  // The limit plus the chunks in flight (64 KiB each), not the whole line.
  CHECK(buf.served() <= kMaxLineBytes + (std::size_t{1} << 18));
  // The same line in memory.
  const std::string text = "0 0\n" + std::string(kMaxLineBytes + 1, ' ') + "\n";
  CHECK_THAT(error_of(text), Catch::StartsWith("in.txt:2: line longer than 1048576 bytes"));
}

TEST_CASE("a line of exactly kMaxLineBytes is read, from memory and from a stream", "[io]") {
  for (const std::size_t bytes : {kMaxLineBytes, kMaxLineBytes + 1}) {
    const std::string text = "0 0\n" + padded_line(bytes) + "\n3 4";
    std::istringstream in(text);
    INFO(bytes);
    if (bytes <= kMaxLineBytes) {
      for (const PointSet& ps : {parse_points(text, "t", false), read_points(in, "t", false)}) {
        REQUIRE(ps.p2.size() == 3);
        CHECK(ps.p2[1] == Point2{1, 2});
        CHECK(ps.p2[2] == Point2{3, 4});
      }
    } else {
      CHECK_THROWS_WITH(parse_points(text, "t", false), Catch::StartsWith("t:2: line longer than"));
      CHECK_THROWS_WITH(read_points(in, "t", false), Catch::StartsWith("t:2: line longer than"));
    }
  }
}

TEST_CASE("reading a stream in chunks gives what parsing the text gives", "[io]") {
  rc::prop("lines across chunk boundaries", [] {
    // Lines of random length (some far longer than a point) so that they
    // straddle the reader's 64 KiB chunks at every offset.
    const int n = *rc::gen::inRange(1, 400);
    std::string text;
    for (int i = 0; i < n; ++i) {
      text += format_hex(random_double()) + std::string(*rc::gen::inRange(1, 3000), ' ') +
              format_decimal(random_double());
      if (*rc::gen::arbitrary<bool>()) text += " # " + std::string(*rc::gen::inRange(0, 500), 'c');
      if (i + 1 < n || *rc::gen::arbitrary<bool>()) text += *rc::gen::arbitrary<bool>() ? "\r\n" : "\n";
    }
    std::istringstream in(text);
    const PointSet a = parse_points(text, "t", false), b = read_points(in, "t", false);
    RC_ASSERT(a.p2.size() == static_cast<std::size_t>(n));
    RC_ASSERT(b.p2.size() == a.p2.size());
    for (std::size_t i = 0; i < a.p2.size(); ++i)
      for (int j = 0; j < 2; ++j) RC_ASSERT(same_bits(a.p2[i][j], b.p2[i][j]));
  });
}

TEST_CASE("a stream of known size is read into room reserved once, whatever its lines", "[io]") {
  // reserve_for_input: after 1024 points, room for the rest at their bytes per
  // point and a sixteenth (so capacity > size shows the reservation ran: a
  // vector grown by doubling is shrunk to its size); lines that grow or shrink
  // after the sample still read whole.
  auto lines = [](std::size_t n, std::size_t pad) {
    std::string t;
    for (std::size_t i = 0; i < n; ++i) t += std::to_string(i % 10) + std::string(pad, ' ') + "0.5\n";
    return t;
  };
  struct Case { std::string text; std::size_t n; bool reserved_once; };
  const Case cases[] = {{lines(5000, 1), 5000, true},
                        {lines(1024, 1) + lines(4000, 100), 5024, false},    // the guess too large: shrunk
                        {lines(1024, 100) + lines(20000, 1), 21024, false}};  // too small: doubling
  for (const Case& c : cases) {
    std::istringstream in(c.text);
    const PointSet a = read_points(in, "t", false), b = parse_points(c.text, "t", false);
    REQUIRE(a.p2.size() == c.n);
    CHECK(a.p2 == b.p2);
    if (c.reserved_once) {
      CHECK(a.p2.capacity() > c.n);
      CHECK(a.p2.capacity() <= c.n * 17 / 16 + 64 + 1);
    }
    CHECK(a.p2.capacity() - a.p2.size() <= a.p2.size() / 8 + 64);
  }
}

TEST_CASE("unreadable files are reported with their name", "[io]") {
  try {
    read_points("/nonexistent/dir/points.txt");
    FAIL("no error");
  } catch (const InputError& e) {
    CHECK_THAT(e.what(), Catch::StartsWith("/nonexistent/dir/points.txt: cannot read"));
  }
  CHECK_THROWS_WITH(read_points("/"), Catch::StartsWith("/: cannot read: is a directory"));
  CHECK_THROWS_WITH(read_file("/"), Catch::StartsWith("/: cannot read: is a directory"));
}

TEST_CASE(".node files (Triangle / TetGen)", "[io]") {
  CHECK(is_node_file("a/b.node"));
  CHECK(is_node_file("B.NODE"));
  CHECK_FALSE(is_node_file("b.nodes"));
  // Indices from 1, one attribute, boundary markers, comments.
  const PointSet a = parse_points("# Triangle\n4 2 1 1\n1 0 0 9.5 1\n2 1 0 9.5 0\n3 1 1 9.5 -1 # c\n4 0x1p-1 1 0 1\n",
                                  "sq.node", true);
  REQUIRE(a.dimension == 2);
  REQUIRE(a.p2.size() == 4);
  CHECK(a.p2[3] == Point2{0.5, 1});
  // Indices from 0, 3D (TetGen), no attributes or markers.
  const PointSet b = parse_points("2 3 0 0\n0 1 2 3\n1 4 5 6\n", "t.node", true);
  REQUIRE(b.dimension == 3);
  REQUIRE(b.p3.size() == 2);
  CHECK(b.p3[1] == Point3{4, 5, 6});

  const auto err = [](const std::string& t) { return error_of(t, true, "m.node"); };
  CHECK_THAT(err("3 2 0 0\n0 0 0\n1 1 0\n"), Catch::Contains("m.node:3: .node count mismatch: the header (line 1) declares 3 points, found 2"));
  CHECK_THAT(err("1 2 0 0\n0 0 0\n1 1 0\n"), Catch::Contains("m.node:3: .node count mismatch"));
  CHECK_THAT(err("2 4 0 0\n"), Catch::Contains("m.node:1: dimension must be 2 or 3, found 4"));
  CHECK_THAT(err("2 2 0\n"), Catch::Contains("m.node:1: bad .node header"));
  CHECK_THAT(err("x 2 0 0\n"), Catch::Contains("m.node:1: bad .node header: #points"));
  CHECK_THAT(err("2 2 0 2\n"), Catch::Contains("m.node:1: bad .node header: #boundary markers"));
  CHECK_THAT(err("0 2 0 0\n"), Catch::Contains("m.node:1: empty input"));
  CHECK_THAT(err("# nothing\n"), Catch::Contains("m.node:1: empty input"));
  CHECK_THAT(err("2 2 0 0\n0 0 0\n2 1 1\n"), Catch::Contains("m.node:3: point index 2 out of sequence: expected 1"));
  CHECK_THAT(err("2 2 0 0\n5 0 0\n6 1 1\n"), Catch::Contains("m.node:2: the first point index must be 0 or 1"));
  CHECK_THAT(err("2 2 1 0\n0 0 0\n1 1 1\n"), Catch::Contains("m.node:2: wrong number of fields: expected 4"));
  CHECK_THAT(err("1 2 0 0\n0 nan 0\n"), Catch::Contains("m.node:2: NaN coordinate"));
  CHECK_THAT(err("1 2 0 1\n0 1 0 x\n"), Catch::Contains("m.node:2: bad boundary marker 'x'"));
  CHECK_THAT(err("1 2 1 0\n0 1 0 zz\n"), Catch::Contains("m.node:2: attribute: unparsable number 'zz'"));
}

TEST_CASE("arbitrary bytes are parsed or rejected with an InputError, never worse", "[io]") {
  rc::prop("plain and .node", [](const std::string& bytes, bool node) {
    try {
      const PointSet ps = parse_points(bytes, "fuzz", node);
      RC_ASSERT(ps.size() > 0);
      RC_ASSERT((ps.dimension == 2 || ps.dimension == 3));
      for (const auto& p : ps.p2) RC_ASSERT((std::isfinite(p[0]) && std::isfinite(p[1])));
      for (const auto& p : ps.p3)
        RC_ASSERT((std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2])));
    } catch (const InputError& e) {
      RC_ASSERT(std::string(e.what()).rfind("fuzz:", 0) == 0);
    }
  });
  rc::prop("number-like lines", [] {
    const auto tok = rc::gen::element<std::string>("1", "-0x1.8p3", "nan", "1e999", ",", " ", "#", "\n",
                                                   "0x", "2.5e-3", "\r", "inf", "+", ".", "e");
    const auto parts = *rc::gen::container<std::vector<std::string>>(tok);
    std::string text;
    for (const auto& p : parts) text += p;
    try {
      (void)parse_points(text, "fuzz", false);
    } catch (const InputError&) {
    }
  });
}

TEST_CASE("points written as hex or decimal read back bit for bit", "[io]") {
  rc::prop("round trip", [](bool hex) {
    PointSet ps;
    ps.dimension = *rc::gen::element(2, 3);
    const int n = *rc::gen::inRange(1, 20);
    for (int i = 0; i < n; ++i) {
      if (ps.dimension == 2) ps.p2.push_back({random_double(), random_double()});
      else ps.p3.push_back({random_double(), random_double(), random_double()});
    }
    std::ostringstream out;
    write_points(out, ps, hex ? FloatFormat::hex : FloatFormat::decimal);
    const PointSet back = parse_points(out.str(), "rt", false);
    RC_ASSERT(back.dimension == ps.dimension);
    RC_ASSERT(back.size() == ps.size());
    for (std::size_t i = 0; i < ps.p2.size(); ++i)
      for (int j = 0; j < 2; ++j) RC_ASSERT(same_bits(back.p2[i][j], ps.p2[i][j]));
    for (std::size_t i = 0; i < ps.p3.size(); ++i)
      for (int j = 0; j < 3; ++j) RC_ASSERT(same_bits(back.p3[i][j], ps.p3[i][j]));
  });
}

TEST_CASE("SIMPLICES writer: every digit count, and across its buffer", "[io]") {
  // The writer formats indices itself; std::to_string is the reference. Each
  // power of ten and its predecessor, the largest index, and enough simplices
  // (random indices) to flush the 64 KiB buffer many times.
  std::vector<std::uint32_t> s;
  for (std::uint64_t p = 1; p <= 10'000'000'000ull; p *= 10)
    for (const std::uint64_t v : {p - 1, p, p + 1})
      if (v <= 0xFFFFFFFFull) s.push_back(static_cast<std::uint32_t>(v));
  s.push_back(0xFFFFFFFFu);
  std::uint64_t x = 88172645463325252ull;
  while (s.size() < 4 * 40000) {
    x ^= x << 13, x ^= x >> 7, x ^= x << 17;
    s.push_back(static_cast<std::uint32_t>(x >> (x % 32)));  // every length
  }
  for (const int dim : {2, 3}) {
    const std::size_t k = static_cast<std::size_t>(dim) + 1;
    std::string expected;
    for (std::size_t i = 0; i + k <= s.size(); i += k)
      for (std::size_t j = 0; j < k; ++j) expected += std::to_string(s[i + j]) + (j + 1 == k ? "\n" : " ");
    std::ostringstream out;
    write_simplices(out, s, dim);
    CHECK(out.str().size() > 4 * 65536);
    CHECK(out.str() == expected);
  }
}

TEST_CASE("SIMPLICES reader and writer", "[io]") {
  const std::vector<std::uint32_t> s{0, 1, 2, 2, 3, 0};
  std::ostringstream out;
  write_simplices(out, s, 2);
  CHECK(out.str() == "0 1 2\n2 3 0\n");
  CHECK(parse_simplices(out.str(), "t", 2, 4) == s);
  CHECK(parse_simplices("# none\n\n", "t", 3, 4).empty());
  CHECK(parse_simplices("0 1 2 3\n", "t", 3, 4) == std::vector<std::uint32_t>{0, 1, 2, 3});
  const auto err = [](const std::string& text, int dim, std::size_t n) -> std::string {
    try {
      parse_simplices(text, "s.txt", dim, n);
    } catch (const InputError& e) {
      return e.what();
    }
    return "";
  };
  CHECK_THAT(err("0 1 2\n0 1 4\n", 2, 4), Catch::Contains("s.txt:2: vertex index 4 out of range (4 points)"));
  CHECK_THAT(err("0 1\n", 2, 4), Catch::Contains("s.txt:1: expected 3 vertex indices per simplex, found 2"));
  CHECK_THAT(err("0 1 2 3\n", 2, 4), Catch::Contains("s.txt:1: expected 3 vertex indices per simplex, found 4"));
  CHECK_THAT(err("\n0 -1 2\n", 2, 4), Catch::Contains("s.txt:2: bad vertex index '-1'"));
  CHECK_THAT(err("0 1 2.0\n", 2, 4), Catch::Contains("s.txt:1: bad vertex index '2.0'"));
  CHECK_THAT(err("0 1 99999999999999999999999\n", 2, 4), Catch::Contains("s.txt:1: bad vertex index"));
}

TEST_CASE("--stats JSON has the contract's keys in order and escapes strings", "[io]") {
  RunResult res;
  res.dimension = 2;
  res.simplices = {0, 1, 2};
  res.distinct_points = 3;
  res.predicates = {{"orient2d", 5}};
  res.counters = {{"walk_steps", 7}, {"flips", 0}};
  StatsRecord rec;
  rec.input_points = 4;
  rec.result = &res;
  rec.outcome = "ok";
  rec.message = "quote \" backslash \\ newline \n bell \x07";
  std::ostringstream out;
  write_stats_json(out, rec);
  const std::string j = out.str();
  std::size_t at = 0;
  for (const char* key : {"\"algorithm\": \"bowyer-watson\"", "\"kernel\": \"adaptive\"", "\"policy\": \"sos\"",
                          "\"order\": \"brio\"", "\"seed\": 0", "\"dimension\": 2", "\"input_points\": 4",
                          "\"distinct_points\": 3", "\"simplices\": 1", "\"seconds\": 0", "\"cpu_seconds\": 0",
                          "\"phase_seconds\": {", "\"order\": 0", "\"triangulate\": 0", "\"output\": 0",
                          "\"peak_rss_bytes\": 0", "\"predicates\": {", "\"orient2d\": 5",
                          "\"counters\": {", "\"walk_steps\": 7", "\"flips\": 0", "\"snapping\": {}",
                          "\"outcome\": \"ok\"",
                          "\"message\": \"quote \\\" backslash \\\\ newline \\n bell \\u0007\""}) {
    const std::size_t p = j.find(key, at);
    INFO(key);
    REQUIRE(p != std::string::npos);
    at = p;
  }
  CHECK(j.front() == '{');
  CHECK(j.substr(j.size() - 2) == "}\n");
  CHECK(peak_rss_bytes() > 0);
}

TEST_CASE("--stats JSON: doubles as std::to_chars writes them, NaN as null, invalid UTF-8 replaced", "[io]") {
  RunResult res;
  res.dimension = 2;
  res.seconds = std::numeric_limits<double>::quiet_NaN();
  res.snapping = {{"points_moved", 1}};
  // nlohmann's Grisu2 writes this double's last digit as 5; the shortest
  // nearest text, std::to_chars's, ends in 6 (both read back to it).
  res.max_snap_displacement = 1.1240817954901996e-308;
  StatsRecord rec;
  rec.result = &res;
  rec.message = "byte \xff end";
  std::ostringstream out;
  write_stats_json(out, rec);
  const std::string j = out.str();
  CHECK_THAT(j, Catch::Contains("\"seconds\": null,\n"));
  CHECK_THAT(j, Catch::Contains("\"snapping\": {\n    \"points_moved\": 1,\n    \"max_displacement\": 1.1240817954901996e-308\n  },\n"));
  CHECK_THAT(j, Catch::Contains("\"message\": \"byte \xef\xbf\xbd end\"\n}\n"));
}
