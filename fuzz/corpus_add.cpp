// See corpus_add.hpp.
#include "fuzz/corpus_add.hpp"

#include <unistd.h>

#include <cerrno>
#include <charconv>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>

#include "cli/point_reader.hpp"
#include "fuzz/corpus_case.hpp"
#include "fuzz/corpus_run.hpp"
#include "fuzz/fuzz_outcome.hpp"

namespace dlab::fuzz {
namespace {

namespace fs = std::filesystem;

// What the comment lines of a campaign's failure file (fuzz/failures.cpp) say,
// and of `dlab shrink`'s output (cli/cmd_shrink.cpp), which keeps its input's
// lines, the replay command as "unshrunk replay:".
struct FailureComments {
  std::string failure;  // "ALGO x KERNEL, 2D: OUTCOME (kind)"
  std::string first_seen, replay, unshrunk_replay;
  std::string shrunk;   // dlab shrink's "shrunk: yes: ..." (its description)
  std::optional<std::uint64_t> order_seed;  // the replay command's --seed
};

std::string_view after(std::string_view line, std::string_view prefix) {
  return line.rfind(prefix, 0) == 0 ? line.substr(prefix.size()) : std::string_view{};
}

FailureComments read_failure_comments(std::string_view text) {
  FailureComments f;
  for (std::size_t pos = 0; pos < text.size();) {
    const std::size_t nl = std::min(text.find('\n', pos), text.size());
    std::string_view l = text.substr(pos, nl - pos);
    pos = nl + 1;
    while (!l.empty() && (l.back() == '\r' || l.back() == ' ')) l.remove_suffix(1);
    if (l.empty() || l.front() != '#') continue;
    l.remove_prefix(1);
    while (!l.empty() && l.front() == ' ') l.remove_prefix(1);
    if (auto v = after(l, "dlab fuzz failure: "); !v.empty()) f.failure = v;
    if (l.rfind("first seen in case ", 0) == 0) f.first_seen = l;
    if (auto v = after(l, "shrunk: yes: "); !v.empty()) f.shrunk = v;
    if (auto v = after(l, "unshrunk replay: "); !v.empty()) f.unshrunk_replay = v;
    if (auto v = after(l, "replay: "); !v.empty()) {
      f.replay = v;
      // The insertion order's seed: the --seed given to dlab triangulate.
      const auto tri = v.find("dlab triangulate");
      const auto seed = tri == v.npos ? v.npos : v.find(" --seed ", tri);
      std::uint64_t s = 0;
      if (seed != v.npos && std::from_chars(v.data() + seed + 8, v.data() + v.size(), s).ec == std::errc())
        f.order_seed = s;
    }
  }
  return f;
}

// The case as it will be written, before its expect lines.
CorpusCase case_from_input(const AddOptions& o) {
  const std::string text = io::read_file(o.input);
  const std::string shown = io::display_name(o.input);
  CorpusCase c;
  if (has_corpus_header(text)) {
    c = parse_corpus_case(text, o.input, ExpectLines::any);
    c.expect.clear();
  } else {
    c.points = io::parse_points(text, shown, io::is_node_file(o.input));
    if (c.points.size() == 0) throw io::InputError(shown + ": no points");
    c.dimension = c.points.dimension;
    const FailureComments f = read_failure_comments(text);
    const std::string& replay = f.unshrunk_replay.empty() ? f.replay : f.unshrunk_replay;
    if (!f.first_seen.empty())
      c.source = "dlab fuzz, " + f.first_seen + (replay.empty() ? "" : "; replay: " + replay) +
                 (f.shrunk.empty() ? "" : "; then dlab shrink");
    if (!f.failure.empty())
      c.exercises = "the " + f.failure + " failure found by dlab fuzz" +
                    (f.shrunk.empty() ? "" : ", shrunk (" + f.shrunk + ")");
    if (f.order_seed) c.order_seed = *f.order_seed;
    if (o.input != "-") c.name = fs::path(o.input).stem().string();
  }
  if (o.name) c.name = *o.name;
  if (o.source) c.source = *o.source;
  if (o.exercises) c.exercises = *o.exercises;
  c.path.clear();
  if (c.name.empty()) throw UsageError("give --name NAME (the input has none)");
  if (!valid_case_name(c.name))
    throw UsageError("the case name '" + c.name + "' is not a file name: use letters, digits, '.', '_', '+', '-' (--name)");
  for (auto [key, value] : {std::pair{"source", &c.source}, {"exercises", &c.exercises}}) {
    if (value->empty())
      throw UsageError(std::string("no ") + key + " for the case: give --" + key +
                       " TEXT (the input is not a corpus case nor a dlab fuzz failure file)");
    if (value->find_first_of("\r\n") != std::string::npos) throw UsageError(std::string("--") + key + " must be one line");
  }
  return c;
}

void write_atomically(const fs::path& path, const std::string& text) {
  const fs::path tmp = path.string() + ".tmp" + std::to_string(getpid());
  {
    std::ofstream f(tmp, std::ios::binary | std::ios::trunc);
    if (!f || !(f << text) || !f.flush()) {
      std::error_code ec;
      fs::remove(tmp, ec);
      throw UsageError("cannot write '" + tmp.string() + "'");
    }
  }
  if (std::rename(tmp.c_str(), path.c_str()) != 0) {
    const std::string why = std::strerror(errno);
    std::error_code ec;
    fs::remove(tmp, ec);
    throw UsageError("cannot write '" + path.string() + "': " + why);
  }
}

}  // namespace

int add_corpus_case(const AddOptions& o, std::ostream& out, std::ostream& err) {
  std::error_code ec;
  if (!fs::is_directory(o.dir, ec) || access(o.dir.c_str(), W_OK | X_OK) != 0)
    throw UsageError("--to: '" + o.dir + "' is not a writable directory");
  CorpusCase c = case_from_input(o);
  const fs::path target = fs::path(o.dir) / (c.name + ".pts");
  if (fs::exists(target, ec) && !o.replace)
    throw UsageError("'" + target.string() + "' exists (--replace rewrites it)");

  if (const std::string w = corpus_selftest_warning(); !w.empty()) err << "dlab corpus: " << w << "\n";
  const std::vector<Pair>& pairs = corpus_pairs();
  const auto records = run_corpus_cases({c}, pairs, o.limits, o.jobs).front();
  bool refused = false;
  std::map<std::string, int> inexact;  // outcome -> pairs
  for (std::size_t j = 0; j < pairs.size(); ++j) {
    const PairRecord& r = records[j];
    const std::string detail = r.detail.empty() ? "" : " (" + r.detail + ")";
    if (r.exact && is_failure(r.outcome)) {
      err << "dlab corpus add: " << r.algo << " " << r.kernel << " gave " << r.outcome << detail
          << ": an exact pair must be ok and CGAL-identical; that is a bug to fix, not to record\n";
      refused = true;
    } else if (r.outcome == kTimeout) {
      err << "dlab corpus add: " << r.algo << " " << r.kernel << " timed out" << detail
          << ": a timeout depends on the machine and is not recorded (a pair that spins is a bug: every loop"
          << " must be bounded; on a slow machine raise --timeout)\n";
      refused = true;
    } else if (r.outcome == kCrash || r.outcome == kOutOfMemory) {
      err << "dlab corpus add: warning: " << r.algo << " " << r.kernel << " gave " << r.outcome << detail
          << " (recorded; an inexact pair must report its failure, not crash: design.md section 3)\n";
    }
    c.expect.push_back({r.algo, r.kernel, r.outcome, 0});
    if (!r.exact) ++inexact[r.outcome];
  }
  if (refused) {
    err << "dlab corpus add: refused: nothing written\n";
    return 1;
  }
  write_atomically(target, format_corpus_case(c));
  out << target.string() << ": " << c.points.size() << " points, " << c.dimension << "D, " << pairs.size()
      << " pairs; inexact:";
  for (const auto& [outcome, n] : inexact) out << " " << n << " " << outcome;
  out << "\n";
  return 0;
}

}  // namespace dlab::fuzz
