// `dlab corpus replay` (issue 12): replays the regression corpus and reports
// every change of an outcome class, in either direction -- an exact pair that
// is no longer ok (or no longer the perturbed, CGAL-identical triangulation:
// `differs`), an inexact pair that fails differently or now passes.
#pragma once
#include <ostream>
#include <string>
#include <vector>

#include "fuzz/isolation.hpp"

namespace dlab::fuzz {

struct ReplayOptions {
  std::vector<std::string> inputs;  // directories (their *.pts files) and case files
  std::vector<std::string> algorithms, kernels;  // restrict the pairs run; empty: all
  Limits limits{60};
  unsigned jobs = 1;
};

// The case files of the inputs, each directory's *.pts sorted by name. Throws
// UsageError for a path that cannot be read, a directory without cases or a
// case given twice.
std::vector<std::string> corpus_files(const std::vector<std::string>& inputs);

// Prints each change as "CASE: ALGO KERNEL expected X, got Y (detail)", in case
// and pair order (whatever the jobs), then "corpus replay: C cases, P pairs, N
// changes". Returns 1 if anything changed, else 0. Throws io::InputError for a
// malformed case ("FILE:LINE: problem"), UsageError for bad options.
int replay_corpus(const ReplayOptions& o, std::ostream& out, std::ostream& err);

}  // namespace dlab::fuzz
