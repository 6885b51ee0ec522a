# insphere: stage B (error_bounds.md 4.3).
#
# Code modelled (predicates/adaptive_kernel.cpp, insphere_slow and insphere_bcd): B =
# the exact determinant of the rounded differences (an expansion), det = B.estimate(),
# bound = isB * perm (stage A's permanent, insphere_stage_a.g), test det > bound (and
# -det > bound).
#
# Reduction (by hand, README.md "per-monomial brackets"; as in orient3d_stage_b.g): B =
# sum sigma mu exactly, D = sum sigma mu T (T over the factors' exact differences, the
# lifted one twice), perm = sum |mu| Q, and det = B (1 + th) with |th| <= 2 eps: the
# relative error of the estimate of the stage's expansions, taken from Shewchuk (1997)
# as error_bounds.md 4.3 and 6 do -- not proved here. det > bound = isB perm (1+db)
# gives B > isB perm (1+db) / (1+th), so +-D > sum |mu| [isB Q (1+db) / (1+th) - |1 - T|].
# Q: the lift (dq e1 e2), product (dp), |.|+|.|, *|z| (qm qz), 3x3 sums (q3a q3b),
# lift*, two sums (qt qu qf): 11 roundings for a lifted x^2 or y^2 in the first two
# terms of a 3x3 minor; the other kinds are this bracket with some of them 0.
#
# The constant before this script, (5 + 72 eps) eps, needs |th| <= 0.39999 eps here
# (error_bounds.md 4.3); (5 + 96 eps) eps holds with the paper's 2 eps.

#@-Eprecision=200
isB = 0x1.400000000000cp-51;  # dlab-constant adaptive::isB

T = (1 + td) * (1 + td) * (1 + tz) * (1 + tx) * (1 + ty);
Q = (1 + dq) * (1 + e1) * (1 + e2) * (1 + dp) * (1 + qm) * (1 + qz) * (1 + q3a) * (1 + q3b)
    * (1 + qt) * (1 + qu) * (1 + qf);
bracket = isB * Q * (1 + db) / (1 + th) - |1 - T|;

{ |dq| <= 1b-53 /\ |e1| <= 1b-53 /\ |e2| <= 1b-53 /\ |dp| <= 1b-53 /\ |qm| <= 1b-53 /\
  |qz| <= 1b-53 /\ |q3a| <= 1b-53 /\ |q3b| <= 1b-53 /\ |qt| <= 1b-53 /\ |qu| <= 1b-53 /\
  |qf| <= 1b-53 /\ |db| <= 1b-53 /\
  |td| <= 1b-53 /\ |tz| <= 1b-53 /\ |tx| <= 1b-53 /\ |ty| <= 1b-53 /\ |th| <= 1b-52
  -> bracket >= 0 /\ bracket in ? }
