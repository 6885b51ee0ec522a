# orient3d: the per-call filter (error_bounds.md 3.4) and the static filter fitted
# to an input (3.5), which is the same bound with every axis maximum replaced by W.
#
# Code modelled (predicates/adaptive_kernel.hpp):
#   orient3d_parts_scalar / orient3d_parts_sse2, bit-identical (3.4):
#     s0 = (adz*(bdx*cdy) + bdz*(cdx*ady)) + cdz*(adx*bdy)
#     s1 = (adz*(bdy*cdx) + bdz*(cdy*adx)) + cdz*(ady*bdx)        det = s0 - s1
#   Orient3dScalar::bound / Orient3dSse2::bound:  o3_ss8 * ((mx' * my') * (mz' * 8))
#   orient3d_static_bound:                         o3_ss8 * ((W' * W') * (W' * 8))
#   m' = max(largest |rounded difference| on the axis, 2^-320); the test is det > bound.
#
# Proved by Gappa, in units of mx' my' mz' (each rounded difference divided by its axis'
# m', so |adx| <= 1 ...; README.md in this folder says why this loses nothing): every
# product and sum of the code rounds with relative error <= 2^-53 (mul_rel, add_rel);
# every product may also underflow by an absolute crumb (2^-1075 divided by the node's
# unit: 2^-1075/lo^2 = 2^-435 for x*y, 2^-1075/lo^3 = 2^-115 for z*(x*y)); the exact
# differences ADX... are within relative 2^-53 of the rounded ones; the bound rounds
# three times (mz' * 8 is exact). Then s = s0 - s1 >= B implies D >= 2^-1000 > 0,
# D the exact determinant.
#
# By hand (error_bounds.md 3.4-3.5): det = fl(s) > B (a double) implies s > B, rounding
# being monotone; sums that underflow are exact and the bound's products are normal
# (floors); no intermediate overflows when B is finite (factor 8); the negative test
# -det > B is this one for the input mirrored in x (every node changes sign, B does
# not); the static filter's W' bounds every rounded difference of a covered call.
# Gappa also prints its best bound on |s - D| (40.000... eps in these units).

@mul = mul_rel<53>;
@add = add_rel<53>;

c8 = 0x1.40000000014p-51;  # dlab-constant adaptive::o3_ss8

# products x*y (x, y rounded differences), each with its underflow crumb
r1 = mul(bdx, cdy); r2 = mul(bdy, cdx);
r3 = mul(cdx, ady); r4 = mul(cdy, adx);
r5 = mul(adx, bdy); r6 = mul(ady, bdx);
p1 = r1 + e1; q1 = r2 + e2;
p2 = r3 + e3; q2 = r4 + e4;
p3 = r5 + e5; q3 = r6 + e6;
# monomials z*(x*y)
t1 = mul(adz, p1); t2 = mul(bdz, p2); t3 = mul(cdz, p3);
u1 = mul(adz, q1); u2 = mul(bdz, q2); u3 = mul(cdz, q3);
m1 = t1 + f1; m2 = t2 + f2; m3 = t3 + f3;
n1 = u1 + f4; n2 = u2 + f5; n3 = u3 + f6;
s0 = add(add(m1, m2), m3);
s1 = add(add(n1, n2), n3);
s = s0 - s1;                       # det = fl(s): its rounding is not counted
B = mul(c8, mul(mul(1, 1), 8));    # o3_ss8 * ((mx' * my') * (mz' * 8)) / (mx' my' mz')

# the same expressions on the exact differences
P1 = BDX*CDY; Q1 = BDY*CDX; P2 = CDX*ADY; Q2 = CDY*ADX; P3 = ADX*BDY; Q3 = ADY*BDX;
M1 = ADZ*P1; M2 = BDZ*P2; M3 = CDZ*P3; N1 = ADZ*Q1; N2 = BDZ*Q2; N3 = CDZ*Q3;
S0 = (M1 + M2) + M3;
S1 = (N1 + N2) + N3;
D = S0 - S1;

{ adx in [-1,1] /\ ady in [-1,1] /\ adz in [-1,1] /\
  bdx in [-1,1] /\ bdy in [-1,1] /\ bdz in [-1,1] /\
  cdx in [-1,1] /\ cdy in [-1,1] /\ cdz in [-1,1] /\
  |ADX -/ adx| <= 1b-53 /\ |ADY -/ ady| <= 1b-53 /\ |ADZ -/ adz| <= 1b-53 /\
  |BDX -/ bdx| <= 1b-53 /\ |BDY -/ bdy| <= 1b-53 /\ |BDZ -/ bdz| <= 1b-53 /\
  |CDX -/ cdx| <= 1b-53 /\ |CDY -/ cdy| <= 1b-53 /\ |CDZ -/ cdz| <= 1b-53 /\
  |e1| <= 1b-435 /\ |e2| <= 1b-435 /\ |e3| <= 1b-435 /\
  |e4| <= 1b-435 /\ |e5| <= 1b-435 /\ |e6| <= 1b-435 /\
  |f1| <= 1b-115 /\ |f2| <= 1b-115 /\ |f3| <= 1b-115 /\
  |f4| <= 1b-115 /\ |f5| <= 1b-115 /\ |f6| <= 1b-115 /\
  s - B >= 0
  -> s - D in ? /\ D >= 1b-1000 }

# Hints: which computed node approximates which exact one, and that a crumb adds
# to the error of the rounding it follows.
s0 ~ S0; s1 ~ S1;
p1 - P1 -> (r1 - P1) + e1; q1 - Q1 -> (r2 - Q1) + e2;
p2 - P2 -> (r3 - P2) + e3; q2 - Q2 -> (r4 - Q2) + e4;
p3 - P3 -> (r5 - P3) + e5; q3 - Q3 -> (r6 - Q3) + e6;
m1 - M1 -> (t1 - M1) + f1; m2 - M2 -> (t2 - M2) + f2; m3 - M3 -> (t3 - M3) + f3;
n1 - N1 -> (u1 - N1) + f4; n2 - N2 -> (u2 - N2) + f5; n3 - N3 -> (u3 - N3) + f6;
