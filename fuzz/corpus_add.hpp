// `dlab corpus add` (issue 12): turns a point file -- a shrunk failure, a
// campaign's DIR/failures/*.txt, or a corpus case whose expect lines are to be
// (re)filled -- into a case of the regression corpus (fuzz/corpus_case.hpp):
// runs all pairs of corpus_pairs() on its points (fuzz/corpus_run.hpp) and
// records each outcome class as an expect line.
//
// Refused (exit 1): an exact pair that is not ok / lower-dimensional (a bug to
// fix, not to record), and any pair that reaches its CPU-time limit (a
// timeout depends on the machine, so it is never recorded). Bad input or
// usage (exit 2): an unreadable INPUT or DIR, an existing case without
// --replace, no provenance (give --source).
#pragma once
#include <optional>
#include <ostream>
#include <string>

#include "fuzz/isolation.hpp"

namespace dlab::fuzz {

struct AddOptions {
  std::string input;  // a point file dlab reads ("-": standard input)
  std::string dir;    // the corpus directory (must exist)
  std::optional<std::string> name, source, exercises;  // override the input's
  bool replace = false;
  Limits limits{60};
  unsigned jobs = 1;
};

// Writes DIR/NAME.pts and prints what it recorded. Returns 0, or 1 when
// refused. Throws io::InputError / UsageError for bad input or usage.
int add_corpus_case(const AddOptions& o, std::ostream& out, std::ostream& err);

}  // namespace dlab::fuzz
