// See corpus_run.hpp.
#include "fuzz/corpus_run.hpp"

#include <cstdlib>

#include "fuzz/scheduler.hpp"
#include "fuzz/selftest.hpp"

namespace dlab::fuzz {

std::vector<std::vector<PairRecord>> run_corpus_cases(const std::vector<CorpusCase>& cases,
                                                      const std::vector<Pair>& pairs, const Limits& limits,
                                                      unsigned jobs) {
  Work w;
  for (std::size_t i = 0; i < cases.size(); ++i) {
    PreparedCase c;
    c.plan.index = i;
    c.plan.order_seed = cases[i].order_seed;
    c.plan.gen.name = "corpus:" + cases[i].name;
    c.plan.gen.dim = cases[i].dimension;
    c.plan.gen.n = cases[i].points.size();
    c.points = cases[i].points;
    w.cases.push_back(std::move(c));
  }
  w.pairs = pairs;
  if (const char* st = std::getenv(kSelftestVariable)) w.selftest = parse_selftest(st);
  w.limits = limits;
  w.timing = false;

  Schedule s;
  s.jobs = jobs;
  s.start = 0;
  s.end = cases.size();
  s.wall_seconds = 10 * limits.cpu_seconds + 10;  // as a campaign's watchdog
  std::vector<std::vector<PairRecord>> out(cases.size());
  run_schedule(
      w, s,
      [&](const CaseDone& d) {
        auto& records = out[d.position];
        for (std::size_t pos = 0; pos < d.lines.size();) {
          const std::size_t nl = d.lines.find('\n', pos);
          records.push_back(parse_json_line(std::string_view(d.lines).substr(pos, nl - pos)));
          pos = nl + 1;
        }
      },
      [] {});
  return out;
}

std::string corpus_selftest_warning() {
  const char* st = std::getenv(kSelftestVariable);
  if (!st) return {};
  return std::string(kSelftestVariable) + "=" + st +
         " is set: deliberate failures are injected (a test of the corpus tools, not a replay)";
}

}  // namespace dlab::fuzz
