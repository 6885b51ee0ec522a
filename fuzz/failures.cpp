// See failures.hpp.
#include "fuzz/failures.hpp"

#include <cstdio>
#include <filesystem>
#include <optional>
#include <sstream>

#include "cli/mesh_picture.hpp"
#include "cli/point_writer.hpp"
#include "fuzz/campaign_files.hpp"
#include "fuzz/case_plan.hpp"
#include "fuzz/failure_mesh.hpp"
#include "fuzz/fuzz_outcome.hpp"
#include "fuzz/shrink.hpp"

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

ShrunkFailure shrink_failure(const PointSet& points, const Pair& pair, std::uint64_t order_seed,
                             const FailureClass& failure, const Limits& limits) {
  ShrunkFailure out;
  const ChildOracle oracle(pair, order_seed, limits);
  const Observed first = oracle.observe(points);
  out.points = points;
  if (!failure.matches(first)) {
    out.note = "no: in a fresh child the case gave " + FailureClass{first.outcome, first.kind}.describe() +
               ", not " + failure.describe();
    return out;
  }
  ShrinkLimits lim;
  const bool slow = failure.outcome == kTimeout || failure.outcome == kOutOfMemory;
  lim.max_tests = (slow ? kCampaignShrinkSlowTests : kCampaignShrinkTests) - 2;  // + the first and last runs
  ShrinkReport r = shrink(points, [&](const PointSet& p) { return failure.matches(oracle.observe(p)); }, lim);
  const Observed last = oracle.observe(r.points);
  r.tests += 2;
  out.points = r.points;
  out.shrunk = true;
  out.detail = last.detail;
  out.note = "yes: " + describe(r) + " (at most " + std::to_string(lim.max_tests + 2) + " in a campaign)";
  if (!failure.matches(last))
    out.note += "; but run again it gave " + FailureClass{last.outcome, last.kind}.describe() + " (flaky)";
  return out;
}

void FailureIndex::add(const PairRecord& r) {
  if (!is_failure(r.outcome)) return;
  First& f = first_[Signature{r.algo, r.kernel, r.dim, r.outcome, r.kind}];
  if (f.count++ == 0 || r.case_index < f.record.case_index) f.record = r;
}

std::size_t FailureIndex::write(const std::string& dir, const CampaignSpec& spec, const Limits& limits) const {
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
    const ShrunkFailure shrunk =
        shrink_failure(gen::generate(plan.gen), pair, plan.order_seed, FailureClass{r.outcome, r.kind}, limits);
    // A picture of the mesh the pair makes of the points written, where it
    // makes one: not-delaunay and invalid results.
    std::optional<cli::MeshPicture> picture;
    fs::path picture_file;
    if (r.outcome == "not-delaunay" || r.outcome == "invalid") {
      if (const auto mesh = failure_mesh(shrunk.points, pair, plan.order_seed, limits)) {
        picture = cli::mesh_picture(mesh->points, mesh->simplices);
        picture_file = folder / (sig.file_stem() + picture->extension);
      }
    }
    std::ostringstream out;
    out << "# dlab fuzz failure: " << r.algo << " x " << r.kernel << ", " << r.dim << "D: " << r.outcome
        << (r.kind.empty() ? "" : " (" + r.kind + ")") << "\n"
        << "# detail: " << r.detail << "\n"
        << "# first seen in case " << r.case_index << " (case seed "
        << r.seed << ", campaign seed " << spec.seed << "), " << r.gen << " n=" << r.n
        << (r.gen_args.empty() ? "" : " " + r.gen_args) << "\n"
        << "# replay: " << replay_command(plan, pair) << "\n"
        << "# shrunk: " << shrunk.note << "\n"
        << (shrunk.shrunk ? "# detail of the points below: " + shrunk.detail + "\n" : "")
        << "# replay the points below: dlab triangulate failures/" << file.filename().string()
        << triangulate_options(pair, plan.order_seed) << "   (from DIR)\n";
    if (picture)
      out << "# picture of their mesh, faults marked by the exact validator: failures/"
          << picture_file.filename().string() << "\n";
    io::write_points(out, shrunk.points, io::FloatFormat::hex);
    write_text_file(file.string(), out.str());
    if (picture) write_text_file(picture_file.string(), picture->text);
    ++written;
  }
  return written;
}

}  // namespace dlab::fuzz
