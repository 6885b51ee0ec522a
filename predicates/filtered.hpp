// filtered<Fast, Exact>: ask Fast first; when it cannot decide, ask Exact.
// One generic wrapper, in the spirit of CGAL's Filtered_predicate (design.md
// section 8): the only thing each predicate adds is which member to call.
//
// The filter interface: Fast answers each predicate with std::optional<Sign>,
// std::nullopt meaning "cannot decide" (e.g. FloatFilter, predicates/float_filter.hpp).
// A Fast answer must be the exact sign whenever it is given; the combination
// is then exactly as exact as Exact. A predicate Fast does not provide goes
// straight to Exact.
// Stages (for counted<>): 0 "filter", 1 "exact".
#pragma once
#include <array>
#include <optional>
#include <string_view>

#include "predicates/kernel.hpp"

namespace dlab {

template <class Fast, class Exact>
struct filtered {
  static constexpr bool exact = Exact::exact;
  static constexpr std::string_view name = Exact::name;  // it answers as Exact does
  static constexpr std::array<std::string_view, 2> stage_names{"filter", "exact"};

  Fast fast{};
  Exact fallback{};

  filtered() = default;
  filtered(const Fast& f, const Exact& e) : fast(f), fallback(e) {}

  Staged orient2d_staged(const Point2& a, const Point2& b, const Point2& c) const
    requires Kernel2<Exact>
  {
    if constexpr (requires { fast.orient2d(a, b, c); })
      return decide([&] { return fast.orient2d(a, b, c); }, [&] { return fallback.orient2d(a, b, c); });
    else
      return {fallback.orient2d(a, b, c), 1};
  }
  Staged incircle_staged(const Point2& a, const Point2& b, const Point2& c, const Point2& d) const
    requires Kernel2<Exact>
  {
    if constexpr (requires { fast.incircle(a, b, c, d); })
      return decide([&] { return fast.incircle(a, b, c, d); },
                    [&] { return fallback.incircle(a, b, c, d); });
    else
      return {fallback.incircle(a, b, c, d), 1};
  }
  Staged orient3d_staged(const Point3& a, const Point3& b, const Point3& c, const Point3& d) const
    requires Kernel3<Exact>
  {
    if constexpr (requires { fast.orient3d(a, b, c, d); })
      return decide([&] { return fast.orient3d(a, b, c, d); },
                    [&] { return fallback.orient3d(a, b, c, d); });
    else
      return {fallback.orient3d(a, b, c, d), 1};
  }
  Staged insphere_staged(const Point3& a, const Point3& b, const Point3& c, const Point3& d,
                         const Point3& e) const
    requires Kernel3<Exact>
  {
    if constexpr (requires { fast.insphere(a, b, c, d, e); })
      return decide([&] { return fast.insphere(a, b, c, d, e); },
                    [&] { return fallback.insphere(a, b, c, d, e); });
    else
      return {fallback.insphere(a, b, c, d, e), 1};
  }

  Sign orient2d(const Point2& a, const Point2& b, const Point2& c) const
    requires Kernel2<Exact>
  {
    return orient2d_staged(a, b, c).sign;
  }
  Sign incircle(const Point2& a, const Point2& b, const Point2& c, const Point2& d) const
    requires Kernel2<Exact>
  {
    return incircle_staged(a, b, c, d).sign;
  }
  Sign orient3d(const Point3& a, const Point3& b, const Point3& c, const Point3& d) const
    requires Kernel3<Exact>
  {
    return orient3d_staged(a, b, c, d).sign;
  }
  Sign insphere(const Point3& a, const Point3& b, const Point3& c, const Point3& d,
                const Point3& e) const
    requires Kernel3<Exact>
  {
    return insphere_staged(a, b, c, d, e).sign;
  }

 private:
  template <class F, class E>
  static Staged decide(F&& filter, E&& exact_answer) {
    if (const std::optional<Sign> s = filter()) return {*s, 0};
    return {exact_answer(), 1};
  }
};

}  // namespace dlab
