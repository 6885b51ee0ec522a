// Compile-time detection of the staged kernel interface (predicates/kernel.hpp:
// `k.orient2d_staged(...)` -> Staged and a static `K::stage_names`), shared by
// the combinators filtered<>, perturbed<> and counted<>.
// A kernel without stages is seen as having one stage, named after the kernel.
#pragma once
#include <array>
#include <cstddef>
#include <iterator>
#include <string_view>

#include "predicates/kernel.hpp"

namespace dlab {

template <class K>
concept HasStageNames = requires { std::size(K::stage_names); K::stage_names[0]; };

template <class K>
concept StagedOrient2d = HasStageNames<K> && requires(const K& k, const Point2& p) {
  { k.orient2d_staged(p, p, p) } -> std::same_as<Staged>;
};
template <class K>
concept StagedIncircle = HasStageNames<K> && requires(const K& k, const Point2& p) {
  { k.incircle_staged(p, p, p, p) } -> std::same_as<Staged>;
};
template <class K>
concept StagedOrient3d = HasStageNames<K> && requires(const K& k, const Point3& p) {
  { k.orient3d_staged(p, p, p, p) } -> std::same_as<Staged>;
};
template <class K>
concept StagedInsphere = HasStageNames<K> && requires(const K& k, const Point3& p) {
  { k.insphere_staged(p, p, p, p, p) } -> std::same_as<Staged>;
};

// Whether K answers for symbolically perturbed points (perturbed<>, and
// wrappers of it that forward `symbolic`).
template <class K>
constexpr bool is_symbolic() {
  if constexpr (requires { K::symbolic; })
    return K::symbolic;
  else
    return false;
}

// Number of stages of K (1 when K has no stages).
template <class K>
constexpr std::size_t stage_count() {
  if constexpr (HasStageNames<K>)
    return std::size(K::stage_names);
  else
    return 1;
}

// K's stage names as a std::array (K::name alone when K has no stages).
template <class K>
constexpr std::array<std::string_view, stage_count<K>()> stage_names_of() {
  std::array<std::string_view, stage_count<K>()> out{};
  if constexpr (HasStageNames<K>) {
    for (std::size_t i = 0; i < out.size(); ++i) out[i] = K::stage_names[i];
  } else {
    out[0] = K::name;
  }
  return out;
}

// The staged answer of each predicate, for any kernel: an unstaged kernel
// answers everything in its stage 0.
template <class K>
Staged orient2d_staged(const K& k, const Point2& a, const Point2& b, const Point2& c) {
  if constexpr (StagedOrient2d<K>)
    return k.orient2d_staged(a, b, c);
  else
    return {k.orient2d(a, b, c), 0};
}
template <class K>
Staged incircle_staged(const K& k, const Point2& a, const Point2& b, const Point2& c,
                       const Point2& d) {
  if constexpr (StagedIncircle<K>)
    return k.incircle_staged(a, b, c, d);
  else
    return {k.incircle(a, b, c, d), 0};
}
template <class K>
Staged orient3d_staged(const K& k, const Point3& a, const Point3& b, const Point3& c,
                       const Point3& d) {
  if constexpr (StagedOrient3d<K>)
    return k.orient3d_staged(a, b, c, d);
  else
    return {k.orient3d(a, b, c, d), 0};
}
template <class K>
Staged insphere_staged(const K& k, const Point3& a, const Point3& b, const Point3& c,
                       const Point3& d, const Point3& e) {
  if constexpr (StagedInsphere<K>)
    return k.insphere_staged(a, b, c, d, e);
  else
    return {k.insphere(a, b, c, d, e), 0};
}

}  // namespace dlab
