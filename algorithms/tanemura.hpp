// Tanemura–Ogawa–Ogita advancing-front Delaunay triangulation, 2D and 3D
// (M. Tanemura, T. Ogawa, N. Ogita, "A new algorithm for three-dimensional
// Voronoi tessellation", J. Comput. Phys. 51 (1983) 191-207; Baker, Handbook of
// Grid Generation §16.2.3; Merriam 1991; a close relative is DeWall, Cignoni,
// Montani, Scopigno, CAD 30 (1998)).
//
// Invariants and steps:
//   * Start: one Delaunay facet found exactly (algorithms/tanemura_start.hpp:
//     a nearest-neighbour edge, in 3D widened to a triangle through a pencil
//     of spheres), processed on both sides.
//   * Front (algorithms/front.hpp): every facet with a simplex on exactly one
//     side, stored oriented so that its open side is positive. A new simplex
//     closes those of its facets already in the front and opens the others;
//     each facet is searched at most once per side.
//   * Search: for an open facet f, the candidates are the points p strictly on
//     its open side (orient_pos(f, p) > 0). The circumspheres through f form a
//     pencil ordered by the signed offset of the centre along f's normal; the
//     Delaunay apex is the candidate of least offset, and for candidates c, d:
//     offset(d) < offset(c)  iff  d is strictly inside the circumsphere of the
//     positive simplex (f, c)  (inside_pos). So: replace the best c by d
//     whenever inside_pos(f, c, d) > 0. Nothing else decides: with the sos
//     policy the kernel is perturbed<...>, which never answers zero on
//     distinct points, so the winner is the apex of CGAL's (and
//     Bowyer–Watson's) perturbed triangulation, independent of the scan order.
//     With `strict` an exact zero is broken by the same symbolic walk (see
//     inside()): the strict result is then the sos one, a Delaunay
//     triangulation (arbitrary tie choices could overlap in 3D).
//   * Hull: a facet with no point strictly on its open side is a hull facet.
//     Points collinear with a hull edge (coplanar with a hull facet) are
//     never candidates, so the hull is made of the Delaunay facets of the
//     points on it, exactly CGAL's hull rule (algorithms/oriented.hpp): a
//     point between two hull vertices is a vertex. Proving it costs a climb
//     through every leaf the facet's plane crosses; on a plane full of points
//     (a lattice's face, oblique to the tree's boxes) that was 450 points per
//     hull facet (rotated lattice, n = 5000). So, exact kernels only: a facet
//     whose vertices lie on the plane of a hull facet found before, open on
//     the same side, is a hull facet at once (on_known_hull_plane).
//   * Search structure (algorithms/kd_tree.hpp): a kd-tree with boxes. The
//     search starts at the leaf of the facet's first vertex and climbs to the
//     root, visiting each sibling subtree on the way, children nearer the
//     facet's centroid (once there is a ball, its centre) first; a node is
//     skipped when its box holds no point on the open side, or, once there
//     is a best candidate, none in its circumsphere, or when its points lie
//     exactly in the facet's hyperplane (algorithms/exact_flats.hpp), or
//     exactly in a hyperplane that meets the sphere in a small ball missing
//     them (flat_ball: the fans off a line or plane). A
//     long facet climbs from every vertex's leaf in turn (its apex may lie
//     beside either end); flat oblique nodes (a line or plane of points) are
//     also tested in their own frame, and balls far larger than their facet
//     in pencil form (algorithms/node_frame.hpp). The apex is near the
//     facet, so the first leaves give a small sphere and the climb costs
//     about one box test per level. The
//     pruning ball is a sphere of the pencil through f whose open-side part
//     contains the best candidate's sphere's (ball_of), its centre and radius
//     ENCLOSED by interval arithmetic (algorithms/interval.hpp) from a proved
//     upper bound of its pencil parameter (algorithms/pencil_parameter.hpp)
//     and, with exact kernels, from plain doubles with proved bounds: the
//     facet's normal (algorithms/facet_normal.hpp, 3D), a point within a
//     proved distance of the pencil's axis (algorithms/pencil_axis.hpp) and
//     the ball itself (algorithms/pencil_ball.hpp),
//     so a skipped box never meets the ball: the tree never decides the
//     winner. The ball is recomputed once per leaf that improved the best
//     (once for all the first leaves), not per improvement: the old one
//     still contains the new best's open-side cap. (A uniform bucket grid,
//     used here before, failed on uneven sets: see kd_tree.hpp.)
//   * Inexact kernels: a facet met by a third simplex, or twice on the same
//     side, a simplex budget exceeded, or a point left out end the run with
//     Outcome::failed; every loop is bounded.
#pragma once
#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "algorithms/box_ball.hpp"
#include "algorithms/circumball.hpp"
#include "algorithms/exact_flats.hpp"
#include "algorithms/facet_normal.hpp"
#include "algorithms/front.hpp"
#include "algorithms/huge_pages.hpp"
#include "algorithms/initial_simplex.hpp"
#include "algorithms/interval.hpp"
#include "algorithms/kd_tree.hpp"
#include "algorithms/oriented.hpp"
#include "algorithms/pencil_axis.hpp"
#include "algorithms/pencil_ball.hpp"
#include "algorithms/pencil_parameter.hpp"
#include "algorithms/tanemura_start.hpp"
#include "algorithms/triangulation_result.hpp"
#include "predicates/mp_kernel.hpp"

namespace dlab {

template <class K, int D>
class Tanemura {
  static_assert(KernelFor<K, D>);
  static constexpr int V = D + 1;
  static constexpr std::uint32_t kNone = 0xFFFFFFFFu;
  using Facet = std::array<std::uint32_t, D>;
  using Table = FacetTable<D>;

 public:
  explicit Tanemura(const K& k = K{}) : k_(k) {}

  // The kernel sees only the points given to run() (the start facet's auxiliary
  // points go to its own MpKernel); variants/driver.hpp may then fit a static
  // filter (tests/test_static_filter.cpp checks the promise).
  static constexpr bool kernel_sees_given_points_only = true;

  TriangulationResult run(std::span<const Point<D>> pts);
  const K& kernel() const { return k_; }

 private:
  // ---- predicates on ids ----
  Sign orient(const Facet& f, const Point<D>& p) const {
    if constexpr (D == 2)
      return orient_pos(k_, pts_[f[0]], pts_[f[1]], p);
    else
      return orient_pos(k_, pts_[f[0]], pts_[f[1]], pts_[f[2]], p);
  }
  // Positive iff p is strictly inside the circumsphere of the positive simplex
  // (f, c). With the sos policy K is perturbed<...> and never answers zero
  // here; with `strict` an exact zero is broken by the same symbolic walk
  // (predicates/perturbed.hpp), so that ties are decided consistently and the
  // front stays a triangulation (an arbitrary choice among cospherical
  // candidates could make overlapping simplices in 3D).
  Sign inside(const Facet& f, const Point<D>& c, const Point<D>& p) const {
    if constexpr (D == 2) {
      const Point2 &a = pts_[f[0]], &b = pts_[f[1]];
      const Sign s = k_.incircle(a, b, c, p);
      if (s != Sign::zero) return s;
      return sos::walk<2>({&a, &b, &c, &p}, [this](const std::array<const Point2*, 3>& t) {
        return k_.orient2d(*t[0], *t[1], *t[2]);
      });
    } else {
      const Point3 &a = pts_[f[0]], &b = pts_[f[1]], &d = pts_[f[2]];
      Sign s = k_.insphere(a, b, d, c, p);
      if (s == Sign::zero)
        s = sos::walk<3>({&a, &b, &d, &c, &p}, [this](const std::array<const Point3*, 4>& t) {
          return k_.orient3d(*t[0], *t[1], *t[2], *t[3]);
        });
      return -s;  // orient_pos > 0 means orient3d < 0 (algorithms/oriented.hpp)
    }
  }

  std::array<Iv, D> scaled(std::uint32_t id) const {  // the tree's enclosure of pts_[id]
    std::array<Iv, D> x;
    for (int i = 0; i < D; ++i) x[i] = tree_.scaled_iv(pts_[id][i], i);
    return x;
  }

  // The search's facet's scaled vertices, bq_'s lower ends (exact where bq_exact_).
  std::array<Point<D>, D> base_points() const {
    std::array<Point<D>, D> q;
    for (int j = 0; j < D; ++j)
      for (int i = 0; i < D; ++i) q[j][i] = bq_[j][i].lo;
    return q;
  }

  static double l1(const Point<D>& x, const Point<D>& y) {
    double s = 0;
    for (int i = 0; i < D; ++i) s += std::fabs(x[i] - y[i]);
    return s;  // a heuristic only (overflow to inf is harmless)
  }

  // apex: the vertex of the simplex behind f (kNone for the start facet).
  std::uint32_t search(const Facet& f, std::uint32_t apex);
  // Leaves this far apart in the tree's order make a long facet (search):
  // 256 cost 5 % more instructions on uniform 3D input (more long facets),
  // 2048 under 2 %, the fans unchanged.
  static constexpr std::uint32_t kNearSlots = 2048;
  bool add_simplex(const Facet& f, std::uint32_t p);  // false: failure (message_ set)
  // Exact kernels: whether f lies in the plane of a hull facet found earlier,
  // with the same open side (then f is a hull facet too: see search).
  bool on_known_hull_plane(const Facet& f);
  void record_hull_plane(const Facet& f, std::uint32_t apex);
  // Exact kernels: which of f's vertices (bit j: f[j]) lie in the
  // hyperplane h of a flat node's points (algorithms/exact_flats.hpp),
  // decided once per hyperplane and search (flat_seen_, flat_mask_). If all
  // do, f lies in h and none of the node's points is a candidate.
  // The kept answer inline (most calls), the deciding out of line: a call
  // to the whole saved and restored a dozen registers for a two-load answer.
  std::uint32_t flat_mask(const Facet& f, std::uint32_t h) {
    return flat_seen_[h] == stamp_ ? flat_mask_[h] : decide_flat_mask(f, h);
  }
  [[gnu::noinline]] std::uint32_t decide_flat_mask(const Facet& f, std::uint32_t h);
  static constexpr std::uint32_t kAllVertices = (1u << D) - 1;
  // Whether point id lies in flat h (exact orientation zero). The points
  // outside flat nodes (beside a line or plane, or on it in a node with a
  // point off it) are asked again and again, and their orientations are
  // exact zeros or nearly so (the adaptive kernel's slow stages): the last
  // answer for each is kept (on_flat_[id], off_flat_[id]: a flat that id is
  // known to lie in, or off).
  bool on_flat(std::uint32_t h, std::uint32_t id);
  // The search's points in a frame's coordinates, computed once per rows_id
  // (frames down a line or plane share their rows: kd_tree.hpp) for the
  // current facet and ball: f0_; nrm_ while there is no ball, else the
  // ball's centre and (huge balls) w.
  struct Projections {
    typename NodeFrame<D>::Projected f0, normal_or_centre, w;
  };
  const Projections& projections(const NodeFrame<D>& fr);
  void new_projections();  // the facet or the ball changed

  // ---- search helpers (scaled coordinates, enclosures) ----
  struct Ball {
    bool bounded = false;
    std::array<Iv, D> centre{};
    double r2 = 0;        // upper bound of the squared radius
    double r2_prune = 0;  // prune_r2(r2): algorithms/box_ball.hpp
    // ball_of only: a box that holds the ball (centre +- sqrt(r2), rounded
    // outwards), for the climb's stop (search).
    std::array<double, D> reach_lo{}, reach_hi{};
    // A ball far larger than the facet (r2 > 2^20 R^2) is also tested in the
    // pencil form (NodeFrame::may_hold_inside): w = 2 (v - centre), v = the
    // facet vertex base_[0] (on every sphere of the pencil), |w| <= w_norm.
    bool huge = false;
    std::array<Iv, D> w{};
    double w_norm = 0;
  };
  // Exact kernels, once there is a best: if D - 1 of f's vertices (mask) and
  // best_ lie in flat h, best_'s sphere meets h's hyperplane in the smallest
  // sphere through these D points (a sphere meets a hyperplane in a sphere of
  // it, and this one passes through them); so a point of h is inside (or on)
  // best_'s sphere iff it is inside (or on) that ball, whose radius is the
  // points' scale, not the sphere's: fans off a line or plane, whose spheres
  // are huge and almost tangent to it, prune the flat's nodes with the axis
  // box test. Else an unbounded Ball. Once per hyperplane and ball
  // (flat_ball_at_).
  //
  // While the ball is fresh (it is, in the climbs), its own trace is used
  // instead (trace_of_ball): a sphere S of the pencil through f passes
  // through f's vertices in h and, on the open side, holds best_'s sphere's
  // points, so a point of h on the open side inside best_'s sphere is inside
  // S's trace (algorithms/circumball.hpp, hyperplane_trace): a dozen
  // interval operations against the circumcentre's forty. The kept answer
  // inline, as flat_mask's.
  const Ball& flat_ball(const Facet& f, std::uint32_t h, std::uint32_t mask) {
    return flat_ball_at_[h] == projection_stamp_ ? flat_balls_[h] : compute_flat_ball(f, h, mask);
  }
  [[gnu::noinline, gnu::flatten]] const Ball& compute_flat_ball(const Facet& f, std::uint32_t h,
                                                                std::uint32_t mask);
  // The trace of ball_ on flat h into t; false where it is unbounded or
  // R^2 - d^2 cancels to below 2^-36 R^2 (its rounding then dominates).
  bool trace_of_ball(std::uint32_t h, Ball& t) const;
  // flatten: the interval operations inlined (half of the search's cost was
  // their calls on uniform 3D input).
  [[gnu::flatten]] Ball ball_of(std::uint32_t c);
  [[gnu::flatten]] void make_pencil();  // nn_, fcen_, vc_, and fr2_ or pencil_base_ (once per search)
  [[gnu::noinline]] bool box_may_be_outer(const std::array<double, D>& lo, const std::array<double, D>& hi) const;
  // The same answer, cheaper: the corner of each axis from the normal's sign
  // (set_outer_corners, once per search); box_may_be_outer decides any prune.
  // Inline: its call cost a fifth of its instructions.
  [[gnu::always_inline]] bool box_may_be_outer_fast(const std::array<double, D>& lo,
                                                    const std::array<double, D>& hi) const;
  void set_outer_corners();
  static bool box_may_meet_ball(const std::array<double, D>& lo, const std::array<double, D>& hi,
                                const Ball& ball) {
    return dlab::box_may_meet_ball<D>(lo, hi, ball.centre, ball.r2_prune);
  }
  [[gnu::always_inline]] inline bool point_may_be_in_ball(const Point<D>& p) const;
  bool point_outside_huge_ball(const Point<D>& p) const;  // see Ball::huge
  double outer_norm() {  // nrm_norm_, computed on first use in a search
    if (nrm_norm_ < 0) {
      Iv nn{0, 0};
      for (int i = 0; i < D; ++i) nn = nn + sq(nrm_[i]);
      nrm_norm_ = sqrt_up(nn.hi);
    }
    return nrm_norm_;
  }
  // Examines the point in a slot of the tree: best_ becomes it if it is a
  // better candidate (the ball is then stale).
  [[gnu::always_inline]] inline void examine(const Facet& f, std::uint32_t slot);
  // Examines the points of a leaf; then the ball follows the best candidate.
  void scan_leaf(const Facet& f, const typename KdTree<D>::Node& leaf);
  // The same for the exceptions of a flat node whose flat part is pruned.
  void scan_exceptions(const Facet& f, const typename ExactFlats<D>::Part& part);
  void refresh_ball();  // ball_ for best_ if it is stale
  // Visits the subtree of node k, pruned, the child nearer target_ first,
  // except the nodes visited already by this search: first_leaves marks
  // them (done_), one_climb skips the first leaves, many_climbs any node
  // marked (a pruned node stays prunable, as the ball only shrinks on the
  // open side). Marking every visit cost instructions on uniform input, so
  // only many_climbs pays for it.
  enum class Walk { first_leaves, one_climb, many_climbs };
  template <Walk W>
  [[gnu::always_inline]] inline void visit(const Facet& f, std::uint32_t k);
  // visit's part after the ball test, out of line: the test inline at each
  // call spares the nodes it prunes the call's register saves (uniform 3D
  // 2*10^4: 1.3 % fewer instructions).
  template <Walk W>
  [[gnu::noinline]] void visit_rest(const Facet& f, std::uint32_t k);
  double distance2_to_target(const typename KdTree<D>::Node& n) const;
  // Whether the target lies beyond the middle of the gap between n's
  // children a (left) and b along n's split axis: nearly the order by
  // distance to the target, at a fraction of its cost (uniform 3D: 0.3 %
  // more points examined, 5.1 % fewer instructions; session 37). Exact
  // kernels only, as the inexact kernels' answers depend on the order, and
  // not on flat nodes (a line's boxes are diagonal: 2D collinear examined
  // 55 % more points).
  bool nearer_right(const typename KdTree<D>::Node& n, std::uint32_t a, std::uint32_t b) const;
  bool ball_inside(const typename KdTree<D>::Node& n) const {  // ball_'s reach strictly inside n's box
    bool in = true;
    for (int i = 0; i < D; ++i) in &= n.lo[i] < ball_.reach_lo[i] && ball_.reach_hi[i] < n.hi[i];
    return in;
  }

  K k_;
  const Point<D>* pts_ = nullptr;
  KdTree<D> tree_;
  Table table_;
  struct Queued {
    Facet f;
    std::uint32_t apex;  // the vertex of the simplex behind f
  };
  std::vector<Queued> queue_;
  // Hull planes (exact kernels): a hull facet and the apex of the simplex
  // behind it (strictly on its closed side); plane_of_[v]: the last one with
  // vertex v, or kNone.
  struct HullPlane {
    Facet f;
    std::uint32_t inner;
  };
  std::vector<HullPlane> hull_planes_;
  std::vector<std::uint32_t> plane_of_;
  ExactFlats<D> flats_;
  std::vector<Projections> projections_;        // per rows_id
  std::vector<std::uint32_t> projected_at_;     // per rows_id: projection_stamp_ when computed
  std::vector<std::uint32_t> f0_projected_at_;  // per rows_id: stamp_ when f0 was projected
  std::uint32_t projection_stamp_ = 0;
  // flat_seen_[h] == stamp_: flat_mask decided hyperplane h in this search,
  // with the answer flat_mask_[h]; flat_ball_at_[h] == projection_stamp_:
  // flat_balls_[h] is flat_ball's answer for the current ball.
  std::vector<std::uint32_t> flat_seen_, flat_ball_at_, on_flat_, off_flat_;
  std::vector<std::uint8_t> flat_mask_;
  std::vector<Ball> flat_balls_;
  // Each flat's hyperplane, scaled: a point on it (refs()[0]) and a normal
  // (enclosures), for trace_of_ball.
  struct FlatPlane {
    std::array<Iv, D> at, normal;
    Iv nn;  // |normal|^2
  };
  std::vector<FlatPlane> flat_planes_;
  FlatPlane flat_plane(const std::array<std::uint32_t, D>& refs) const;  // through D points
  std::vector<std::uint32_t> out_;
  std::string message_;
  bool keep_closed_ = !K::exact;
  std::uint64_t max_simplices_ = 0;
  // search state
  Facet base_{};                     // the facet rotated for the enclosures (see search)
  std::array<Iv, D> f0_{};           // scaled base_[0]
  std::array<Iv, D> nrm_{};          // outer normal (scaled), enclosure
  double nrm_norm_ = -1;             // an upper bound of |nrm_| (outer_norm; -1: not yet)
  bool pencil_ready_ = false;        // make_pencil ran for this facet
  Iv nn_{};                          // |nrm_|^2 (make_pencil; not set for 2D balls in doubles)
  std::array<Iv, D> fcen_{};         // the pencil's base X0 (make_pencil; enclosure)
  std::array<std::array<Iv, D>, D> bq_{};  // scaled base_ vertices (bq_[0] = f0_)
  bool bq_exact_ = false;                  // every bq_ enclosure is a point
  std::array<std::array<Iv, D>, D> vc_{};  // base_[j] - X0 (enclosures)
  Iv fr2_{};                         // |base_[0] - X0|^2 (enclosure; X0 = C only)
  double base_r2_ = 0;               // about |base_[0] - X0|^2 (the scale of Ball::huge)
  bool pencil_in_doubles_ = false;   // X0 from pencil_axis.hpp, the balls from pencil_base_
  PencilBase<D> pencil_base_{};      // pencil_in_doubles_ only (pencil_ball.hpp)
  std::array<double, D> target_{};   // the facet's centroid, then the ball's centre (scaled, rounded): visit order only
  // box_may_be_outer_fast: per axis, whether the box's upper end maximises
  // nrm_i (x_i - f0_i), and f0_i's end to subtract; outer_mixed_: an
  // enclosure nrm_i spans zero (then the four-corner test).
  std::array<std::uint64_t, D> outer_hi_{};  // all ones: the upper end (a bit mask: no branch)
  std::array<double, D> outer_f0_{};
  bool outer_mixed_ = false;
  std::array<std::uint32_t, D> first_leaves_{};  // the leaves of the facet's vertices
  // done_[k] == stamp_: node k's subtree was visited by this search.
  std::vector<std::uint32_t> done_;
  std::uint32_t stamp_ = 0;
  std::uint32_t best_ = kNone;
  // An enclosure of the circumsphere of (f, b) for best_ or an earlier best b
  // of this search (valid: there is one; stale: best_ has moved since, within
  // the leaf being scanned: a sound prune still, see scan_leaf).
  Ball ball_;
  bool ball_valid_ = false, ball_stale_ = false;
  bool defer_ball_ = false;  // scan_leaf leaves the ball stale (search refreshes it)
  int near_f_at_ = 0;  // an end of the facet's shortest edge (L1; index in f)
  // counters
  std::uint64_t searches_ = 0, hull_facets_ = 0, examined_ = 0, candidates_ = 0, improvements_ = 0,
                balls_ = 0, nodes_visited_ = 0, leaves_visited_ = 0, closed_ = 0, duplicates_ = 0,
                hull_examined_ = 0,  // points examined by the searches that found no candidate
                hull_by_plane_ = 0,  // hull facets settled by a known hull plane (no climb)
                flat_skips_ = 0,     // nodes skipped as lying in the facet's hyperplane
                flat_ball_skips_ = 0;  // flat nodes outside the ball's trace on their hyperplane (flat_ball)
};

template <class K, int D>
void Tanemura<K, D>::make_pencil() {
  // Enclosures of the pencil's base X0 = q0 + c, a point of its axis, and of
  // each vertex minus X0. Exact kernels, where the vertices' scaled
  // coordinates are exact: X0 is a point within a proved distance of the
  // axis (algorithms/pencil_axis.hpp, plain doubles; in 2D near the edge's
  // midpoint), and the balls come from plain doubles too (pencil_base_:
  // algorithms/pencil_ball.hpp). Else X0 is f's circumcentre C
  // (algorithms/circumball.hpp, intervals), in f's plane, with |v - X0|^2
  // (fr2_). Inexact kernels keep the circumcentre: their answers can depend
  // on the pruning (see ball_of).
  pencil_ready_ = true;
  // |n|^2: for the 3D axis point and the circumcentre (not the 2D balls in doubles).
  bool have_nn = false;
  const auto normal_norm2 = [&] {
    if (!have_nn) {
      nn_ = Iv{0, 0};
      for (int i = 0; i < D; ++i) nn_ = nn_ + sq(nrm_[i]);
      have_nn = true;
    }
    return nn_;
  };
  std::array<Iv, D> c;
  pencil_in_doubles_ = false;
  if constexpr (K::exact) {
    if (bq_exact_) {
      const std::array<Point<D>, D> q = base_points();
      std::optional<AxisPoint<D>> a;
      if constexpr (D == 3)
        a = pencil_axis_point(q, nrm_, normal_norm2());
      else
        a = edge_axis_point(q);
      if (a) {
        pencil_in_doubles_ = true;
        base_r2_ = 0;
        for (int i = 0; i < D; ++i) {
          c[i] = Iv{Iv::lower_rel(a->y[i] - a->d), Iv::upper_rel(a->y[i] + a->d)};
          base_r2_ += a->y[i] * a->y[i];
        }
        pencil_base_ = pencil_base<D>(q[0], a->y, a->d, nrm_);
      }
    }
  }
  if (!pencil_in_doubles_) {
    const Circumball<D> cb = circumball<D>(bq_, nrm_, normal_norm2());
    c = cb.offset;
    fr2_ = cb.r2;
    base_r2_ = fr2_.hi;
  }
  for (int i = 0; i < D; ++i) fcen_[i] = f0_[i] + c[i];
  for (int j = 0; j < D; ++j)
    for (int i = 0; i < D; ++i)
      vc_[j][i] = j == 0 ? Iv{-c[i].hi, -c[i].lo} : bq_[j][i] - fcen_[i];
}

template <class K, int D>
typename Tanemura<K, D>::Ball Tanemura<K, D>::ball_of(std::uint32_t c) {
  // The spheres through f form a pencil: centre X0 + t n (X0 = fcen_, a
  // point of the axis through the centre of f's circumcircle: make_pencil;
  // n = nrm_ is orthogonal to the facet), squared radius |v - X0 - t n|^2 for
  // any vertex v. With R = |v - X0| the one through c has
  //   t_c = (|c - X0|^2 - R^2) / (2 n.(c - f0)),
  // and a point p on the open side is inside S_t iff t exceeds t_p; so for any
  // T >= t_c the open-side part of S_T contains that of S_{t_c}, which is all
  // that a prune needs (the box tests keep the other side out). T is the
  // upper end of an enclosure of t_c, a double, so the centre is X0 + T n
  // with enclosed roundings only. Both terms are evaluated from the facet
  // vertex v nearest to c, with e = c - v (exact identities for the true
  // values, as |v - X0| = R and n.(v - f0) = 0):
  //   |c - X0|^2 - R^2 = |e|^2 + 2 e.(v - X0),   n.(c - f0) = n.e.
  // From f0 instead, when c is a near-duplicate of another vertex, both
  // cancel to below their rounding errors and t is unbounded or far too big.
  Ball b;
  if (!pencil_ready_) make_pencil();
  int k = 0;
  double near = l1(pts_[c], pts_[base_[0]]);
  for (int j = 1; j < D; ++j)
    if (const double dj = l1(pts_[c], pts_[base_[j]]); dj < near) near = dj, k = j;
  // T: in plain doubles with an a-priori bound where c and v have exact
  // scaled coordinates (algorithms/pencil_parameter.hpp), else in intervals.
  // Exact kernels only: an inexact kernel's answer can depend on which points
  // the pruning leaves, and the corpus records those answers.
  std::array<Iv, D> xs;
  std::array<double, D> x, q;
  bool exact_points = K::exact;
  for (int i = 0; i < D; ++i) {
    xs[i] = tree_.scaled_iv(pts_[c][i], i);
    x[i] = xs[i].lo;
    q[i] = bq_[k][i].lo;
    exact_points &= xs[i].lo == xs[i].hi && bq_[k][i].lo == bq_[k][i].hi;
  }
  const std::optional<double> fast =
      exact_points ? pencil_parameter_upper<D>(x, q, vc_[k], nrm_) : std::nullopt;
  Iv T;
  if (fast) {
    T = Iv::exact(*fast);
  } else {
    Iv num{0, 0}, cross{0, 0}, den{0, 0};
    for (int i = 0; i < D; ++i) {
      const Iv e = xs[i] - bq_[k][i];
      num = num + sq(e);
      cross = cross + e * vc_[k][i];
      den = den + nrm_[i] * e;
    }
    num = num + (cross + cross);
    const Iv t = num / (den + den);
    if (!t.bounded()) return b;
    T = Iv::exact(t.hi);
  }
  Iv r2;
  if (pencil_in_doubles_) {
    // Centre and radius in plain doubles (algorithms/pencil_ball.hpp).
    const std::optional<PencilBall<D>> s = pencil_ball(pencil_base_, T.hi);
    if (!s) return b;
    for (int i = 0; i < D; ++i)
      b.centre[i] = {Iv::lower_rel(s->centre[i] - s->delta[i]), Iv::upper_rel(s->centre[i] + s->delta[i])};
    r2 = Iv{0, s->r2};
  } else {
    for (int i = 0; i < D; ++i) {
      b.centre[i] = fcen_[i] + T * nrm_[i];
      if (!b.centre[i].bounded()) return b;
    }
    // |v - C - T n|^2 = |v - C|^2 + T^2 |n|^2 (C in f's plane).
    r2 = fr2_ + sq(T) * nn_;
    if (!r2.bounded()) return b;
  }
  b.r2 = r2.hi;
  b.r2_prune = prune_r2(r2.hi);
  b.bounded = true;
  const Iv r = Iv::exact(sqrt_up(r2.hi));
  for (int i = 0; i < D; ++i) {
    b.reach_lo[i] = (b.centre[i] - r).lo;
    b.reach_hi[i] = (b.centre[i] + r).hi;
  }
  if (r2.hi > 0x1p20 * base_r2_) {
    // v - centre = (v - X0) - T n, with vc_[0] = v - X0.
    Iv w2{0, 0};
    for (int i = 0; i < D; ++i) {
      b.w[i] = (vc_[0][i] - T * nrm_[i]) * Iv::exact(2);
      w2 = w2 + sq(b.w[i]);
    }
    b.w_norm = sqrt_up(w2.hi);
    b.huge = std::isfinite(b.w_norm);
  }
  return b;
}

template <class K, int D>
bool Tanemura<K, D>::box_may_be_outer(const std::array<double, D>& lo,
                                      const std::array<double, D>& hi) const {
  // Upper bound of nrm . (x - f0) over the box (nrm, f0 enclosures; each term's
  // maximum is at a corner of its product rectangle, rounded up); <= 0:
  // nothing strictly outer. NaN compares false: keep.
  // Plain doubles, with a relative slack of 2^-44 for their few roundings: a
  // difference is exact or has relative error 2^-53 (subnormal differences are
  // exact), each product likewise unless it underflows; a possibly
  // underflowed product keeps the box (only exact zeros, from a zero factor,
  // pass). So axis-aligned hull planes (zero normal components, zero
  // differences) settle the boxes that touch them.
  double s = 0, a = 0;
  for (int i = 0; i < D; ++i) {
    const double nl = nrm_[i].lo, nh = nrm_[i].hi;
    if (nl == 0 && nh == 0) continue;
    const double dlo = lo[i] - f0_[i].hi, dhi = hi[i] - f0_[i].lo;
    const double m = std::max(std::max(nl * dlo, nl * dhi), std::max(nh * dlo, nh * dhi));
    if (!(std::fabs(m) >= 0x1p-960))
      for (const double x : {nl, nh})
        for (const double d : {dlo, dhi})
          if (x != 0 && d != 0 && !(std::fabs(x * d) >= 0x1p-960)) return true;
    s += m;
    a += std::fabs(m);
  }
  return !(s + 0x1p-44 * a <= 0);
}

template <class K, int D>
void Tanemura<K, D>::set_outer_corners() {
  outer_mixed_ = false;
  for (int i = 0; i < D; ++i) {
    outer_hi_[i] = nrm_[i].lo >= 0 ? ~std::uint64_t{0} : 0;
    outer_f0_[i] = outer_hi_[i] ? f0_[i].lo : f0_[i].hi;
    outer_mixed_ |= !(nrm_[i].lo >= 0) && !(nrm_[i].hi <= 0);  // NaN: mixed
  }
}

template <class K, int D>
inline bool Tanemura<K, D>::box_may_be_outer_fast(const std::array<double, D>& lo,
                                           const std::array<double, D>& hi) const {
  // With nrm_i >= 0 (both ends), n (x_i - f0_i) is largest at x_i = hi_i,
  // f0_i = f0_i.lo for either end n of nrm_i, and rounding is monotone: the
  // largest of box_may_be_outer's four rounded products is one of these two
  // (mirror image for nrm_i <= 0). So s and a are box_may_be_outer's (its
  // skipped zero axes add zeros), and where this keeps the box so does it;
  // a prune is left to it (its underflow guards).
  if (outer_mixed_) return box_may_be_outer(lo, hi);
  double s = 0, a = 0;
  for (int i = 0; i < D; ++i) {
    // lo[i] or hi[i], selected bitwise: a branch here mispredicted on a
    // quarter of the boxes (the choice changes from one facet to the next).
    const std::uint64_t m = outer_hi_[i];
    const double x = std::bit_cast<double>((std::bit_cast<std::uint64_t>(lo[i]) & ~m) |
                                           (std::bit_cast<std::uint64_t>(hi[i]) & m));
    const double d = x - outer_f0_[i];
    const double p = std::max(nrm_[i].lo * d, nrm_[i].hi * d);
    s += p;
    a += std::fabs(p);
  }
  if (!(s + 0x1p-44 * a <= 0)) return true;
  return box_may_be_outer(lo, hi);
}

template <class K, int D>
bool Tanemura<K, D>::point_may_be_in_ball(const Point<D>& p) const {
  if (ball_.huge) [[unlikely]]
    if (point_outside_huge_ball(p)) return false;
  std::array<double, D> x;
  if (tree_.exact_enclosures()) [[likely]] {
    for (int i = 0; i < D; ++i) x[i] = tree_.scaled_exact(p[i], i);
  } else {
    for (int i = 0; i < D; ++i) {
      const Iv v = tree_.scaled_iv(p[i], i);
      if (v.lo != v.hi) return true;  // underflowed scaling: do not prune
      x[i] = v.lo;
    }
  }
  return box_may_meet_ball(x, x, ball_);
}

template <class K, int D>
bool Tanemura<K, D>::point_outside_huge_ball(const Point<D>& p) const {
  // |p - v|^2 + w . (p - v) > 0 (see Ball), in interval arithmetic.
  Iv g{0, 0};
  for (int i = 0; i < D; ++i) {
    const Iv e = tree_.scaled_iv(p[i], i) - f0_[i];
    g = g + sq(e) + ball_.w[i] * e;
  }
  return g.lo > 0;
}

template <class K, int D>
void Tanemura<K, D>::examine(const Facet& f, std::uint32_t slot) {
  const std::uint32_t id = tree_.id(slot);
  bool vertex = false;
  for (int j = 0; j < D; ++j) vertex |= f[j] == id;
  if (vertex || id == best_) return;
  ++examined_;
  const Point<D>& p = tree_.coords(slot);
  // Certainly outside the current best sphere: cannot improve it.
  if (ball_valid_ && ball_.bounded && !point_may_be_in_ball(p)) return;
  if (orient(f, p) != Sign::positive) return;
  ++candidates_;
  if (best_ == kNone || inside(f, pts_[best_], p) == Sign::positive) {
    // A better candidate lies inside the current sphere, on the open side,
    // and its own sphere's open-side part lies inside the old one's (same
    // pencil, smaller offset): the old ball still prunes soundly for the
    // new best, so it is recomputed only once the leaf is done.
    best_ = id;
    ball_stale_ = true;
    ++improvements_;
  }
}

template <class K, int D>
void Tanemura<K, D>::scan_leaf(const Facet& f, const typename KdTree<D>::Node& leaf) {
  ++leaves_visited_;
  for (std::uint32_t k = leaf.begin; k < leaf.end; ++k) examine(f, k);
  if (!defer_ball_) refresh_ball();
}

template <class K, int D>
void Tanemura<K, D>::scan_exceptions(const Facet& f, const typename ExactFlats<D>::Part& part) {
  // A first leaf's points were examined at the start (examining one again
  // is harmless, as examine skips best_, but costs).
  for (const std::uint32_t slot : flats_.exceptions(part)) {
    bool first = false;
    for (int j = 0; j < D; ++j) first |= tree_.leaf_of(tree_.id(slot)) == first_leaves_[j];
    if (!first) examine(f, slot);
  }
  refresh_ball();
}

template <class K, int D>
void Tanemura<K, D>::refresh_ball() {
  if (!ball_stale_) return;
  ball_ = ball_of(best_);
  new_projections();
  // Children nearer the ball's centre first: the points deepest inside the
  // ball are the likeliest to improve on the best. In a fan off a line the
  // better candidates lie between the facet and the best, one after the
  // other along the line; from the centre the search halves that stretch at
  // each improvement instead of walking it leaf by leaf (2D collinear, n =
  // 65536: 2.92 M points examined -> 2.41 M).
  if (ball_.bounded)
    for (int i = 0; i < D; ++i) target_[i] = ball_.centre[i].lo / 2 + ball_.centre[i].hi / 2;
  ball_stale_ = false;
  ball_valid_ = true;
  ++balls_;
}

template <class K, int D>
double Tanemura<K, D>::distance2_to_target(const typename KdTree<D>::Node& n) const {
  double d2 = 0;
  for (int i = 0; i < D; ++i) {
    const double g = pos_part(n.lo[i] - target_[i]) + pos_part(target_[i] - n.hi[i]);
    d2 += g * g;
  }
  return d2;
}

template <class K, int D>
bool Tanemura<K, D>::nearer_right(const typename KdTree<D>::Node& n, std::uint32_t a, std::uint32_t b) const {
  const int axis = KdTree<D>::split_axis(n);
  return target_[axis] - tree_.node(a).hi[axis] > tree_.node(b).lo[axis] - target_[axis];
}

template <class K, int D>
template <typename Tanemura<K, D>::Walk W>
void Tanemura<K, D>::visit(const Facet& f, std::uint32_t k) {
  if constexpr (W != Walk::one_climb) {
    if (done_[k] == stamp_) return;
    done_[k] = stamp_;
  }
  const typename KdTree<D>::Node& n = tree_.node(k);
  ++nodes_visited_;
  // The ball test first: it is cheaper and, during the climb, prunes most nodes.
  if (ball_valid_ && ball_.bounded && !box_may_meet_ball(n.lo, n.hi, ball_)) return;
  visit_rest<W>(f, k);
}

template <class K, int D>
template <typename Tanemura<K, D>::Walk W>
void Tanemura<K, D>::visit_rest(const Facet& f, std::uint32_t k) {
  const typename KdTree<D>::Node& n = tree_.node(k);
  // Flat oblique points (fans off a line or plane): their oriented box, in
  // the climbs (the first leaves are scanned anyway); the outer side there
  // only while there is no ball (a hull facet's climb).
  const NodeFrame<D>* fr = W == Walk::first_leaves ? nullptr : tree_.frame(k);
  // The flat tests come before the outer-side test: they prune most flat
  // nodes, from answers kept for the search (flat_mask) or the ball
  // (flat_ball), and the outer-side test cost as much as they do.
  if constexpr (K::exact)
    if (tree_.framed(k))
      if (const std::uint32_t h = flats_.of_node(k); h != ExactFlats<D>::kNone) {
        // The flat part pruned: only the exceptions remain, where the box
        // may hold an outer point. A first leaf with exceptions is scanned
        // whole (see scan_exceptions).
        const typename ExactFlats<D>::Part* part = flats_.part(k);
        const auto flat_part_pruned = [&] {
          if (part && box_may_be_outer_fast(n.lo, n.hi)) scan_exceptions(f, *part);
        };
        if (W != Walk::first_leaves || !part) {
          if (const std::uint32_t mask = flat_mask(f, h); mask == kAllVertices) {
            ++flat_skips_;
            return flat_part_pruned();
          } else if (const std::uint32_t off = mask ^ kAllVertices;  // one vertex off the flat
                     W != Walk::first_leaves && best_ != kNone && (off & (off - 1)) == 0) {
            // A trace far smaller than the sphere (a fan off a line: the
            // sphere huge and almost tangent to it) decides alone: the
            // sphere's own tests would prune no node that meets it. (A fan
            // off a line in 3D has a trace about as large as its sphere, on
            // the plane through the line and a point beside it.)
            if (const Ball& t = flat_ball(f, h, mask); t.bounded) {
              if (!(part ? box_may_meet_ball(part->lo, part->hi, t) : box_may_meet_ball(n.lo, n.hi, t))) {
                ++flat_ball_skips_;
                return flat_part_pruned();
              }
              if (!part && ball_valid_ && ball_.bounded && t.r2 < 0x1p-20 * ball_.r2) fr = nullptr;
            }
          }
        }
      }
  if (!box_may_be_outer_fast(n.lo, n.hi)) return;
  if (fr) {
    const Projections& p = projections(*fr);
    if (!(ball_valid_ && ball_.bounded)) {
      if (!fr->may_be_outer(p.f0, p.normal_or_centre, outer_norm())) return;
    } else if (!fr->may_meet_ball(p.normal_or_centre, ball_.r2_prune) ||
               (ball_.huge && !fr->may_hold_inside(p.f0, p.w, ball_.w_norm))) {
      return;
    }
  }
  if (KdTree<D>::is_leaf(n)) {
    if constexpr (W == Walk::one_climb)
      for (int j = 0; j < D; ++j)
        if (first_leaves_[j] == k) return;
    return scan_leaf(f, n);
  }
  std::uint32_t a = tree_.left(k), b = n.right;
  const bool right_first = K::exact && !tree_.framed(k)
                               ? nearer_right(n, a, b)
                               : distance2_to_target(tree_.node(b)) < distance2_to_target(tree_.node(a));
  if (right_first) std::swap(a, b);
  visit<W>(f, a);
  visit<W>(f, b);  // recursion depth: the tree's, about log2(n / kLeaf)
}

template <class K, int D>
const typename Tanemura<K, D>::Projections& Tanemura<K, D>::projections(const NodeFrame<D>& fr) {
  Projections& p = projections_[fr.rows_id];
  if (projected_at_[fr.rows_id] == projection_stamp_) return p;
  projected_at_[fr.rows_id] = projection_stamp_;
  if (f0_projected_at_[fr.rows_id] != stamp_) {  // f0 stays for the whole search
    f0_projected_at_[fr.rows_id] = stamp_;
    p.f0 = fr.project(f0_);
  }
  if (!(ball_valid_ && ball_.bounded)) {
    p.normal_or_centre = fr.project(nrm_);
    return p;
  }
  p.normal_or_centre = fr.project(ball_.centre);
  if (ball_.huge) p.w = fr.project(ball_.w);
  return p;
}

template <class K, int D>
void Tanemura<K, D>::new_projections() {
  if (++projection_stamp_ == 0) {  // wrapped: no projection or flat ball may look current
    std::fill(projected_at_.begin(), projected_at_.end(), 0u);
    std::fill(flat_ball_at_.begin(), flat_ball_at_.end(), 0u);
    projection_stamp_ = 1;
  }
}

template <class K, int D>
bool Tanemura<K, D>::on_flat(std::uint32_t h, std::uint32_t id) {
  if (flats_.of_point(id) == h) return true;
  if (off_flat_[id] == h) return false;
  if (on_flat_[id] == h) return true;
  const std::array<std::uint32_t, D>& r = flats_.refs(h);
  Sign s;
  if constexpr (D == 2)
    s = k_.orient2d(pts_[r[0]], pts_[r[1]], pts_[id]);
  else
    s = k_.orient3d(pts_[r[0]], pts_[r[1]], pts_[r[2]], pts_[id]);
  (s == Sign::zero ? on_flat_ : off_flat_)[id] = h;
  return s == Sign::zero;
}

template <class K, int D>
std::uint32_t Tanemura<K, D>::decide_flat_mask(const Facet& f, std::uint32_t h) {
  std::uint32_t mask = 0;
  for (int j = 0; j < D; ++j)
    if (on_flat(h, f[j])) mask |= 1u << j;
  flat_seen_[h] = stamp_;
  flat_mask_[h] = static_cast<std::uint8_t>(mask);
  return mask;
}

template <class K, int D>
const typename Tanemura<K, D>::Ball& Tanemura<K, D>::compute_flat_ball(const Facet& f, std::uint32_t h,
                                                                      std::uint32_t mask) {
  Ball& b = flat_balls_[h];
  flat_ball_at_[h] = projection_stamp_;
  if (ball_valid_ && !ball_stale_ && ball_.bounded && trace_of_ball(h, b)) return b;
  b.bounded = false;
  if (!on_flat(h, best_)) return b;
  std::array<std::array<Iv, D>, D> q;
  int m = 0;
  for (int j = 0; j < D; ++j)
    if (mask >> j & 1u) q[m++] = scaled(f[j]);
  q[m] = scaled(best_);
  std::array<Iv, D> n{};
  if constexpr (D == 3) {
    std::array<Iv, 3> u, v;
    for (int i = 0; i < 3; ++i) u[i] = q[1][i] - q[0][i], v[i] = q[2][i] - q[0][i];
    n = cross(u, v);
  }
  const Circumball<D> cb = circumball<D>(q, n);
  for (int i = 0; i < D; ++i) {
    b.centre[i] = q[0][i] + cb.offset[i];
    if (!b.centre[i].bounded()) return b;
  }
  if (!cb.r2.bounded()) return b;
  b.r2 = cb.r2.hi;
  b.r2_prune = prune_r2(b.r2);
  b.bounded = true;
  return b;
}

template <class K, int D>
bool Tanemura<K, D>::trace_of_ball(std::uint32_t h, Ball& t) const {
  const FlatPlane& pl = flat_planes_[h];
  const Trace<D> tr = hyperplane_trace<D>(ball_.centre, ball_.r2, pl.at, pl.normal, pl.nn);
  t.bounded = false;
  for (int i = 0; i < D; ++i)
    if (!tr.centre[i].bounded()) return false;
  if (!tr.r2.bounded() || !(tr.r2.hi >= 0x1p-36 * ball_.r2)) return false;
  t.centre = tr.centre;
  t.r2 = tr.r2.hi;
  t.r2_prune = prune_r2(t.r2);
  t.huge = false;
  return t.bounded = true;
}

template <class K, int D>
typename Tanemura<K, D>::FlatPlane Tanemura<K, D>::flat_plane(const std::array<std::uint32_t, D>& refs) const {
  FlatPlane pl;
  pl.at = scaled(refs[0]);
  std::array<std::array<Iv, D>, D - 1> e;  // the other points minus at
  for (int j = 1; j < D; ++j) {
    const std::array<Iv, D> q = scaled(refs[j]);
    for (int i = 0; i < D; ++i) e[j - 1][i] = q[i] - pl.at[i];
  }
  if constexpr (D == 2)
    pl.normal = {Iv{0, 0} - e[0][1], e[0][0]};
  else
    pl.normal = cross(e[0], e[1]);
  pl.nn = Iv{0, 0};
  for (int i = 0; i < D; ++i) pl.nn = pl.nn + sq(pl.normal[i]);
  return pl;
}

template <class K, int D>
bool Tanemura<K, D>::on_known_hull_plane(const Facet& f) {
  // A hull facet h has no point strictly on its open side (exact search). If
  // every vertex of f lies on h's plane (exact orient = 0) and h's inner
  // point (the apex behind h, strictly on its closed side) is strictly on
  // f's closed side, f's open half-space is h's: f has no candidate either.
  for (int j = 0; j < D; ++j) {
    const std::uint32_t h = plane_of_[f[j]];
    if (h == kNone) continue;
    bool seen = false;
    for (int i = 0; i < j; ++i) seen |= plane_of_[f[i]] == h;
    if (seen) continue;
    const HullPlane& hp = hull_planes_[h];
    bool coplanar = true;
    for (int i = 0; i < D && coplanar; ++i) {
      bool shared = false;
      for (int m = 0; m < D; ++m) shared |= hp.f[m] == f[i];
      if (!shared) coplanar = orient(hp.f, pts_[f[i]]) == Sign::zero;
    }
    if (coplanar && orient(f, pts_[hp.inner]) == Sign::negative) return true;
  }
  return false;
}

template <class K, int D>
void Tanemura<K, D>::record_hull_plane(const Facet& f, std::uint32_t apex) {
  if (apex == kNone) return;
  const auto h = static_cast<std::uint32_t>(hull_planes_.size());
  hull_planes_.push_back({f, apex});
  for (int j = 0; j < D; ++j) plane_of_[f[j]] = h;
}

template <class K, int D>
std::uint32_t Tanemura<K, D>::search(const Facet& f, std::uint32_t apex) {
  ++searches_;
  best_ = kNone;
  double near_f = std::numeric_limits<double>::infinity();
  for (int j = 0; j < D; ++j)
    for (int i = j + 1; i < D; ++i)
      if (const double d = l1(pts_[f[i]], pts_[f[j]]); d < near_f) near_f = d, near_f_at_ = j;
  ball_valid_ = ball_stale_ = false;
  // Outer normal enclosure (scaled): orient_pos(f, p) has the sign of nrm . (p - f0).
  // The enclosures below start from an end of the facet's shortest edge
  // (a rotation: same orientation). From the far vertex of a sliver facet
  // (two near-duplicate vertices), both edges are long and inexact, their
  // cross product cancels to below its rounding error, and the normal's
  // enclosure then spans zero: no pruning at all (3D near-duplicates).
  base_ = f;
  std::rotate(base_.begin(), base_.begin() + near_f_at_, base_.end());
  std::array<std::array<Iv, D>, D> q;
  for (int j = 0; j < D; ++j)
    for (int i = 0; i < D; ++i) q[j][i] = tree_.scaled_iv(pts_[base_[j]][i], i);
  f0_ = q[0];
  bq_ = q;
  bq_exact_ = true;
  for (int j = 0; j < D; ++j)
    for (int i = 0; i < D; ++i) bq_exact_ &= q[j][i].lo == q[j][i].hi;
  // Exact kernels in 3D with exact scaled vertices: the normal from plain
  // doubles (algorithms/facet_normal.hpp) where that is not exact anyway.
  // Inexact kernels keep the interval products: their answers can depend on
  // the pruning (see ball_of).
  std::optional<std::array<Iv, 3>> fast_normal;
  if constexpr (D == 3 && K::exact)
    if (bq_exact_) fast_normal = facet_normal(base_points());
  if constexpr (D == 2) {
    const Iv ux = tight_sub(q[1][0], q[0][0]), uy = tight_sub(q[1][1], q[0][1]);
    nrm_ = {tight_sub(Iv{0, 0}, uy), ux};
  } else if (fast_normal) {
    nrm_ = *fast_normal;
  } else {
    std::array<Iv, 3> u, v;
    for (int i = 0; i < 3; ++i) u[i] = tight_sub(q[1][i], q[0][i]), v[i] = tight_sub(q[2][i], q[0][i]);
    const auto cross = [&](int j, int k) { return tight_sub(tight_mul(u[j], v[k]), tight_mul(u[k], v[j])); };
    nrm_ = {cross(1, 2), cross(2, 0), cross(0, 1)};
  }
  pencil_ready_ = false;
  new_projections();
  set_outer_corners();
  nrm_norm_ = -1;  // not yet (outer_norm)
  for (int i = 0; i < D; ++i) {
    double s = 0;
    for (int j = 0; j < D; ++j) s += q[j][i].lo;
    target_[i] = s / D;
  }
  // First the leaves of the facet's vertices (the apex is usually near one of
  // them: a fan of long facets, as on collinear sets, finds it beside the
  // near vertex), one ball for the best of them; then the climb from f[0]'s
  // leaf to the root, visiting the sibling subtree on the way, or for a long
  // facet the climbs from each vertex's leaf, one level at a time for all
  // vertices in turn. A long facet's apex may lie
  // beside either end, just across a split: in a fan off a line (or plane),
  // climbing from the far end alone improved the best leaf by leaf along the
  // whole line, and the balls of apices with their centre on the closed side
  // are huge. Every node is visited or pruned: the search is exhaustive; no
  // subtree is visited twice (done_).
  if (++stamp_ == 0) {  // wrapped: no node may look done, nothing decided or projected
    std::fill(done_.begin(), done_.end(), 0u);
    std::fill(flat_seen_.begin(), flat_seen_.end(), 0u);
    std::fill(f0_projected_at_.begin(), f0_projected_at_.end(), 0u);
    stamp_ = 1;
  }
  defer_ball_ = true;
  for (int j = 0; j < D; ++j) visit<Walk::first_leaves>(f, first_leaves_[j] = tree_.leaf_of(f[j]));
  defer_ball_ = false;
  // No candidate near f: f may be a hull facet. On a hull plane found before
  // (a lattice's face: all its points are coplanar, so the climb would visit
  // every leaf that the plane crosses), f is one: exact kernels only (an
  // inexact kernel's hull facet is no proof).
  (void)apex;
  if constexpr (K::exact) {
    if (best_ == kNone && on_known_hull_plane(f)) {
      ++hull_by_plane_;
      return kNone;
    }
  }
  refresh_ball();
  // Climb from every vertex's leaf together, one level at a time; two climbs
  // that meet go on as one. Only for a facet whose vertices' leaves are far
  // apart in the tree's order (a long facet); else from f[0]'s alone, as the
  // extra climbs cost 12 % of the instructions on uniform 3D input.
  bool long_facet = false;
  const std::uint32_t first = tree_.node(first_leaves_[0]).begin;
  for (int j = 1; j < D; ++j) {
    const std::uint32_t b = tree_.node(first_leaves_[j]).begin;
    long_facet |= (b > first ? b - first : first - b) > kNearSlots;
  }
  if (!long_facet) {
    // The climb stops once the ball lies strictly inside the box of the
    // subtree covered so far (k's). Its sibling subtrees on the way up hold
    // points beyond a split of k's points; with every enclosure a point
    // (exact_enclosures), k's box ends at k's own extreme coordinates,
    // within each split, so those points are all outside the ball. Most of
    // a climb on uniform input: a 2D search at 10^6 visited 24 nodes.
    const bool may_stop = tree_.exact_enclosures();
    for (std::uint32_t k = first_leaves_[0]; k != KdTree<D>::root(); k = tree_.parent(k)) {
      if (may_stop && ball_valid_ && ball_.bounded && ball_inside(tree_.node(k))) break;
      visit<Walk::one_climb>(f, tree_.sibling(k));
    }
    return best_;
  }
  std::array<std::uint32_t, D> at = first_leaves_;
  int climbs = D;
  // A fan off a flat (D - 1 vertices in a flat node, the apex off it) finds
  // its apex beside the flat vertices: the climb from the vertex off the
  // flat only tested the siblings on its way, one by one, where one climb's
  // coarser siblings are pruned whole (any one climb visits or prunes every
  // node).
  if constexpr (K::exact)
    if (flats_.count() > 0) {
      int on = 0;
      for (int j = 0; j < D; ++j)
        if (flats_.of_point(f[j]) != ExactFlats<D>::kNone) at[on++] = first_leaves_[j];
      if (on > 0) climbs = on;
    }
  for (;;) {
    for (int j = climbs - 1; j >= 0; --j) {
      bool ends = at[j] == KdTree<D>::root();
      for (int i = 0; i < j; ++i) ends |= at[i] == at[j];
      if (ends) at[j] = at[--climbs];
    }
    if (climbs == 0) break;
    for (int j = 0; j < climbs; ++j) {
      visit<Walk::many_climbs>(f, tree_.sibling(at[j]));
      at[j] = tree_.parent(at[j]);
    }
  }
  return best_;
}

template <class K, int D>
bool Tanemura<K, D>::add_simplex(const Facet& f, std::uint32_t p) {
  std::array<std::uint32_t, V> s;
  for (int j = 0; j < D; ++j) s[j] = f[j];
  s[D] = p;
  if (out_.size() / V >= max_simplices_) {
    message_ = "the front did not terminate within " + std::to_string(max_simplices_) + " simplices" +
               (K::exact ? " (a bug: the kernel is exact)" : "");
    return false;
  }
  out_.insert(out_.end(), s.begin(), s.end());
  // Facets opposite j < D contain p; oriented outwards (see the header).
  // Their slots are fetched together, then probed.
  std::array<Facet, D> gs, keys;
  for (int j = 0; j < D; ++j) {
    Facet& g = gs[j];
    int n = 0;
    for (int i = 0; i < V; ++i)
      if (i != j) g[n++] = s[i];
    if ((D - j) % 2 == 0) std::swap(g[0], g[1]);
    keys[j] = Table::sorted(g);
    table_.prefetch(keys[j]);
  }
  for (int j = 0; j < D; ++j) {
    const Facet& g = gs[j];
    const Facet& key = keys[j];
    const std::size_t at = table_.find(key);
    if (at == Table::npos) {
      table_.insert(key, g, Table::State::open);
      queue_.push_back({g, s[j]});
      continue;
    }
    typename Table::Slot& slot = table_.at(at);
    if (slot.state == Table::State::closed) {
      message_ = "a facet was met by a third simplex (inconsistent predicates)";
      return false;
    }
    if (slot.odd == Table::odd(g)) {  // same orientation (see FacetTable)
      message_ = "two simplices on the same side of a facet (inconsistent predicates)";
      return false;
    }
    ++closed_;
    if (keep_closed_)
      slot.state = Table::State::closed;
    else
      table_.erase(at);
  }
  return true;
}

template <class K, int D>
TriangulationResult Tanemura<K, D>::run(std::span<const Point<D>> pts) {
  TriangulationResult res;
  pts_ = pts.data();
  const std::size_t n = pts.size();
  // This and the run's other large arrays on huge pages (algorithms/huge_pages.hpp).
  std::vector<std::uint32_t> merged = huge_vector(n, kNotProcessed);

  const InitialSimplex<D> init = initial_simplex_or_outcome<D>(k_, pts, res);
  if (!init.found) return res;

  // Duplicates: the points sorted lexicographically with their ids, as
  // records (a comparison reads no memory elsewhere); each group maps to its
  // first id. The distinct ids, in increasing order, by one pass; then the
  // records hold their points in that order, for the tree (whose splits, and
  // so the searches' order and the inexact kernels' answers, depend on it).
  using Slot = typename KdTree<D>::Slot;
  std::vector<Slot> slots;
  reserve_huge(slots, n);
  for (std::uint32_t i = 0; i < n; ++i) slots.push_back({pts[i], i});
  std::sort(slots.begin(), slots.end(),
            [](const Slot& a, const Slot& b) { return a.x < b.x || (a.x == b.x && a.id < b.id); });
  for (std::size_t k = 0; k < n; ++k) {
    const std::uint32_t id = slots[k].id;
    if (k > 0 && slots[k].x == slots[k - 1].x) {
      merged[id] = merged[slots[k - 1].id];
      ++duplicates_;
    } else {
      merged[id] = id;
    }
  }
  std::vector<std::uint32_t> uniq;
  reserve_huge(uniq, n - duplicates_);
  for (std::uint32_t i = 0; i < n; ++i)
    if (merged[i] == i) {
      slots[uniq.size()] = {pts[i], i};
      uniq.push_back(i);
    }
  slots.resize(uniq.size());
  const std::uint64_t nu = uniq.size();
  max_simplices_ = D == 2 ? 2 * nu + 8 : (nu * (nu >= 3 ? nu - 3 : 0)) / 2 + 8;
  if constexpr (!K::exact)
    if (D == 3) max_simplices_ = std::min<std::uint64_t>(max_simplices_, 64 * nu + 1024);

  tree_.build(std::move(slots), n);
  done_.assign(tree_.node_count(), 0u);
  projections_.resize(tree_.frame_count());
  projected_at_.assign(tree_.frame_count(), 0u);
  f0_projected_at_.assign(tree_.frame_count(), 0u);
  if constexpr (K::exact) {
    flats_.build(k_, tree_, pts, init.ids);
    flat_seen_.assign(flats_.count(), 0u);
    flat_mask_.assign(flats_.count(), 0);
    flat_ball_at_.assign(flats_.count(), 0u);
    flat_balls_.assign(flats_.count(), Ball{});
    flat_planes_.clear();
    for (std::uint32_t h = 0; h < flats_.count(); ++h) flat_planes_.push_back(flat_plane(flats_.refs(h)));
    // Per point, only where there are flats (12 bytes a point of uniform input otherwise).
    on_flat_.assign(flats_.count() > 0 ? n : 0, ExactFlats<D>::kNone);
    off_flat_.assign(flats_.count() > 0 ? n : 0, ExactFlats<D>::kNone);
  }
  if constexpr (K::exact) assign_huge(plane_of_, n, kNone);
  reserve_huge(out_, static_cast<std::size_t>((D == 2 ? 2.0 : 6.6) * static_cast<double>(nu) + 16) * V);

  const StartFacet<D> start = find_start_facet<D>(pts, uniq);
  bool ok = start.found;
  if (!ok) message_ = start.why;
  if (ok) {
    Facet f = start.ids;
    for (int side = 0; side < 2 && ok; ++side) {
      if (side == 1) std::swap(f[0], f[1]);
      const std::uint32_t p = search(f, kNone);
      if (p == kNone) {
        ++hull_facets_;
        continue;
      }
      ok = add_simplex(f, p);
    }
  }
  std::size_t head = 0;
  while (ok && head < queue_.size()) {
    const auto [f, apex] = queue_[head++];
    if (head > 4096 && 2 * head > queue_.size()) {  // compact the FIFO
      queue_.erase(queue_.begin(), queue_.begin() + static_cast<std::ptrdiff_t>(head));
      head = 0;
    }
    // The next facet's slot is fetched during this one's search.
    if (head < queue_.size()) table_.prefetch(Table::sorted(queue_[head].f));
    const std::size_t at = table_.find(Table::sorted(f));
    if (at == Table::npos || table_.at(at).state != Table::State::open) continue;  // closed since
    const std::uint64_t examined_before = examined_;
    const std::uint32_t p = search(f, apex);  // reads the table only
    if (keep_closed_)
      table_.at(at).state = Table::State::closed;
    else
      table_.erase(at);
    if (p == kNone) {
      ++hull_facets_;
      hull_examined_ += examined_ - examined_before;
      if constexpr (K::exact) record_hull_plane(f, apex);
      continue;
    }
    ok = add_simplex(f, p);
  }

  if (ok) {
    // Every distinct point must be a vertex (an exact run guarantees it).
    std::vector<char> present(n, 0);
    for (std::uint32_t v : out_) present[v] = 1;
    for (std::uint32_t id : uniq)
      if (!present[id]) {
        ok = false;
        message_ = "point " + std::to_string(id) +
                   " is in no simplex (no candidate found where one must exist)" +
                   (K::exact ? " (a bug: the kernel is exact)" : "");
        break;
      }
  }
  const std::uint64_t bytes =
      tree_.bytes() + table_.bytes() + out_.capacity() * 4 + queue_.capacity() * sizeof(Queued) +
      hull_planes_.capacity() * sizeof(HullPlane) + plane_of_.capacity() * 4 + flats_.bytes() +
      projections_.capacity() * sizeof(Projections) + projected_at_.capacity() * 8 +
      flat_seen_.capacity() * 4 + flat_mask_.capacity() + flat_ball_at_.capacity() * 4 + (on_flat_.capacity() + off_flat_.capacity()) * 4 +
      flat_balls_.capacity() * sizeof(Ball) + flat_planes_.capacity() * sizeof(FlatPlane);
  if (!ok) {
    res.outcome = RunOutcome::failed;
    res.message = message_;
  } else {
    res.simplices = std::move(out_);
  }
  res.merged_into = std::move(merged);
  const std::uint64_t per_facet_x1000 = searches_ ? (1000 * examined_) / searches_ : 0;
  res.counters = {
      {"facets_searched", searches_},
      {"hull_facets", hull_facets_},
      {"facets_closed", closed_},
      {"points_examined", examined_},
      {"points_examined_per_facet_x1000", per_facet_x1000},
      {"points_examined_hull_facets", hull_examined_},
      {"hull_facets_by_plane", hull_by_plane_},
      {"flat_nodes", flats_.count()},
      {"flat_nodes_skipped", flat_skips_},
      {"flat_nodes_outside_ball", flat_ball_skips_},
      {"candidates_outer", candidates_},
      {"sphere_updates", improvements_},
      {"balls_computed", balls_},
      {"nodes_visited", nodes_visited_},
      {"leaves_visited", leaves_visited_},
      {"max_front", table_.max_size()},
      {"duplicates", duplicates_},
      {"tree_nodes", tree_.node_count()},
      {"bytes_reserved", bytes},
  };
  return res;
}

}  // namespace dlab
