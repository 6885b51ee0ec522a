# orient3d: stage C (error_bounds.md 4.4), after stages A and B.
#
# Code modelled (predicates/adaptive_kernel.cpp, orient3d_slow):
#   perm = (|bdxcdy| + |cdxbdy|)*|adz| + ... (stage A's permanent)
#   bound = o3C * perm + result_err * |det|                   (det: stage B's estimate)
#   det += (adz*((bdx*cdyt + cdy*bdxt) - (bdy*cdxt + cdx*bdyt)) + adzt*(bdx*cdy - bdy*cdx))
#        + (bdz*(...) + bdzt*(...))                            [row b, alike]
#        + (cdz*(...) + cdzt*(...));                           [row c]
#   test det > bound
#
# Reduction as in orient2d_stage_c.g. Kinds of path for the monomial adz*bdx*cdy of
# row a or b (tails tz, tx, ty; the other monomials alike), the first-order term of:
#   cdyt: product, pair sum, difference, *adz, row sum, first sum, second sum
#         (p1 s1 dA pz r o1 o2);   bdxt: p2 s1 dA pz r o1 o2
#   adzt: minor product, minor difference, *adzt, row sum, o1 o2 (m md pt r o1 o2)
#   Q: product, |.|+|.|, *|z|, first sum, second sum (dp qm qz q1 q2)
# row c: no first sum (o1, q1). Roundings that are the same double in two places (the
# minor bdx*cdy - bdy*cdx of K and of stage A's det) are separate variables here, which
# only widens what is proved.

#@-Eprecision=200
o3C = 0x1.a000000000009p-102;  # dlab-constant adaptive::o3C

Cy = (1 + p1) * (1 + s1) * (1 + dA) * (1 + pz) * (1 + r) * (1 + o2);
Cx = (1 + p2) * (1 + s1) * (1 + dA) * (1 + pz) * (1 + r) * (1 + o2);
Cz = (1 + m) * (1 + md) * (1 + pt) * (1 + r) * (1 + o2);
Eab = (1 + tz) * (1 + tx) * (1 + ty) - 1 - (ty * Cy + tx * Cx + tz * Cz) * (1 + o1);
Ec = (1 + tz) * (1 + tx) * (1 + ty) - 1 - ty * Cy - tx * Cx - tz * Cz;
Qc = (1 + dp) * (1 + qm) * (1 + qz) * (1 + q2) * (1 + b1) * (1 + b3);
rows_ab = o3C * Qc * (1 + q1) - |Eab|;
row_c = o3C * Qc - |Ec|;

{ |p1| <= 1b-53 /\ |p2| <= 1b-53 /\ |s1| <= 1b-53 /\ |dA| <= 1b-53 /\ |pz| <= 1b-53 /\
  |r| <= 1b-53 /\ |o1| <= 1b-53 /\ |o2| <= 1b-53 /\ |m| <= 1b-53 /\ |md| <= 1b-53 /\
  |pt| <= 1b-53 /\ |dp| <= 1b-53 /\ |qm| <= 1b-53 /\ |qz| <= 1b-53 /\ |q1| <= 1b-53 /\
  |q2| <= 1b-53 /\ |b1| <= 1b-53 /\ |b3| <= 1b-53 /\
  |tz| <= 1b-53 /\ |tx| <= 1b-53 /\ |ty| <= 1b-53
  -> rows_ab >= 0 /\ row_c >= 0 /\ rows_ab in ? }

Eab -> tx * ((1 + tz) - 1) + ty * ((1 + tz) * (1 + tx) - 1)
       + ty * (1 - Cy * (1 + o1)) + tx * (1 - Cx * (1 + o1)) + tz * (1 - Cz * (1 + o1));
Ec -> tx * ((1 + tz) - 1) + ty * ((1 + tz) * (1 + tx) - 1)
      + ty * (1 - Cy) + tx * (1 - Cx) + tz * (1 - Cz);
