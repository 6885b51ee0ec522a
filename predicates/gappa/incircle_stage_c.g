# incircle: stage C (error_bounds.md 4.4), after stages A and B.
#
# Code modelled (predicates/adaptive_kernel.cpp, incircle_slow):
#   perm = (|bdxcdy| + |bdycdx|)*alift + ... (stage A's permanent; alift = adx*adx + ady*ady)
#   bound = icC * perm + result_err * |det|                   (det: stage B's estimate)
#   det += ((adx*adx + ady*ady)*((bdx*cdyt + cdy*bdxt) - (bdy*cdxt + cdx*bdyt))
#           + 2*(adx*adxt + ady*adyt)*(bdx*cdy - bdy*cdx))
#        + (row b, alike) + (row c, alike);   test det > bound
#
# Reduction as in orient2d_stage_c.g. For the monomial adx^2 bdx cdy of row a or b
# (tails ta twice, tb, tc; the other monomials alike), the first-order term of:
#   adxt (twice: the factor 2 is exact): product adx*adxt, pair sum, minor product,
#         minor difference, *minor, row sum, first sum, second sum
#         (pl sl m md pp r o1 o2)
#   cdyt: square, lift sum, product, pair sum, difference, lift*, row sum, o1 o2
#         (lq ls p1 s1 dA pa r o1 o2);   bdxt: lq ls p2 s1 dA pa r o1 o2
#   Q: product, |.|+|.|, square, lift sum, *lift, first sum, second sum
#      (dp qm qq ql qt q1 q2)
# row c: no first sum (o1, q1). The lift and the minor are the same doubles in K, in
# stage A's det and in perm; they are separate variables here (only widens the claim).

#@-Eprecision=200
icC = 0x1.6000000000009p-101;  # dlab-constant adaptive::icC

Ca = (1 + pl) * (1 + sl) * (1 + m) * (1 + md) * (1 + pp) * (1 + r) * (1 + o2);
Cc = (1 + lq) * (1 + ls) * (1 + p1) * (1 + s1) * (1 + dA) * (1 + pa) * (1 + r) * (1 + o2);
Cb = (1 + lq) * (1 + ls) * (1 + p2) * (1 + s1) * (1 + dA) * (1 + pa) * (1 + r) * (1 + o2);
T = (1 + ta) * (1 + ta) * (1 + tb) * (1 + tc);
Eab = T - 1 - (2 * ta * Ca + tb * Cb + tc * Cc) * (1 + o1);
Ec = T - 1 - 2 * ta * Ca - tb * Cb - tc * Cc;
Qc = (1 + dp) * (1 + qm) * (1 + qq) * (1 + ql) * (1 + qt) * (1 + q2) * (1 + b1) * (1 + b3);
rows_ab = icC * Qc * (1 + q1) - |Eab|;
row_c = icC * Qc - |Ec|;

{ |pl| <= 1b-53 /\ |sl| <= 1b-53 /\ |m| <= 1b-53 /\ |md| <= 1b-53 /\ |pp| <= 1b-53 /\
  |r| <= 1b-53 /\ |o1| <= 1b-53 /\ |o2| <= 1b-53 /\ |lq| <= 1b-53 /\ |ls| <= 1b-53 /\
  |p1| <= 1b-53 /\ |p2| <= 1b-53 /\ |s1| <= 1b-53 /\ |dA| <= 1b-53 /\ |pa| <= 1b-53 /\
  |dp| <= 1b-53 /\ |qm| <= 1b-53 /\ |qq| <= 1b-53 /\ |ql| <= 1b-53 /\ |qt| <= 1b-53 /\
  |q1| <= 1b-53 /\ |q2| <= 1b-53 /\ |b1| <= 1b-53 /\ |b3| <= 1b-53 /\
  |ta| <= 1b-53 /\ |tb| <= 1b-53 /\ |tc| <= 1b-53
  -> rows_ab >= 0 /\ row_c >= 0 /\ rows_ab in ? }

Eab -> ta * ((1 + ta) - 1) + tb * ((1 + ta) * (1 + ta) - 1)
       + tc * ((1 + ta) * (1 + ta) * (1 + tb) - 1)
       + 2 * ta * (1 - Ca * (1 + o1)) + tb * (1 - Cb * (1 + o1)) + tc * (1 - Cc * (1 + o1));
Ec -> ta * ((1 + ta) - 1) + tb * ((1 + ta) * (1 + ta) - 1)
      + tc * ((1 + ta) * (1 + ta) * (1 + tb) - 1)
      + 2 * ta * (1 - Ca) + tb * (1 - Cb) + tc * (1 - Cc);
