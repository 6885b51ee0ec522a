// See summary.hpp.
#include "fuzz/summary.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "fuzz/fuzz_outcome.hpp"

namespace dlab::fuzz {
namespace {

std::string percent(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3g%%", 100 * x);
  return buf;
}

std::string pad(std::string s, std::size_t w) {
  if (s.size() < w) s.append(w - s.size(), ' ');
  return s;
}

}  // namespace

Interval wilson_interval(std::uint64_t failures, std::uint64_t runs) {
  if (runs == 0) return {0, 1};
  const double z = 1.959963984540054;  // the 97.5 % quantile of the standard normal
  const double n = static_cast<double>(runs);
  const double p = static_cast<double>(failures) / n;
  const double d = 1 + z * z / n;
  const double centre = (p + z * z / (2 * n)) / d;
  const double half = z / d * std::sqrt(p * (1 - p) / n + z * z / (4 * n * n));
  // At x = 0 (x = n) the lower (upper) end is 0 (1) exactly; rounding would not say so.
  return {failures == 0 ? 0.0 : std::max(0.0, centre - half), failures == runs ? 1.0 : std::min(1.0, centre + half)};
}

void Summary::add(const PairRecord& r) {
  Row& row = rows_[{r.algo, r.kernel, r.gen}];
  ++row.runs;
  ++records_;
  if (r.case_index != last_case_) {
    ++cases_;
    last_case_ = r.case_index;
  }
  if (r.exact) ++exact_runs_;
  if (is_failure(r.outcome)) {
    ++row.failures;
    ++row.by_class[r.outcome];
    ++failures_;
    if (r.exact) ++exact_failures_;
  }
}

std::string Summary::table() const {
  std::vector<std::vector<std::string>> cells = {
      {"algorithm", "kernel", "generator", "runs", "failures", "rate", "95% Wilson", "by class"}};
  for (const auto& a : spec_.algorithms)
    for (const auto& k : spec_.kernels)
      for (const auto& g : spec_.generators) {
        const auto it = rows_.find({a, k, g});
        if (it == rows_.end()) continue;
        const Row& row = it->second;
        const Interval ci = wilson_interval(row.failures, row.runs);
        std::string classes;
        for (std::string_view c : kOutcomeOrder)
          if (auto f = row.by_class.find(std::string(c)); f != row.by_class.end())
            classes += (classes.empty() ? "" : ", ") + std::string(c) + " " + std::to_string(f->second);
        cells.push_back({a, k, g, std::to_string(row.runs), std::to_string(row.failures),
                         percent(static_cast<double>(row.failures) / static_cast<double>(row.runs)),
                         std::string("[").append(percent(ci.lo)).append(", ").append(percent(ci.hi)).append("]"), classes.empty() ? "-" : classes});
      }
  std::vector<std::size_t> width(cells[0].size(), 0);
  for (const auto& row : cells)
    for (std::size_t c = 0; c < row.size(); ++c) width[c] = std::max(width[c], row[c].size());
  std::string out;
  for (const auto& row : cells) {
    std::string line;
    for (std::size_t c = 0; c < row.size(); ++c) line += c + 1 < row.size() ? pad(row[c], width[c] + 2) : row[c];
    out += line + "\n";
  }
  out += std::to_string(cases_) + " cases, " + std::to_string(records_) + " case x pairs, " +
         std::to_string(failures_) + " failures; exact pairs: " + std::to_string(exact_runs_) + " runs, " +
         std::to_string(exact_failures_) + " failures" + (exact_failures_ ? " (bugs)" : "") + "\n";
  return out;
}

}  // namespace dlab::fuzz
