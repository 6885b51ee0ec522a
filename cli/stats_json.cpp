// See stats_json.hpp.
#include "cli/stats_json.hpp"

#include <sys/resource.h>

#include "cli/numbers.hpp"

namespace dlab::io {
namespace {

void write_counters(std::ostream& out, const Counters& c, const char* indent) {
  if (c.empty()) {
    out << "{}";
    return;
  }
  out << "{\n";
  for (std::size_t i = 0; i < c.size(); ++i)
    out << indent << "  " << json_string(c[i].first) << ": " << c[i].second
        << (i + 1 < c.size() ? ",\n" : "\n");
  out << indent << "}";
}

// JSON has no NaN/infinity: such a value is written as null.
std::string json_number(double x) {
  if (!(x == x) || x - x != 0) return "null";
  return format_decimal(x);
}

}  // namespace

std::string json_string(std::string_view s) {
  std::string o = "\"";
  for (char ch : s) {
    const auto c = static_cast<unsigned char>(ch);
    switch (c) {
      case '"': o += "\\\""; break;
      case '\\': o += "\\\\"; break;
      case '\n': o += "\\n"; break;
      case '\t': o += "\\t"; break;
      case '\r': o += "\\r"; break;
      default:
        if (c < 0x20 || c == 0x7f) {
          static const char* h = "0123456789abcdef";
          o += "\\u00";
          o += h[c >> 4];
          o += h[c & 15];
        } else {
          o += ch;  // UTF-8 passes through
        }
    }
  }
  return o + "\"";
}

void write_stats_json(std::ostream& out, const StatsRecord& r) {
  const RunResult& res = *r.result;
  const std::size_t k = static_cast<std::size_t>(res.dimension) + 1;
  out << "{\n";
  out << "  \"algorithm\": " << json_string(r.options.algorithm) << ",\n";
  out << "  \"kernel\": " << json_string(r.options.kernel) << ",\n";
  out << "  \"policy\": " << json_string(r.options.policy) << ",\n";
  out << "  \"order\": " << json_string(r.options.order) << ",\n";
  out << "  \"location\": " << json_string(r.options.location) << ",\n";
  out << "  \"seed\": " << r.options.seed << ",\n";
  out << "  \"dimension\": " << res.dimension << ",\n";
  out << "  \"input_points\": " << r.input_points << ",\n";
  out << "  \"distinct_points\": " << res.distinct_points << ",\n";
  out << "  \"inserted_points\": " << res.inserted_points << ",\n";
  out << "  \"simplices\": " << res.simplices.size() / k << ",\n";
  out << "  \"seconds\": " << json_number(res.seconds) << ",\n";
  out << "  \"peak_rss_bytes\": " << r.peak_rss_bytes << ",\n";
  out << "  \"predicates\": ";
  write_counters(out, res.predicates, "  ");
  out << ",\n  \"counters\": ";
  write_counters(out, res.counters, "  ");
  out << ",\n  \"snapping\": ";
  if (res.snapping.empty()) {
    out << "{}";
  } else {
    out << "{\n";
    for (const auto& [key, v] : res.snapping) out << "    " << json_string(key) << ": " << v << ",\n";
    out << "    \"max_displacement\": " << json_number(res.max_snap_displacement) << "\n  }";
  }
  out << ",\n  \"outcome\": " << json_string(r.outcome) << ",\n";
  out << "  \"validated\": " << (r.validated ? "true" : "false") << ",\n";
  out << "  \"message\": " << json_string(r.message) << "\n}\n";
}

std::uint64_t peak_rss_bytes() {
  rusage u{};
  if (getrusage(RUSAGE_SELF, &u) != 0) return 0;
  return static_cast<std::uint64_t>(u.ru_maxrss) * 1024u;
}

}  // namespace dlab::io
