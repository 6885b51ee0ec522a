// The reference an exact pair's result must equal: the symbolically perturbed
// Delaunay triangulation (design.md section 2), computed by Bowyer-Watson under
// the sos policy with the exact validator's kernel, a floating filter in front
// of GMP (fuzz/reference_kernel.cpp). Bowyer-Watson with the mp kernel is
// simplex for simplex CGAL's Delaunay_triangulation_2/3
// (tests/test_oracle_properties.cpp), and this one equals it
// (tests/test_fuzz_campaign.cpp). It is independent of the fast kernels under
// test (adaptive, integer): none of their code runs.
#pragma once
#include <optional>

#include "variants/outcome.hpp"
#include "variants/run.hpp"

namespace dlab::fuzz {

// Bowyer-Watson, sos, filtered<FloatFilter, MpKernel> (fuzz/reference_kernel.cpp).
RunResult run_reference(const PointSet& points);

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
