// Runs one case of a campaign, pair by pair, in the calling process: generate
// the points, run each pair through dlab::run(), classify the result
// (variants/outcome.hpp: every result is judged by the exact validator), and
// compare an exact pair's valid Delaunay result with the perturbed reference
// (fuzz/reference.hpp) -- `differs` if it is not that triangulation.
// Isolation (fuzz/isolation.hpp) calls this in child processes.
#pragma once
#include <cstdint>
#include <memory>

#include "fuzz/campaign_spec.hpp"
#include "fuzz/case_plan.hpp"
#include "fuzz/record.hpp"
#include "fuzz/reference.hpp"

namespace dlab::fuzz {

struct PreparedCase {
  CasePlan plan;
  PointSet points;
};

// Throws std::invalid_argument when the generator refuses its options.
PreparedCase prepare_case(const CampaignSpec& spec, std::uint64_t i);

// The record's fields that do not depend on the run (outcome still empty).
PairRecord record_header(const PreparedCase& c, const Pair& p);

class CaseRunner {
 public:
  // `c` must outlive the runner.
  explicit CaseRunner(const PreparedCase& c) : case_(&c), reference_(c.points) {}
  PairRecord run(const Pair& p, bool timing);

 private:
  const PreparedCase* case_;
  Reference reference_;  // on the input points, computed at most once per case
};

}  // namespace dlab::fuzz
