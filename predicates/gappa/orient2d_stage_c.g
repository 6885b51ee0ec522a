# orient2d: stage C (error_bounds.md 4.4), after stages A and B.
#
# Code modelled (predicates/adaptive_kernel.cpp, orient2d_slow):
#   detsum = dl + dr (dl = acx*bcy, dr = acy*bcx)            (stage A's permanent)
#   bound = o2C * detsum + result_err * |det|                 (det: stage B's estimate)
#   det += (acx*bcyt + bcy*acxt) - (acy*bcxt + bcx*acyt);   test det > bound
# (acxt ... the exact tails of the rounded differences: acx_exact = acx + acxt.)
#
# Reduction (by hand, README.md "per-monomial brackets"): D = sum sigma mu T with mu
# the monomials of the rounded differences and T = prod (1 + t) over their factors
# (t = tail / rounded difference, |t| <= eps); B = sum sigma mu exactly; K = the
# computed correction = sum sigma mu sum_j t_j C_j, C_j the product of (1 + d) over the
# roundings on the path of the j-th first-order term; perm = sum |mu| Q. det > bound
# gives estimate + K > bound (monotone rounding), so
#   +-D > sum |mu| [o2C Q (1+b1)(1+b3) - |T - 1 - sum_j t_j C_j|] + |B| [stage_c_estimate.g]
# (b1 rounds o2C * perm, b3 the sum of the bound's two products). One kind of path,
# for the monomial acx*bcy (ta, tb its tails; acy*bcx alike):
#   bcyt term: product, pair sum, difference (p1 s1 f);  acxt term: p2 s1 f
#   Q: product, sum (dp qs)
# The hint rewrites T - 1 - sum t C without its cancelling first-order terms (Gappa
# checks that both sides are equal; run_gappa.cmake fails if they are not).

#@-Eprecision=200
o2C = 0x1.2000000000004p-103;  # dlab-constant adaptive::o2C

Cb = (1 + p1) * (1 + s1) * (1 + f);
Ca = (1 + p2) * (1 + s1) * (1 + f);
E = (1 + ta) * (1 + tb) - 1 - tb * Cb - ta * Ca;
rows = o2C * (1 + dp) * (1 + qs) * (1 + b1) * (1 + b3) - |E|;

{ |p1| <= 1b-53 /\ |p2| <= 1b-53 /\ |s1| <= 1b-53 /\ |f| <= 1b-53 /\ |dp| <= 1b-53 /\
  |qs| <= 1b-53 /\ |b1| <= 1b-53 /\ |b3| <= 1b-53 /\ |ta| <= 1b-53 /\ |tb| <= 1b-53
  -> rows >= 0 /\ rows in ? }

E -> tb * ((1 + ta) - 1) + tb * (1 - Cb) + ta * (1 - Ca);
