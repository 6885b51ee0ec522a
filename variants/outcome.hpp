// The outcome of a run, classified once for every caller: `dlab triangulate`,
// `dlab flip`, the fuzzer and the regression corpus (design.md section 5, issue
// 12). One class per outcome, one exit status per class, one stderr line of one
// format whatever algorithm x kernel produced it:
//
//   class              exit  stderr line (nothing for ok)
//   ok                 0     -
//   lower-dimensional  0     dlab CMD: lower-dimensional: WHY (PAIR)
//   not-delaunay       1     dlab CMD: not-delaunay: N facets not locally Delaunay (first: ...) (PAIR)
//   invalid            1     dlab CMD: invalid: CHECK: WHAT (first: ...) (PAIR)
//   reported           1     dlab CMD: reported: THE ALGORITHM'S MESSAGE (PAIR)
//   differs            1     dlab CMD: differs: K of M simplices not in the perturbed reference ... (PAIR)
//
// `differs` is an exact pair's valid Delaunay result that is not the symbolically
// perturbed (CGAL-identical) triangulation; classify() cannot see it: the fuzzer
// and the corpus compare with a reference (fuzz/reference.hpp).
//
// PAIR is "ALGORITHM[ --exact-sphere][ --enclosing-box], KERNEL kernel". When the
// pair promises a Delaunay triangulation (pair_is_exact) and the class is not ok
// or lower-dimensional, the line ends "; a bug: the pair is exact".
//
// CHECK groups the validator's checks (algorithms/validate.hpp) as the fuzzer
// names them: indices (index_range, duplicate_reference), orientation,
// overlap (duplicate_simplex, facet_same_side, cover_degree), adjacency
// (non_manifold_facet, disconnected), hull-coverage (boundary_manifold,
// boundary_convex), missing-point (missing_vertex).
#pragma once
#include <cstdint>
#include <string>
#include <string_view>

#include "algorithms/validate.hpp"
#include "variants/run.hpp"

namespace dlab {

enum class OutcomeClass { ok, lower_dimensional, not_delaunay, invalid, reported, differs };

// "ok", "lower-dimensional", "not-delaunay", "invalid", "reported", "differs".
std::string_view outcome_name(OutcomeClass c);
// 0 for ok and lower-dimensional, 1 for the others (design.md section 5).
int exit_status(OutcomeClass c);

struct Outcome {
  OutcomeClass kind = OutcomeClass::ok;
  std::string detail;            // one line, no newline; empty for ok
  std::string_view check;        // invalid: the group of the first failed check (see above)
  Check first_check = Check::count_;  // invalid: the validator's first failed check
  std::uint64_t count = 0;       // not-delaunay: facets; invalid: offenders of first_check
  bool validated = false;        // the exact validator judged the result
  bool exact_pair = false;       // the pair promised ok (as passed to classify)
  // An exact pair that gives anything but ok (or lower-dimensional) is a bug.
  bool bug() const {
    return exact_pair && kind != OutcomeClass::ok && kind != OutcomeClass::lower_dimensional;
  }
};

// True when the pair promises a valid Delaunay triangulation for every finite
// input: an exact kernel (adaptive, integer, mp) and not George's floating
// sphere test nor his enclosing box (both may end valid but not Delaunay, or
// short of the hull, by design: papers/george1997).
bool pair_is_exact(const RunOptions& o);

enum class Validate {
  always,        // judge every result (a report the run attached is reused)
  unless_exact,  // trust an exact pair's own verdict unless the run attached a report
};

// Classifies a run of `input` (the points as given; the result's own points,
// snapped by `integer`, are validated when it has them). A result that the
// algorithm reported as failed is `reported`; any other result is judged by
// the exact validator (r.validation if present) unless `when` is
// unless_exact and exact_pair. Validator exceptions (e.g. bad_alloc) make the
// result `invalid`.
Outcome classify(const PointSet& input, const RunResult& r, bool exact_pair,
                 Validate when = Validate::always);

// Classifies a validator report alone (ok, lower-dimensional, not-delaunay, invalid).
Outcome classify_report(const ValidationReport& rep, bool exact_pair);

// "ALGORITHM[ --exact-sphere][ --enclosing-box], KERNEL kernel".
std::string describe_pair(const RunOptions& o);

// The stderr line (no newline) of a non-ok outcome of `command` ("triangulate").
std::string outcome_line(std::string_view command, const Outcome& o, std::string_view pair);

}  // namespace dlab
