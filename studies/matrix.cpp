// See matrix.hpp.
#include "studies/matrix.hpp"

#include <algorithm>

#include "fuzz/campaign_spec.hpp"
#include "variants/outcome.hpp"

namespace dlab::study {

RunOptions RunSpec::options() const {
  RunOptions o = fuzz::make_pair(algorithm, kernel).options(seed);
  o.policy = policy;
  o.order = order;
  if (location != "-") o.location = location;
  return o;
}

bool RunSpec::exact_pair() const { return !is_baseline() && pair_is_exact(options()); }

bool location_is_selectable(const std::string& algorithm) {
  return algorithm == "bowyer-watson" || algorithm == "lawson";
}

std::vector<RunSpec> expand_matrix(const StudyConfig& c) {
  std::vector<RunSpec> runs;
  RunSpec r;
  auto add = [&] {
    r.id = runs.size();
    runs.push_back(r);
  };
  for (std::size_t i = 0; i < c.inputs.size(); ++i) {
    const InputSpec& in = c.inputs[i];
    r.input = i;
    for (std::uint64_t n : in.ns)
      for (std::uint64_t seed : in.seeds)
        for (std::uint32_t rep = 0; rep < c.repeats; ++rep) {
          r.n = n;
          r.seed = seed;
          r.repeat = rep;
          r.tool = "dlab";
          for (const auto& algo : c.algorithms) {
            r.algorithm = algo;
            const bool selectable = location_is_selectable(fuzz::make_pair(algo, "mp").algorithm);
            for (const auto& kernel : c.kernels) {
              r.kernel = kernel;
              for (const auto& order : c.orders) {
                r.order = order;
                std::vector<std::string> done;
                for (const auto& policy : c.policies) {
                  r.policy = policy != "default" ? policy : kernel_is_exact(kernel) ? "sos" : "strict";
                  if (std::find(done.begin(), done.end(), r.policy) != done.end()) continue;
                  done.push_back(r.policy);
                  if (!selectable) {
                    r.location = "-";
                    add();
                    continue;
                  }
                  for (const auto& location : c.locations) {
                    r.location = location;
                    add();
                  }
                }
              }
            }
          }
          for (const auto& b : c.baselines) {
            if (b == "cgal-epeck" && n > c.epeck_max_n) continue;
            r.tool = r.algorithm = b;
            r.kernel = r.order = r.policy = r.location = "-";
            add();
          }
        }
  }
  return runs;
}

Shard parse_shard(const std::string& text) {
  const auto slash = text.find('/');
  Shard s;
  auto number = [&](const std::string& t, std::uint64_t& out) {
    if (t.empty() || t.size() > 9 || t.find_first_not_of("0123456789") != std::string::npos) return false;
    out = std::stoull(t);
    return true;
  };
  if (slash == std::string::npos || !number(text.substr(0, slash), s.k) || !number(text.substr(slash + 1), s.n) ||
      s.k < 1 || s.k > s.n)
    throw ConfigError("--shard: '" + text + "' is not k/n with 1 <= k <= n");
  return s;
}

}  // namespace dlab::study
