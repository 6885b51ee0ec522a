# Stage C of all four predicates: the estimate's share of the bound (error_bounds.md 4.4).
#
# Code modelled (predicates/adaptive_kernel.cpp, orient2d_slow ... insphere_bcd):
#   det = B.estimate()                                   (stage B)
#   bound = XC * perm + result_err * |det|;   det = det + K;   test det > bound
# XC * perm and the first-order correction K are the per-predicate scripts
# (orient2d_stage_c.g ... insphere_stage_c.g); they reduce the claim to
#   +-D > sum |mu| [XC-bracket] + |B| [result_err * |1 + th| (1+b2)(1+b3) - |th|],
# where B is the exact expansion of stage B and det = B (1 + th), |th| <= 2 eps: the
# estimate's relative error, taken from Shewchuk (1997) as the stage-B scripts do --
# not proved here (error_bounds.md 4.3, 6). b2 rounds result_err * |det| and b3 the
# sum of the two products (both normal, error_bounds.md 2). This script proves the
# second bracket >= 0. The final addition det + K costs nothing (monotone rounding: its
# rounded value exceeds the double bound only if the exact sum does).

#@-Eprecision=200
re = 0x1.8000000000002p-52;  # dlab-constant adaptive::result_err

est = re * |1 + th| * (1 + b2) * (1 + b3) - |th|;

{ |th| <= 1b-52 /\ |b2| <= 1b-53 /\ |b3| <= 1b-53
  -> est >= 0 /\ est in ? }
