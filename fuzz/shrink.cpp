// See shrink.hpp.
#include "fuzz/shrink.hpp"

#include <vector>

#include "fuzz/shrink_ddmin.hpp"

namespace dlab::fuzz {
namespace {

PointSet subset_of(const PointSet& s, const std::vector<std::size_t>& keep) {
  PointSet out;
  out.dimension = s.dimension;
  for (std::size_t i : keep)
    if (s.dimension == 2)
      out.p2.push_back(s.p2[i]);
    else
      out.p3.push_back(s.p3[i]);
  return out;
}

std::string describe(const ShrinkSize& z) {
  return std::to_string(z.points) + (z.points == 1 ? " point, " : " points, ") + std::to_string(z.bits) +
         " significant bits";
}

// ddmin over the current points; returns whether it removed any.
bool remove_points(Simplifier& s) {
  const PointSet current = s.points();
  const std::vector<std::size_t> keep =
      ddmin(current.size(), [&](const std::vector<std::size_t>& d) { return s.fails(subset_of(current, d)); });
  if (keep.size() == current.size()) return false;
  s.keep(subset_of(current, keep));
  return true;
}

}  // namespace

ShrinkReport shrink(const PointSet& failing, const PointTest& fails, const ShrinkLimits& limits) {
  ShrinkReport r;
  const PointTest budgeted = [&](const PointSet& p) {
    if (r.tests >= limits.max_tests) {
      r.budget_spent = true;
      return false;
    }
    ++r.tests;
    return fails(p);
  };
  Simplifier s(failing, budgeted);
  r.before = s.size();
  while (r.rounds < limits.max_rounds && !r.budget_spent) {
    ++r.rounds;
    bool kept = remove_points(s);
    kept = translate_toward_origin(s) || kept;
    kept = snap_whole_set(s) || kept;
    kept = simplify_each_coordinate(s) || kept;
    if (!kept) {
      r.fixpoint = !r.budget_spent;
      break;
    }
  }
  r.points = s.points();
  r.after = s.size();
  return r;
}

std::string describe(const ShrinkReport& r) {
  std::string s = describe(r.before) + " -> " + describe(r.after) + "; " + std::to_string(r.tests) + " tests";
  if (r.budget_spent)
    s += "; test budget spent";
  else if (!r.fixpoint)
    s += "; no fixpoint after " + std::to_string(r.rounds) + " rounds";
  return s;
}

}  // namespace dlab::fuzz
