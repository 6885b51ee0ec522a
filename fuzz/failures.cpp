// See failures.hpp.
#include "fuzz/failures.hpp"

#include <cstdio>
#include <filesystem>
#include <sstream>

#include "cli/point_writer.hpp"
#include "fuzz/campaign_files.hpp"
#include "fuzz/case_plan.hpp"
#include "fuzz/fuzz_outcome.hpp"

namespace dlab::fuzz {
namespace {

std::string clean(std::string_view s, std::size_t max) {
  std::string o;
  for (char c : s) {
    const char l = (c >= 'A' && c <= 'Z') ? static_cast<char>(c - 'A' + 'a') : c;
    const bool keep = (l >= 'a' && l <= 'z') || (l >= '0' && l <= '9') || l == '+';
    if (keep)
      o += l;
    else if (!o.empty() && o.back() != '-')
      o += '-';
    if (o.size() >= max) break;
  }
  while (!o.empty() && o.back() == '-') o.pop_back();
  return o;
}

}  // namespace

std::string Signature::file_stem() const {
  std::string s = clean(algo, 40) + "." + clean(kernel, 20) + "." + std::to_string(dim) + "d." + clean(outcome, 20);
  if (!kind.empty()) {
    std::uint32_t h = 2166136261u;  // FNV-1a
    for (unsigned char c : kind) h = (h ^ c) * 16777619u;
    char hex[9];
    std::snprintf(hex, sizeof hex, "%08x", h);
    s.append(".").append(clean(kind, 40)).append("-").append(hex);
  }
  return s;
}

PointSet shrink_failure(const PointSet& points, const Pair&, std::string_view, bool& shrunk) {
  shrunk = false;
  return points;
}

void FailureIndex::add(const PairRecord& r) {
  if (!is_failure(r.outcome)) return;
  First& f = first_[Signature{r.algo, r.kernel, r.dim, r.outcome, r.kind}];
  if (f.count++ == 0 || r.case_index < f.record.case_index) f.record = r;
}

std::size_t FailureIndex::write(const std::string& dir, const CampaignSpec& spec) const {
  namespace fs = std::filesystem;
  const fs::path folder = fs::path(dir) / "failures";
  std::error_code ec;
  fs::create_directories(folder, ec);
  if (ec) throw UsageError("cannot create '" + folder.string() + "': " + ec.message());
  std::size_t written = 0;
  for (const auto& [sig, first] : first_) {
    const fs::path file = folder / (sig.file_stem() + ".txt");
    if (fs::exists(file)) continue;
    const PairRecord& r = first.record;
    const CasePlan plan = plan_case(spec, r.case_index);
    const Pair pair = make_pair(r.algo, r.kernel);
    bool shrunk = false;
    const PointSet points = shrink_failure(gen::generate(plan.gen), pair, r.outcome, shrunk);
    std::ostringstream out;
    out << "# dlab fuzz failure: " << r.algo << " x " << r.kernel << ", " << r.dim << "D: " << r.outcome
        << (r.kind.empty() ? "" : " (" + r.kind + ")") << "\n"
        << "# detail: " << r.detail << "\n"
        << "# first seen in case " << r.case_index << " (case seed "
        << r.seed << ", campaign seed " << spec.seed << "), " << r.gen << " n=" << r.n
        << (r.gen_args.empty() ? "" : " " + r.gen_args) << "\n"
        << "# replay: " << replay_command(plan, pair) << "\n"
        << "# shrunk: " << (shrunk ? "yes" : "no (the shrinker's hook: fuzz/failures.hpp shrink_failure)") << "\n";
    io::write_points(out, points, io::FloatFormat::hex);
    write_text_file(file.string(), out.str());
    ++written;
  }
  return written;
}

}  // namespace dlab::fuzz
