# incircle: stage A (error_bounds.md 4.2), out of line after the exponent guard.
#
# Code modelled (predicates/adaptive_kernel.cpp, incircle_slow):
#   bdxcdy = bdx*cdy ... (six products)   alift = adx*adx + ady*ady (blift, clift alike)
#   det  = (alift*(bdxcdy - bdycdx) + blift*(cdxady - cdyadx)) + clift*(adxbdy - adybdx)
#   perm = (|bdxcdy| + |bdycdx|)*alift + (|cdxady| + |cdyadx|)*blift
#          + (|adxbdy| + |adybdx|)*clift
#   bound = icA * perm;   test det > bound (and -det > bound)
#
# Reduction (by hand, README.md "per-monomial brackets"; as in orient3d_stage_a.g):
# +-D > sum |mu| [icA Q (1+db) - |C - T|] with, for a monomial x_a^2 x_b y_c (the
# square's and the lift sum's roundings dq, dl and the product's dp are the same
# doubles in det and perm; T has the square's exact difference twice):
#   rows a, b: C = square, lift sum, product, minor difference, lift*minor, first sum
#                  (dq dl dp dm dt ds)
#              Q = dq dl dp, |.|+|.|, *lift, first sum, second sum   (qm qt q1 q2)
#   row c:     C = dq dl dp dm dt;   Q = dq dl dp qm qt q2

#@-Eprecision=200
icA = 0x1.4000000000006p-50;  # dlab-constant adaptive::icA

T = (1 + t1) * (1 + t1) * (1 + t2) * (1 + t3);
L = (1 + dq) * (1 + dl);
rows_ab = icA * L * (1 + dp) * (1 + qm) * (1 + qt) * (1 + q1) * (1 + q2) * (1 + db)
          - |L * (1 + dp) * (1 + dm) * (1 + dt) * (1 + ds) - T|;
row_c = icA * L * (1 + dp) * (1 + qm) * (1 + qt) * (1 + q2) * (1 + db)
        - |L * (1 + dp) * (1 + dm) * (1 + dt) - T|;

{ |dq| <= 1b-53 /\ |dl| <= 1b-53 /\ |dp| <= 1b-53 /\ |dm| <= 1b-53 /\ |dt| <= 1b-53 /\
  |ds| <= 1b-53 /\ |qm| <= 1b-53 /\ |qt| <= 1b-53 /\ |q1| <= 1b-53 /\ |q2| <= 1b-53 /\
  |db| <= 1b-53 /\ |t1| <= 1b-53 /\ |t2| <= 1b-53 /\ |t3| <= 1b-53
  -> rows_ab >= 0 /\ row_c >= 0 /\ rows_ab in ? }
