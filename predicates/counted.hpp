// counted<K>: K with call counters, per predicate and, for staged kernels
// (predicates/kernel.hpp: `*_staged` + `stage_names`), per answering stage.
// In the spirit of Geogram's PCK PredicateStats (design.md section 8).
//
// Counting never changes an answer: every call forwards to K and returns K's
// sign. The counters live in one PredicateCounters object shared by all copies
// of a counted<K> (copies of the kernel, e.g. inside an algorithm, keep counting
// into the same place); each call costs one plain integer increment through a
// pointer (a staged call counts at its stage only; the total is the sum).
// Not thread-safe: one counted<K> family per thread.
//
// Names (stable, in this order): for each of orient2d, incircle, orient3d,
// insphere: "<pred>", then "<pred>.<stage>" for each stage of K when K is
// staged for that predicate; then, if K provides them, "coplanar_orientation"
// and "coplanar_incircle" (perturbed<K>'s hull predicates).
#pragma once
#include <array>
#include <cstdint>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "predicates/counters.hpp"
#include "predicates/kernel.hpp"
#include "predicates/stages.hpp"

namespace dlab {

struct PredicateCounters {
  enum Pred : int { orient2d, incircle, orient3d, insphere, coplanar_orientation, coplanar_incircle };
  static constexpr int predicates = 6;
  static constexpr int max_stages = 8;
  static constexpr std::array<const char*, predicates> names{
      "orient2d", "incircle", "orient3d", "insphere", "coplanar_orientation", "coplanar_incircle"};
  std::array<std::uint64_t, predicates> calls{};  // unstaged calls
  std::array<std::array<std::uint64_t, max_stages>, predicates> stage{};
  std::uint64_t total(int p) const {
    std::uint64_t t = calls[p];
    for (std::uint64_t c : stage[p]) t += c;
    return t;
  }
};

template <class K>
concept HasCoplanarPredicates = requires(const K& k, const Point3& p) {
  { k.coplanar_orientation(p, p, p) } -> std::same_as<Sign>;
  { k.coplanar_incircle(p, p, p, p) } -> std::same_as<Sign>;
};

template <class K>
struct counted {
  static constexpr bool exact = K::exact;
  static constexpr std::string_view name = K::name;
  static constexpr bool symbolic = is_symbolic<K>();
  static_assert(stage_count<K>() <= PredicateCounters::max_stages);

  K base{};
  std::shared_ptr<PredicateCounters> stats = std::make_shared<PredicateCounters>();

  counted() = default;
  explicit counted(const K& k) : base(k) {}
  counted(const K& k, std::shared_ptr<PredicateCounters> shared)
      : base(k), stats(std::move(shared)) {}

  // One thread's copy, counting into counters of its own; add_counts sums them
  // back once the threads are done (algorithms/parallel_bowyer_watson.hpp).
  counted with_own_counters() const { return counted(base, std::make_shared<PredicateCounters>()); }
  void add_counts(const counted& other) const {
    for (int p = 0; p < PredicateCounters::predicates; ++p) {
      stats->calls[p] += other.stats->calls[p];
      for (int s = 0; s < PredicateCounters::max_stages; ++s) stats->stage[p][s] += other.stats->stage[p][s];
    }
  }

  // ---- predicates ----
  Sign orient2d(const Point2& a, const Point2& b, const Point2& c) const
    requires Kernel2<K>
  {
    if constexpr (StagedOrient2d<K>) return orient2d_staged(a, b, c).sign;
    ++stats->calls[PredicateCounters::orient2d];
    return base.orient2d(a, b, c);
  }
  Sign incircle(const Point2& a, const Point2& b, const Point2& c, const Point2& d) const
    requires Kernel2<K>
  {
    if constexpr (StagedIncircle<K>) return incircle_staged(a, b, c, d).sign;
    ++stats->calls[PredicateCounters::incircle];
    return base.incircle(a, b, c, d);
  }
  Sign orient3d(const Point3& a, const Point3& b, const Point3& c, const Point3& d) const
    requires Kernel3<K>
  {
    if constexpr (StagedOrient3d<K>) return orient3d_staged(a, b, c, d).sign;
    ++stats->calls[PredicateCounters::orient3d];
    return base.orient3d(a, b, c, d);
  }
  Sign insphere(const Point3& a, const Point3& b, const Point3& c, const Point3& d,
                const Point3& e) const
    requires Kernel3<K>
  {
    if constexpr (StagedInsphere<K>) return insphere_staged(a, b, c, d, e).sign;
    ++stats->calls[PredicateCounters::insphere];
    return base.insphere(a, b, c, d, e);
  }

  // ---- staged interface, forwarded (and counted) when K has it ----
  static constexpr auto stage_names = stage_names_of<K>();

  Staged orient2d_staged(const Point2& a, const Point2& b, const Point2& c) const
    requires StagedOrient2d<K>
  {
    return count(PredicateCounters::orient2d, base.orient2d_staged(a, b, c));
  }
  Staged incircle_staged(const Point2& a, const Point2& b, const Point2& c, const Point2& d) const
    requires StagedIncircle<K>
  {
    return count(PredicateCounters::incircle, base.incircle_staged(a, b, c, d));
  }
  Staged orient3d_staged(const Point3& a, const Point3& b, const Point3& c, const Point3& d) const
    requires StagedOrient3d<K>
  {
    return count(PredicateCounters::orient3d, base.orient3d_staged(a, b, c, d));
  }
  Staged insphere_staged(const Point3& a, const Point3& b, const Point3& c, const Point3& d,
                         const Point3& e) const
    requires StagedInsphere<K>
  {
    return count(PredicateCounters::insphere, base.insphere_staged(a, b, c, d, e));
  }

  // ---- perturbed<K>'s extra predicates, forwarded when present ----
  Sign coplanar_orientation(const Point3& p, const Point3& q, const Point3& r) const
    requires HasCoplanarPredicates<K>
  {
    ++stats->calls[PredicateCounters::coplanar_orientation];
    return base.coplanar_orientation(p, q, r);
  }
  Sign coplanar_incircle(const Point3& a, const Point3& b, const Point3& c, const Point3& p) const
    requires HasCoplanarPredicates<K>
  {
    ++stats->calls[PredicateCounters::coplanar_incircle];
    return base.coplanar_incircle(a, b, c, p);
  }

  // ---- snapping kernels (integer): forwarded so counted<K> snaps as K does ----
  template <class Points>
  auto snap_all(Points& pts)
    requires requires(K& k) { k.snap_all(pts); }
  {
    return base.snap_all(pts);
  }

  // ---- reading the counters ----
  void reset() const { *stats = PredicateCounters{}; }

  Counters counters() const {
    Counters out;
    auto emit = [&](int p, bool staged) {
      out.emplace_back(PredicateCounters::names[p], stats->total(p));
      if (staged)
        for (std::size_t s = 0; s < stage_names.size(); ++s)
          out.emplace_back(std::string(PredicateCounters::names[p]) + "." +
                               std::string(stage_names[s]),
                           stats->stage[p][s]);
    };
    emit(PredicateCounters::orient2d, StagedOrient2d<K>);
    emit(PredicateCounters::incircle, StagedIncircle<K>);
    emit(PredicateCounters::orient3d, StagedOrient3d<K>);
    emit(PredicateCounters::insphere, StagedInsphere<K>);
    if constexpr (HasCoplanarPredicates<K>) {
      emit(PredicateCounters::coplanar_orientation, false);
      emit(PredicateCounters::coplanar_incircle, false);
    }
    return out;
  }

 private:
  Staged count(int p, Staged s) const {
    if (s.stage < PredicateCounters::max_stages)
      ++stats->stage[p][s.stage];
    else
      ++stats->calls[p];
    return s;
  }
};

}  // namespace dlab
