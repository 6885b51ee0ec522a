// Floating-point expansion arithmetic, written from the mathematics of
// J. R. Shewchuk, "Adaptive Precision Floating-Point Arithmetic and Fast Robust
// Geometric Predicates", Discrete & Computational Geometry 18 (1997), sections 2-3:
// Two-Sum / Fast-Two-Sum (Knuth, Dekker; Theorems 6-7), Split and Two-Product
// (Dekker; Theorems 17-18), Grow-Expansion (Theorem 10), Fast-Expansion-Sum
// (Theorem 13), Scale-Expansion (Theorem 19), Compress (section 2.8), and the
// "estimate" (approximate value) of an expansion.
//
// An expansion is an array e[0..n) of doubles whose exact sum is the value it
// represents, ordered by increasing magnitude, pairwise nonoverlapping (the
// lowest set bit of a larger component is above the highest set bit of a
// smaller one). The *_zeroelim routines drop zero components but always keep at
// least one component, so a length is never 0 (the value zero is {0}).
//
// Preconditions (the theorems' hypotheses): IEEE binary64, round to nearest
// even, no contraction (-ffp-contract=off, set globally), no overflow, and no
// underflow that loses bits. Callers guarantee the last one by keeping every
// operand a multiple of a power of two >= 2^-1074 (the "grid" argument in
// predicates/error_bounds.md, section 2): then every rounding error below is
// itself representable. Split additionally needs |a| < 2^996 (the product
// a * (2^27 + 1) must not overflow).
//
// Two-Product uses std::fma only when the target has a hardware FMA (__FMA__);
// otherwise Dekker's Split, so results are identical either way (both exact).
#pragma once
#include <cmath>
#include <cstddef>

namespace dlab::xp {

// x + y == a + b exactly, x = fl(a + b). (Knuth; Theorem 7.)
inline void two_sum(double a, double b, double& x, double& y) {
  x = a + b;
  const double bv = x - a;
  const double av = x - bv;
  y = (a - av) + (b - bv);
}

// Same, when the exponent of a is at least that of b (|a| >= |b| suffices). (Dekker; Theorem 6.)
inline void fast_two_sum(double a, double b, double& x, double& y) {
  x = a + b;
  y = b - (x - a);
}

// x + y == a - b exactly, x = fl(a - b).
inline void two_diff(double a, double b, double& x, double& y) {
  x = a - b;
  const double bv = a - x;
  const double av = x + bv;
  y = (a - av) + (bv - b);
}

// The roundoff of x = fl(a - b): a - b == x + tail exactly.
inline double two_diff_tail(double a, double b, double x) {
  const double bv = a - x;
  const double av = x + bv;
  return (a - av) + (bv - b);
}

// a == hi + lo, each with at most 26 significant bits (Dekker; Theorem 17). |a| < 2^996.
inline void split(double a, double& hi, double& lo) {
  constexpr double splitter = 134217729.0;  // 2^27 + 1
  const double c = splitter * a;
  const double big = c - a;
  hi = c - big;
  lo = a - hi;
}

// x + y == a * b exactly, x = fl(a * b). (Dekker; Theorem 18.)
inline void two_product(double a, double b, double& x, double& y) {
  x = a * b;
#ifdef __FMA__
  y = std::fma(a, b, -x);
#else
  double ahi, alo, bhi, blo;
  split(a, ahi, alo);
  split(b, bhi, blo);
  const double err1 = x - ahi * bhi;
  const double err2 = err1 - alo * bhi;
  const double err3 = err2 - ahi * blo;
  y = alo * blo - err3;
#endif
}

// x + y == a * a exactly.
inline void two_square(double a, double& x, double& y) {
  x = a * a;
#ifdef __FMA__
  y = std::fma(a, a, -x);
#else
  double ahi, alo;
  split(a, ahi, alo);
  const double err1 = x - ahi * ahi;
  const double err3 = err1 - (ahi + ahi) * alo;
  y = alo * alo - err3;
#endif
}

// (a1 + a0) - b == x2 + x1 + x0 exactly (a1 + a0 an expansion). Unrolled Grow-Expansion.
inline void two_one_diff(double a1, double a0, double b, double& x2, double& x1, double& x0) {
  double i;
  two_diff(a0, b, i, x0);
  two_sum(a1, i, x2, x1);
}

// (a1 + a0) - (b1 + b0) == x3 + x2 + x1 + x0 exactly; a nonoverlapping expansion
// (zero components are kept). Expansion-Sum unrolled for two 2-component inputs.
inline void two_two_diff(double a1, double a0, double b1, double b0, double& x3, double& x2,
                         double& x1, double& x0) {
  double j, z;
  two_one_diff(a1, a0, b0, j, z, x0);
  two_one_diff(j, z, b1, x3, x2, x1);
}

// Grow-Expansion with zero elimination: h = e + b; h has room for elen + 1.
// Returns the length of h (>= 1).
inline int grow_expansion_zeroelim(int elen, const double* e, double b, double* h) {
  double q = b;
  int hn = 0;
  for (int i = 0; i < elen; ++i) {
    double hh;
    two_sum(q, e[i], q, hh);
    if (hh != 0.0) h[hn++] = hh;
  }
  if (q != 0.0 || hn == 0) h[hn++] = q;
  return hn;
}

// Fast-Expansion-Sum with zero elimination: h = e + f (Theorem 13; needs
// round-to-even and nonadjacent inputs, which every routine here produces).
// h has room for elen + flen and must not alias e or f. Returns the length (>= 1).
inline int fast_expansion_sum_zeroelim(int elen, const double* e, int flen, const double* f,
                                       double* h) {
  // Merge by magnitude on the fly: g_k is the next smallest of e[ei], f[fi].
  // The selection is branch-free (the merge order is data-dependent and its
  // mispredicted branches dominated the cost), and so is zero elimination.
  int ei = 0, fi = 0;
  auto take = [&]() -> double {  // with bounds checks: only for the first two
    const bool te = (fi >= flen) || (ei < elen && std::fabs(e[ei]) <= std::fabs(f[fi]));
    return te ? e[ei++] : f[fi++];
  };
  const int m = elen + flen;
  double q = take();
  int hn = 0;
  if (m >= 2) {
    const double g2 = take();
    double hh;
    fast_two_sum(g2, q, q, hh);  // |g2| >= |g1|
    h[hn] = hh;
    hn += hh != 0.0;
    auto absorb = [&](double g) {
      two_sum(q, g, q, hh);
      h[hn] = hh;
      hn += hh != 0.0;
    };
    while (ei < elen && fi < flen) {
      const double ev = e[ei], fv = f[fi];
      const bool te = std::fabs(ev) <= std::fabs(fv);
      ei += te;
      fi += !te;
      absorb(te ? ev : fv);
    }
    while (ei < elen) absorb(e[ei++]);
    while (fi < flen) absorb(f[fi++]);
  }
  if (q != 0.0 || hn == 0) h[hn++] = q;
  return hn;
}

// Scale-Expansion with zero elimination: h = b * e (Theorem 19). h has room for
// 2 * elen and must not alias e. Returns the length (>= 1).
inline int scale_expansion_zeroelim(int elen, const double* e, double b, double* h) {
  double q, hh;
  two_product(e[0], b, q, hh);
  int hn = 0;
  h[hn] = hh;
  hn += hh != 0.0;
  for (int i = 1; i < elen; ++i) {
    double t1, t0, sum;
    two_product(e[i], b, t1, t0);
    two_sum(q, t0, sum, hh);
    h[hn] = hh;
    hn += hh != 0.0;
    fast_two_sum(t1, sum, q, hh);
    h[hn] = hh;
    hn += hh != 0.0;
  }
  if (q != 0.0 || hn == 0) h[hn++] = q;
  return hn;
}

// Compress (section 2.8): the same value as a nonadjacent expansion whose
// largest component approximates the value within one ulp. h has room for elen
// and may alias e. Returns the length (>= 1).
inline int compress(int elen, const double* e, double* h) {
  // Downward pass: from the largest component, carry Q; park the large parts at the top.
  int bottom = elen - 1;
  double q = e[bottom];
  // Stores parked in h[bottom..]; reads only e[i] with i < bottom: safe when h == e.
  for (int i = elen - 2; i >= 0; --i) {
    double qnew, qq;
    fast_two_sum(q, e[i], qnew, qq);
    if (qq != 0.0) {
      h[bottom--] = qnew;
      q = qq;
    } else {
      q = qnew;
    }
  }
  h[bottom] = q;
  // Upward pass: from the smallest parked part, emit roundoffs from the bottom.
  int top = 0;
  for (int i = bottom + 1; i < elen; ++i) {
    double qnew, qq;
    fast_two_sum(h[i], q, qnew, qq);
    if (qq != 0.0) h[top++] = qq;
    q = qnew;
  }
  h[top++] = q;
  return top;
}

// Approximate value: components summed from the smallest (relative error about
// one ulp for a nonoverlapping expansion; Shewchuk's "Estimate").
inline double estimate(int elen, const double* e) {
  double q = e[0];
  for (int i = 1; i < elen; ++i) q += e[i];
  return q;
}

// Exact sign of an expansion: the sign of its largest nonzero component.
inline int sign(int elen, const double* e) {
  for (int i = elen - 1; i >= 0; --i)
    if (e[i] != 0.0) return e[i] > 0 ? 1 : -1;
  return 0;
}

// A fixed-capacity expansion on the stack; N is a proven maximum length.
template <int N>
struct Expansion {
  static constexpr int capacity = N;
  double c[N];
  int n = 0;
  int sign() const { return xp::sign(n, c); }
  double estimate() const { return xp::estimate(n, c); }
  void negate() {
    for (int i = 0; i < n; ++i) c[i] = -c[i];
  }
  // Compress in place (same value, usually far fewer components: a value of
  // b significant bits needs about b/53 nonadjacent components).
  Expansion& compress() {
    n = xp::compress(n, c, c);
    return *this;
  }
};

// The exact difference a - b as a 1- or 2-component expansion.
inline Expansion<2> diff(double a, double b) {
  Expansion<2> r;
  double x, y;
  two_diff(a, b, x, y);
  if (y == 0.0) {
    r.c[0] = x;
    r.n = 1;
  } else {
    r.c[0] = y;
    r.c[1] = x;
    r.n = 2;
  }
  return r;
}

template <int N, int M>
Expansion<N + M> operator+(const Expansion<N>& e, const Expansion<M>& f) {
  Expansion<N + M> h;
  h.n = fast_expansion_sum_zeroelim(e.n, e.c, f.n, f.c, h.c);
  return h;
}

template <int N, int M>
Expansion<N + M> operator-(const Expansion<N>& e, const Expansion<M>& f) {
  double g[M];  // -f, only f.n entries touched
  for (int i = 0; i < f.n; ++i) g[i] = -f.c[i];
  Expansion<N + M> h;
  h.n = fast_expansion_sum_zeroelim(e.n, e.c, f.n, g, h.c);
  return h;
}

template <int N>
Expansion<2 * N> scale(const Expansion<N>& e, double b) {
  Expansion<2 * N> h;
  h.n = scale_expansion_zeroelim(e.n, e.c, b, h.c);
  return h;
}

// Product of two expansions: sum over the components of f of e scaled by them.
// Length <= 2 * N * M (each scale gives <= 2N, M of them summed).
template <int N, int M>
Expansion<2 * N * M> operator*(const Expansion<N>& e, const Expansion<M>& f) {
  Expansion<2 * N * M> acc;
  acc.n = scale_expansion_zeroelim(e.n, e.c, f.c[0], acc.c);
  if (f.n == 1) return acc;
  Expansion<2 * N * M> tmp;
  double s[2 * N];
  Expansion<2 * N * M>* cur = &acc;
  Expansion<2 * N * M>* other = &tmp;
  for (int j = 1; j < f.n; ++j) {
    const int sn = scale_expansion_zeroelim(e.n, e.c, f.c[j], s);
    other->n = fast_expansion_sum_zeroelim(cur->n, cur->c, sn, s, other->c);
    Expansion<2 * N * M>* t = cur;
    cur = other;
    other = t;
  }
  if (cur != &acc) {
    acc.n = cur->n;
    for (int i = 0; i < cur->n; ++i) acc.c[i] = cur->c[i];
  }
  return acc;
}

// Expansion from a single double, and from the exact product of two doubles.
inline Expansion<1> single(double a) {
  Expansion<1> r;
  r.c[0] = a;
  r.n = 1;
  return r;
}
inline Expansion<2> product(double a, double b) {
  Expansion<2> r;
  double x, y;
  two_product(a, b, x, y);
  if (y == 0.0) {
    r.c[0] = x;
    r.n = 1;
  } else {
    r.c[0] = y;
    r.c[1] = x;
    r.n = 2;
  }
  return r;
}

}  // namespace dlab::xp
