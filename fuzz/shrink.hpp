// `dlab shrink` (issue 12): a failing point set -> a smaller one that fails the
// same way. Rounds of
//   1. ddmin over the points (fuzz/shrink_ddmin.hpp: Zeller and Hildebrandt,
//      IEEE TSE 2002), down to a 1-minimal set;
//   2. the coordinate passes (fuzz/shrink_coords.hpp): translate toward the
//      origin, snap the whole set (integers, fewer significant bits), then
//      each coordinate (0, the nearest integer, fewer significant bits);
// repeated until a round keeps nothing (a fixpoint: the result is then the
// 1-minimal output of that round's ddmin), the test budget is spent, or
// max_rounds rounds have run. The test says whether a set shows "the same
// failure" (fuzz/shrink_oracle.hpp runs it in a child process); nothing here
// reads a clock or draws a random number, so the result is a function of the
// input, the test's answers and the limits.
#pragma once
#include <cstdint>
#include <string>

#include "fuzz/shrink_coords.hpp"
#include "variants/run.hpp"

namespace dlab::fuzz {

struct ShrinkLimits {
  std::uint64_t max_tests = 20000;  // after it, every test answers "passes" without running
  int max_rounds = 32;
};

struct ShrinkReport {
  PointSet points;
  ShrinkSize before, after;
  std::uint64_t tests = 0;  // tests run (the caller's own check of the input not included)
  int rounds = 0;
  bool budget_spent = false;
  bool fixpoint = false;  // the last round kept nothing: points is 1-minimal
};

// `failing` must fail (the caller has checked); so does the result.
ShrinkReport shrink(const PointSet& failing, const PointTest& fails, const ShrinkLimits& limits);

// "20 points, 2113 significant bits -> 3 points, 9 significant bits; 312 tests"
// (+ "; test budget spent" or "; no fixpoint after N rounds" when not 1-minimal).
std::string describe(const ShrinkReport& r);

}  // namespace dlab::fuzz
