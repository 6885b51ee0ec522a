# insphere: stage C (error_bounds.md 4.4), after stages A and B; our own correction
# formula (the paper's is not reproduced), so isC is our own constant.
#
# Code modelled (predicates/adaptive_kernel.cpp, insphere_slow and insphere_bcd):
#   perm: stage A's permanent (insphere_stage_a.g)
#   fbc = bex*cey - cex*bey ... (six float 2x2 minors)
#   dbc2 = (bext*cey + bex*ceyt) - (cext*bey + cex*beyt) ... (their first-order changes)
#   fabc = (aez*fbc - bez*fac) + cez*fab ... (float 3x3 minors)
#   dabc = ((aezt*fbc - bezt*fac) + cezt*fab) + ((aez*dbc2 - bez*dac2) + cez*dab2) ...
#   dlift = (dex*dex + dey*dey) + dez*dez   ddlift = 2*((dex*dext + dey*deyt) + dez*dezt)
#   td = dlift*dabc + ddlift*fabc   (ta, tb, tc alike)
#   bound = isC * perm + result_err * |det|;   det += (td - tc) + (tb - ta);   test det > bound
#
# Reduction as in orient2d_stage_c.g. For the monomial dex^2 aez bex cey (a lift's
# square times a monomial of the 3x3 minor: tails td twice, tz, tx, ty; the other
# monomials alike), the first-order term of:
#   dext (twice; the 2 is exact): product, two lift sums (lp l1 l2), minor product,
#         minor difference, *z (m md mz), 3x3 inner and outer sums (i1 i2), ddlift*,
#         row sum, two final sums (pp ts u1 u2)
#   aezt: minor product, difference, *aezt (m2 md2 zp), tail-part sums (j1 j2),
#         tail + change (dd), dlift* (pl), the lift (lq f1 f2), ts u1 u2
#   bext: product, pair sum, difference (q1 qs qd), *aez (kz), change sums (k1 k2),
#         dd pl, the lift, ts u1 u2;   ceyt: q2 qs qd kz k1 k2 dd pl, lift, ts u1 u2
#   Q: the lift (dq e1 e2), product (dp), |.|+|.|, *|z| (qm qz), 3x3 sums (q3a q3b),
#      lift*, two sums (qt qu qf)   (insphere_stage_a.g)
# One bracket covers every kind of monomial: a lifted z^2 has one lift sum fewer (l1,
# f1, e1), the third term of a 3x3 minor one sum fewer (i1, j1, k1, q3a); such a kind is
# the bracket below with those roundings 0, inside their range. The same double in two
# places (lifts, minors, shared sums) is a separate variable here: that only widens
# what is proved.

#@-Eprecision=200
isC = 0x1.4000000000020p-100;  # dlab-constant adaptive::isC

T = (1 + td) * (1 + td) * (1 + tz) * (1 + tx) * (1 + ty);
R2 = td * ((1 + td) - 1) + tz * ((1 + td) * (1 + td) - 1)
     + tx * ((1 + td) * (1 + td) * (1 + tz) - 1)
     + ty * ((1 + td) * (1 + td) * (1 + tz) * (1 + tx) - 1);
Out = (1 + ts) * (1 + u1) * (1 + u2);
D = (1 + lp) * (1 + l1) * (1 + l2);
F = (1 + lq) * (1 + f1) * (1 + f2);
P = (1 + dq) * (1 + e1) * (1 + e2);
M = (1 + m) * (1 + md) * (1 + mz) * (1 + i1) * (1 + i2);
Z = (1 + m2) * (1 + md2) * (1 + zp) * (1 + j1) * (1 + j2) * (1 + dd) * (1 + pl);
X = (1 + q1) * (1 + qs) * (1 + qd) * (1 + kz) * (1 + k1) * (1 + k2) * (1 + dd) * (1 + pl);
Y = (1 + q2) * (1 + qs) * (1 + qd) * (1 + kz) * (1 + k1) * (1 + k2) * (1 + dd) * (1 + pl);
Q = (1 + dp) * (1 + qm) * (1 + qz) * (1 + q3a) * (1 + q3b) * (1 + qt) * (1 + qu) * (1 + qf)
    * (1 + b1) * (1 + b3);
CL = D * M * (1 + pp) * Out;
E = T - 1 - 2 * td * CL - (tz * Z + tx * X + ty * Y) * F * Out;
bracket = isC * P * Q - |E|;

{ |lp| <= 1b-53 /\ |l1| <= 1b-53 /\ |l2| <= 1b-53 /\ |lq| <= 1b-53 /\ |f1| <= 1b-53 /\
  |f2| <= 1b-53 /\ |dq| <= 1b-53 /\ |e1| <= 1b-53 /\ |e2| <= 1b-53 /\ |m| <= 1b-53 /\
  |md| <= 1b-53 /\ |mz| <= 1b-53 /\ |i1| <= 1b-53 /\ |i2| <= 1b-53 /\ |m2| <= 1b-53 /\
  |md2| <= 1b-53 /\ |zp| <= 1b-53 /\ |j1| <= 1b-53 /\ |j2| <= 1b-53 /\ |dd| <= 1b-53 /\
  |pl| <= 1b-53 /\ |q1| <= 1b-53 /\ |q2| <= 1b-53 /\ |qs| <= 1b-53 /\ |qd| <= 1b-53 /\
  |kz| <= 1b-53 /\ |k1| <= 1b-53 /\ |k2| <= 1b-53 /\ |pp| <= 1b-53 /\ |ts| <= 1b-53 /\
  |u1| <= 1b-53 /\ |u2| <= 1b-53 /\ |dp| <= 1b-53 /\ |qm| <= 1b-53 /\ |qz| <= 1b-53 /\
  |q3a| <= 1b-53 /\ |q3b| <= 1b-53 /\ |qt| <= 1b-53 /\ |qu| <= 1b-53 /\ |qf| <= 1b-53 /\
  |b1| <= 1b-53 /\ |b3| <= 1b-53 /\
  |td| <= 1b-53 /\ |tz| <= 1b-53 /\ |tx| <= 1b-53 /\ |ty| <= 1b-53
  -> bracket >= 0 /\ bracket in ? }

E -> R2 + 2 * td * (1 - CL) + tz * (1 - Z * F * Out) + tx * (1 - X * F * Out)
     + ty * (1 - Y * F * Out);
