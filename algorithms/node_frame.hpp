// An oriented bounding box for a node of the search tree (algorithms/kd_tree.hpp)
// whose points are flat: on a line (2D, 3D) or a plane (3D) oblique to the
// axes. Their axis-aligned box is as thick as it is long, so it meets every
// large sphere that passes near the line or plane: the fans of a few points
// off a line or plane (dlab gen collinear, coplanar) have circumspheres of
// radius about L^2 / h hugging it, and the box-pruned Tanemura search examined
// every point (issue 17 section 3; papers/triangulation_costs.md). In a frame
// fitted to the points the box is as thin as they are. Oriented boxes in
// bounding-volume hierarchies: Gottschalk, Lin, Manocha, "OBBTree", SIGGRAPH
// 1996; the frame here is the cheap extreme-point fit, not PCA.
//
// Soundness (the frame only PRUNES, like the tree): the rows u_k need not be
// orthonormal. For every point x of the node, y = U x lies in [lo, hi]
// (enclosures), and for any c, |U (x - c)|^2 <= s |x - c|^2 with s any upper
// bound of the largest eigenvalue of U U^T; Gershgorin's theorem gives s =
// max_k sum_j |u_k . u_j|, bounded above with intervals. So if the squared
// distance between [lo, hi] and an enclosure of U c exceeds s r^2, no point
// of the node is within r of c.
#pragma once
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <vector>

#include "algorithms/interval.hpp"

namespace dlab {

template <int D>
struct NodeFrame {
  std::array<std::array<double, D>, D> u;  // rows: an almost orthonormal basis
  std::array<double, D> lo, hi;            // enclosure of u_k . x over the node's points
  double s_prune;                          // Gershgorin bound s, times 1 + 2^-44 (see may_meet_ball)
  double inv_s;                            // a lower bound of 1 / s
  double skew;                             // 2 eta (see may_hold_inside), or infinity
  // Frames with the same rows_id have the same rows (KdTree shares a
  // parent's rows down a line or plane), so a point projected once serves
  // them all (the search caches its projections per rows_id).
  std::uint32_t rows_id = 0;

  // An enclosure of U x: a point in frame coordinates.
  struct Projected {
    std::array<Iv, D> y;
  };
  [[gnu::flatten]] Projected project(const std::array<Iv, D>& x) const;

  // A frame for points given by their coordinate enclosures, worth keeping
  // only if its thinnest extent is at most 1/16 of the thinnest extent of
  // their axis-aligned box [box_lo, box_hi] (else nothing: the axis box prunes
  // about as well, and the frame test costs D^2 interval products).
  static std::optional<NodeFrame> fit(const std::vector<std::array<Iv, D>>& pts,
                                      const std::array<double, D>& box_lo,
                                      const std::array<double, D>& box_hi);

  // fit's rule: the thinnest extent of the frame's box is at most 1/16 of
  // the thinnest extent of the axis-aligned box [box_lo, box_hi].
  bool worth_it(const std::array<double, D>& box_lo, const std::array<double, D>& box_hi) const;
  double thinnest() const;  // the thinnest extent of the frame's box

  // The frame with rows u (any finite, independent rows: the bound s makes
  // the test sound whatever their angles), its box over pts and s.
  static std::optional<NodeFrame> make(const std::vector<std::array<Iv, D>>& pts,
                                       const std::array<std::array<double, D>, D>& u);

  // False only if no point of the node is within the ball of squared radius
  // at most r2_prune / (1 + 2^-44) around a centre in `centre` (the
  // tree's ball test's convention: r2_prune = r2 (1 + 2^-44) + 2^-1000).
  [[gnu::flatten]] bool may_meet_ball(const Projected& centre, double r2_prune) const;
  bool may_meet_ball(const std::array<Iv, D>& centre, double r2_prune) const {
    return may_meet_ball(project(centre), r2_prune);
  }

  // The same question for a ball far larger than the node, asked without
  // its radius: with v on the sphere and w = 2 (v - c), a point x is inside
  // iff g(x) = |x - v|^2 + w . (x - v) < 0 (as |x - c|^2 - r^2 = g(x)), whose
  // terms are of the size of |x - v| |w| and |x - v|^2 instead of r^2: the
  // radius test's slack, r^2 2^-44, was wider than the gap between a line
  // and the huge circles of a fan off it. False only if g > 0 on the node,
  // for every v in `v` and w in `w` with |w| <= w_norm. In the frame, z =
  // U (x - v) lies in [lo - U v, hi - U v]; |x - v|^2 >= |z|^2 / s; and w .
  // (x - v) = w' . z with w' = U^-T w, |w' - U w| <= |U^-T| |I - U^T U| |w|
  // <= eta / sqrt(1 - eta) |w| <= 2 eta |w| for eta <= 1/2, eta a
  // Gershgorin bound of |I - U U^T| (the same norm as |I - U^T U|). So g is
  // at least a sum over k of one-variable quadratics, each bounded below
  // exactly (its vertex or an end), in interval arithmetic.
  [[gnu::flatten]] bool may_hold_inside(const Projected& v, const Projected& w, double w_norm) const;
  bool may_hold_inside(const std::array<Iv, D>& v, const std::array<Iv, D>& w, double w_norm) const {
    return may_hold_inside(project(v), project(w), w_norm);
  }

  // False only if n . (x - f0) <= 0 for every point x of the node, for
  // every f0 in `f0` and n in `n` with |n| <= n_norm: nothing strictly on the
  // open side of a facet (a hull facet's climb has no ball to prune with).
  // As above, n . (x - f0) = n' . z with z = U (x - f0) in [lo - U f0,
  // hi - U f0] and n' = U^-T n within 2 eta |n| of U n: at most the sum over
  // k of the largest corner of the product of their enclosures.
  [[gnu::flatten]] bool may_be_outer(const Projected& f0, const Projected& n, double n_norm) const;
  bool may_be_outer(const std::array<Iv, D>& f0, const std::array<Iv, D>& n, double n_norm) const {
    return may_be_outer(project(f0), project(n), n_norm);
  }
};

namespace node_frame_detail {

template <int D>
double dot(const std::array<double, D>& a, const std::array<double, D>& b) {
  double s = 0;
  for (int i = 0; i < D; ++i) s += a[i] * b[i];
  return s;
}

template <int D>
std::array<double, D> unit(std::array<double, D> a) {
  const double n = std::sqrt(dot<D>(a, a));
  for (double& x : a) x /= n;
  return a;
}

inline std::array<double, 3> cross(const std::array<double, 3>& a, const std::array<double, 3>& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

}  // namespace node_frame_detail

template <int D>
std::optional<NodeFrame<D>> NodeFrame<D>::fit(const std::vector<std::array<Iv, D>>& pts,
                                              const std::array<double, D>& box_lo,
                                              const std::array<double, D>& box_hi) {
  using namespace node_frame_detail;
  if (pts.size() < 2) return std::nullopt;
  // The direction: between the extreme points along the widest axis (plain
  // doubles, lower ends: the choice of frame needs no rigour).
  int axis = 0;
  double thin_axis = box_hi[0] - box_lo[0];
  for (int i = 1; i < D; ++i) {
    if (box_hi[i] - box_lo[i] > box_hi[axis] - box_lo[axis]) axis = i;
    thin_axis = std::min(thin_axis, box_hi[i] - box_lo[i]);
  }
  if (!(thin_axis > 0) || !std::isfinite(thin_axis)) return std::nullopt;  // flat on an axis already
  std::size_t a = 0, b = 0;
  for (std::size_t k = 1; k < pts.size(); ++k) {
    if (pts[k][axis].lo < pts[a][axis].lo) a = k;
    if (pts[k][axis].lo > pts[b][axis].lo) b = k;
  }
  std::array<double, D> d;
  for (int i = 0; i < D; ++i) d[i] = pts[b][i].lo - pts[a][i].lo;
  NodeFrame f;
  f.u[0] = unit<D>(d);
  if constexpr (D == 2) {
    f.u[1] = {-f.u[0][1], f.u[0][0]};
  } else {
    // The normal: from the point farthest from the line, unless the points
    // are (nearly) collinear; then any direction off the line.
    double far = 0;
    std::array<double, 3> n{};
    for (const auto& p : pts) {
      const std::array<double, 3> c = cross(f.u[0], {p[0].lo - pts[a][0].lo, p[1].lo - pts[a][1].lo,
                                                     p[2].lo - pts[a][2].lo});
      if (const double c2 = dot<3>(c, c); c2 > far) far = c2, n = c;
    }
    if (!(far > 0x1p-60 * dot<3>(d, d))) {
      int k = 0;
      for (int i = 1; i < 3; ++i)
        if (std::fabs(f.u[0][i]) < std::fabs(f.u[0][k])) k = i;
      std::array<double, 3> e{};
      e[k] = 1;
      n = cross(f.u[0], e);
    }
    f.u[2] = unit<3>(n);
    f.u[1] = unit<3>(cross(f.u[2], f.u[0]));
  }
  for (int k = 0; k < D; ++k)
    if (!std::isfinite(dot<D>(f.u[k], f.u[k]))) return std::nullopt;
  // Worth it? First in plain doubles (most nodes stop here).
  double lo[D], hi[D];
  for (std::size_t m = 0; m < pts.size(); ++m)
    for (int k = 0; k < D; ++k) {
      double y = 0;
      for (int i = 0; i < D; ++i) y += f.u[k][i] * pts[m][i].lo;
      lo[k] = m == 0 ? y : std::min(lo[k], y);
      hi[k] = m == 0 ? y : std::max(hi[k], y);
    }
  double thin = hi[0] - lo[0];
  for (int k = 1; k < D; ++k) thin = std::min(thin, hi[k] - lo[k]);
  if (!(thin * 16 <= thin_axis)) return std::nullopt;
  auto made = make(pts, f.u);
  if (!made || !made->worth_it(box_lo, box_hi)) return std::nullopt;
  return made;
}

template <int D>
double NodeFrame<D>::thinnest() const {
  double thin = hi[0] - lo[0];
  for (int k = 1; k < D; ++k) thin = std::min(thin, hi[k] - lo[k]);
  return thin;
}

template <int D>
bool NodeFrame<D>::worth_it(const std::array<double, D>& box_lo, const std::array<double, D>& box_hi) const {
  double thin_axis = box_hi[0] - box_lo[0];
  for (int k = 1; k < D; ++k) thin_axis = std::min(thin_axis, box_hi[k] - box_lo[k]);
  return thinnest() * 16 <= thin_axis;
}

template <int D>
std::optional<NodeFrame<D>> NodeFrame<D>::make(const std::vector<std::array<Iv, D>>& pts,
                                               const std::array<std::array<double, D>, D>& u) {
  NodeFrame f;
  f.u = u;
  // The box in the frame: enclosures of u_k . x.
  for (std::size_t m = 0; m < pts.size(); ++m) {
    const Projected p = f.project(pts[m]);
    for (int k = 0; k < D; ++k) {
      const Iv& y = p.y[k];
      if (!y.bounded()) return std::nullopt;
      f.lo[k] = m == 0 ? y.lo : std::min(f.lo[k], y.lo);
      f.hi[k] = m == 0 ? y.hi : std::max(f.hi[k], y.hi);
    }
  }
  // Gershgorin on the Gram matrix G = U U^T (s) and on I - G (eta), rounded
  // upwards: the largest |row sum| of each.
  double s = 0, eta = 0;
  for (int k = 0; k < D; ++k) {
    Iv row{0, 0}, row_dev{0, 0};
    for (int j = 0; j < D; ++j) {
      Iv g{0, 0};
      for (int i = 0; i < D; ++i) g = g + Iv::exact(u[k][i]) * Iv::exact(u[j][i]);
      const Iv dev = k == j ? g - Iv::exact(1) : g;
      row = row + Iv::exact(std::max(std::fabs(g.lo), std::fabs(g.hi)));
      row_dev = row_dev + Iv::exact(std::max(std::fabs(dev.lo), std::fabs(dev.hi)));
    }
    s = std::max(s, row.hi);
    eta = std::max(eta, row_dev.hi);
  }
  // Slack for the one rounding of r2_prune * s_prune in may_meet_ball.
  f.s_prune = Iv::upper_rel(s * (1 + 0x1p-44));
  if (!std::isfinite(f.s_prune) || !(s > 0) || pts.empty()) return std::nullopt;
  f.inv_s = (Iv::exact(1) / Iv::exact(s)).lo;
  f.skew = eta <= 0.5 ? Iv::upper_rel(2 * eta) : std::numeric_limits<double>::infinity();
  return f;
}

template <int D>
typename NodeFrame<D>::Projected NodeFrame<D>::project(const std::array<Iv, D>& x) const {
  // In plain doubles, about four times cheaper than interval products (the
  // projections were a fifth of Tanemura's time on 2D collinear input). With
  // x_i in m_i +- r_i (m_i = lo_i / 2 + hi_i / 2, r_i an upper bound of its
  // distance to either end), u . x lies in u . m +- sum |u_i| r_i; the
  // rounded u . m (D products, D - 1 sums) is within gamma_D sum |u_i m_i|
  // of the exact one (Higham, Accuracy and Stability of Numerical
  // Algorithms, 2002, section 3.1: gamma_n = n 2^-53 / (1 - n 2^-53), below
  // 2^-51 for n <= 3), plus 2^-1074 per product that underflows. So the
  // radius R = (sum |u_i| (r_i + 2^-51 |m_i|)) (1 + 2^-48) + 2^-1069, its
  // own 3D roundings of non-negative terms (relative 2^-53 each) inside the
  // factor, and the ends rounded outwards. A NaN or an
  // infinity anywhere makes an end NaN or infinite: the tests keep the node.
  Projected p;
  std::array<double, D> m, r;
  for (int i = 0; i < D; ++i) {
    m[i] = x[i].lo / 2 + x[i].hi / 2;
    r[i] = Iv::upper_rel(std::max(x[i].hi - m[i], m[i] - x[i].lo));
  }
  for (int k = 0; k < D; ++k) {
    double y = 0, rad = 0;
    for (int i = 0; i < D; ++i) {
      y += u[k][i] * m[i];
      rad += std::fabs(u[k][i]) * (r[i] + 0x1p-51 * std::fabs(m[i]));
    }
    rad = rad * (1 + 0x1p-48) + 0x1p-1069;
    p.y[k] = {Iv::lower_rel(y - rad), Iv::upper_rel(y + rad)};
  }
  return p;
}

template <int D>
bool NodeFrame<D>::may_meet_ball(const Projected& centre, double r2_prune) const {
  // Squared distance between the frame box and an enclosure of U c, in plain
  // doubles: the same few roundings as the axis box test (kd_tree users'
  // r2_prune slack absorbs them); s_prune carries the product's rounding.
  double d2 = 0;
  for (int k = 0; k < D; ++k) {
    const Iv& y = centre.y[k];
    const double g = std::max(0.0, std::max(lo[k] - y.hi, y.lo - hi[k]));
    d2 += g * g;
  }
  return !(d2 > r2_prune * s_prune);  // NaN: keep
}

namespace node_frame_detail {

// A lower bound of min a z^2 + b z over z in [p, q] (a > 0, p <= q): at p if
// the derivative is >= 0 there, at q if <= 0 there, else the vertex's value
// -b^2 / (4 a). NaN when unbounded.
[[gnu::always_inline]] inline double least_of_quadratic(double a, double b, double p, double q) {
  const Iv A = Iv::exact(a), B = Iv::exact(b), P = Iv::exact(p), Q = Iv::exact(q), two = Iv::exact(2);
  const auto at = [&](const Iv& z) { return (A * sq(z) + B * z).lo; };
  if ((two * A * P + B).lo >= 0) return at(P);
  if ((two * A * Q + B).hi <= 0) return at(Q);
  return (Iv{0, 0} - sq(B) / (A * Iv::exact(4))).lo;
}

}  // namespace node_frame_detail

template <int D>
bool NodeFrame<D>::may_hold_inside(const Projected& v, const Projected& w, double w_norm) const {
  using node_frame_detail::least_of_quadratic;
  const double eps = Iv::upper_rel(w_norm * skew);
  Iv total{0, 0};
  for (int k = 0; k < D; ++k) {
    const Iv &uv = v.y[k], &uw = w.y[k];
    const double p = (Iv::exact(lo[k]) - uv).lo, q = (Iv::exact(hi[k]) - uv).hi;
    // w'_k in [uw - eps, uw + eps]: the least of w'_k z is at its lower end
    // for z >= 0, at its upper end for z <= 0.
    const double b_pos = (uw - Iv::exact(eps)).lo, b_neg = (uw + Iv::exact(eps)).hi;
    double least;
    if (q <= 0)
      least = least_of_quadratic(inv_s, b_neg, p, q);
    else if (p >= 0)
      least = least_of_quadratic(inv_s, b_pos, p, q);
    else
    {
      const double l1 = least_of_quadratic(inv_s, b_neg, p, 0), l2 = least_of_quadratic(inv_s, b_pos, 0, q);
      least = l1 < l2 || std::isnan(l1) ? l1 : l2;  // NaN stays
    }
    total = total + Iv::exact(least);
  }
  return !(total.lo > 0);  // NaN: keep
}

template <int D>
bool NodeFrame<D>::may_be_outer(const Projected& f0, const Projected& n, double n_norm) const {
  const Iv eps = Iv::exact(Iv::upper_rel(n_norm * skew));
  Iv total{0, 0};
  for (int k = 0; k < D; ++k) {
    const Iv &uf = f0.y[k], &un = n.y[k];
    const Iv z{(Iv::exact(lo[k]) - uf).lo, (Iv::exact(hi[k]) - uf).hi};
    total = total + Iv{(un - eps).lo, (un + eps).hi} * z;
  }
  return !(total.hi <= 0);  // NaN: keep
}

}  // namespace dlab
