// See meta.hpp.
#include "studies/meta.hpp"

#include <unistd.h>

#include <ctime>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <thread>

namespace dlab::study {
namespace {

std::string cpu_model() {
  std::ifstream in("/proc/cpuinfo");
  std::string line;
  while (std::getline(in, line))
    if (line.rfind("model name", 0) == 0) {
      const auto colon = line.find(':');
      if (colon != std::string::npos) return line.substr(line.find_first_not_of(" \t", colon + 1));
    }
  return "unknown";
}

std::string host_name() {
  char buf[256] = {};
  if (gethostname(buf, sizeof buf - 1) != 0) return "unknown";
  return buf;
}

}  // namespace

std::string utc_now() {
  const std::time_t t = std::time(nullptr);
  std::tm tm{};
  gmtime_r(&t, &tm);
  char buf[32];
  std::strftime(buf, sizeof buf, "%Y-%m-%dT%H:%M:%SZ", &tm);
  return buf;
}

nlohmann::ordered_json environment_json(const BuildInfo& b) {
  nlohmann::ordered_json j;
  j["dlab_version"] = b.version;
  j["git_commit"] = b.commit;
  j["git_dirty"] = b.commit_dirty;
  j["compiler"] = b.compiler;
  j["build_type"] = b.build_type;
  j["compile_flags"] = b.flags;
  j["cpu_model"] = cpu_model();
  j["cpus_online"] = std::thread::hardware_concurrency();
  j["hostname"] = host_name();
  return j;
}

nlohmann::ordered_json new_meta(const StudyConfig& config, const Shard& shard, const BuildInfo& build) {
  nlohmann::ordered_json j;
  j["study"] = config.name;
  j["config_path"] = config.path;
  j["shard"] = std::to_string(shard.k) + "/" + std::to_string(shard.n);
  j["started_utc"] = utc_now();
  j["complete"] = false;
  const nlohmann::ordered_json env = environment_json(build);
  for (const auto& [k, v] : env.items()) j[k] = v;
  j["config"] = config.json;
  return j;
}

nlohmann::ordered_json read_meta(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw ConfigError(path + ": cannot read");
  std::ostringstream text;
  text << in.rdbuf();
  const auto j = nlohmann::ordered_json::parse(text.str(), nullptr, false);
  if (j.is_discarded() || !j.is_object() || !j.contains("config") || !j.contains("shard") ||
      !j["shard"].is_string())
    throw ConfigError(path + ": not the meta.json of a dlab study");
  return j;
}

void write_meta(const std::string& path, const nlohmann::ordered_json& meta) {
  const std::string tmp = path + ".tmp";
  {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    out << meta.dump(2) << "\n";
    if (!out.flush()) throw ConfigError("cannot write '" + tmp + "'");
  }
  std::error_code ec;
  std::filesystem::rename(tmp, path, ec);
  if (ec) throw ConfigError("cannot write '" + path + "': " + ec.message());
}

bool same_config(const nlohmann::ordered_json& a, const nlohmann::ordered_json& b) {
  // Plain json keeps objects sorted by key: equal documents compare equal.
  return nlohmann::json::parse(a.dump()) == nlohmann::json::parse(b.dump());
}

}  // namespace dlab::study
