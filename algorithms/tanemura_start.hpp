// The first facet of the Tanemura–Ogawa–Ogita front (algorithms/tanemura.hpp):
// a facet that is STRICTLY Delaunay — some sphere through its vertices has
// every other input point strictly outside — so it belongs to the Delaunay
// triangulation whatever the symbolic perturbation (CGAL's included).
//
// 2D and 3D edge: a, and b a nearest neighbour of a. The closed ball with
// diameter ab holds no other point x: x in it means (x-a).(x-b) <= 0, hence
// |x-a|^2 <= |a-b|^2 - |x-b|^2 < |a-b|^2, contradicting nearest (ties
// included). So (x-a).(x-b) > 0 for every other x; this is verified exactly.
//
// 3D triangle: the spheres through a and b form the pencil
//   S_t(x) = (x-a).(x-b) - t L(x),  L(x) = det[b-a; v-a; x-a]
// (L vanishes on line ab; v is a chosen point off that line). For L(x) > 0,
// x is inside S_t iff t > t(x) = (x-a).(x-b) / L(x) > 0. Let c minimise t on
// the side L > 0, uniquely. Then S_t(c) passes through a, b, c and every other
// point is strictly outside it: on L > 0 because t(x) > t(c); on L < 0 and
// L = 0 because (x-a).(x-b) > 0 and t(c) L(x) <= 0. So abc is strictly
// Delaunay. A tie off the circle through a, b and c (a, b and both minimisers
// on one sphere whose centre lies on the pencil's line of centres) happens for
// one plane (a, b, v) per such sphere, i.e. per Delaunay cell around ab: v
// is then changed (deterministic pseudo-random draws, planes checked exactly
// to be distinct, so at most n + 1 planes are ever needed). Ties ON that circle hold for
// every v; the apex is then chosen among them by the in-plane perturbed
// in-circle test (see tanemura_start.cpp), which gives the triangle of the
// perturbed (CGAL) triangulation — the start is then Delaunay for the sos
// policy (and for strict, which breaks ties the same way in this algorithm). The comparisons t(x) < t(y), i.e.
// sign(S0(x) L(y) - S0(y) L(x)), are exact: interval filter, then GMP rationals.
#pragma once
#include <array>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "predicates/point.hpp"

namespace dlab {

template <int D>
struct StartFacet {
  bool found = false;
  std::array<std::uint32_t, D> ids{};
  std::string why;  // when !found
};

// `ids`: the distinct points (at least D+1, not all collinear / coplanar).
template <int D>
StartFacet<D> find_start_facet(std::span<const Point<D>> pts, const std::vector<std::uint32_t>& ids);

extern template StartFacet<2> find_start_facet<2>(std::span<const Point2>, const std::vector<std::uint32_t>&);
extern template StartFacet<3> find_start_facet<3>(std::span<const Point3>, const std::vector<std::uint32_t>&);

}  // namespace dlab
