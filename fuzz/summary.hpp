// The summary of a campaign: for each algorithm x kernel x generator, how many
// runs, how many failed (any outcome but ok and lower-dimensional), the failure
// rate with its 95 % Wilson score interval, and the failures by class.
//
// Wilson, "Probable inference, the law of succession, and statistical
// inference", JASA 22 (1927): for x failures in n runs, p = x/n, z = 1.96,
//   centre = (p + z^2/(2n)) / (1 + z^2/n),
//   half   = z / (1 + z^2/n) * sqrt(p(1-p)/n + z^2/(4n^2)).
// Unlike p +- z sqrt(p(1-p)/n) it stays inside [0, 1] and is not empty at
// x = 0 (for n runs without a failure the upper end is about 3.84/n).
#pragma once
#include <cstdint>
#include <map>
#include <string>
#include <tuple>
#include <vector>

#include "fuzz/campaign_spec.hpp"
#include "fuzz/record.hpp"

namespace dlab::fuzz {

struct Interval {
  double lo = 0, hi = 1;
};
Interval wilson_interval(std::uint64_t failures, std::uint64_t runs);

class Summary {
 public:
  explicit Summary(const CampaignSpec& spec) : spec_(spec) {}
  void add(const PairRecord& r);
  // The table (rows in the campaign's algorithm, kernel, generator order) and
  // a closing line with the totals. Deterministic: no timing in it.
  std::string table() const;
  std::uint64_t exact_failures() const { return exact_failures_; }
  std::uint64_t records() const { return records_; }

 private:
  struct Row {
    std::uint64_t runs = 0, failures = 0;
    std::map<std::string, std::uint64_t> by_class;
  };
  CampaignSpec spec_;
  std::map<std::tuple<std::string, std::string, std::string>, Row> rows_;  // algo, kernel, gen
  std::uint64_t records_ = 0, failures_ = 0, exact_runs_ = 0, exact_failures_ = 0;
  std::uint64_t cases_ = 0, last_case_ = UINT64_MAX;  // records come grouped by case
};

}  // namespace dlab::fuzz
