// Exact rational 3-vectors for the tests of Tanemura's plain-double pruning
// bounds (test_facet_normal, test_pencil_axis, test_pencil_ball), and the
// facet normal's enclosure as Tanemura's search computes it for exact
// kernels (algorithms/tanemura.hpp, search).
#pragma once
#include <boost/multiprecision/gmp.hpp>

#include <array>
#include <optional>

#include "algorithms/facet_normal.hpp"
#include "algorithms/interval.hpp"

namespace dlab::rational_vectors {

using Q = boost::multiprecision::mpq_rational;
using QV = std::array<Q, 3>;
using Tri = std::array<std::array<double, 3>, 3>;

inline QV cross(const QV& a, const QV& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
inline Q dot(const QV& a, const QV& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

// (q1 - q0) x (q2 - q0) enclosed: facet_normal where it answers, else the
// exact interval products (a point on short operands).
inline std::array<Iv, 3> search_normal(const Tri& q) {
  if (const std::optional<std::array<Iv, 3>> n = facet_normal(q)) return *n;
  std::array<Iv, 3> u, v;
  for (int i = 0; i < 3; ++i) {
    u[i] = tight_sub(Iv::exact(q[1][i]), Iv::exact(q[0][i]));
    v[i] = tight_sub(Iv::exact(q[2][i]), Iv::exact(q[0][i]));
  }
  const auto c = [&](int j, int k) { return tight_sub(tight_mul(u[j], v[k]), tight_mul(u[k], v[j])); };
  return {c(1, 2), c(2, 0), c(0, 1)};
}
inline Iv norm2(const std::array<Iv, 3>& n) { return sq(n[0]) + sq(n[1]) + sq(n[2]); }

}  // namespace dlab::rational_vectors
