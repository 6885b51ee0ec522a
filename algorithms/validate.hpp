// The exact validator: is a list of simplices a Delaunay triangulation of a
// point set?  Used by `dlab check`, the tests and the fuzzer.
//
// Input: the points (dimension 2 or 3) and the finite simplices as flat index
// lists, d+1 zero-based indices per simplex, each positively oriented
// (det[v1-v0; ...; vd-v0] > 0). Every predicate is exact (a floating filter in
// front of the GMP kernel), so a verdict never depends on rounding.
//
// What is checked (each with a count and the first offender), in O(n + m)
// expected time with hashed facets (n points, m simplices):
//   index_range         an index >= number of points (other checks are skipped)
//   duplicate_reference an index names a later copy of a duplicated point
//                       (the contract: duplicates refer to their first occurrence)
//   orientation         a simplex not strictly positively oriented
//   duplicate_simplex   the same vertex set twice
//   non_manifold_facet  a facet in more than two simplices
//   facet_same_side     the two simplices of a facet on the same side of it
//                       (combinatorially: equal induced orientations) = overlap
//   boundary_manifold   the boundary facets do not form one closed manifold
//                       (2D: each boundary vertex has one boundary edge in and
//                       one out; 3D: each boundary ridge in exactly two boundary
//                       facets, boundary connected with Euler characteristic 2)
//   boundary_convex     a reflex boundary ridge (a neighbouring boundary facet's
//                       far vertex strictly outside a boundary facet's plane);
//                       2D also: a locally convex boundary that turns more than
//                       once (count of lexicographic local minima != 1)
//   cover_degree        the number of simplices covering one symbolically
//                       perturbed point p = v0 + e(w1-v0) + e^2(w2-v0) + ...
//                       (inside the first valid simplex) is not 1
//   disconnected        the simplices (joined through shared facets) form more
//                       than one component
//   missing_vertex      a distinct input point is not a vertex of any simplex
//                       (for full-dimensional input; lower-dimensional input
//                       must give zero simplices)
//   not_delaunay        an interior facet that is not locally Delaunay (the far
//                       vertex of one neighbour strictly inside the circumcircle
//                       / circumsphere of the other)
// Why these suffice: positive orientation + two-sided facets make the union a
// branched covering of its image of constant degree away from the boundary; the
// degree is 1 at p, so nothing overlaps; a connected boundary that is a closed
// manifold, locally convex at every ridge (and in 2D turning once) bounds a
// convex region, which holds every input point because every point is a
// vertex, and whose vertices are input points: it is the convex hull
// (Devillers, Liotta, Preparata, Tamassia, "Checking the convexity of polytopes
// and the planarity of subdivisions", CGTA 11 (1998)). Local Delaunay of every
// interior facet of a triangulation of the hull implies global Delaunay
// (Delaunay's lemma; e.g. Edelsbrunner, "Geometry and Topology for Mesh
// Generation", 2001, ch. 1.2). In 3D a locally convex immersed boundary that
// wraps around twice is not ruled out by these local tests alone; the degree
// test at p catches it whenever p is covered twice.
#pragma once
#include <array>
#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "predicates/point.hpp"
#include "predicates/point_set.hpp"

namespace dlab {

enum class Check : int {
  index_range,
  duplicate_reference,
  orientation,
  duplicate_simplex,
  non_manifold_facet,
  facet_same_side,
  boundary_manifold,
  boundary_convex,
  cover_degree,
  disconnected,
  missing_vertex,
  not_delaunay,
  count_  // number of checks
};
inline constexpr int kCheckCount = static_cast<int>(Check::count_);

std::string_view check_name(Check c);

struct CheckResult {
  std::uint64_t count = 0;
  std::int64_t simplex = -1;  // first offending simplex (index into the list), or -1
  int facet = -1;             // its facet (opposite that local vertex), or -1
  std::int64_t point = -1;    // first offending point, or -1
};

struct ValidationReport {
  int dimension = 2;
  std::size_t points = 0;
  std::size_t distinct_points = 0;
  std::size_t simplices = 0;
  std::size_t interior_facets = 0;
  std::size_t boundary_facets = 0;
  // Interior facets whose far vertex lies exactly on the circumcircle /
  // circumsphere of the simplex across (counted only when the Delaunay check
  // runs). Not a failure; but when it is 0 in a valid Delaunay result, every
  // interior facet is strictly locally Delaunay, the lifted surface is strictly
  // convex, and the Delaunay triangulation is unique -- it is then also the
  // symbolically perturbed one (the fuzzer skips its reference).
  std::uint64_t cospherical_facets = 0;
  bool lower_dimensional = false;  // fewer than d+1 affinely independent points
  bool skipped = false;            // geometric checks skipped (bad indices)
  std::array<CheckResult, kCheckCount> checks{};

  const CheckResult& operator[](Check c) const { return checks[static_cast<int>(c)]; }
  CheckResult& operator[](Check c) { return checks[static_cast<int>(c)]; }
  // A valid triangulation of the convex hull with every distinct point a vertex.
  bool valid() const;
  // valid() and every interior facet locally Delaunay.
  bool delaunay() const { return valid() && (*this)[Check::not_delaunay].count == 0; }
  std::uint64_t non_delaunay_facets() const { return (*this)[Check::not_delaunay].count; }
  // One line per failed check ("orientation: 2 (first: simplex 7)"), or "valid Delaunay".
  std::string summary() const;
};

ValidationReport validate(std::span<const Point2> points, std::span<const std::uint32_t> simplices);
ValidationReport validate(std::span<const Point3> points, std::span<const std::uint32_t> simplices);
ValidationReport validate(const PointSet& points, std::span<const std::uint32_t> simplices);

// One flagged item: the check and its simplex / facet / point (-1 where none),
// as in CheckResult. The overload below lists every one (not only the first of
// each check), in the order found, for pictures (`dlab draw`); its report is
// the same as validate()'s.
struct Offence {
  Check check;
  std::int64_t simplex = -1;
  int facet = -1;
  std::int64_t point = -1;
};
ValidationReport validate(const PointSet& points, std::span<const std::uint32_t> simplices,
                          std::vector<Offence>& offences);

// For simplices given in either orientation (scipy.spatial.Delaunay's are
// mixed): swaps the first two vertices of each simplex whose exact orientation
// (the convention above, decided by the same exact kernel) is negative, so that
// validate() can check the rest as usual. A simplex of zero volume, or with an
// index out of range, is left as it is for validate() to report. Returns the
// number of simplices swapped.
std::size_t orient_positively(const PointSet& points, std::span<std::uint32_t> simplices);

}  // namespace dlab
