// One case of the degeneracy regression corpus (tests/corpus/README.md): a
// file NAME.pts holding a header of `# key: value` lines, then the points, one
// per line, in hexadecimal floats. Keys:
//   case        NAME (the file name without .pts)
//   source      provenance: a public issue or paper with its link, or the campaign
//   exercises   what the case tests, one line
//   dimension   2 or 3 (the points' dimension)
//   order-seed  optional: the seed of the brio insertion order of every pair (0)
//   expect      repeated: ALGO KERNEL OUTCOME, one per pair of corpus_pairs()
// Anything else in the header is an error "FILE:LINE: problem" (io::InputError,
// exit 2): an unknown key, a malformed or duplicate expect line, an unknown
// algorithm, kernel or outcome, a `timeout` (it depends on the machine), an
// exact pair expecting a failure, a missing key.
#pragma once
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "fuzz/campaign_spec.hpp"
#include "variants/run.hpp"

namespace dlab::fuzz {

struct Expectation {
  std::string algo, kernel, outcome;
  std::size_t line = 0;  // in the case file
};

struct CorpusCase {
  std::string path;  // as given (messages)
  std::string name, source, exercises;
  int dimension = 2;
  std::uint64_t order_seed = 0;
  std::vector<Expectation> expect;  // as in the file
  PointSet points;
  // The first line after the header (a missing key is reported there).
  std::size_t header_end = 1;
  std::size_t name_line = 0;  // of `# case:`

  // The expectation of pair `p`, or nullptr.
  const Expectation* expectation(const Pair& p) const;
};

// The full matrix every case states: the fuzzer's algorithms (bowyer-watson,
// lawson, tanemura, george, george+exact-sphere, george+enclosing-box) x every
// kernel (adaptive, integer, mp, float, epsilon), algorithm-major.
const std::vector<Pair>& corpus_pairs();

// True if `text` starts with a corpus header: its leading comment lines hold a
// `# case:` line.
bool has_corpus_header(std::string_view text);

enum class ExpectLines { all, any };  // all: every pair of corpus_pairs() must have one

// Parses a case file's text; `path` names it in messages. Throws io::InputError.
CorpusCase parse_corpus_case(std::string_view text, const std::string& path, ExpectLines rule);
// Reads and parses FILE; also checks that `case` is the file's name.
CorpusCase read_corpus_case(const std::string& path);

// The file's text: header (case, source, exercises, dimension, order-seed if
// not 0, the expect lines in corpus_pairs() order), then the points in %a.
std::string format_corpus_case(const CorpusCase& c);

// A name usable as NAME.pts: letters, digits, '.', '_', '+', '-'; not starting with '.'.
bool valid_case_name(std::string_view name);

}  // namespace dlab::fuzz
