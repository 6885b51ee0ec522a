# orient2d: stage A (error_bounds.md 4.2), out of line after the exponent guard.
#
# Code modelled (predicates/adaptive_kernel.cpp, orient2d_slow):
#   dl = acx*bcy   dr = acy*bcx   det = dl - dr
#   (signs of dl, dr differ or one is zero: answered at once, F1)
#   detsum = dl + dr  (or -dl - dr)   bound = o2A * detsum;   test det > bound
#
# Reduction (by hand, README.md "per-monomial brackets"): after the guard of
# error_bounds.md 2 nothing underflows, and each rounding is relative. With a = acx*bcy
# and b = acy*bcx the exact products of the rounded differences (a, b >= 0; the mirror
# image covers a, b <= 0), s = dl - dr (det = fl(s)), D the exact determinant:
#   s - D = a [(1+d1) - (1+ta1)(1+ta2)] - b [(1+d2) - (1+tb1)(1+tb2)]
#   bound = o2A (a(1+d1) + b(1+d2)) (1+d3) (1+db)
# and det > bound gives s > bound (monotone rounding), so
#   +-D > a [o2A (1+d1)(1+d3)(1+db) - |(1+d1) - (1+ta1)(1+ta2)|] + b [the same in d2, tb],
# and the bracket, proved >= 0 below, is the whole claim.

#@-Eprecision=200
o2A = 0x1.8000000000004p-52;  # dlab-constant adaptive::o2A

mono = o2A * (1 + d1) * (1 + d3) * (1 + db) - |(1 + d1) - (1 + ta1) * (1 + ta2)|;

{ |d1| <= 1b-53 /\ |d3| <= 1b-53 /\ |db| <= 1b-53 /\ |ta1| <= 1b-53 /\ |ta2| <= 1b-53
  -> mono >= 0 /\ mono in ? }
