// See stats_json.hpp.
#include "cli/stats_json.hpp"

#include <sys/resource.h>

#include <iterator>

#include <nlohmann/json.hpp>

#include "cli/numbers.hpp"

namespace dlab::io {
namespace {

using Json = nlohmann::ordered_json;  // keeps the keys in insertion order

// Strings with invalid UTF-8 (a message may quote a file's bytes) get U+FFFD
// instead of nlohmann's exception: the file stays valid JSON.
std::string dump(const Json& v) { return v.dump(-1, ' ', false, Json::error_handler_t::replace); }

// nlohmann writes a double with Grisu2, whose digits are not always the
// nearest shortest ones (1.1240817954901996e-308 comes out ...995) and with
// "0.0" for 0; design.md's --stats numbers are std::to_chars's shortest
// round-trip text (numbers.hpp), and JSON has no NaN/infinity: null.
std::string number(double x) {
  if (!(x == x) || x - x != 0) return "null";
  return format_decimal(x);
}

// Two-space indentation, one key per line, "{}" for an empty object: what
// nlohmann's dump(2) writes, but doubles through number().
void write(std::ostream& out, const Json& v, int indent) {
  if (v.is_number_float()) {
    out << number(v.get<double>());
    return;
  }
  if (!v.is_object() || v.empty()) {
    out << dump(v);
    return;
  }
  const std::string pad(static_cast<std::size_t>(indent) + 2, ' ');
  out << "{\n";
  for (auto it = v.begin(); it != v.end(); ++it) {
    out << pad << dump(it.key()) << ": ";
    write(out, it.value(), indent + 2);
    out << (std::next(it) != v.end() ? ",\n" : "\n");
  }
  out << pad.substr(2) << "}";
}

Json counters(const Counters& c) {
  Json o = Json::object();
  for (const auto& [key, n] : c) o[key] = n;
  return o;
}

}  // namespace

std::string json_string(std::string_view s) { return dump(Json(std::string(s))); }

void write_stats_json(std::ostream& out, const StatsRecord& r) {
  const RunResult& res = *r.result;
  const std::size_t k = static_cast<std::size_t>(res.dimension) + 1;
  Json j;
  j["algorithm"] = r.options.algorithm;
  j["kernel"] = r.options.kernel;
  j["policy"] = r.options.policy;
  j["order"] = r.options.order;
  j["location"] = r.options.location;
  j["seed"] = r.options.seed;
  j["dimension"] = res.dimension;
  j["input_points"] = r.input_points;
  j["distinct_points"] = res.distinct_points;
  j["inserted_points"] = res.inserted_points;
  j["simplices"] = res.simplices.size() / k;
  j["seconds"] = res.seconds;
  j["cpu_seconds"] = res.cpu_seconds;
  Json phases = Json::object();
  phases["order"] = res.phase_seconds.order;
  phases["triangulate"] = res.phase_seconds.triangulate;
  phases["output"] = res.phase_seconds.output;
  j["phase_seconds"] = phases;
  j["peak_rss_bytes"] = r.peak_rss_bytes;
  j["predicates"] = counters(res.predicates);
  j["counters"] = counters(res.counters);
  Json snapping = Json::object();
  if (!res.snapping.empty()) {
    for (const auto& [key, v] : res.snapping) snapping[key] = v;
    snapping["max_displacement"] = res.max_snap_displacement;
  }
  j["snapping"] = snapping;
  j["outcome"] = r.outcome;
  j["validated"] = r.validated;
  j["message"] = r.message;
  write(out, j, 0);
  out << "\n";
}

std::uint64_t peak_rss_bytes() {
  rusage u{};
  if (getrusage(RUSAGE_SELF, &u) != 0) return 0;
  return static_cast<std::uint64_t>(u.ru_maxrss) * 1024u;
}

}  // namespace dlab::io
