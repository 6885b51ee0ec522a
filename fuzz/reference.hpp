// The reference an exact pair's result must equal: the symbolically perturbed
// Delaunay triangulation (design.md section 2), computed by Bowyer-Watson with
// the mp kernel under the sos policy -- simplex for simplex CGAL's
// Delaunay_triangulation_2/3 (tests/test_oracle_properties.cpp checks this).
// It is independent of every fast kernel under test (adaptive, integer): GMP
// evaluates every predicate.
#pragma once
#include <optional>

#include "variants/outcome.hpp"
#include "variants/run.hpp"

namespace dlab::fuzz {

class Reference {
 public:
  // `points` must outlive the Reference.
  explicit Reference(const PointSet& points) : points_(&points) {}
  // Computed on the first call, kept for the others.
  const RunResult& result();

 private:
  const PointSet* points_;
  std::optional<RunResult> result_;
};

// For an exact pair's result that classify() found ok or lower-dimensional:
// `differs` when its canonical simplex list (algorithms/canonical_simplices.hpp)
// is not the reference's, with how many simplices are not the reference's and
// the first; `o` unchanged otherwise.
Outcome compare_with_reference(Outcome o, const RunResult& r, const RunResult& reference);

}  // namespace dlab::fuzz
