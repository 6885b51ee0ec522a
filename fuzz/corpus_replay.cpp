// See corpus_replay.hpp.
#include "fuzz/corpus_replay.hpp"

#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <set>

#include "fuzz/corpus_case.hpp"
#include "fuzz/corpus_run.hpp"

namespace dlab::fuzz {
namespace {

namespace fs = std::filesystem;

// The pairs of corpus_pairs() whose algorithm and kernel are listed (all if a list is empty).
std::vector<Pair> selected_pairs(const ReplayOptions& o) {
  for (const auto& a : o.algorithms) fuzz::make_pair(a, "mp");  // UsageError for an unknown name
  for (const auto& k : o.kernels) fuzz::make_pair("bowyer-watson", k);
  std::vector<Pair> out;
  for (const Pair& p : corpus_pairs()) {
    const bool algo = o.algorithms.empty() ||
                      std::find(o.algorithms.begin(), o.algorithms.end(), p.algo_name()) != o.algorithms.end();
    const bool kernel =
        o.kernels.empty() || std::find(o.kernels.begin(), o.kernels.end(), p.kernel) != o.kernels.end();
    if (algo && kernel) out.push_back(p);
  }
  return out;
}

}  // namespace

std::vector<std::string> corpus_files(const std::vector<std::string>& inputs) {
  std::vector<std::string> files;
  for (const auto& in : inputs) {
    std::error_code ec;
    if (!fs::is_directory(in, ec)) {
      if (access(in.c_str(), R_OK) != 0) throw UsageError("cannot read '" + in + "': " + std::strerror(errno));
      files.push_back(in);
      continue;
    }
    std::vector<std::string> here;
    fs::directory_iterator it(in, ec), end;
    if (ec) throw UsageError("cannot read the directory '" + in + "': " + ec.message());
    for (; it != end; it.increment(ec)) {
      if (ec) throw UsageError("cannot read the directory '" + in + "': " + ec.message());
      if (it->path().extension() == ".pts") here.push_back(it->path().string());
    }
    if (here.empty()) throw UsageError("no cases (*.pts) in '" + in + "'");
    std::sort(here.begin(), here.end());
    files.insert(files.end(), here.begin(), here.end());
  }
  std::set<std::string> seen;
  for (const auto& f : files)
    if (!seen.insert(fs::weakly_canonical(f).string()).second) throw UsageError("'" + f + "' is given twice");
  return files;
}

int replay_corpus(const ReplayOptions& o, std::ostream& out, std::ostream& err) {
  const std::vector<Pair> pairs = selected_pairs(o);
  if (pairs.empty()) throw UsageError("--algo and --kernel select no pair");
  std::vector<CorpusCase> cases;
  std::set<std::string> names;
  for (const auto& f : corpus_files(o.inputs)) {
    cases.push_back(read_corpus_case(f));
    if (!names.insert(cases.back().name).second) throw UsageError("two cases are named '" + cases.back().name + "'");
  }
  if (const std::string w = corpus_selftest_warning(); !w.empty()) err << "dlab corpus: " << w << "\n";
  const auto records = run_corpus_cases(cases, pairs, o.limits, o.jobs);
  std::size_t changes = 0;
  for (std::size_t i = 0; i < cases.size(); ++i)
    for (std::size_t j = 0; j < pairs.size(); ++j) {
      const std::string& expected = cases[i].expectation(pairs[j])->outcome;
      const PairRecord& r = records[i][j];
      if (r.outcome == expected) continue;
      ++changes;
      out << cases[i].name << ": " << r.algo << " " << r.kernel << " expected " << expected << ", got " << r.outcome
          << (r.detail.empty() ? "" : " (" + r.detail + ")") << "\n";
    }
  out << "corpus replay: " << cases.size() << " case" << (cases.size() == 1 ? "" : "s") << ", "
      << cases.size() * pairs.size() << " pairs, " << changes << " change" << (changes == 1 ? "" : "s") << "\n";
  return changes == 0 ? 0 : 1;
}

}  // namespace dlab::fuzz
