// See campaign_files.hpp.
#include "fuzz/campaign_files.hpp"

#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

namespace dlab::fuzz {
namespace {

using Json = nlohmann::ordered_json;

constexpr const char* kFormat = "dlab-fuzz-campaign 1";

std::string list_text(const std::vector<std::string>& v) {
  std::string s;
  for (const auto& x : v) s += (s.empty() ? "" : ",") + x;
  return s;
}

// "{\"case\":123," -> 123; false if the line does not start so.
bool case_of(const std::string& line, std::uint64_t& out) {
  static const std::string prefix = "{\"case\":";
  if (line.compare(0, prefix.size(), prefix) != 0) return false;
  std::uint64_t v = 0;
  std::size_t i = prefix.size(), digits = 0;
  for (; i < line.size() && line[i] >= '0' && line[i] <= '9' && digits < 20; ++i, ++digits)
    v = v * 10 + static_cast<std::uint64_t>(line[i] - '0');
  if (digits == 0 || i >= line.size() || line[i] != ',') return false;
  out = v;
  return true;
}

}  // namespace

std::string campaign_json(const StoredCampaign& c) {
  Json j;
  j["format"] = kFormat;
  j["algo"] = c.spec.algorithms;
  j["kernel"] = c.spec.kernels;
  j["gen"] = c.spec.generators;
  j["dim"] = c.spec.dim;
  j["n"] = {c.spec.n_lo, c.spec.n_hi};
  j["seed"] = c.spec.seed;
  j["shard"] = {c.spec.shard, c.spec.shards};
  j["cpu_seconds"] = static_cast<std::uint64_t>(c.limits.cpu_seconds);
  j["memory_mib"] = c.limits.memory_bytes >> 20;
  j["selftest"] = c.spec.selftest;
  j["cases"] = c.cases ? Json(*c.cases) : Json(nullptr);
  return j.dump() + "\n";
}

StoredCampaign read_campaign_json(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw UsageError("cannot read '" + path + "'");
  std::stringstream ss;
  ss << in.rdbuf();
  StoredCampaign c;
  try {
    const Json j = Json::parse(ss.str());
    if (j.at("format") != kFormat) throw UsageError("'" + path + "' is not a dlab fuzz campaign file");
    c.spec.algorithms = j.at("algo").get<std::vector<std::string>>();
    c.spec.kernels = j.at("kernel").get<std::vector<std::string>>();
    c.spec.generators = j.at("gen").get<std::vector<std::string>>();
    c.spec.dim = j.at("dim").get<int>();
    c.spec.n_lo = j.at("n").at(0).get<std::uint64_t>();
    c.spec.n_hi = j.at("n").at(1).get<std::uint64_t>();
    c.spec.seed = j.at("seed").get<std::uint64_t>();
    c.spec.shard = j.at("shard").at(0).get<std::uint64_t>();
    c.spec.shards = j.at("shard").at(1).get<std::uint64_t>();
    c.limits.cpu_seconds = static_cast<double>(j.at("cpu_seconds").get<std::uint64_t>());
    c.limits.memory_bytes = j.at("memory_mib").get<std::uint64_t>() << 20;
    c.spec.selftest = j.at("selftest").get<std::string>();
    if (!j.at("cases").is_null()) c.cases = j.at("cases").get<std::uint64_t>();
  } catch (const Json::exception& e) {
    throw UsageError("'" + path + "' is malformed: " + e.what());
  }
  if (c.spec.shard < 1 || c.spec.shard > c.spec.shards || c.spec.n_lo < 1 || c.spec.n_lo > c.spec.n_hi)
    throw UsageError("'" + path + "' is malformed: bad shard or n range");
  return c;
}

std::string campaign_difference(const StoredCampaign& there, const StoredCampaign& here, bool ignore_shard) {
  const auto& a = there.spec;
  const auto& b = here.spec;
  const auto diff = [](const std::string& what, const std::string& x, const std::string& y) {
    return what + ": " + (x.empty() ? "none" : x) + " there, " + (y.empty() ? "none" : y) + " here";
  };
  if (a.algorithms != b.algorithms) return diff("--algo", list_text(a.algorithms), list_text(b.algorithms));
  if (a.kernels != b.kernels) return diff("--kernel", list_text(a.kernels), list_text(b.kernels));
  if (a.generators != b.generators) return diff("--gen", list_text(a.generators), list_text(b.generators));
  if (a.dim != b.dim) return diff("--dim", std::to_string(a.dim), std::to_string(b.dim));
  if (a.n_lo != b.n_lo || a.n_hi != b.n_hi)
    return diff("--n", std::to_string(a.n_lo) + ".." + std::to_string(a.n_hi),
                std::to_string(b.n_lo) + ".." + std::to_string(b.n_hi));
  if (a.seed != b.seed) return diff("--seed", std::to_string(a.seed), std::to_string(b.seed));
  if (!ignore_shard && (a.shard != b.shard || a.shards != b.shards))
    return diff("--shard", std::to_string(a.shard) + "/" + std::to_string(a.shards),
                std::to_string(b.shard) + "/" + std::to_string(b.shards));
  if (there.limits.cpu_seconds != here.limits.cpu_seconds)
    return diff("--timeout", std::to_string(static_cast<std::uint64_t>(there.limits.cpu_seconds)),
                std::to_string(static_cast<std::uint64_t>(here.limits.cpu_seconds)));
  if (there.limits.memory_bytes != here.limits.memory_bytes)
    return diff("--memory", std::to_string(there.limits.memory_bytes >> 20),
                std::to_string(here.limits.memory_bytes >> 20));
  if (a.selftest != b.selftest) return diff("DLAB_FUZZ_SELFTEST", a.selftest, b.selftest);
  return "";
}

ResultsScan scan_results(const std::string& path, const CampaignSpec& spec, std::size_t pairs) {
  ResultsScan s;
  std::ifstream in(path, std::ios::binary);
  if (!in) return s;  // no results yet
  std::string line;
  std::uint64_t line_no = 0, offset = 0, in_group = 0;
  while (std::getline(in, line)) {
    ++line_no;
    const bool complete = !in.eof();  // getline stopped at a newline
    const std::uint64_t next_offset = offset + line.size() + (complete ? 1 : 0);
    std::uint64_t c = 0;
    if (!complete) {  // torn by an interruption: redone
      s.dropped_lines += 1 + in_group;
      return s;
    }
    if (!case_of(line, c))
      throw UsageError(path + ":" + std::to_string(line_no) + ": not a dlab fuzz record");
    if (c != spec.case_index(s.cases))
      throw UsageError(path + ":" + std::to_string(line_no) + ": case " + std::to_string(c) + " where case " +
                       std::to_string(spec.case_index(s.cases)) + " was expected (a different campaign or shard?)");
    offset = next_offset;
    if (++in_group == pairs) {
      ++s.cases;
      s.bytes = offset;
      in_group = 0;
    }
  }
  s.dropped_lines += in_group;
  return s;
}

void for_each_record(const std::string& path, const std::function<void(const PairRecord&)>& f) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw UsageError("cannot read '" + path + "'");
  std::string line;
  std::uint64_t line_no = 0;
  while (std::getline(in, line)) {
    ++line_no;
    if (in.eof()) throw UsageError(path + ":" + std::to_string(line_no) + ": incomplete last line");
    try {
      f(parse_json_line(line));
    } catch (const std::runtime_error& e) {
      if (dynamic_cast<const UsageError*>(&e)) throw;
      throw UsageError(path + ":" + std::to_string(line_no) + ": " + e.what());
    }
  }
}

void write_text_file(const std::string& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  if (!out || !(out << text) || !out.flush()) throw UsageError("cannot write '" + path + "'");
}

}  // namespace dlab::fuzz
