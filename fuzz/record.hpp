// One line of DIR/results.jsonl: one case x pair of a campaign. Keys, in this
// fixed order: case, seed, gen, gen_args, n, dim, algo, kernel, exact, outcome,
// kind, detail, counters, predicates, seconds.
//   seed      the case seed (fuzz/case_plan.hpp); gen, gen_args, n, dim: the
//             points (`dlab gen GEN --dim DIM --n N --seed ... GEN_ARGS`; n is
//             the number of points generated)
//   exact     the pair promises ok (any other outcome is a bug)
//   outcome   ok, lower-dimensional, not-delaunay, invalid, reported, differs
//             (variants/outcome.hpp), crash, timeout, out-of-memory (the child
//             process died: fuzz/isolation.hpp)
//   kind      what kind of that outcome, for failure signatures: the invalid
//             check group, the reported message with numbers replaced by '#',
//             the signal of a crash; empty otherwise
//   detail    the one-line detail of the outcome
//   counters, predicates: the run's named counters (variants/run.hpp), those
//             that are not 0, in the run's order
//   seconds   run + classification of this pair (0 with --no-timing)
#pragma once
#include <cstdint>
#include <string>
#include <string_view>

#include "variants/run.hpp"

namespace dlab::fuzz {

struct PairRecord {
  std::uint64_t case_index = 0;
  std::uint64_t seed = 0;
  std::string gen, gen_args;
  std::uint64_t n = 0;
  int dim = 2;
  std::string algo, kernel;
  bool exact = false;
  std::string outcome, kind, detail;
  Counters counters, predicates;
  double seconds = 0;
};

// One JSON object, no newline.
std::string to_json_line(const PairRecord& r);
// Throws std::runtime_error saying what is wrong with the line.
PairRecord parse_json_line(std::string_view line);

}  // namespace dlab::fuzz
