// See shrink_oracle.hpp.
#include "fuzz/shrink_oracle.hpp"

#include <stdexcept>
#include <utility>

#include "fuzz/record.hpp"
#include "fuzz/scheduler.hpp"

namespace dlab::fuzz {

std::string FailureClass::describe() const {
  if (!kind) return outcome + " (any kind)";
  return kind->empty() ? outcome : outcome + " (" + *kind + ")";
}

ChildOracle::ChildOracle(Pair pair, std::uint64_t order_seed, Limits limits, std::vector<Misbehaviour> selftest)
    : pair_(std::move(pair)), order_seed_(order_seed), limits_(limits), selftest_(std::move(selftest)) {}

Observed ChildOracle::observe(const PointSet& points) const {
  Work w;  // one case (the points) x one pair, as fuzz/corpus_run.cpp runs its cases
  PreparedCase c;
  c.plan.order_seed = order_seed_;
  c.plan.gen.name = "shrink";
  c.plan.gen.dim = points.dimension;
  c.plan.gen.n = points.size();
  c.points = points;
  w.cases.push_back(std::move(c));
  w.pairs = {pair_};
  w.selftest = selftest_;
  w.limits = limits_;
  w.timing = false;
  Schedule s;
  s.end = 1;
  s.single = true;
  s.wall_seconds = 10 * limits_.cpu_seconds + 10;  // a campaign's watchdog
  std::string line;
  run_schedule(w, s, [&](const CaseDone& d) { line = d.lines; }, [] {});
  if (line.empty() || line.back() != '\n') throw std::runtime_error("the shrinker's child gave no record");
  line.pop_back();
  const PairRecord r = parse_json_line(line);
  return {r.outcome, r.kind, r.detail};
}

}  // namespace dlab::fuzz
