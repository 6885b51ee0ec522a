# incircle: stage B (error_bounds.md 4.3).
#
# Code modelled (predicates/adaptive_kernel.cpp, incircle_slow): B = the exact
# determinant of the rounded differences (an expansion), det = B.estimate(), bound = icB
# * perm (incircle_stage_a.g: rows a, b dq dl dp qm qt q1 q2; row c without q1), test
# det > bound (and -det > bound).
#
# Reduction (by hand, README.md "per-monomial brackets"): B = sum sigma mu exactly, D =
# sum sigma mu T (T over the factors' exact differences), the stage-A permanent is sum
# |mu| Q, and det = B (1 + th) with |th| <= 2 eps: the relative error of the estimate of
# the stage's expansions, taken from Shewchuk (1997) as error_bounds.md 4.3 and 6 do --
# not proved here. det > bound = icB perm (1+db) gives B > icB perm (1+db) / (1+th), so
# +-D > sum |mu| [icB Q (1+db) / (1+th) - |1 - T|].

#@-Eprecision=200
icB = 0x1.0000000000006p-51;  # dlab-constant adaptive::icB

T = (1 + t1) * (1 + t1) * (1 + t2) * (1 + t3);
Q_ab = (1 + dq) * (1 + dl) * (1 + dp) * (1 + qm) * (1 + qt) * (1 + q1) * (1 + q2);
Q_c = (1 + dq) * (1 + dl) * (1 + dp) * (1 + qm) * (1 + qt) * (1 + q2);
rows_ab = icB * Q_ab * (1 + db) / (1 + th) - |1 - T|;
row_c = icB * Q_c * (1 + db) / (1 + th) - |1 - T|;

{ |dl| <= 1b-53 /\ |dp| <= 1b-53 /\ |dq| <= 1b-53 /\ |q1| <= 1b-53 /\ |q2| <= 1b-53 /\
  |qm| <= 1b-53 /\ |qt| <= 1b-53 /\ |t1| <= 1b-53 /\ |t2| <= 1b-53 /\ |t3| <= 1b-53 /\
  |db| <= 1b-53 /\ |th| <= 1b-52
  -> rows_ab >= 0 /\ row_c >= 0 /\ rows_ab in ? }
