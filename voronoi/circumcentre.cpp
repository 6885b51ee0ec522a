// See circumcentre.hpp.
#include "voronoi/circumcentre.hpp"

#include <algorithm>
#include <climits>
#include <cmath>
#include <cstdint>
#include <span>

namespace dlab::voronoi {
namespace {

// An mpz_t with a destructor.
struct Z {
  mpz_t v;
  Z() { mpz_init(v); }
  ~Z() { mpz_clear(v); }
  Z(const Z&) = delete;
  Z& operator=(const Z&) = delete;
  operator mpz_ptr() { return v; }
  operator mpz_srcptr() const { return v; }
};

// The exponent E of the least significant bit over the coordinates: every
// coordinate is an integer multiple of 2^E (zeros aside). E = 0 if all are 0.
long common_exponent(std::span<const double> xs) {
  long e_min = LONG_MAX;
  for (double x : xs) {
    if (!std::isfinite(x)) throw std::domain_error("circumcentre of a non-finite point");
    if (x == 0) continue;
    int e = 0;
    std::frexp(x, &e);  // x = m 2^e, 0.5 <= |m| < 1: m 2^53 is an integer
    e_min = std::min(e_min, static_cast<long>(e) - 53);
  }
  return e_min == LONG_MAX ? 0 : e_min;
}

// out = x / 2^e, an integer (e from common_exponent).
void scaled(mpz_ptr out, double x, long e) {
  if (x == 0) {
    mpz_set_ui(out, 0);
    return;
  }
  int ex = 0;
  const double m = std::frexp(x, &ex);
  mpz_set_d(out, std::ldexp(m, 53));  // |m 2^53| < 2^53: exact
  mpz_mul_2exp(out, out, static_cast<mp_bitcnt_t>(static_cast<long>(ex) - 53 - e));
}

}  // namespace

double round_quotient(const mpz_t num, const mpz_t den, long exp2) {
  const int sign = mpz_sgn(num) * mpz_sgn(den);
  if (mpz_sgn(den) == 0) throw std::domain_error("round_quotient: zero denominator");
  if (sign == 0) return 0.0;
  Z n, d, q, r;
  mpz_abs(n, num);
  mpz_abs(d, den);
  // e = floor(log2(n / d)): nb - db or one less.
  long e = static_cast<long>(mpz_sizeinbase(n, 2)) - static_cast<long>(mpz_sizeinbase(d, 2));
  {
    Z lhs, rhs;  // n >= d 2^e ?
    mpz_set(lhs, n);
    mpz_set(rhs, d);
    if (e >= 0)
      mpz_mul_2exp(rhs, rhs, static_cast<mp_bitcnt_t>(e));
    else
      mpz_mul_2exp(lhs, lhs, static_cast<mp_bitcnt_t>(-e));
    if (mpz_cmp(lhs, rhs) < 0) --e;
  }
  // q = floor(n 2^k / d): 53 bits for a normal result; for a subnormal one
  // (e + exp2 < -1022) the last bit weighs 2^-1074, so k = exp2 + 1074.
  const long k = std::min(52 - e, exp2 + 1074);
  if (k >= 0)
    mpz_mul_2exp(n, n, static_cast<mp_bitcnt_t>(k));
  else
    mpz_mul_2exp(d, d, static_cast<mp_bitcnt_t>(-k));
  mpz_fdiv_qr(q, r, n, d);
  mpz_mul_2exp(r, r, 1);  // compare 2r with d: above half, or a tie to even
  const int c = mpz_cmp(r, d);
  if (c > 0 || (c == 0 && mpz_odd_p(q.v))) mpz_add_ui(q, q, 1);
  // q <= 2^53: exact as a double; ldexp rounds nothing (or overflows to inf).
  const long shift = exp2 - k;
  const double mag = std::ldexp(mpz_get_d(q), static_cast<int>(std::clamp(shift, -4000L, 4000L)));
  return sign < 0 ? -mag : mag;
}

Point2 circumcentre(const Point2& a, const Point2& b, const Point2& c) {
  const double xs[] = {a[0], a[1], b[0], b[1], c[0], c[1]};
  const long e = common_exponent(xs);
  Z A[2], u[2], v[2], t;
  for (int i = 0; i < 2; ++i) {
    scaled(A[i], a[i], e);
    scaled(u[i], b[i], e);
    scaled(v[i], c[i], e);
    mpz_sub(u[i], u[i], A[i]);
    mpz_sub(v[i], v[i], A[i]);
  }
  Z det, lu, lv, dx, dy;
  mpz_mul(det, u[0], v[1]);
  mpz_submul(det, u[1], v[0]);
  if (mpz_sgn(det.v) == 0) throw FlatSimplex("circumcentre of a flat triangle");
  mpz_mul(lu, u[0], u[0]);
  mpz_addmul(lu, u[1], u[1]);
  mpz_mul(lv, v[0], v[0]);
  mpz_addmul(lv, v[1], v[1]);
  mpz_mul(dx, lu, v[1]);  // Det_x = |u|^2 v_y - |v|^2 u_y
  mpz_submul(dx, lv, u[1]);
  mpz_mul(dy, lv, u[0]);  // Det_y = |v|^2 u_x - |u|^2 v_x
  mpz_submul(dy, lu, v[0]);
  // c_i 2^-e = A_i + Det_i / (2 Det) = (2 Det A_i + Det_i) / (2 Det).
  Z den, num;
  mpz_mul_2exp(den, det, 1);
  Point2 out{};
  const mpz_srcptr d_i[] = {dx, dy};
  for (int i = 0; i < 2; ++i) {
    mpz_mul(num, den, A[i]);
    mpz_add(num, num, d_i[i]);
    out[i] = round_quotient(num, den, e);
  }
  return out;
}

Point3 circumcentre(const Point3& a, const Point3& b, const Point3& c, const Point3& d) {
  const double xs[] = {a[0], a[1], a[2], b[0], b[1], b[2], c[0], c[1], c[2], d[0], d[1], d[2]};
  const long e = common_exponent(xs);
  Z A[3], u[3], v[3], w[3];
  for (int i = 0; i < 3; ++i) {
    scaled(A[i], a[i], e);
    scaled(u[i], b[i], e);
    scaled(v[i], c[i], e);
    scaled(w[i], d[i], e);
    mpz_sub(u[i], u[i], A[i]);
    mpz_sub(v[i], v[i], A[i]);
    mpz_sub(w[i], w[i], A[i]);
  }
  // Cross products v x w, w x u, u x v.
  Z vw[3], wu[3], uv[3];
  const auto cross = [](Z (&out)[3], Z (&p)[3], Z (&q)[3]) {
    for (int i = 0; i < 3; ++i) {
      const int j = (i + 1) % 3, k = (i + 2) % 3;
      mpz_mul(out[i], p[j], q[k]);
      mpz_submul(out[i], p[k], q[j]);
    }
  };
  cross(vw, v, w);
  cross(wu, w, u);
  cross(uv, u, v);
  Z det, lu, lv, lw;
  mpz_mul(det, u[0], vw[0]);
  mpz_addmul(det, u[1], vw[1]);
  mpz_addmul(det, u[2], vw[2]);
  if (mpz_sgn(det.v) == 0) throw FlatSimplex("circumcentre of a flat tetrahedron");
  const auto norm2 = [](mpz_ptr out, Z (&p)[3]) {
    mpz_mul(out, p[0], p[0]);
    mpz_addmul(out, p[1], p[1]);
    mpz_addmul(out, p[2], p[2]);
  };
  norm2(lu, u);
  norm2(lv, v);
  norm2(lw, w);
  // Det_i = |u|^2 (v x w)_i + |v|^2 (w x u)_i + |w|^2 (u x v)_i.
  Z den, num;
  mpz_mul_2exp(den, det, 1);
  Point3 out{};
  for (int i = 0; i < 3; ++i) {
    mpz_mul(num, den, A[i]);
    mpz_addmul(num, lu, vw[i]);
    mpz_addmul(num, lv, wu[i]);
    mpz_addmul(num, lw, uv[i]);
    out[i] = round_quotient(num, den, e);
  }
  return out;
}

}  // namespace dlab::voronoi
