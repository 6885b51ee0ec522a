// The "same failure" test of `dlab shrink` (fuzz/shrink.hpp). A point set is
// run with the pair exactly as a campaign runs a case x pair: in a child
// process under the campaign's CPU-time and memory limits (fuzz/scheduler.hpp,
// fuzz/isolation.hpp, fuzz/child_limits.hpp), classified by fuzz/case_runner.hpp
// (the exact validator; for an exact pair, the perturbed reference), or named
// crash / timeout / out-of-memory by how the child ended -- so a crashing or
// hanging inexact pair cannot take the shrinker down, and those classes shrink too.
#pragma once
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "fuzz/campaign_spec.hpp"
#include "fuzz/isolation.hpp"
#include "fuzz/selftest.hpp"
#include "variants/run.hpp"

namespace dlab::fuzz {

// What one run gave: the record's outcome, kind and detail (fuzz/record.hpp).
struct Observed {
  std::string outcome, kind, detail;
};

// The failure to keep: its outcome class and, unless any kind will do, its
// kind (fuzz/fuzz_outcome.hpp: the invalid check group, the reported message
// with its numbers as '#', the crash's signal, the timeout's cpu or wall).
struct FailureClass {
  std::string outcome;
  std::optional<std::string> kind;  // nothing: any kind
  bool matches(const Observed& o) const { return o.outcome == outcome && (!kind || o.kind == *kind); }
  // "invalid (orientation)", "not-delaunay", "reported (any kind)".
  std::string describe() const;
};

class ChildOracle {
 public:
  // `selftest`: DLAB_FUZZ_SELFTEST's misbehaviours (fuzz/selftest.hpp), CASE 0
  // being every run -- for the tests of `dlab shrink` only.
  ChildOracle(Pair pair, std::uint64_t order_seed, Limits limits, std::vector<Misbehaviour> selftest = {});
  // Runs `points` in a fresh child. Throws std::runtime_error if it cannot fork.
  Observed observe(const PointSet& points) const;

 private:
  Pair pair_;
  std::uint64_t order_seed_;
  Limits limits_;
  std::vector<Misbehaviour> selftest_;
};

}  // namespace dlab::fuzz
