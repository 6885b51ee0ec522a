// See columns.hpp.
#include "studies/columns.hpp"

#include <algorithm>
#include <cstdio>
#include <stdexcept>
#include <unordered_map>

#include "studies/config.hpp"
#include "studies/matrix.hpp"

namespace dlab::study {
namespace {

std::vector<std::string> make_predicate_names() {
  // Stages in the order a call meets them (predicates/adaptive_kernel.hpp:
  // semi-static filter, dynamic filter, Shewchuk's A-D, the mp fallback), then
  // the single stage of each other kernel, then symbolic perturbation.
  const char* const stages[] = {"static", "filter", "A",     "B",       "C",      "D",
                                "mp",     "integer", "float", "epsilon", "perturbation"};
  std::vector<std::string> out;
  for (const char* p : {"orient2d", "incircle", "orient3d", "insphere"}) {
    out.emplace_back(p);
    for (const char* s : stages) out.push_back(std::string(p) + "." + s);
  }
  out.emplace_back("coplanar_orientation");
  out.emplace_back("coplanar_incircle");
  return out;
}

}  // namespace

const std::vector<std::string>& predicate_counter_names() {
  static const std::vector<std::string> names = make_predicate_names();
  return names;
}

const std::vector<std::string>& algorithm_counter_names() {
  static const std::vector<std::string> names = {
      // point location and the mesh (bowyer-watson, lawson, george)
      "walk_steps", "scan_tests", "duplicates", "mesh_slots", "mesh_bytes_reserved", "simplices_created",
      // cavities (bowyer-watson, george)
      "cavity_simplices", "max_cavity_simplices", "max_cavity_boundary", "cavity_size_1", "cavity_size_2_3",
      "cavity_size_4_7", "cavity_size_8_15", "cavity_size_16_31", "cavity_size_32_63", "cavity_size_64_up",
      // bowyer-watson --threads T: the workers, their rounds and boxes, the points they put back
      "threads", "parallel_rounds", "parallel_boxes_max", "deferred_insertions", "insertions_alone",
      // lawson: insertions by type, flips by type
      "insert_1_3", "insert_2_4", "insert_1_4", "insert_2_6", "insert_n_2n", "insert_exterior", "exterior_facets",
      "insert_on_hull", "flips_2_2", "flips_2_3", "flips_3_2", "flips_4_4", "hull_edge_removals", "flips_total",
      "unflippable_tests", "retry_rounds",
      // tanemura: the advancing front and its search tree
      "facets_searched", "hull_facets", "facets_closed", "points_examined", "points_examined_per_facet_x1000",
      "points_examined_hull_facets", "candidates_outer", "sphere_updates", "balls_computed", "nodes_visited",
      "leaves_visited", "max_front", "tree_nodes", "bytes_reserved", "hull_facets_by_plane", "flat_nodes",
      "flat_nodes_skipped", "flat_nodes_outside_ball",
      // george: the approximate cavity and its corrections, the result's distance from Delaunay
      "base_simplices", "approx_cavity_simplices", "float_sphere_tests", "corrected_insertions", "correction_rounds",
      "removed_for_visibility", "added_for_zero_volume", "zero_volume_not_addable", "removed_for_connectivity",
      "removed_for_enclosed_vertex", "valid", "non_delaunay_facets",
      // george+enclosing-box: what removing the box leaves missing
      "box_simplices_removed", "hull_facets_missing", "hull_volume_missing_ppm", "missing_vertices",
      "reflex_boundary_ridges"};
  return names;
}

const std::vector<std::string>& leading_columns() {
  static const std::vector<std::string> names = {
      "run",    "input",        "generator",       "dimension", "n",       "seed",    "repeat",
      "tool",   "algorithm",    "kernel",          "order",     "policy",  "location", "input_points",
      "distinct_points", "simplices", "outcome", "message", "wall_seconds", "cpu_seconds", "peak_rss_bytes"};
  return names;
}

const std::vector<std::string>& measured_columns() {
  static const std::vector<std::string> names = {"wall_seconds", "cpu_seconds", "peak_rss_bytes"};
  return names;
}

std::string csv_header() {
  std::string h;
  for (const auto& c : leading_columns()) h += (h.empty() ? "" : ",") + c;
  for (const auto& c : predicate_counter_names()) h += ",pred." + c;
  for (const auto& c : algorithm_counter_names()) h += ",ctr." + c;
  return h;
}

std::size_t column_count() {
  return leading_columns().size() + predicate_counter_names().size() + algorithm_counter_names().size();
}

std::string csv_field(std::string_view s) {
  if (s.find_first_of(",\"\r\n") == std::string_view::npos) return std::string(s);
  std::string o = "\"";
  for (char c : s) o += c == '"' ? std::string("\"\"") : std::string(1, c);
  return o + "\"";
}

std::vector<std::string> csv_split(std::string_view line) {
  std::vector<std::string> out(1);
  bool quoted = false;
  for (std::size_t i = 0; i < line.size(); ++i) {
    const char c = line[i];
    if (quoted) {
      if (c != '"') {
        out.back() += c;
      } else if (i + 1 < line.size() && line[i + 1] == '"') {
        out.back() += '"';
        ++i;
      } else {
        quoted = false;
        if (i + 1 < line.size() && line[i + 1] != ',') throw std::invalid_argument("text after a closing quote");
      }
    } else if (c == ',') {
      out.emplace_back();
    } else if (c == '"' && out.back().empty()) {
      quoted = true;
    } else {
      out.back() += c;
    }
  }
  if (quoted) throw std::invalid_argument("unterminated quote");
  return out;
}

namespace {

std::string number(const std::optional<std::uint64_t>& v) { return v ? std::to_string(*v) : std::string(); }

// Measured seconds: 9 significant digits (nanoseconds below 1 s).
std::string seconds(const std::optional<double>& v) {
  if (!v) return "";
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.9g", *v);
  return buf;
}

void append_counters(std::string& row, const std::vector<std::string>& names, const Counters& values,
                     std::vector<std::string>* unknown) {
  std::vector<std::string> cells(names.size());
  for (const auto& [name, v] : values) {
    const auto it = std::find(names.begin(), names.end(), name);
    if (it == names.end()) {
      if (unknown) unknown->push_back(name);
      continue;
    }
    cells[static_cast<std::size_t>(it - names.begin())] = std::to_string(v);
  }
  for (const auto& c : cells) row.append(",").append(c);
}

}  // namespace

std::string csv_row(const StudyConfig& config, const RunSpec& s, const RunMeasure& m,
                    std::vector<std::string>* unknown) {
  const InputSpec& in = config.inputs.at(s.input);
  std::string row = std::to_string(s.id);
  for (const std::string& cell :
       {csv_field(in.label), csv_field(in.file.empty() ? in.generator : "file"), std::to_string(in.dimension),
        std::to_string(s.n), std::to_string(s.seed), std::to_string(s.repeat), s.tool, s.algorithm, s.kernel,
        s.order, s.policy, s.location, number(m.input_points), number(m.distinct_points), number(m.simplices),
        csv_field(m.outcome), csv_field(m.message), seconds(m.wall_seconds), seconds(m.cpu_seconds),
        number(m.peak_rss_bytes)})
    row.append(",").append(cell);
  append_counters(row, predicate_counter_names(), m.predicates, unknown);
  append_counters(row, algorithm_counter_names(), m.counters, unknown);
  return row;
}

}  // namespace dlab::study
