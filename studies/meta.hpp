// DIR/meta.json: what makes a study reproducible from its own output -- the
// configuration as given, the shard, and where and with what it ran: dlab's
// version and git commit, compiler and flags, CPU model, host name, dates (UTC).
#pragma once
#include <string>

#include <nlohmann/json.hpp>

#include "studies/config.hpp"
#include "studies/matrix.hpp"

namespace dlab::study {

// What the `dlab` binary knows about its own build (cli/version.hpp.in).
struct BuildInfo {
  std::string version, commit, compiler, build_type, flags;
  bool commit_dirty = false;
};

// "2025-11-23T17:45:12Z".
std::string utc_now();

// The machine and build part of meta.json (no config, no shard).
nlohmann::ordered_json environment_json(const BuildInfo& build);

// A new study's meta.json ("complete": false until the last run is written).
nlohmann::ordered_json new_meta(const StudyConfig& config, const Shard& shard, const BuildInfo& build);

// Reads DIR/meta.json; throws ConfigError naming the file when it is not one.
nlohmann::ordered_json read_meta(const std::string& path);
// Writes it whole (through a temporary file renamed over it).
void write_meta(const std::string& path, const nlohmann::ordered_json& meta);

// The same study: equal configurations, key order and spacing aside.
bool same_config(const nlohmann::ordered_json& a, const nlohmann::ordered_json& b);

}  // namespace dlab::study
