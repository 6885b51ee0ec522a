// The kernel concepts: what an algorithm may ask about points.
//
// Sign conventions are Shewchuk's ("Adaptive Precision Floating-Point Arithmetic
// and Fast Robust Geometric Predicates", 1997), exactly:
//   orient2d(a,b,c)     = sign det[a-c; b-c]                 > 0: a,b,c counterclockwise
//   incircle(a,b,c,d)   = sign det[(a-d,|a-d|^2); ...]       > 0: d inside circle abc (abc ccw)
//   orient3d(a,b,c,d)   = sign det[a-d; b-d; c-d]            > 0: d below plane abc seen ccw from above
//   insphere(a,b,c,d,e) = sign det[(a-e,|a-e|^2); ...]       > 0: e inside sphere abcd if orient3d(a,b,c,d) > 0
// Note: CGAL's orientation(p,q,r,s) in 3D is the opposite sign of orient3d, and
// CGAL's side_of_oriented_sphere is the opposite sign of insphere.
//
// A kernel is a small copyable object (it may carry state: a grid, counters).
// `K::exact` says whether every answer is the exact sign for the points the
// kernel works on (for the integer kernel: the snapped points).
#pragma once
#include <concepts>
#include <span>
#include <string_view>
#include <vector>

#include "predicates/point.hpp"
#include "predicates/sign.hpp"

namespace dlab {

template <class K>
concept KernelBase = std::copy_constructible<K> && requires {
  { K::exact } -> std::convertible_to<bool>;
  { K::name } -> std::convertible_to<std::string_view>;
};

template <class K>
concept Kernel2 = KernelBase<K> && requires(const K& k, const Point2& p) {
  { k.orient2d(p, p, p) } -> std::same_as<Sign>;
  { k.incircle(p, p, p, p) } -> std::same_as<Sign>;
};

template <class K>
concept Kernel3 = KernelBase<K> && requires(const K& k, const Point3& p) {
  { k.orient3d(p, p, p, p) } -> std::same_as<Sign>;
  { k.insphere(p, p, p, p, p) } -> std::same_as<Sign>;
};

template <class K, int D>
concept KernelFor = (D == 2 && Kernel2<K>) || (D == 3 && Kernel3<K>);

// A kernel that moves points (the integer kernel snaps them to its grid)
// says so; the driver then triangulates the moved points.
template <class K, int D>
concept SnappingKernel = requires(K& k, std::vector<Point<D>>& pts) {
  k.snap_all(pts);
};

// A kernel with a static filter (adaptive: orient3d) can be fitted to the points
// it will be asked about: k.fit_static_filter(points) (predicates/adaptive_kernel.hpp
// says which calls the fitted filter covers). variants/driver.hpp fits it only for
// algorithms that promise to pass the kernel nothing but those points.
template <class K, int D>
concept StaticFilterKernel = requires(K& k, std::span<const Point<D>> pts) {
  k.fit_static_filter(pts);
};

// Staged kernels (adaptive, filtered) can also say which stage answered:
// `k.orient2d_staged(a,b,c)` returns {sign, stage index}; `K::stage_names`
// lists the stages. `counted<K>` uses this when it is present.
struct Staged {
  Sign sign;
  unsigned char stage;
};

}  // namespace dlab
