# insphere: the lift filter (error_bounds.md 3.1-3.2).
#
# Code modelled (predicates/adaptive_kernel.hpp, AdaptiveKernel::insphere_first_then):
#   ab = aex*bey - bex*aey   bc = bex*cey - cex*bey   cd = cex*dey - dex*cey
#   da = dex*aey - aex*dey   ac = aex*cey - cex*aey   bd = bex*dey - dex*bey
#   abc = (aez*bc - bez*ac) + cez*ab      bcd = (bez*cd - cez*bd) + dez*bc
#   cda = (cez*da + dez*ac) + aez*cd      dab = (dez*ab + aez*bd) + bez*da
#   alift = (aex*aex + aey*aey) + aez*aez   (blift, clift, dlift alike)
#   det = (dlift*abc - clift*dab) + (blift*cda - alift*bcd)
#   L' = max(largest lift, is_lo^2)   mz' = max(largest |z difference|, is_lo)
#   bound = is_lift128 * (((L' * 128) * L') * mz'),  is_lo = 2^-185; test det > bound.
#
# Proved by Gappa, with x and y differences, and z inside the lifts (aezl ...), in units
# of sqrt(L'), and z inside the 3x3 minors (aez ...) in units of mz' (README.md: why
# this loses nothing; a z occurs in both roles as two variables, which only widens the
# model). A lift bounds its own squares: x^2 <= (1 + 2^-53) L' (3.2), so
# |aex| <= sqrt(1 + 2^-53) <= 1 + 2^-54. Every product and sum rounds with relative
# error <= 2^-53 (mul_rel, add_rel, sub_rel); every product may underflow by a crumb
# 2^-1075 / (its unit): 2^-705 for degree 2 (>= is_lo^2), 2^-520 for degree 3, 2^-150
# for lift * minor (degree 5); the exact differences are within relative 2^-53 of the
# rounded ones; the bound rounds three times (L' * 128 is exact). Then s >= B implies
# D >= 2^-1000 > 0 (s: the exact sum of the last addition, D: the exact determinant).
#
# By hand (error_bounds.md 3.2): det = fl(s) > B implies s > B (monotone rounding);
# underflowing sums are exact and the bound's products are normal (floors); the factor
# 128 makes B infinite whenever a node of det overflows; -det > B is this case for the
# input mirrored in x. Gappa also prints its best bound on |s - D| (1032.000... eps).

@mul = mul_rel<53>;
@add = add_rel<53>;
@sub = sub_rel<53>;

c128 = 0x1.0200000001025p-50;  # dlab-constant adaptive::is_lift128

# 2x2 minors, each product with its underflow crumb
ab1 = mul(aex, bey); ab2 = mul(bex, aey); ab = sub(ab1 + g1, ab2 + g2);
bc1 = mul(bex, cey); bc2 = mul(cex, bey); bc = sub(bc1 + g3, bc2 + g4);
cd1 = mul(cex, dey); cd2 = mul(dex, cey); cd = sub(cd1 + g5, cd2 + g6);
da1 = mul(dex, aey); da2 = mul(aex, dey); da = sub(da1 + g7, da2 + g8);
ac1 = mul(aex, cey); ac2 = mul(cex, aey); ac = sub(ac1 + g9, ac2 + g10);
bd1 = mul(bex, dey); bd2 = mul(dex, bey); bd = sub(bd1 + g11, bd2 + g12);
# 3x3 minors
abc1 = mul(aez, bc); abc2 = mul(bez, ac); abc3 = mul(cez, ab);
bcd1 = mul(bez, cd); bcd2 = mul(cez, bd); bcd3 = mul(dez, bc);
cda1 = mul(cez, da); cda2 = mul(dez, ac); cda3 = mul(aez, cd);
dab1 = mul(dez, ab); dab2 = mul(aez, bd); dab3 = mul(bez, da);
abc = add(sub(abc1 + h1, abc2 + h2), abc3 + h3);
bcd = add(sub(bcd1 + h4, bcd2 + h5), bcd3 + h6);
cda = add(add(cda1 + h7, cda2 + h8), cda3 + h9);
dab = add(add(dab1 + h10, dab2 + h11), dab3 + h12);
# lifts
al1 = mul(aex, aex); al2 = mul(aey, aey); al3 = mul(aezl, aezl);
bl1 = mul(bex, bex); bl2 = mul(bey, bey); bl3 = mul(bezl, bezl);
cl1 = mul(cex, cex); cl2 = mul(cey, cey); cl3 = mul(cezl, cezl);
dl1 = mul(dex, dex); dl2 = mul(dey, dey); dl3 = mul(dezl, dezl);
alift = add(add(al1 + k1, al2 + k2), al3 + k3);
blift = add(add(bl1 + k4, bl2 + k5), bl3 + k6);
clift = add(add(cl1 + k7, cl2 + k8), cl3 + k9);
dlift = add(add(dl1 + k10, dl2 + k11), dl3 + k12);
# det; the last addition is not rounded here (det = fl(s))
t1 = mul(dlift, abc); t2 = mul(clift, dab); t3 = mul(blift, cda); t4 = mul(alift, bcd);
w1 = sub(t1 + f1, t2 + f2); w2 = sub(t3 + f3, t4 + f4);
s = w1 + w2;
B = mul(c128, mul(mul(128, 1), 1));   # is_lift128 * (((L' * 128) * L') * mz') / (L'^2 mz')

# the same expressions on the exact differences
AB = AEX*BEY - BEX*AEY; BC = BEX*CEY - CEX*BEY; CD = CEX*DEY - DEX*CEY;
DA = DEX*AEY - AEX*DEY; AC = AEX*CEY - CEX*AEY; BD = BEX*DEY - DEX*BEY;
ABC = (AEZ*BC - BEZ*AC) + CEZ*AB;
BCD = (BEZ*CD - CEZ*BD) + DEZ*BC;
CDA = (CEZ*DA + DEZ*AC) + AEZ*CD;
DAB = (DEZ*AB + AEZ*BD) + BEZ*DA;
ALIFT = (AEX*AEX + AEY*AEY) + AEZL*AEZL; BLIFT = (BEX*BEX + BEY*BEY) + BEZL*BEZL;
CLIFT = (CEX*CEX + CEY*CEY) + CEZL*CEZL; DLIFT = (DEX*DEX + DEY*DEY) + DEZL*DEZL;
W1 = DLIFT*ABC - CLIFT*DAB; W2 = BLIFT*CDA - ALIFT*BCD;
D = W1 + W2;

{ aex in [-0x1.00000000000004p0, 0x1.00000000000004p0] /\ aey in [-0x1.00000000000004p0, 0x1.00000000000004p0] /\ aezl in [-0x1.00000000000004p0, 0x1.00000000000004p0] /\ aez in [-1,1] /\
  bex in [-0x1.00000000000004p0, 0x1.00000000000004p0] /\ bey in [-0x1.00000000000004p0, 0x1.00000000000004p0] /\ bezl in [-0x1.00000000000004p0, 0x1.00000000000004p0] /\ bez in [-1,1] /\
  cex in [-0x1.00000000000004p0, 0x1.00000000000004p0] /\ cey in [-0x1.00000000000004p0, 0x1.00000000000004p0] /\ cezl in [-0x1.00000000000004p0, 0x1.00000000000004p0] /\ cez in [-1,1] /\
  dex in [-0x1.00000000000004p0, 0x1.00000000000004p0] /\ dey in [-0x1.00000000000004p0, 0x1.00000000000004p0] /\ dezl in [-0x1.00000000000004p0, 0x1.00000000000004p0] /\ dez in [-1,1] /\
  |AEX -/ aex| <= 1b-53 /\ |AEY -/ aey| <= 1b-53 /\ |AEZL -/ aezl| <= 1b-53 /\ |AEZ -/ aez| <= 1b-53 /\
  |BEX -/ bex| <= 1b-53 /\ |BEY -/ bey| <= 1b-53 /\ |BEZL -/ bezl| <= 1b-53 /\ |BEZ -/ bez| <= 1b-53 /\
  |CEX -/ cex| <= 1b-53 /\ |CEY -/ cey| <= 1b-53 /\ |CEZL -/ cezl| <= 1b-53 /\ |CEZ -/ cez| <= 1b-53 /\
  |DEX -/ dex| <= 1b-53 /\ |DEY -/ dey| <= 1b-53 /\ |DEZL -/ dezl| <= 1b-53 /\ |DEZ -/ dez| <= 1b-53 /\
  |g1| <= 1b-705 /\ |g2| <= 1b-705 /\ |g3| <= 1b-705 /\ |g4| <= 1b-705 /\ |g5| <= 1b-705 /\ |g6| <= 1b-705 /\
  |g7| <= 1b-705 /\ |g8| <= 1b-705 /\ |g9| <= 1b-705 /\ |g10| <= 1b-705 /\ |g11| <= 1b-705 /\ |g12| <= 1b-705 /\
  |k1| <= 1b-705 /\ |k2| <= 1b-705 /\ |k3| <= 1b-705 /\ |k4| <= 1b-705 /\ |k5| <= 1b-705 /\ |k6| <= 1b-705 /\
  |k7| <= 1b-705 /\ |k8| <= 1b-705 /\ |k9| <= 1b-705 /\ |k10| <= 1b-705 /\ |k11| <= 1b-705 /\ |k12| <= 1b-705 /\
  |h1| <= 1b-520 /\ |h2| <= 1b-520 /\ |h3| <= 1b-520 /\ |h4| <= 1b-520 /\ |h5| <= 1b-520 /\ |h6| <= 1b-520 /\
  |h7| <= 1b-520 /\ |h8| <= 1b-520 /\ |h9| <= 1b-520 /\ |h10| <= 1b-520 /\ |h11| <= 1b-520 /\ |h12| <= 1b-520 /\
  |f1| <= 1b-150 /\ |f2| <= 1b-150 /\ |f3| <= 1b-150 /\ |f4| <= 1b-150 /\
  s - B >= 0
  -> s - D in ? /\ D >= 1b-1000 }

# Hints: which computed node approximates which exact one, and that a crumb adds
# to the error of the rounding it follows.
ab ~ AB; bc ~ BC; cd ~ CD; da ~ DA; ac ~ AC; bd ~ BD;
abc ~ ABC; bcd ~ BCD; cda ~ CDA; dab ~ DAB;
alift ~ ALIFT; blift ~ BLIFT; clift ~ CLIFT; dlift ~ DLIFT;
w1 ~ W1; w2 ~ W2;
ab1 + g1 - AEX*BEY -> (ab1 - AEX*BEY) + g1;  ab2 + g2 - BEX*AEY -> (ab2 - BEX*AEY) + g2;
bc1 + g3 - BEX*CEY -> (bc1 - BEX*CEY) + g3;  bc2 + g4 - CEX*BEY -> (bc2 - CEX*BEY) + g4;
cd1 + g5 - CEX*DEY -> (cd1 - CEX*DEY) + g5;  cd2 + g6 - DEX*CEY -> (cd2 - DEX*CEY) + g6;
da1 + g7 - DEX*AEY -> (da1 - DEX*AEY) + g7;  da2 + g8 - AEX*DEY -> (da2 - AEX*DEY) + g8;
ac1 + g9 - AEX*CEY -> (ac1 - AEX*CEY) + g9;  ac2 + g10 - CEX*AEY -> (ac2 - CEX*AEY) + g10;
bd1 + g11 - BEX*DEY -> (bd1 - BEX*DEY) + g11;  bd2 + g12 - DEX*BEY -> (bd2 - DEX*BEY) + g12;
abc1 + h1 - AEZ*BC -> (abc1 - AEZ*BC) + h1;  abc2 + h2 - BEZ*AC -> (abc2 - BEZ*AC) + h2;
abc3 + h3 - CEZ*AB -> (abc3 - CEZ*AB) + h3;  bcd1 + h4 - BEZ*CD -> (bcd1 - BEZ*CD) + h4;
bcd2 + h5 - CEZ*BD -> (bcd2 - CEZ*BD) + h5;  bcd3 + h6 - DEZ*BC -> (bcd3 - DEZ*BC) + h6;
cda1 + h7 - CEZ*DA -> (cda1 - CEZ*DA) + h7;  cda2 + h8 - DEZ*AC -> (cda2 - DEZ*AC) + h8;
cda3 + h9 - AEZ*CD -> (cda3 - AEZ*CD) + h9;  dab1 + h10 - DEZ*AB -> (dab1 - DEZ*AB) + h10;
dab2 + h11 - AEZ*BD -> (dab2 - AEZ*BD) + h11;  dab3 + h12 - BEZ*DA -> (dab3 - BEZ*DA) + h12;
al1 + k1 - AEX*AEX -> (al1 - AEX*AEX) + k1;  al2 + k2 - AEY*AEY -> (al2 - AEY*AEY) + k2;
al3 + k3 - AEZL*AEZL -> (al3 - AEZL*AEZL) + k3;  bl1 + k4 - BEX*BEX -> (bl1 - BEX*BEX) + k4;
bl2 + k5 - BEY*BEY -> (bl2 - BEY*BEY) + k5;  bl3 + k6 - BEZL*BEZL -> (bl3 - BEZL*BEZL) + k6;
cl1 + k7 - CEX*CEX -> (cl1 - CEX*CEX) + k7;  cl2 + k8 - CEY*CEY -> (cl2 - CEY*CEY) + k8;
cl3 + k9 - CEZL*CEZL -> (cl3 - CEZL*CEZL) + k9;  dl1 + k10 - DEX*DEX -> (dl1 - DEX*DEX) + k10;
dl2 + k11 - DEY*DEY -> (dl2 - DEY*DEY) + k11;  dl3 + k12 - DEZL*DEZL -> (dl3 - DEZL*DEZL) + k12;
t1 + f1 - DLIFT*ABC -> (t1 - DLIFT*ABC) + f1;  t2 + f2 - CLIFT*DAB -> (t2 - CLIFT*DAB) + f2;
t3 + f3 - BLIFT*CDA -> (t3 - BLIFT*CDA) + f3;  t4 + f4 - ALIFT*BCD -> (t4 - ALIFT*BCD) + f4;
