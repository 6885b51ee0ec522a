// See mesh_marks.hpp.
#include "cli/mesh_marks.hpp"

#include <algorithm>
#include <map>

namespace dlab::cli {
namespace {

// The sorted vertex indices of facet `facet` (opposite vertex `facet`) of simplex s.
std::vector<std::uint32_t> facet_key(std::span<const std::uint32_t> simplices, int k, std::int64_t s,
                                     int facet) {
  std::vector<std::uint32_t> f;
  for (int i = 0; i < k; ++i)
    if (i != facet) f.push_back(simplices[static_cast<std::size_t>(s) * k + i]);
  std::sort(f.begin(), f.end());
  return f;
}

std::array<std::uint32_t, 2> as_edge(const std::vector<std::uint32_t>& f) { return {f[0], f[1]}; }

}  // namespace

MeshMarks mesh_marks(const PointSet& points, std::span<const std::uint32_t> simplices,
                     ValidationReport& report) {
  std::vector<Offence> offences;
  report = validate(points, simplices, offences);
  const int k = points.dimension + 1;
  const std::size_t m = simplices.size() / static_cast<std::size_t>(k);
  MeshMarks marks;
  marks.inverted.assign(m, 0);
  marks.overlapping.assign(m, 0);
  marks.non_delaunay_facets.assign(m, 0);
  marks.missing.assign(points.size(), 0);
  // The simplices on each facet (combinatorial: both sides), built only when a
  // non-Delaunay facet or an overlap needs it. Index offences (Check::index_range) skip the
  // geometric checks, so every facet here has indices in range.
  std::map<std::vector<std::uint32_t>, std::vector<std::size_t>> on_facet;
  auto sharing = [&](const std::vector<std::uint32_t>& f) -> const std::vector<std::size_t>& {
    if (on_facet.empty())
      for (std::size_t s = 0; s < m; ++s)
        for (int i = 0; i < k; ++i) on_facet[facet_key(simplices, k, static_cast<std::int64_t>(s), i)].push_back(s);
    return on_facet[f];
  };
  for (const Offence& o : offences) {
    switch (o.check) {
      case Check::not_delaunay: {  // listed once per facet: flag the simplices on both sides
        const auto f = facet_key(simplices, k, o.simplex, o.facet);
        for (std::size_t s : sharing(f)) ++marks.non_delaunay_facets[s];
        if (k == 3) marks.non_delaunay_edges.push_back(as_edge(f));
        break;
      }
      case Check::facet_same_side:
      case Check::non_manifold_facet: {
        const auto f = facet_key(simplices, k, o.simplex, o.facet);
        if (k == 3) marks.overlap_edges.push_back(as_edge(f));
        for (std::size_t s : sharing(f)) marks.overlapping[s] = 1;
        break;
      }
      case Check::cover_degree:
      case Check::duplicate_simplex:
        if (o.simplex >= 0) marks.overlapping[static_cast<std::size_t>(o.simplex)] = 1;
        break;
      case Check::orientation:
        marks.inverted[static_cast<std::size_t>(o.simplex)] = 1;
        break;
      case Check::missing_vertex:
        marks.missing[static_cast<std::size_t>(o.point)] = 1;
        break;
      default:
        break;
    }
  }
  for (auto* list : {&marks.non_delaunay_edges, &marks.overlap_edges}) {
    std::sort(list->begin(), list->end());
    list->erase(std::unique(list->begin(), list->end()), list->end());
  }
  for (Check c : {Check::index_range, Check::duplicate_reference, Check::boundary_manifold,
                  Check::boundary_convex, Check::disconnected}) {
    const CheckResult& r = report[c];
    if (r.count == 0) continue;
    std::string line = std::string(check_name(c)) + ": " + std::to_string(r.count) + " (first:";
    if (r.simplex >= 0) line += " simplex " + std::to_string(r.simplex);
    if (r.point >= 0) line += " point " + std::to_string(r.point);
    marks.other.push_back(line + ")");
  }
  marks.other.push_back(report.delaunay() ? "exact validator: valid Delaunay"
                        : report.valid()  ? "exact validator: valid, not Delaunay"
                                          : "exact validator: invalid");
  return marks;
}

}  // namespace dlab::cli
