# orient3d: stage A (error_bounds.md 4.2), out of line after the exponent guard.
#
# Code modelled (predicates/adaptive_kernel.cpp, orient3d_slow):
#   bdxcdy = bdx*cdy ... (six products)
#   det  = (adz*(bdxcdy - cdxbdy) + bdz*(cdxady - adxcdy)) + cdz*(adxbdy - bdxady)
#   perm = (|bdxcdy| + |cdxbdy|)*|adz| + (|cdxady| + |adxcdy|)*|bdz|
#          + (|adxbdy| + |bdxady|)*|cdz|
#   bound = o3A * perm;   test det > bound (and -det > bound)
#
# Reduction (by hand, README.md "per-monomial brackets"): after the guard of
# error_bounds.md 2 nothing underflows, every rounding is relative, and s (det = fl(s))
# and perm are sums over the six monomials mu of the rounded differences:
#   s = sum sigma mu C,   D = sum sigma mu T,   perm = sum |mu| Q,
# C, Q the products of (1 + d) over the roundings on the monomial's path in det and in
# perm, T the product of (1 + t) over its three factors' exact differences. det > bound
# gives s > bound (monotone rounding), so +-D > sum |mu| [o3A Q (1+db) - |C - T|]: each
# bracket >= 0 (below, one per kind of path) proves the claim. Paths (the product's
# rounding dp is the same double in det and perm):
#   rows a, b: C = product, minor difference, *z, first sum          (dp dm dz ds)
#              Q = product, |.|+|.|, *|z|, first sum, second sum    (dp qm qz q1 q2)
#   row c:     C = dp dm dz;   Q = dp qm qz q2

#@-Eprecision=200
o3A = 0x1.c000000000007p-51;  # dlab-constant adaptive::o3A

T = (1 + t1) * (1 + t2) * (1 + t3);
rows_ab = o3A * (1 + dp) * (1 + qm) * (1 + qz) * (1 + q1) * (1 + q2) * (1 + db)
          - |(1 + dp) * (1 + dm) * (1 + dz) * (1 + ds) - T|;
row_c = o3A * (1 + dp) * (1 + qm) * (1 + qz) * (1 + q2) * (1 + db)
        - |(1 + dp) * (1 + dm) * (1 + dz) - T|;

{ |dp| <= 1b-53 /\ |dm| <= 1b-53 /\ |dz| <= 1b-53 /\ |ds| <= 1b-53 /\
  |qm| <= 1b-53 /\ |qz| <= 1b-53 /\ |q1| <= 1b-53 /\ |q2| <= 1b-53 /\ |db| <= 1b-53 /\
  |t1| <= 1b-53 /\ |t2| <= 1b-53 /\ |t3| <= 1b-53
  -> rows_ab >= 0 /\ row_c >= 0 /\ rows_ab in ? }
