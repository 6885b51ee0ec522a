// The circumcentre of a triangle (2D) or tetrahedron (3D) with double
// coordinates, computed exactly and rounded once: each coordinate is
//   c_i = a_i + Det_i / (2 Det),
// Det = det[b-a; c-a] (2D) or det[b-a; c-a; d-a] (3D) and Det_i the same
// determinant with column i replaced by the squared lengths |v-a|^2 (Cramer's
// rule for the equations 2 (v-a).(c-a) = |v-a|^2, v = b, c[, d]); e.g.
// J. O'Rourke, "Computational Geometry in C", 2nd ed., 1998, section 7.1 (2D),
// and its 3D analogue. The determinants are exact integers (GMP) after
// scaling every coordinate by one power of two, and the quotient is rounded to
// the nearest double, ties to even (round_quotient), once: the result is the
// double nearest the exact centre (subnormal or infinite when it must be).
// This file constructs coordinates; it decides no sign for an algorithm.
#pragma once
#include <array>
#include <stdexcept>

#include <gmp.h>

#include "predicates/point.hpp"

namespace dlab::voronoi {

// A flat simplex (Det = 0) has no circumcentre.
struct FlatSimplex : std::domain_error {
  using std::domain_error::domain_error;
};

Point2 circumcentre(const Point2& a, const Point2& b, const Point2& c);
Point3 circumcentre(const Point3& a, const Point3& b, const Point3& c, const Point3& d);

// The double nearest num / den * 2^exp2 (den != 0), ties to even; +-0 for a
// zero numerator, +-infinity beyond the largest double. mpq_get_d truncates;
// this rounds: q = floor(|num| 2^k / |den|) with k chosen so that q has 53
// significant bits (fewer in the subnormal range), then the remainder r
// decides: 2r > |den| or (2r == |den| and q odd) rounds q up.
double round_quotient(const mpz_t num, const mpz_t den, long exp2);

}  // namespace dlab::voronoi
