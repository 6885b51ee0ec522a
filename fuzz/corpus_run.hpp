// Runs corpus cases (fuzz/corpus_case.hpp) x pairs the way a campaign runs its
// cases: in child processes under CPU-time and memory limits, J at a time
// (fuzz/scheduler.hpp), each pair classified by fuzz/case_runner.hpp -- the
// exact validator, and for an exact pair the perturbed reference (`differs`).
// Every pair runs with dlab triangulate's defaults for its kernel (sos for
// exact kernels, strict for the others) and the brio order seeded with the
// case's order-seed.
#pragma once
#include <string>
#include <vector>

#include "fuzz/corpus_case.hpp"
#include "fuzz/isolation.hpp"
#include "fuzz/record.hpp"

namespace dlab::fuzz {

// DLAB_FUZZ_SELFTEST (fuzz/selftest.hpp) applies, CASE being the position of
// a case in `cases`. Returns the records, [case][pair], in the given orders;
// `seconds` is 0. Throws UsageError for a malformed DLAB_FUZZ_SELFTEST.
std::vector<std::vector<PairRecord>> run_corpus_cases(const std::vector<CorpusCase>& cases,
                                                      const std::vector<Pair>& pairs, const Limits& limits,
                                                      unsigned jobs);

// The stderr warning when DLAB_FUZZ_SELFTEST is set; empty when it is not.
std::string corpus_selftest_warning();

}  // namespace dlab::fuzz
