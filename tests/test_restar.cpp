// Re-starring a 3D cavity (algorithms/cavity.hpp, Restar<3>): the new
// tetrahedra's internal facets are paired through one table keyed by their
// directed boundary edges, kept from call to call (a stamp marks the live
// entries; the table grows for large cavities).  A Restar that has served
// earlier cavities must link each new one as a new Restar does, refuse a
// facet of three new simplices or one without a partner the same way, and
// leave nothing behind after a refusal.  Checked by re-starring the same
// cavities, one after the other, in two copies of a Delaunay mesh (Lawson's,
// kept by keep_mesh()): in one by a single Restar that serves every call, in
// the other by a new Restar for each; the mesh built must pass
// check_structure.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "algorithms/cavity.hpp"
#include "algorithms/cavity_search.hpp"
#include "algorithms/lawson.hpp"
#include "algorithms/locate.hpp"
#include "fuzz/generators.hpp"
#include "predicates/adaptive_kernel.hpp"
#include "predicates/perturbed.hpp"

using namespace dlab;

namespace {

using K = perturbed<AdaptiveKernel>;

std::vector<std::uint32_t> words(const Mesh<3>& m) {
  std::vector<std::uint32_t> w;
  for (std::uint32_t s = 0; s < m.slots(); ++s)
    for (int j = 0; j < 4; ++j) w.insert(w.end(), {m.vertex(s, j), m.neighbour(s, j)});
  return w;
}

std::size_t boundary_vertices(const std::vector<BoundaryRecord<3>>& records) {
  std::vector<std::uint32_t> v;
  for (const BoundaryRecord<3>& r : records)
    for (int j = 0; j < 4; ++j)
      if (j != r.slot) v.push_back(r.v[j]);
  std::sort(v.begin(), v.end());
  return static_cast<std::size_t>(std::unique(v.begin(), v.end()) - v.begin());
}

}  // namespace

TEST_CASE("re-star 3D: a Restar used before links as a new one does", "[restar]") {
  const std::size_t n = 2000;
  std::vector<Point<3>> pts = gen::uniform<3>(n, 31);
  Lawson<K, 3> dt;
  dt.keep_mesh();
  REQUIRE(dt.run(std::span<const Point<3>>(pts)).outcome == RunResult::Outcome::ok);
  Mesh<3> fresh_mesh = dt.mesh(), reused_mesh = dt.mesh();

  // New points: inside and outside the hull, and far outside it, where the
  // visible part of the hull has more than 32 vertices (large cavities).
  std::vector<Point<3>> extra;
  for (const Point<3>& q : gen::uniform<3>(200, 32)) extra.push_back({q[0] * 1.4 - 0.2, q[1] * 1.4 - 0.2, q[2] * 1.4 - 0.2});
  for (std::size_t j = 0; j < 40; ++j) {
    const double t = double(j) / 40;
    extra.insert(extra.begin() + std::ptrdiff_t(5 * j), Point<3>{50 * (t - 0.5), 0.5 + 40 * t, -30 + 7 * t});
  }
  const std::size_t first_new = pts.size();
  pts.insert(pts.end(), extra.begin(), extra.end());

  Restar<3> reused;
  const K k;
  WalkRng rng;
  std::uint32_t start = 0;
  while (!fresh_mesh.alive(start)) ++start;
  std::vector<std::uint32_t> cavity;
  std::vector<BoundaryRecord<3>> records;
  TopBitMarks bits;
  std::size_t large = 0, small_after_large = 0, broken = 0;
  bool after_large = false;
  for (std::size_t j = first_new; j < pts.size(); ++j) {
    const auto i = static_cast<std::uint32_t>(j);
    const Located loc = visibility_walk<K, 3>(k, fresh_mesh, pts.data(), start, pts[i], 1u << 20, rng);
    REQUIRE((loc.end == Located::End::inside || loc.end == Located::End::outside));
    REQUIRE(search_cavity<K, 3>(k, fresh_mesh, pts.data(), i, loc.simplex, TopBitMarks::kIn,
                                TopBitMarks::kOut, cavity, records, bits));
    for (std::uint32_t s : cavity) TopBitMarks::unmark(fresh_mesh, s, TopBitMarks::kIn);
    for (const BoundaryRecord<3>& r : records)
      TopBitMarks::unmark(fresh_mesh, Mesh<3>::simplex_of(r.outside), TopBitMarks::kOut);

    const bool is_large = boundary_vertices(records) > 32;
    large += is_large;
    small_after_large += after_large && !is_large;
    after_large = is_large;

    // Every fifth cavity first goes in with one record twice (a facet of
    // three new simplices: the first record's facets then find their own
    // keys waiting, the last one's find their partners already paired) or
    // one record missing (facets without a partner): refused alike, and
    // nothing left behind.
    if (j % 5 == 0) {
      std::vector<BoundaryRecord<3>> wrong = records;
      const bool twice = j % 10 == 0;
      if (twice)
        wrong.push_back(j % 20 == 0 ? records.front() : records.back());
      else
        wrong.erase(wrong.begin() + std::ptrdiff_t(j % wrong.size()));
      Mesh<3> a = fresh_mesh, b = reused_mesh;
      std::string error_a, error_b;
      Restar<3>().star(a, cavity, wrong, error_a);
      reused.star(b, cavity, wrong, error_b);
      REQUIRE(error_a == (twice ? "cavity boundary is not a manifold (a facet shared by more than two new simplices)"
                                : "cavity boundary is not closed (a new facet without a partner)"));
      REQUIRE(error_b == error_a);
      ++broken;
    }

    std::string error_fresh, error_reused;
    start = Restar<3>().star(fresh_mesh, cavity, records, error_fresh);
    REQUIRE(reused.star(reused_mesh, cavity, records, error_reused) == start);
    REQUIRE(error_fresh.empty());
    REQUIRE(error_reused.empty());
    REQUIRE(words(reused_mesh) == words(fresh_mesh));
  }
  REQUIRE(fresh_mesh.check_structure().empty());
  CHECK(large >= 5);
  CHECK(small_after_large >= 5);
  CHECK(broken >= 40);
}
