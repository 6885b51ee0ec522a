# orient2d: the inline first stage (error_bounds.md 4.6).
#
# Code modelled (predicates/adaptive_kernel.hpp, AdaptiveKernel::orient2d_first_then):
#   dl = acx*bcy   dr = acy*bcx   det = dl - dr
#   bound = o2_fast * |dl + dr| + o2_fast_abs;   test det > bound (and -det > bound)
# No exponent guard runs before it: products may underflow.
#
# Reduction (by hand, README.md "per-monomial brackets"): a = acx*bcy and b = acy*bcx
# are the exact products of the rounded differences. If a and b have strictly opposite
# signs, det has the sign of the exact determinant D whenever det != 0 (F1), so only
# a, b >= 0 remains (the input mirrored in x covers a, b <= 0). With the standard model
# fl(v) = v(1+d) + e (|d| <= 2^-53; |e| <= 2^-1075, e = 0 for sums):
#   dl = a(1+d1) + e1   dr = b(1+d2) + e2   |dl + dr| = (dl + dr)(1+d3)
#   bound = (o2_fast |dl + dr| (1+d4) + e4 + o2_fast_abs)(1+d5)
#   D = a(1+ta1)(1+ta2) - b(1+tb1)(1+tb2)     (exact differences, |t| <= 2^-53)
# and det = fl(s) > bound gives s = dl - dr > bound (monotone rounding), so
#   +-D > bound - |s - D| >= a [mono(d1, ta)] + b [mono(d2, tb)] + [crumbs]
# with the two brackets proved >= 0 below for all d, t, e (mono for a; b's is the same
# expression in its own variables). The crumb bracket needs only o2_fast_abs > about
# 3 * 2^-1075: the code's 2^-1072 holds one binade more than Gappa needs, so its companion
# check divides it by 4 (tighten=4) instead of 2.

#@-Eprecision=200
o2_fast = 0x1.8000000001804p-52;            # dlab-constant adaptive::o2_fast
o2_fast_abs = 0x0.0000000000004p-1022;      # dlab-constant adaptive::o2_fast_abs tighten=4

mono = o2_fast * (1 + d1) * (1 + d3) * (1 + d4) * (1 + d5) - |(1 + d1) - (1 + ta1) * (1 + ta2)|;
crumbs = o2_fast * (e1 + e2) * (1 + d3) * (1 + d4) * (1 + d5) + (e4 + o2_fast_abs) * (1 + d5)
         - |e1| - |e2|;

{ |d1| <= 1b-53 /\ |d3| <= 1b-53 /\ |d4| <= 1b-53 /\ |d5| <= 1b-53 /\
  |ta1| <= 1b-53 /\ |ta2| <= 1b-53 /\
  |e1| <= 1b-1075 /\ |e2| <= 1b-1075 /\ |e4| <= 1b-1075
  -> mono >= 0 /\ crumbs >= 0 /\ mono in ? }
