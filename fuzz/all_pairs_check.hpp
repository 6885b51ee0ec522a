// The oracle of the coverage-guided fuzz targets: run every algorithm x kernel
// pair on one small point set and say whether any broke its promise.
//
//   exact pairs (bowyer-watson, lawson, tanemura, george --exact-sphere, each
//   with adaptive, integer, mp, policy sos): the result must be the perturbed
//   reference (fuzz/reference.hpp), simplex for simplex and outcome for
//   outcome. The reference itself is judged once by the exact validator, so a
//   result equal to it is a valid Delaunay triangulation. The integer kernel
//   triangulates its snapped points (variants/driver.hpp): its result is
//   compared with the reference of those points, as `dlab fuzz` does
//   (fuzz/case_runner.cpp).
//   the same four algorithms with adaptive under the strict policy: exact too,
//   but a Delaunay triangulation is not unique on degenerate input, so the
//   validator judges it (variants/outcome.hpp's classify must say ok or
//   lower-dimensional).
//   no-crash pairs (each algorithm with float and epsilon; George's floating
//   sphere and his enclosing box with adaptive): any outcome is fine, a thrown
//   std::exception included (the campaign classifies it `reported`); the
//   validator still judges the result, so that it runs on broken meshes too.
//   A crash, a sanitizer report, a hang or an allocation that does not end is
//   the fuzzing engine's to catch.
#pragma once
#include <cstdint>
#include <optional>
#include <string>

#include "variants/run.hpp"

namespace dlab::fuzz {

struct PairFailure {
  std::string pair;  // variants/outcome.hpp's describe_pair, with the policy and order
  std::string what;  // one line
};

// The first broken promise, or nothing. Pairs run in the given insertion
// order and seed. std::bad_alloc propagates.
std::optional<PairFailure> check_all_pairs(const PointSet& points, const std::string& order,
                                           std::uint64_t seed);

}  // namespace dlab::fuzz
