// See corpus_case.hpp.
#include "fuzz/corpus_case.hpp"

#include <algorithm>
#include <charconv>
#include <filesystem>
#include <map>
#include <sstream>

#include "cli/point_reader.hpp"
#include "cli/point_writer.hpp"
#include "fuzz/fuzz_outcome.hpp"

namespace dlab::fuzz {
namespace {

constexpr std::string_view kKeys[] = {"case", "source", "exercises", "dimension", "order-seed", "expect"};
constexpr std::string_view kAlgorithms[] = {"bowyer-watson", "lawson", "tanemura", "george", "george+exact-sphere",
                                            "george+enclosing-box"};

template <class Range>
std::string join(const Range& r) {
  std::string s;
  for (const auto& x : r) s.append(s.empty() ? "" : ", ").append(x);
  return s;
}

template <class Range>
bool contains(const Range& r, std::string_view x) {
  return std::find(std::begin(r), std::end(r), x) != std::end(r);
}

std::string_view trim(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t' || s.back() == '\r')) s.remove_suffix(1);
  return s;
}

std::vector<std::string_view> words(std::string_view s) {
  std::vector<std::string_view> out;
  for (std::size_t i = 0; i < s.size();) {
    while (i < s.size() && (s[i] == ' ' || s[i] == '\t')) ++i;
    const std::size_t start = i;
    while (i < s.size() && s[i] != ' ' && s[i] != '\t') ++i;
    if (i > start) out.push_back(s.substr(start, i - start));
  }
  return out;
}

// A header line "# key: value": false if `line` (a comment) is not one.
bool split_header_line(std::string_view line, std::string_view& key, std::string_view& value) {
  line.remove_prefix(1);  // '#'
  line = trim(line);
  std::size_t k = 0;
  while (k < line.size() && ((line[k] >= 'a' && line[k] <= 'z') || line[k] == '-')) ++k;
  if (k == 0 || k >= line.size() || line[k] != ':') return false;
  key = line.substr(0, k);
  value = trim(line.substr(k + 1));
  return true;
}

class HeaderParser {
 public:
  HeaderParser(CorpusCase& c, const std::string& name) : c_(c), name_(name) {}

  [[noreturn]] void fail(std::size_t line, const std::string& what) const {
    throw io::InputError(name_ + ":" + std::to_string(line) + ": " + what);
  }

  void line(std::size_t no, std::string_view key, std::string_view value) {
    if (!contains(kKeys, key))
      fail(no, "unknown key '" + std::string(key) + "' (known: " + join(kKeys) + ")");
    if (value.empty()) fail(no, "empty value of '" + std::string(key) + "'");
    if (key == "expect") return expect(no, value);
    if (const auto it = seen_.find(std::string(key)); it != seen_.end())
      fail(no, "duplicate key '" + std::string(key) + "' (first on line " + std::to_string(it->second) + ")");
    seen_[std::string(key)] = no;
    if (key == "case") {
      if (!valid_case_name(value)) fail(no, "case '" + std::string(value) + "' is not a file name ([A-Za-z0-9._+-])");
      c_.name = value;
      c_.name_line = no;
    } else if (key == "source") {
      c_.source = value;
    } else if (key == "exercises") {
      c_.exercises = value;
    } else if (key == "dimension") {
      if (value != "2" && value != "3") fail(no, "dimension must be 2 or 3, not '" + std::string(value) + "'");
      c_.dimension = value[0] - '0';
    } else if (key == "order-seed") {
      const auto [end, ec] = std::from_chars(value.data(), value.data() + value.size(), c_.order_seed);
      if (ec != std::errc() || end != value.data() + value.size())
        fail(no, "order-seed must be an integer in 0..2^64-1, not '" + std::string(value) + "'");
    }
  }

  std::size_t line_of(const std::string& key) const {
    const auto it = seen_.find(key);
    return it == seen_.end() ? 0 : it->second;
  }

 private:
  void expect(std::size_t no, std::string_view value) {
    const auto w = words(value);
    if (w.size() != 3) fail(no, "expect needs ALGO KERNEL OUTCOME, got '" + std::string(value) + "'");
    if (!contains(kAlgorithms, w[0]))
      fail(no, "unknown algorithm '" + std::string(w[0]) + "' (known: " + join(kAlgorithms) + ")");
    if (!contains(kernel_names(), w[1]))
      fail(no, "unknown kernel '" + std::string(w[1]) + "' (known: " + join(kernel_names()) + ")");
    if (w[2] == kTimeout)
      fail(no, "timeout depends on the machine's speed and is never an expected outcome (tests/corpus/README.md)");
    if (!contains(kOutcomeOrder, w[2]))
      fail(no, "unknown outcome '" + std::string(w[2]) + "' (known: " + join(kOutcomeOrder) + ")");
    const Pair p = fuzz::make_pair(std::string(w[0]), std::string(w[1]));
    if (p.exact() && w[2] != "ok" && w[2] != "lower-dimensional")
      fail(no, std::string(w[0]) + " " + std::string(w[1]) +
                   " is an exact pair: it expects ok or lower-dimensional (any other outcome is a bug to fix, "
                   "not to record)");
    const std::string pair = std::string(w[0]) + " " + std::string(w[1]);
    if (const auto it = pairs_.find(pair); it != pairs_.end())
      fail(no, "duplicate expect for " + pair + " (first on line " + std::to_string(it->second) + ")");
    pairs_[pair] = no;
    c_.expect.push_back({std::string(w[0]), std::string(w[1]), std::string(w[2]), no});
  }

  CorpusCase& c_;
  const std::string& name_;
  std::map<std::string, std::size_t> seen_, pairs_;
};

}  // namespace

const Expectation* CorpusCase::expectation(const Pair& p) const {
  const std::string algo = p.algo_name();
  for (const auto& e : expect)
    if (e.algo == algo && e.kernel == p.kernel) return &e;
  return nullptr;
}

const std::vector<Pair>& corpus_pairs() {
  static const std::vector<Pair> pairs = [] {
    std::vector<Pair> v;
    for (const auto a : kAlgorithms)
      for (const auto& k : kernel_names()) v.push_back(fuzz::make_pair(std::string(a), k));
    return v;
  }();
  return pairs;
}

bool valid_case_name(std::string_view name) {
  if (name.empty() || name.size() > 200 || name.front() == '.') return false;
  return std::all_of(name.begin(), name.end(), [](char ch) {
    return (ch >= 'a' && ch <= 'z') || (ch >= 'A' && ch <= 'Z') || (ch >= '0' && ch <= '9') || ch == '.' ||
           ch == '_' || ch == '+' || ch == '-';
  });
}

bool has_corpus_header(std::string_view text) {
  std::istringstream in{std::string(text.substr(0, std::min<std::size_t>(text.size(), 1 << 16)))};
  for (std::string l; std::getline(in, l);) {
    const std::string_view t = trim(l);
    if (t.empty()) continue;
    if (t.front() != '#') return false;
    std::string_view key, value;
    if (split_header_line(t, key, value) && key == "case") return true;
  }
  return false;
}

CorpusCase parse_corpus_case(std::string_view text, const std::string& path, ExpectLines rule) {
  CorpusCase c;
  c.path = path;
  const std::string name = io::display_name(path);
  HeaderParser header(c, name);
  std::size_t no = 0, first_data = 0;
  for (std::size_t pos = 0; pos < text.size();) {
    const std::size_t nl = std::min(text.find('\n', pos), text.size());
    const std::string_view l = trim(text.substr(pos, nl - pos));
    pos = nl + 1;
    ++no;
    if (l.empty()) continue;
    if (l.front() != '#') {
      if (first_data == 0) first_data = no;
      continue;
    }
    if (first_data != 0)
      header.fail(no, "a comment after the points (the header of `# key: value` lines comes first)");
    std::string_view key, value;
    if (!split_header_line(l, key, value)) header.fail(no, "not a `# key: value` header line");
    header.line(no, key, value);
  }
  c.header_end = first_data != 0 ? first_data : no + 1;
  for (const char* key : {"case", "source", "exercises", "dimension"})
    if (header.line_of(key) == 0) header.fail(c.header_end, std::string("missing `# ") + key + ":` in the header");
  c.points = io::parse_points(text, name, false);
  if (c.points.size() == 0) header.fail(c.header_end, "no points");
  if (c.points.dimension != c.dimension)
    header.fail(header.line_of("dimension"), "dimension " + std::to_string(c.dimension) + " but the points have " +
                                                 std::to_string(c.points.dimension) + " coordinates");
  if (rule == ExpectLines::all)
    for (const Pair& p : corpus_pairs())
      if (!c.expectation(p))
        header.fail(c.header_end, "no expect line for " + p.algo_name() + " " + p.kernel +
                                      " (every case states all " + std::to_string(corpus_pairs().size()) +
                                      " pairs; dlab corpus add FILE --to DIR --replace fills them)");
  return c;
}

CorpusCase read_corpus_case(const std::string& path) {
  CorpusCase c = parse_corpus_case(io::read_file(path), path, ExpectLines::all);
  const std::string stem = std::filesystem::path(path).stem().string();
  if (c.name != stem)
    throw io::InputError(io::display_name(path) + ":" + std::to_string(c.name_line) + ": case '" + c.name +
                         "' but the file is named " + stem + ".pts");
  return c;
}

std::string format_corpus_case(const CorpusCase& c) {
  std::ostringstream out;
  out << "# case: " << c.name << "\n# source: " << c.source << "\n# exercises: " << c.exercises
      << "\n# dimension: " << c.dimension << "\n";
  if (c.order_seed != 0) out << "# order-seed: " << c.order_seed << "\n";
  for (const Pair& p : corpus_pairs())
    if (const Expectation* e = c.expectation(p)) out << "# expect: " << e->algo << " " << e->kernel << " " << e->outcome << "\n";
  io::write_points(out, c.points, io::FloatFormat::hex);
  return out.str();
}

}  // namespace dlab::fuzz
