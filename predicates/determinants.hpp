// The four predicate determinants, written once over any number type T.
// Coordinates of type P[i] are converted to T before any arithmetic, so with an
// exact T (GMP integers, wide fixed integers) the result is the exact value.
// Expansions (Shewchuk 1997, section 4 / appendix; the cofactor form of the
// 3x3 and 4x4 determinants after translating the last point to the origin):
//   orient2d = (a-c)x (b-c)y - (a-c)y (b-c)x
//   incircle = |a-d|^2 M(b,c) - |b-d|^2 M(a,c) + |c-d|^2 M(a,b),   M(p,q) = px qy - py qx
//   orient3d = adx (bdy cdz - bdz cdy) + bdx (cdy adz - cdz ady) + cdx (ady bdz - adz bdy)
//   insphere = 4x4 Laplace expansion along the lifted column, minors by 2x2 products.
#pragma once

namespace dlab::det {

template <class T, class P>
constexpr T orient2d(const P& a, const P& b, const P& c) {
  const T acx = T(a[0]) - T(c[0]), acy = T(a[1]) - T(c[1]);
  const T bcx = T(b[0]) - T(c[0]), bcy = T(b[1]) - T(c[1]);
  return T(acx * bcy) - T(acy * bcx);
}

template <class T, class P>
constexpr T incircle(const P& a, const P& b, const P& c, const P& d) {
  const T adx = T(a[0]) - T(d[0]), ady = T(a[1]) - T(d[1]);
  const T bdx = T(b[0]) - T(d[0]), bdy = T(b[1]) - T(d[1]);
  const T cdx = T(c[0]) - T(d[0]), cdy = T(c[1]) - T(d[1]);
  const T alift = T(adx * adx) + T(ady * ady);
  const T blift = T(bdx * bdx) + T(bdy * bdy);
  const T clift = T(cdx * cdx) + T(cdy * cdy);
  const T bc = T(bdx * cdy) - T(bdy * cdx);
  const T ca = T(cdx * ady) - T(cdy * adx);
  const T ab = T(adx * bdy) - T(ady * bdx);
  return T(T(alift * bc) + T(blift * ca)) + T(clift * ab);
}

template <class T, class P>
constexpr T orient3d(const P& a, const P& b, const P& c, const P& d) {
  const T adx = T(a[0]) - T(d[0]), ady = T(a[1]) - T(d[1]), adz = T(a[2]) - T(d[2]);
  const T bdx = T(b[0]) - T(d[0]), bdy = T(b[1]) - T(d[1]), bdz = T(b[2]) - T(d[2]);
  const T cdx = T(c[0]) - T(d[0]), cdy = T(c[1]) - T(d[1]), cdz = T(c[2]) - T(d[2]);
  return T(T(adx * T(T(bdy * cdz) - T(bdz * cdy))) + T(bdx * T(T(cdy * adz) - T(cdz * ady)))) +
         T(cdx * T(T(ady * bdz) - T(adz * bdy)));
}

template <class T, class P>
constexpr T insphere(const P& a, const P& b, const P& c, const P& d, const P& e) {
  const T aex = T(a[0]) - T(e[0]), aey = T(a[1]) - T(e[1]), aez = T(a[2]) - T(e[2]);
  const T bex = T(b[0]) - T(e[0]), bey = T(b[1]) - T(e[1]), bez = T(b[2]) - T(e[2]);
  const T cex = T(c[0]) - T(e[0]), cey = T(c[1]) - T(e[1]), cez = T(c[2]) - T(e[2]);
  const T dex = T(d[0]) - T(e[0]), dey = T(d[1]) - T(e[1]), dez = T(d[2]) - T(e[2]);
  // 2x2 minors of the x,y columns.
  const T ab = T(aex * bey) - T(bex * aey);
  const T bc = T(bex * cey) - T(cex * bey);
  const T cd = T(cex * dey) - T(dex * cey);
  const T da = T(dex * aey) - T(aex * dey);
  const T ac = T(aex * cey) - T(cex * aey);
  const T bd = T(bex * dey) - T(dex * bey);
  // 3x3 minors of the x,y,z columns.
  const T abc = T(T(aez * bc) - T(bez * ac)) + T(cez * ab);
  const T bcd = T(T(bez * cd) - T(cez * bd)) + T(dez * bc);
  const T cda = T(T(cez * da) + T(dez * ac)) + T(aez * cd);
  const T dab = T(T(dez * ab) + T(aez * bd)) + T(bez * da);
  const T alift = T(T(aex * aex) + T(aey * aey)) + T(aez * aez);
  const T blift = T(T(bex * bex) + T(bey * bey)) + T(bez * bez);
  const T clift = T(T(cex * cex) + T(cey * cey)) + T(cez * cez);
  const T dlift = T(T(dex * dex) + T(dey * dey)) + T(dez * dez);
  return T(T(dlift * abc) - T(clift * dab)) + T(T(blift * cda) - T(alift * bcd));
}

}  // namespace dlab::det
