# insphere: stage A (error_bounds.md 4.2), out of line after the exponent guard.
#
# Code modelled (predicates/adaptive_kernel.cpp, insphere_slow):
#   aexbey = aex*bey ... (twelve products)   ab = aexbey - bexaey ... (six 2x2 minors)
#   abc = (aez*bc - bez*ac) + cez*ab ...     alift = (aex*aex + aey*aey) + aez*aez ...
#   det  = (dlift*abc - clift*dab) + (blift*cda - alift*bcd)
#   pab = |aexbey| + |bexaey| ...   pabc = (|aez|*pbc + |bez|*pac) + |cez|*pab ...
#   perm = (dlift*pabc + clift*pdab) + (blift*pcda + alift*pbcd)
#   bound = isA * perm;   test det > bound (and -det > bound)
#
# Reduction (by hand, README.md "per-monomial brackets"; as in orient3d_stage_a.g):
# +-D > sum |mu| [isA Q (1+db) - |C - T|]. A monomial is (a square of the lift) *
# z * x * y of the 3x3 minor; the lift's roundings and the 2x2 product's dp are the
# same doubles in det and perm; T has the square's exact difference twice. Kinds:
#   lift: x or y squared: square, sum, sum (dq dl1 dl2); z squared: dq dl2
#   3x3:  first two terms: 2x2 difference, *z, inner sum, outer sum (dm dz d3a d3b);
#         third term: dm dz d3b
#   C = lift * dp * 3x3 * lift*minor, outer difference (dt du)
#   Q = lift * dp * |.|+|.|, *|z|, [inner sum], outer sum (qm qz [q3a] q3b)
#       * lift*minor, inner sum, final sum (qt qu qf)

#@-Eprecision=200
isA = 0x1.0000000000007p-49;  # dlab-constant adaptive::isA

T = (1 + t1) * (1 + t1) * (1 + t2) * (1 + t3) * (1 + t4);
Lxy = (1 + dq) * (1 + dl1) * (1 + dl2);
Lz = (1 + dq) * (1 + dl2);
Cout = (1 + dt) * (1 + du);
Qout = (1 + qt) * (1 + qu) * (1 + qf) * (1 + db);
M12 = (1 + dm) * (1 + dz) * (1 + d3a) * (1 + d3b);
M3 = (1 + dm) * (1 + dz) * (1 + d3b);
P12 = (1 + qm) * (1 + qz) * (1 + q3a) * (1 + q3b);
P3 = (1 + qm) * (1 + qz) * (1 + q3b);
xy_12 = isA * Lxy * (1 + dp) * P12 * Qout - |Lxy * (1 + dp) * M12 * Cout - T|;
xy_3 = isA * Lxy * (1 + dp) * P3 * Qout - |Lxy * (1 + dp) * M3 * Cout - T|;
z_12 = isA * Lz * (1 + dp) * P12 * Qout - |Lz * (1 + dp) * M12 * Cout - T|;
z_3 = isA * Lz * (1 + dp) * P3 * Qout - |Lz * (1 + dp) * M3 * Cout - T|;

{ |dq| <= 1b-53 /\ |dl1| <= 1b-53 /\ |dl2| <= 1b-53 /\ |dp| <= 1b-53 /\ |dm| <= 1b-53 /\
  |dz| <= 1b-53 /\ |d3a| <= 1b-53 /\ |d3b| <= 1b-53 /\ |dt| <= 1b-53 /\ |du| <= 1b-53 /\
  |qm| <= 1b-53 /\ |qz| <= 1b-53 /\ |q3a| <= 1b-53 /\ |q3b| <= 1b-53 /\ |qt| <= 1b-53 /\
  |qu| <= 1b-53 /\ |qf| <= 1b-53 /\ |db| <= 1b-53 /\
  |t1| <= 1b-53 /\ |t2| <= 1b-53 /\ |t3| <= 1b-53 /\ |t4| <= 1b-53
  -> xy_12 >= 0 /\ xy_3 >= 0 /\ z_12 >= 0 /\ z_3 >= 0 /\ xy_12 in ? }
