# orient3d: stage B (error_bounds.md 4.3).
#
# Code modelled (predicates/adaptive_kernel.cpp, orient3d_slow): B = the exact
# determinant of the rounded differences (an expansion), det = B.estimate(), bound = o3B
# * perm (orient3d_stage_a.g: rows a, b dp qm qz q1 q2; row c dp qm qz q2), test det >
# bound (and -det > bound).
#
# Reduction (by hand, README.md "per-monomial brackets"): B = sum sigma mu exactly, D =
# sum sigma mu T (T over the factors' exact differences), the stage-A permanent is sum
# |mu| Q, and det = B (1 + th) with |th| <= 2 eps: the relative error of the estimate of
# the stage's expansions, taken from Shewchuk (1997) as error_bounds.md 4.3 and 6 do --
# not proved here. det > bound = o3B perm (1+db) gives B > o3B perm (1+db) / (1+th), so
# +-D > sum |mu| [o3B Q (1+db) / (1+th) - |1 - T|].

#@-Eprecision=200
o3B = 0x1.8000000000007p-52;  # dlab-constant adaptive::o3B

T = (1 + t1) * (1 + t2) * (1 + t3);
Q_ab = (1 + dp) * (1 + qm) * (1 + qz) * (1 + q1) * (1 + q2);
Q_c = (1 + dp) * (1 + qm) * (1 + qz) * (1 + q2);
rows_ab = o3B * Q_ab * (1 + db) / (1 + th) - |1 - T|;
row_c = o3B * Q_c * (1 + db) / (1 + th) - |1 - T|;

{ |dp| <= 1b-53 /\ |q1| <= 1b-53 /\ |q2| <= 1b-53 /\ |qm| <= 1b-53 /\ |qz| <= 1b-53 /\
  |t1| <= 1b-53 /\ |t2| <= 1b-53 /\ |t3| <= 1b-53 /\ |db| <= 1b-53 /\ |th| <= 1b-52
  -> rows_ab >= 0 /\ row_c >= 0 /\ rows_ab in ? }
