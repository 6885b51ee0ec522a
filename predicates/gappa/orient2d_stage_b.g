# orient2d: stage B (error_bounds.md 4.3).
#
# Code modelled (predicates/adaptive_kernel.cpp, orient2d_slow): B = the exact
# determinant of the rounded differences (an expansion), det = B.estimate(), bound = o2B
# * detsum (its paths: product dp, sum q1), test det > bound (and -det > bound).
#
# Reduction (by hand, README.md "per-monomial brackets"): B = sum sigma mu exactly, D =
# sum sigma mu T (T over the factors' exact differences), the stage-A permanent is sum
# |mu| Q, and det = B (1 + th) with |th| <= 2 eps: the relative error of the estimate of
# the stage's expansions, taken from Shewchuk (1997) as error_bounds.md 4.3 and 6 do --
# not proved here. det > bound = o2B perm (1+db) gives B > o2B perm (1+db) / (1+th), so
# +-D > sum |mu| [o2B Q (1+db) / (1+th) - |1 - T|].

#@-Eprecision=200
o2B = 0x1.0000000000003p-52;  # dlab-constant adaptive::o2B

T = (1 + t1) * (1 + t2);
Q_ab = (1 + dp) * (1 + q1);
rows_ab = o2B * Q_ab * (1 + db) / (1 + th) - |1 - T|;

{ |dp| <= 1b-53 /\ |q1| <= 1b-53 /\ |t1| <= 1b-53 /\ |t2| <= 1b-53 /\ |db| <= 1b-53 /\
  |th| <= 1b-52
  -> rows_ab >= 0 /\ rows_ab in ? }
