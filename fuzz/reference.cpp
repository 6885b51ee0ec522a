// See reference.hpp.
#include "fuzz/reference.hpp"

#include <algorithm>
#include <iterator>
#include <string>

#include "algorithms/canonical_simplices.hpp"

namespace dlab::fuzz {
namespace {

template <int D>
std::string simplex_text(const IndexSimplex<D>& s) {
  std::string t;
  for (auto v : s) t += (t.empty() ? "" : " ") + std::to_string(v);
  return t;
}

template <int D>
Outcome compare(Outcome o, const RunResult& r, const RunResult& ref) {
  const auto mine = canonical_simplices<D>(r.simplices);
  const auto theirs = canonical_simplices<D>(ref.simplices);
  if (mine == theirs && r.outcome == ref.outcome) return o;
  std::vector<IndexSimplex<D>> extra;
  std::set_difference(mine.begin(), mine.end(), theirs.begin(), theirs.end(), std::back_inserter(extra));
  o.kind = OutcomeClass::differs;
  o.count = extra.size();
  o.detail = std::to_string(extra.size()) + " of " + std::to_string(mine.size()) +
             " simplices not in the perturbed reference (Bowyer-Watson, sos, exact: " +
             std::to_string(theirs.size()) + " simplices)";
  if (!extra.empty()) o.detail += " (first: " + simplex_text<D>(extra.front()) + ")";
  return o;
}

}  // namespace

const RunResult& Reference::result() {
  if (!result_) result_ = run_reference(*points_);
  return *result_;
}

Outcome compare_with_reference(Outcome o, const RunResult& r, const RunResult& reference) {
  if (o.kind != OutcomeClass::ok && o.kind != OutcomeClass::lower_dimensional) return o;
  return r.dimension == 3 ? compare<3>(std::move(o), r, reference) : compare<2>(std::move(o), r, reference);
}

}  // namespace dlab::fuzz
