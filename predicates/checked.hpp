// checked<K1, K2>: asks both kernels every question and records the inputs on
// which they disagree -- the cheapest fuzzing oracle (CGAL's Kernel_checker,
// design.md section 8). Answers are K1's, so an algorithm run on checked<K1,K2>
// behaves exactly as on K1.
//
// The log is shared by all copies (like counted<>): it keeps the number of
// checks and of disagreements and the first `keep` disagreements in full (the
// points as exact doubles, printable as hexadecimal floats for a regression
// test). With `Policy::throw_on_disagreement` the first disagreement throws
// KernelDisagreement instead (after being logged).
// Kernels that move points (the integer kernel snaps) answer for other points:
// compare them on points both see identically (e.g. already snapped).
#pragma once
#include <cstdint>
#include <cstdio>
#include <memory>
#include <stdexcept>
#include <string>
#include <tuple>
#include <type_traits>
#include <vector>

#include "predicates/kernel.hpp"

namespace dlab {

struct Disagreement {
  std::string predicate;        // "orient2d", "incircle", "orient3d", "insphere"
  int dimension = 2;
  std::vector<double> coords;   // the points' coordinates in argument order
  Sign first = Sign::zero, second = Sign::zero;

  // e.g. "incircle 0x1p+0 0x0p+0 ... : -1 vs 0" (the `dlab predicate` argument order).
  std::string describe() const {
    std::string s = predicate;
    char buf[64];
    for (double x : coords) {
      std::snprintf(buf, sizeof buf, " %a", x);
      s += buf;
    }
    std::snprintf(buf, sizeof buf, " : %d vs %d", to_int(first), to_int(second));
    return s + buf;
  }
};

struct KernelDisagreement : std::runtime_error {
  Disagreement what_happened;
  explicit KernelDisagreement(const Disagreement& d)
      : std::runtime_error("kernels disagree: " + d.describe()), what_happened(d) {}
};

struct DisagreementLog {
  std::uint64_t checks = 0;
  std::uint64_t disagreements = 0;
  std::size_t keep = 1000;  // at most this many kept in full
  std::vector<Disagreement> kept;
};

template <class K1, class K2>
struct checked {
  enum class Policy { record, throw_on_disagreement };

  static constexpr bool exact = K1::exact;
  static constexpr std::string_view name = K1::name;

  K1 first{};
  K2 second{};
  Policy policy = Policy::record;
  std::shared_ptr<DisagreementLog> log = std::make_shared<DisagreementLog>();

  checked() = default;
  checked(const K1& k1, const K2& k2, Policy p = Policy::record)
      : first(k1), second(k2), policy(p) {}

  Sign orient2d(const Point2& a, const Point2& b, const Point2& c) const
    requires Kernel2<K1> && Kernel2<K2>
  {
    return compare("orient2d", first.orient2d(a, b, c), second.orient2d(a, b, c), a, b, c);
  }
  Sign incircle(const Point2& a, const Point2& b, const Point2& c, const Point2& d) const
    requires Kernel2<K1> && Kernel2<K2>
  {
    return compare("incircle", first.incircle(a, b, c, d), second.incircle(a, b, c, d), a, b, c,
                   d);
  }
  Sign orient3d(const Point3& a, const Point3& b, const Point3& c, const Point3& d) const
    requires Kernel3<K1> && Kernel3<K2>
  {
    return compare("orient3d", first.orient3d(a, b, c, d), second.orient3d(a, b, c, d), a, b, c,
                   d);
  }
  Sign insphere(const Point3& a, const Point3& b, const Point3& c, const Point3& d,
                const Point3& e) const
    requires Kernel3<K1> && Kernel3<K2>
  {
    return compare("insphere", first.insphere(a, b, c, d, e), second.insphere(a, b, c, d, e), a,
                   b, c, d, e);
  }

  std::uint64_t disagreements() const { return log->disagreements; }
  std::uint64_t checks() const { return log->checks; }

 private:
  template <class... P>
  Sign compare(const char* predicate, Sign s1, Sign s2, const P&... pts) const {
    ++log->checks;
    if (s1 != s2) [[unlikely]] {
      ++log->disagreements;
      Disagreement d;
      d.predicate = predicate;
      d.dimension = static_cast<int>(std::tuple_size_v<std::common_type_t<P...>>);
      (d.coords.insert(d.coords.end(), pts.begin(), pts.end()), ...);
      d.first = s1;
      d.second = s2;
      if (log->kept.size() < log->keep) log->kept.push_back(d);
      if (policy == Policy::throw_on_disagreement) throw KernelDisagreement(d);
    }
    return s1;
  }
};

}  // namespace dlab
