// The first, strictly Delaunay, facet of the Tanemura–Ogawa–Ogita front: see
// algorithms/tanemura_start.hpp for the construction and its proof. All signs
// are exact (interval filter, then GMP rationals; every double converts
// exactly); floating point only picks the likely answer, which is verified.
#include "algorithms/tanemura_start.hpp"

#include <boost/multiprecision/gmp.hpp>
#include <algorithm>
#include <cmath>
#include <limits>

#include "algorithms/interval.hpp"
#include "predicates/mp_kernel.hpp"
#include "predicates/perturbed.hpp"

namespace dlab {
namespace {

using Q = boost::multiprecision::mpq_rational;

// The filters' interval arithmetic, widened by nextafter (Iv::down / up), not
// by Iv's relative step: on huge coordinates the products overflow, and
// down(+inf) = DBL_MAX still bounds the exact value, where Iv's operators give
// NaN and the sign would go to GMP (2D `gen huge`, n = 5000: 2 M -> 96 M
// instructions in this file). Not in the search's hot loop: the speed of
// these does not matter.
struct Ivn {
  double lo = 0, hi = 0;
  static Ivn exact(double x) { return {x, x}; }
  operator Iv() const { return {lo, hi}; }
  friend Ivn operator+(Ivn a, Ivn b) { return {Iv::down(a.lo + b.lo), Iv::up(a.hi + b.hi)}; }
  friend Ivn operator-(Ivn a, Ivn b) { return {Iv::down(a.lo - b.hi), Iv::up(a.hi - b.lo)}; }
  friend Ivn operator*(Ivn a, Ivn b) {
    const double p1 = a.lo * b.lo, p2 = a.lo * b.hi, p3 = a.hi * b.lo, p4 = a.hi * b.hi;
    if (std::isnan(p1) || std::isnan(p2) || std::isnan(p3) || std::isnan(p4))
      return {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::quiet_NaN()};
    return {Iv::down(std::min(std::min(p1, p2), std::min(p3, p4))),
            Iv::up(std::max(std::max(p1, p2), std::max(p3, p4)))};
  }
};

template <int D>
struct Exact {
  const Point<D>& a;
  const Point<D>& b;
  // 3D pencil: L(x) = (x - a) . nrm, nrm = (b - a) x (v - a).
  std::array<Ivn, 3> nrm_iv{};
  std::array<Q, 3> nrm_q{};

  Ivn s0_iv(const Point<D>& x) const {
    Ivn s{0, 0};
    for (int i = 0; i < D; ++i) s = s + (Ivn::exact(x[i]) - Ivn::exact(a[i])) * (Ivn::exact(x[i]) - Ivn::exact(b[i]));
    return s;
  }
  Q s0_q(const Point<D>& x) const {
    Q s = 0;
    for (int i = 0; i < D; ++i) s += (Q(x[i]) - Q(a[i])) * (Q(x[i]) - Q(b[i]));
    return s;
  }
  int s0_sign(const Point<D>& x) const {
    const Ivn s = s0_iv(x);
    if (s.lo > 0) return 1;
    if (s.hi < 0) return -1;
    return s0_q(x).sign();
  }
  void set_v(const Point3& v) {
    if constexpr (D == 3) {
      std::array<Ivn, 3> u, w;
      std::array<Q, 3> uq, wq;
      for (int i = 0; i < 3; ++i) {
        u[i] = Ivn::exact(b[i]) - Ivn::exact(a[i]);
        w[i] = Ivn::exact(v[i]) - Ivn::exact(a[i]);
        uq[i] = Q(b[i]) - Q(a[i]);
        wq[i] = Q(v[i]) - Q(a[i]);
      }
      for (int i = 0; i < 3; ++i) {
        const int j = (i + 1) % 3, k = (i + 2) % 3;
        nrm_iv[i] = u[j] * w[k] - u[k] * w[j];
        nrm_q[i] = uq[j] * wq[k] - uq[k] * wq[j];
      }
    }
  }
  Ivn l_iv(const Point<D>& x) const {
    Ivn s{0, 0};
    for (int i = 0; i < D; ++i) s = s + (Ivn::exact(x[i]) - Ivn::exact(a[i])) * nrm_iv[i];
    return s;
  }
  Q l_q(const Point<D>& x) const {
    Q s = 0;
    for (int i = 0; i < D; ++i) s += (Q(x[i]) - Q(a[i])) * nrm_q[i];
    return s;
  }
  int l_sign(const Point<D>& x) const {
    const Ivn s = l_iv(x);
    if (s.lo > 0) return 1;
    if (s.hi < 0) return -1;
    return l_q(x).sign();
  }
  // sign(t(x) - t(y)) for L(x), L(y) of sign `side` (t = S0 / (side L)):
  // sign(S0(x) L(y) - S0(y) L(x)) * side.
  int compare_t(const Point<D>& x, const Point<D>& y, int side) const {
    const Ivn d = s0_iv(x) * l_iv(y) - s0_iv(y) * l_iv(x);
    int s;
    if (d.lo > 0)
      s = 1;
    else if (d.hi < 0)
      s = -1;
    else
      s = (s0_q(x) * l_q(y) - s0_q(y) * l_q(x)).sign();
    return s * side;
  }
};

std::uint64_t splitmix(std::uint64_t& s) {
  std::uint64_t z = (s += 0x9E3779B97F4A7C15ull);
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  return z ^ (z >> 31);
}

}  // namespace

template <int D>
StartFacet<D> find_start_facet(std::span<const Point<D>> pts, const std::vector<std::uint32_t>& ids) {
  StartFacet<D> r;
  if (ids.size() < static_cast<std::size_t>(D + 1)) {
    r.why = "fewer than D+1 distinct points";
    return r;
  }
  const std::uint32_t ia = ids[0];
  const Point<D>& a = pts[ia];
  // Nearest neighbour of a in floating point (scaled by 2^-e against overflow)...
  double big = 0;
  for (std::uint32_t id : ids)
    for (int i = 0; i < D; ++i) big = std::max(big, std::fabs(pts[id][i]));
  int e = 0;
  std::frexp(big, &e);
  const double s = std::ldexp(1.0, std::clamp(-e, -1000, 1000));
  std::uint32_t ib = ids[1];
  double best = std::numeric_limits<double>::infinity();
  for (std::uint32_t id : ids) {
    if (id == ia) continue;
    double d2 = 0;
    for (int i = 0; i < D; ++i) {
      const double t = pts[id][i] * s - a[i] * s;
      d2 += t * t;
    }
    if (d2 < best) {
      best = d2;
      ib = id;
    }
  }
  // ... then verified exactly: (x-a).(x-b) > 0 for all other x. A failure
  // names a strictly nearer point (see the header), so this ends.
  for (std::size_t round = 0;; ++round) {
    Exact<D> ex{a, pts[ib]};
    std::uint32_t nearer = ia;
    for (std::uint32_t id : ids) {
      if (id == ia || id == ib) continue;
      if (ex.s0_sign(pts[id]) <= 0) {
        nearer = id;
        break;
      }
    }
    if (nearer == ia) break;
    ib = nearer;
    if (round > ids.size()) {
      r.why = "nearest-neighbour verification did not settle (a bug)";
      return r;
    }
  }
  if constexpr (D == 2) {
    r.found = true;
    r.ids = {ia, ib};
    return r;
  } else {
    const Point3& b = pts[ib];
    // v = a + u W, u random in [-1, 1]^3. W is at least 2^-20 |a| so that v
    // resolves many directions even when b is an ulp from a (near-duplicates).
    double w = 0;
    for (int i = 0; i < 3; ++i) w = std::max({w, std::fabs(b[i] - a[i]), 0x1p-20 * std::fabs(a[i])});
    // b - a overflows near the top binade: half of it is finite. (A fixed
    // w = 1 was below an ulp of such an a, so every v moved along one axis
    // only and every draw repeated the first plane.)
    if (!std::isfinite(w)) {
      w = 0;
      for (int i = 0; i < 3; ++i) w = std::max({w, std::fabs(0.5 * b[i] - 0.5 * a[i]), 0x1p-20 * std::fabs(a[i])});
    }
    if (w == 0) w = 1;
    // Each rejected plane (a, b, v) is the plane of centres of one empty sphere
    // through a, b and two tied points off a circle with them: one per
    // Delaunay cell around the edge ab, so at most |ids| planes are bad. The
    // planes tried are pairwise distinct (checked exactly), so |ids| + 1 of
    // them always succeed; random v only makes the first one succeed in
    // practice. `draws` bounds the (measure-zero) draws that repeat a plane.
    const MpKernel mp;
    std::vector<Point3> planes;
    std::uint64_t seed = 0x5EED;
    const std::size_t max_planes = ids.size() + 1, max_draws = 64 * max_planes;
    for (std::size_t draws = 0; draws < max_draws && planes.size() < max_planes; ++draws) {
      Point3 v;
      for (int i = 0; i < 3; ++i) {
        const double u = static_cast<double>(splitmix(seed) >> 11) * 0x1p-53 * 2.0 - 1.0;
        v[i] = a[i] + u * w;
        if (!std::isfinite(v[i])) v[i] = a[i] - u * w;
      }
      bool repeated = false;
      for (const Point3& old : planes) repeated |= mp.orient3d(a, b, old, v) == Sign::zero;
      if (repeated) continue;
      Exact<3> ex{a, b};
      ex.set_v(v);
      // Side with points; approximate minimiser of t there.
      int side = 0;
      std::uint32_t ic = ia;
      double tbest = std::numeric_limits<double>::infinity();
      for (int sd : {1, -1}) {
        for (std::uint32_t id : ids) {
          if (id == ia || id == ib) continue;
          if (ex.l_sign(pts[id]) != sd) continue;
          const Ivn s0 = ex.s0_iv(pts[id]), l = ex.l_iv(pts[id]);
          const double t = (0.5 * (s0.lo + s0.hi)) / (sd * 0.5 * (l.lo + l.hi));
          if (ic == ia || t < tbest || !std::isfinite(tbest)) {
            if (ic == ia || t < tbest) {
              tbest = t;
              ic = id;
            }
          }
        }
        if (ic != ia) {
          side = sd;
          break;
        }
      }
      if (side == 0) continue;  // v on line ab: not a plane, draw again
      planes.push_back(v);
      // Exact minimum; restart whenever a smaller t appears (finitely often).
      std::vector<std::uint32_t> ties;
      for (std::size_t round = 0; round <= ids.size(); ++round) {
        bool changed = false;
        ties.clear();
        for (std::uint32_t id : ids) {
          if (id == ia || id == ib || id == ic) continue;
          if (ex.l_sign(pts[id]) != side) continue;
          const int c = ex.compare_t(pts[id], pts[ic], side);
          if (c < 0) {
            ic = id;
            changed = true;
            break;
          }
          if (c == 0) ties.push_back(id);
        }
        if (!changed) break;
      }
      if (!ties.empty()) {
        // Ties on one circle with a and b hold for every pencil: the points on
        // the empty sphere are then a, b and the tied points, all on one
        // circle, whose convex polygon (ab an edge of it: a tied point on the
        // minor arc would make (x-a).(x-b) < 0) is a face of the Delaunay
        // subdivision. Its perturbed triangulation is the in-plane perturbed
        // Delaunay one (restriction of the perturbed lifting to the face;
        // CGAL's coplanar_side_of_bounded_circle with perturbation): the apex
        // of ab is the tied point with no other inside its circle with a, b.
        // Ties off that plane depend on v: try another direction.
        bool coplanar = true;
        for (std::uint32_t y : ties) coplanar &= mp.orient3d(a, b, pts[ic], pts[y]) == Sign::zero;
        if (!coplanar) continue;
        const perturbed<MpKernel> pmp;
        for (std::uint32_t y : ties)
          if (pmp.coplanar_incircle(a, b, pts[ic], pts[y]) == Sign::positive) ic = y;
      }
      r.found = true;
      r.ids = {ia, ib, ic};
      return r;
    }
    r.why = "no strictly Delaunay starting triangle found on " + std::to_string(planes.size()) +
            " distinct pencil planes (a bug: at most " + std::to_string(ids.size()) + " can fail)";
    return r;
  }
}

template StartFacet<2> find_start_facet<2>(std::span<const Point2>, const std::vector<std::uint32_t>&);
template StartFacet<3> find_start_facet<3>(std::span<const Point3>, const std::vector<std::uint32_t>&);

}  // namespace dlab
