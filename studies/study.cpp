// See study.hpp.
#include "studies/study.hpp"

#include <fcntl.h>
#include <poll.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstring>
#include <filesystem>
#include <map>
#include <optional>
#include <set>

#include "fuzz/campaign_spec.hpp"
#include "studies/columns.hpp"
#include "studies/inputs.hpp"
#include "studies/progress.hpp"
#include "studies/run_child.hpp"
#include "studies/runs_file.hpp"
#include "variants/outcome.hpp"
#if DLAB_STUDY_BASELINES
#include "studies/baselines.hpp"
#endif

namespace dlab::study {
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

std::string runs_path(const std::string& dir) { return (fs::path(dir) / "runs.csv").string(); }
std::string meta_path(const std::string& dir) { return (fs::path(dir) / "meta.json").string(); }

std::string shard_text(const Shard& s) { return std::to_string(s.k) + "/" + std::to_string(s.n); }

// Creates DIR if needed; returns its meta.json: the one there (same config and
// shard, else an error) or a new one.
nlohmann::ordered_json prepare_directory(const StudyOptions& o) {
  std::error_code ec;
  fs::create_directories(o.dir, ec);
  if (ec || !fs::is_directory(o.dir))
    throw ConfigError("cannot use '" + o.dir + "' as the study directory" + (ec ? ": " + ec.message() : ""));
  if (access(o.dir.c_str(), R_OK | W_OK | X_OK) != 0)
    throw ConfigError("cannot read and write '" + o.dir + "': " + std::strerror(errno));
  if (!fs::exists(meta_path(o.dir))) {
    if (fs::exists(runs_path(o.dir)))
      throw ConfigError("'" + runs_path(o.dir) + "' exists without meta.json: not a study directory");
    return new_meta(o.config, o.shard, o.build);
  }
  nlohmann::ordered_json meta = read_meta(meta_path(o.dir));
  if (!same_config(meta["config"], o.config.json))
    throw ConfigError("'" + o.dir + "' holds a study of another configuration (its meta.json has the config " +
                      "it was started with); use another --out");
  if (meta["shard"] != shard_text(o.shard))
    throw ConfigError("'" + o.dir + "' holds shard " + meta["shard"].get<std::string>() + " of this study, not " +
                      shard_text(o.shard));
  return meta;
}

void append_all(int fd, const std::string& s, const std::string& path) {
  std::size_t done = 0;
  while (done < s.size()) {
    const ssize_t w = ::write(fd, s.data() + done, s.size() - done);
    if (w < 0 && errno == EINTR) continue;
    if (w <= 0) throw ConfigError("error writing '" + path + "': " + std::strerror(errno));
    done += static_cast<std::size_t>(w);
  }
}

bool is_failure(const std::string& outcome) { return outcome != "ok" && outcome != "lower-dimensional"; }

// A row of a pair that promises a Delaunay result, with a failure outcome.
bool exact_failure(const std::string& row) {
  if (field(row, "tool") != "dlab" || !is_failure(field(row, "outcome"))) return false;
  return pair_is_exact(fuzz::make_pair(field(row, "algorithm"), field(row, "kernel")).options(0));
}

// Outcome counts and the exact pairs' failures of a runs.csv; 1 if there is one.
int summarize(const std::string& path, std::ostream& out) {
  const RunsFile f = read_runs(path);
  std::map<std::string, std::uint64_t> outcomes;
  std::vector<std::string> bugs;
  for (const auto& [id, row] : f.rows) {
    ++outcomes[field(row, "outcome")];
    if (exact_failure(row))
      bugs.push_back("run " + std::to_string(id) + " (" + field(row, "algorithm") + " x " + field(row, "kernel") +
                     ", " + field(row, "input") + " n=" + field(row, "n") + " seed " + field(row, "seed") +
                     "): " + field(row, "outcome") + ": " + field(row, "message"));
  }
  out << path << ": " << f.rows.size() << " rows;";
  for (const auto& [o, c] : outcomes) out << " " << o << " " << c;
  out << "\n";
  for (std::size_t i = 0; i < bugs.size() && i < 20; ++i) out << "exact pair failed: " << bugs[i] << "\n";
  if (bugs.size() > 20) out << "... and " << bugs.size() - 20 << " more exact-pair failures\n";
  out.flush();
  return bugs.empty() ? 0 : 1;
}

// The baselines of the config that cannot run here, with the reason; one notice each.
std::map<std::string, std::string> unavailable_baselines(const StudyConfig& c, std::ostream& err) {
  std::map<std::string, std::string> out;
  for (const auto& b : c.baselines) {
#if DLAB_STUDY_BASELINES
    if (auto why = baseline_unavailable(b)) out[b] = *why;
#else
    out[b] = "the external baselines are not part of this build";
#endif
    if (out.count(b)) err << "dlab study: skipping baseline " << b << ": " << out[b] << " (no rows)\n";
  }
  return out;
}

}  // namespace

int run_study(StudyOptions o, std::ostream& out, std::ostream& err) {
  if (o.jobs < 1) o.jobs = 1;
  check_inputs(o.config);
  nlohmann::ordered_json meta = prepare_directory(o);
  const std::string runs = runs_path(o.dir);

  std::vector<RunSpec> mine;
  std::map<std::uint64_t, const RunSpec*> by_id;
  for (RunSpec& r : expand_matrix(o.config))
    if (o.shard.has(r.id)) mine.push_back(std::move(r));
  for (const RunSpec& r : mine) by_id[r.id] = &r;

  std::set<std::uint64_t> done;
  if (fs::exists(runs)) {
    const RunsFile f = read_runs(runs);
    std::error_code ec;
    fs::resize_file(runs, f.bytes, ec);
    if (ec) throw ConfigError("cannot truncate '" + runs + "': " + ec.message());
    for (const auto& [id, row] : f.rows) {
      if (!by_id.count(id))
        throw ConfigError(runs + ": run " + std::to_string(id) + " is not a run of this study's shard");
      done.insert(id);
    }
    if (!f.rows.empty() || f.partial_line)
      err << "dlab study: resuming after " << f.rows.size() << " rows"
          << (f.partial_line ? " (a cut last line dropped)" : "") << "\n";
  }
  meta["complete"] = false;
  write_meta(meta_path(o.dir), meta);

  const int fd = ::open(runs.c_str(), O_WRONLY | O_CREAT | O_APPEND | O_CLOEXEC, 0644);
  if (fd < 0) throw ConfigError("cannot write '" + runs + "': " + std::strerror(errno));
  struct Closer {
    int fd;
    ~Closer() { ::close(fd); }
  } closer{fd};
  if (fs::file_size(runs) == 0) append_all(fd, csv_header() + "\n", runs);

  const auto unavailable = unavailable_baselines(o.config, err);
  std::vector<const RunSpec*> todo;
  for (const RunSpec& r : mine)
    if (!done.count(r.id) && !(r.is_baseline() && unavailable.count(r.tool))) todo.push_back(&r);

  // Rows go to the file in id order: a finished run waits in `ready` for the
  // runs before it (nullopt: skipped, no row).
  std::map<std::uint64_t, std::optional<std::string>> ready;
  std::size_t next_to_write = 0, next_to_start = 0;
  std::uint64_t finished = 0, not_ok = 0;
  std::set<std::string> unknown_names;
  std::vector<RunChild> active;
  Progress progress(done.size() + todo.size(), done.size());
  const double wall_limit = 10 * o.config.timeout_seconds + 10;
  const auto t0 = Clock::now();

  auto write_ready = [&] {
    while (next_to_write < todo.size()) {
      const auto it = ready.find(todo[next_to_write]->id);
      if (it == ready.end()) break;
      if (it->second) append_all(fd, *it->second + "\n", runs);
      ready.erase(it);
      ++next_to_write;
    }
  };

  try {
    while (next_to_write < todo.size()) {
      while (active.size() < o.jobs && next_to_start < todo.size())
        active.emplace_back(o.config, *todo[next_to_start++]);
      std::vector<pollfd> fds;
      for (const RunChild& c : active) fds.push_back({c.fd(), POLLIN, 0});
      if (::poll(fds.data(), fds.size(), 200) < 0 && errno != EINTR)
        throw ConfigError(std::string("poll: ") + std::strerror(errno));
      for (std::size_t i = active.size(); i-- > 0;) {
        RunChild& c = active[i];
        if (fds[i].revents == 0) {
          if (std::chrono::duration<double>(Clock::now() - c.started()).count() > wall_limit)
            c.kill_for_wall_time();
          continue;
        }
        if (c.read()) continue;
        const RunSpec& spec = *by_id.at(c.id());
        RunChild::Result r = c.finish(o.config.timeout_seconds, o.config.memory_limit_mib);
        active.erase(active.begin() + static_cast<std::ptrdiff_t>(i));
        if (!r.error.empty()) throw ConfigError(r.error);
        if (!r.interrupted.empty())
          throw ConfigError("run " + std::to_string(spec.id) + " was interrupted by " + r.interrupted +
                            "; the same command resumes the study");
        if (!r.measure) {
          err << "dlab study: run " << spec.id << " (" << spec.tool << " on " << o.config.inputs[spec.input].label
              << ") skipped: " << r.skipped << "\n";
          ready[spec.id] = std::nullopt;
        } else {
          std::vector<std::string> unknown;
          ready[spec.id] = csv_row(o.config, spec, *r.measure, &unknown);
          for (const auto& name : unknown)
            if (unknown_names.insert(name).second)
              err << "dlab study: counter '" << name << "' has no column (studies/columns.cpp); dropped\n";
          if (is_failure(r.measure->outcome)) ++not_ok;
        }
        ++finished;
      }
      write_ready();
      progress.update(finished, not_ok);
    }
  } catch (...) {
    write_ready();
    progress.finish();
    throw;
  }
  progress.finish();
  const double seconds = std::chrono::duration<double>(Clock::now() - t0).count();
  meta["complete"] = true;
  meta["finished_utc"] = utc_now();
  write_meta(meta_path(o.dir), meta);
  err << "dlab study: " << finished << " runs in " << seconds << " s with " << o.jobs << " job"
      << (o.jobs == 1 ? "" : "s") << "\n";
  return summarize(runs, out);
}

int merge_studies(const std::vector<std::string>& dirs, const std::string& out_dir, const BuildInfo& build,
                  std::ostream& out, std::ostream& err) {
  if (dirs.empty()) throw ConfigError("study merge: no shard directories");
  std::optional<nlohmann::ordered_json> config;
  std::uint64_t shards = 0;
  std::set<std::uint64_t> seen;
  std::map<std::uint64_t, std::string> rows;
  nlohmann::ordered_json metas = nlohmann::ordered_json::array();
  for (const auto& dir : dirs) {
    nlohmann::ordered_json meta = read_meta(meta_path(dir));
    Shard s;
    try {
      s = parse_shard(meta["shard"].get<std::string>());
    } catch (const ConfigError&) {
      throw ConfigError(meta_path(dir) + ": bad shard '" + meta["shard"].get<std::string>() + "'");
    }
    if (!config) {
      config = meta["config"];
      shards = s.n;
    } else if (!same_config(*config, meta["config"])) {
      throw ConfigError("'" + dir + "' holds a shard of another study (its config differs from '" + dirs[0] + "')");
    } else if (s.n != shards) {
      throw ConfigError("'" + dir + "' is shard " + shard_text(s) + ", not one of " + std::to_string(shards));
    }
    if (!seen.insert(s.k).second) throw ConfigError("shard " + shard_text(s) + " is given twice");
    if (meta.value("complete", false) != true)
      throw ConfigError("'" + dir + "' is not complete (shard " + shard_text(s) +
                        " was interrupted: rerun its command to finish it)");
    const RunsFile f = read_runs(runs_path(dir));
    for (const auto& [id, row] : f.rows) {
      if (!s.has(id)) throw ConfigError(runs_path(dir) + ": run " + std::to_string(id) + " is not in shard " + shard_text(s));
      rows.emplace(id, row);
    }
    meta.erase("config");
    meta["directory"] = dir;
    metas.push_back(meta);
  }
  if (seen.size() != shards)
    throw ConfigError("study merge: " + std::to_string(seen.size()) + " of " + std::to_string(shards) +
                      " shards given");

  std::error_code ec;
  fs::create_directories(out_dir, ec);
  if (ec || !fs::is_directory(out_dir)) throw ConfigError("cannot use '" + out_dir + "' as the output directory");
  if (fs::exists(meta_path(out_dir)) || fs::exists(runs_path(out_dir)))
    throw ConfigError("'" + out_dir + "' already holds a study");
  std::string text = csv_header() + "\n";
  for (const auto& [id, row] : rows) text += row + "\n";
  const int fd = ::open(runs_path(out_dir).c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0644);
  if (fd < 0) throw ConfigError("cannot write '" + runs_path(out_dir) + "': " + std::strerror(errno));
  append_all(fd, text, runs_path(out_dir));
  ::close(fd);

  nlohmann::ordered_json meta;
  meta["study"] = (*config).value("name", std::string());
  meta["shard"] = "1/1";
  meta["merged_utc"] = utc_now();
  meta["complete"] = true;
  meta["merged_by"] = environment_json(build);
  meta["shards"] = metas;
  meta["config"] = *config;
  write_meta(meta_path(out_dir), meta);
  err << "dlab study merge: " << shards << " shards, " << rows.size() << " rows\n";
  return summarize(runs_path(out_dir), out);
}

}  // namespace dlab::study
