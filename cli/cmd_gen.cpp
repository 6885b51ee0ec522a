// `dlab gen GENERATOR [options]`: writes a seeded point set (fuzz/generators.hpp)
// in the INPUT format, one point per line. Coordinates are hexadecimal floats by
// default (exact); --decimal writes the shortest decimal that reads back to the
// same double (also exact). Same arguments -> same bytes on every machine.
#include <fstream>
#include <iostream>
#include <stdexcept>

#include "cli/args.hpp"
#include "cli/commands.hpp"
#include "cli/point_writer.hpp"
#include "fuzz/generators.hpp"

namespace dlab::cli {
namespace {

const char* const kGenHelp =
    "usage: dlab gen GENERATOR [-o FILE] [--n N] [--dim 2|3] [--seed S] [--decimal] [options]\n"
    "generators (N points unless said otherwise; 'exact' = integer coordinates, possibly scaled\n"
    "by a power of two, so the degeneracy is exact):\n"
    "  uniform          uniform in [--lo, --hi]^dim (default [0,1])\n"
    "  gaussian         Irwin-Hall approximation of N(0, --sigma^2) (default sigma 1)\n"
    "  clustered        --clusters K (10) gaussian clusters of --sigma (0.01) in [0,1]^dim\n"
    "  lattice          the first N points of the smallest integer grid m^dim\n"
    "  rotated-lattice  the lattice under an exact rational rotation (3-4-5; 3D: quaternion 2,1,1,1)\n"
    "  cocircular       exact: N lattice points of one circle (2D) / sphere (3D), scaled into [-1,1]\n"
    "  cospherical      the same, 3D by default\n"
    "  collinear        exact: N - --off (3) points on a line, --off points exactly off it\n"
    "  coplanar         3D, exact: N - --off points on a plane, --off points exactly off it\n"
    "  near-degenerate  an exact set (--base, default cocircular/cospherical) with every\n"
    "                   coordinate moved by a random number of ulps in [-k, k] (--ulps k, 1)\n"
    "  near-duplicates  N points: copies (--copies, 4) of uniform points moved by <= --ulps (1)\n"
    "  huge             uniform in [-1,1]^dim times 2^--exp (default 1000, about 1e301)\n"
    "  tiny             random integers in [-2^20, 2^20] times 2^--exp (default -1074: subnormals)\n"
    "  kettner-grid     2D: (0.5 + x 2^-53, 0.5 + y 2^-53), x,y < --side (256), then (12,12), (24,24)\n"
    "                   (Kettner et al. 2008); --n is ignored\n"
    "  kettner-hull     2D: the incremental-hull failure set --set A1|A2|B1|B2 of Kettner et al. 2008\n"
    "binade edges (exact; --exp E in -1074..1023, seeded when absent, half the time among\n"
    "-1074 -1073 -1023 -1022 -1021 -1 0 1 50..54 1022 1023; --sign positive|negative|mixed,\n"
    "default mixed: each axis's sign seeded):\n"
    "  binade-lattice   a lattice whose every axis is +-2^E + i 2^S, i in [-m/2, m/2): it crosses\n"
    "                   the binade edge 2^E; --step-exp S in max(E-52,-1074)..E (default: one of\n"
    "                   the three finest, seeded); S = E-52 steps by one ulp above the edge\n"
    "  binade-doubles   a lattice whose every axis is the consecutive doubles around +-2^E\n"
    "                   (spacing 2^(E-53) below the edge, 2^(E-52) above)\n"
    "  half-integers    N distinct points of a grid whose axes are consecutive multiples of 1/2\n"
    "                   (that are doubles) around +-2^51, +-2^52, +-2^53 (--exp fixes it) or 0\n"
    "                   (issue 17: half-integers in [2^51, 2^52) passed an integer test)\n"
    "  extreme-doubles  N distinct points of a grid whose axes hold the largest finite doubles,\n"
    "                   the smallest subnormals (both signs) and 0\n"
    "  pdb-like         well-spaced points (a grid of --spacing, default 1.9, jittered by a quarter\n"
    "                   of it) with coordinates printed as PDB's %8.3f and read back (Liu & Snoeyink 2005)\n";

}  // namespace

int cmd_gen(int argc, char** argv) {
  try {
    const Args a = parse_args(argc, argv, 2,
                              {"-o", "--n", "--dim", "--seed", "--off", "--ulps", "--base",
                               "--clusters", "--sigma", "--copies", "--side", "--exp", "--set",
                               "--lo", "--hi", "--step-exp", "--sign", "--spacing"},
                              {"--decimal", "--hex", "--help"});
    if (a.has("--help")) {
      std::cout << kGenHelp;
      return 0;
    }
    if (a.positional.size() != 1)
      throw UsageError(a.positional.empty() ? "missing GENERATOR (dlab gen --help lists them)"
                                            : "unexpected argument '" + a.positional[1] + "'");
    if (a.has("--decimal") && a.has("--hex")) throw UsageError("--decimal and --hex exclude each other");
    gen::GenOptions o;
    o.name = a.positional[0];
    o.n = a.u64("--n", o.n, std::uint64_t{1} << 28);
    o.dim = static_cast<int>(a.i64("--dim", 0, 2, 3));
    o.seed = a.u64("--seed", 0);
    o.off = a.u64("--off", o.off, std::uint64_t{1} << 28);
    o.ulps = a.i64("--ulps", o.ulps, 0, 1 << 20);
    o.base = a.get("--base").value_or("");
    o.clusters = a.u64("--clusters", o.clusters, 1u << 24);
    o.sigma = a.real("--sigma", o.sigma);
    o.copies = a.u64("--copies", o.copies, std::uint64_t{1} << 28);
    o.side = a.u64("--side", o.side, 4096);
    if (a.get("--exp")) {
      o.exp = static_cast<int>(a.i64("--exp", 0, -1074, 1023));
      o.exp_set = true;
    }
    if (a.get("--step-exp")) {
      o.step_exp = static_cast<int>(a.i64("--step-exp", 0, -1074, 1023));
      o.step_exp_set = true;
    }
    o.sign = a.get("--sign").value_or(o.sign);
    o.set = a.get("--set").value_or(o.set);
    o.lo = a.real("--lo", o.lo);
    o.hi = a.real("--hi", o.hi);
    o.spacing = a.real("--spacing", o.spacing);

    const PointSet ps = gen::generate(o);
    const auto fmt = a.has("--decimal") ? io::FloatFormat::decimal : io::FloatFormat::hex;
    if (auto path = a.get("-o"); path && *path != "-") {
      std::ofstream out(*path, std::ios::binary);
      if (!out) throw UsageError("cannot write '" + *path + "'");
      io::write_points(out, ps, fmt);
      if (!out.flush()) throw UsageError("error writing '" + *path + "'");
    } else {
      io::write_points(std::cout, ps, fmt);
      std::cout.flush();
    }
    return 0;
  } catch (const UsageError& e) {
    std::cerr << "dlab gen: " << e.what() << "\n";
    return 2;
  } catch (const std::invalid_argument& e) {
    std::cerr << "dlab gen: " << e.what() << "\n";
    return 2;
  }
}

}  // namespace dlab::cli
