# incircle: the lift filter (error_bounds.md 3.3).
#
# Code modelled (predicates/adaptive_kernel.hpp, AdaptiveKernel::incircle_first_then):
#   alift = adx*adx + ady*ady   (blift, clift alike)
#   bc = bdx*cdy - bdy*cdx   ca = cdx*ady - cdy*adx   ab = adx*bdy - ady*bdx
#   det = (alift*bc + blift*ca) + clift*ab
#   S' = max((alift + blift) + clift, ic_lift_lo)   bound = ic_lift_filter * (S' * S')
#   ic_lift_lo = 2^-480; test det > bound (and -det > bound).
#
# Reduction (by hand, error_bounds.md 3.3 and README.md "per-monomial brackets"):
# with x = the rounded differences, the exact determinant D is a sum of monomials
# mu (x_a^2 x_b y_c and the like) and s (det = fl(s)) is the same sum with each
# monomial multiplied by C = the product of (1+d) over the roundings on its path, D
# with T = the product of (1+t) over its factors' exact differences. Paths in this
# order: rows a and b: square, lift sum, minor product, minor difference, lift*minor,
# first sum = 6 roundings; row c: 5 (no first sum). So |s - D| <= P max|C - T| + crumbs,
# P = sum |mu| <= (L_a + L_b + L_c)^2 / 3 (L_a = x_a^2 + y_a^2 exact; 3.3),
# L_a + L_b + L_c <= S' / sr, sr >= a product of four (1 + d) (square, lift sum, two
# sums; row c has three), and the bound is ic_lift_filter * S'^2 (1+b1)(1+b2) (S' * S'
# and the product by the constant are normal: S' >= 2^-480). Since det > bound gives
# s > bound (monotone rounding), in units of S'^2:
#   +-D > bound - |s - D| >= ic_lift_filter (1+b1)(1+b2) - |C - T| / (3 sr^2) - crumbs,
# proved >= 0 below for each row. crumbs: the twelve degree-2 products may underflow by
# 2^-1075 <= 2^-595 S', later multiplied by a lift or a minor (<= S'), and the three
# degree-4 products by 2^-1075 <= 2^-115 S'^2; with the crumbs of S itself this is below
# 2^-112 S'^2 (|cr| below).

#@-Eprecision=200
ic_lift_filter = 0x1.aaaaaaaaac567p-52;  # dlab-constant adaptive::ic_lift_filter

sr = (1 + g1) * (1 + g2) * (1 + g3) * (1 + g4);
T = (1 + t1) * (1 + t1) * (1 + t2) * (1 + t3);
rows_ab = ic_lift_filter * (1 + b1) * (1 + b2)
          - |(1 + d1) * (1 + d2) * (1 + d3) * (1 + d4) * (1 + d5) * (1 + d6) - T| / (3 * sr * sr)
          - |cr|;
row_c = ic_lift_filter * (1 + b1) * (1 + b2)
        - |(1 + d1) * (1 + d2) * (1 + d3) * (1 + d4) * (1 + d5) - T| / (3 * sr * sr)
        - |cr|;

{ |d1| <= 1b-53 /\ |d2| <= 1b-53 /\ |d3| <= 1b-53 /\ |d4| <= 1b-53 /\ |d5| <= 1b-53 /\
  |d6| <= 1b-53 /\ |t1| <= 1b-53 /\ |t2| <= 1b-53 /\ |t3| <= 1b-53 /\
  |g1| <= 1b-53 /\ |g2| <= 1b-53 /\ |g3| <= 1b-53 /\ |g4| <= 1b-53 /\
  |b1| <= 1b-53 /\ |b2| <= 1b-53 /\ |cr| <= 1b-112
  -> rows_ab >= 0 /\ row_c >= 0 /\ rows_ab in ? }
