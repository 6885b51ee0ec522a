// `dlab gen GENERATOR [options]`: writes a seeded point set (fuzz/generators.hpp)
// in the INPUT format, one point per line. Coordinates are hexadecimal floats by
// default (exact); --decimal writes the shortest decimal that reads back to the
// same double (also exact). Same arguments -> same bytes on every machine.
#include <fstream>
#include <iostream>
#include <stdexcept>

#include "cli/cli_app.hpp"
#include "cli/commands.hpp"
#include "cli/point_writer.hpp"
#include "fuzz/generators.hpp"

namespace dlab::cli {
namespace {

const char* const kGenSynopsis =
    "usage: dlab gen GENERATOR [-o FILE] [--n N] [--dim 2|3] [--seed S] [--decimal] [options]\n";

const char* const kGenerators =
    "Writes a seeded point set, one point per line: same arguments, same bytes on every machine.\n"
    "Generators (N points unless said otherwise; 'exact' = integer coordinates, possibly scaled\n"
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
  gen::GenOptions o;
  std::string out_path = "-";
  bool decimal = false, hex = false;
  CommandLine cl("gen", kGenSynopsis, kGenerators,
                 "  dlab gen uniform --n 1000 --seed 7 -o points.txt\n"
                 "  dlab gen cospherical --n 200 --decimal > sphere.txt\n"
                 "  dlab gen near-degenerate --base cocircular --ulps 4 --n 64 --seed 3\n"
                 "  dlab gen binade-lattice --exp 52 --sign positive --n 100\n",
                 "Exit status: 0, 2 bad usage (an unknown generator, an option out of range).\n");
  CLI::App& app = cl.app();
  app.add_option("GENERATOR", o.name, "one of the generators above")->required();
  app.add_option("-o", out_path, "the points (-: standard output)")->type_name("FILE")->capture_default_str();
  add_unsigned(app, "--n", o.n, std::uint64_t{1} << 28, "number of points");
  add_integer(app, "--dim", o.dim, 2, 3, "dimension (default: 3 for cospherical and coplanar, else 2)")
      ->default_str("");
  add_unsigned(app, "--seed", o.seed, UINT64_MAX, "the seed");
  app.add_flag("--decimal", decimal, "coordinates as shortest round-trip decimals (numpy.loadtxt)");
  app.add_flag("--hex", hex, "coordinates as C99 hexadecimal floats (the default)")->excludes("--decimal");
  add_unsigned(app, "--off", o.off, std::uint64_t{1} << 28, "collinear, coplanar: points off the line or plane");
  add_integer(app, "--ulps", o.ulps, 0, 1 << 20, "near-degenerate, near-duplicates: largest move in ulps");
  app.add_option("--base", o.base, "near-degenerate: the exact set to perturb (default cocircular/cospherical)")
      ->type_name("GENERATOR");
  add_unsigned(app, "--clusters", o.clusters, 1u << 24, "clustered: number of clusters");
  add_real(app, "--sigma", o.sigma, "gaussian (default 1), clustered (default 0.01): standard deviation")
      ->default_str("");
  add_unsigned(app, "--copies", o.copies, std::uint64_t{1} << 28, "near-duplicates: copies of each point");
  add_unsigned(app, "--side", o.side, 4096, "kettner-grid: side of the grid");
  add_integer(app, "--exp", o.exp, -1074, 1023,
              "huge (default 1000), tiny (default -1074): scale 2^E; binade-*, half-integers: the edge 2^E\n"
              "(default seeded)")
      ->type_name("E")->default_str("");
  add_integer(app, "--step-exp", o.step_exp, -1074, 1023, "binade-lattice: lattice step 2^S (default seeded)")
      ->type_name("S")->default_str("");
  add_choice(app, "--sign", o.sign, {"positive", "negative", "mixed"},
             "binade-*, half-integers: the axes' signs (mixed: seeded per axis)");
  add_choice(app, "--set", o.set, {"A1", "A2", "B1", "B2"}, "kettner-hull: which failure set");
  add_real(app, "--lo", o.lo, "uniform: lower end of the box");
  add_real(app, "--hi", o.hi, "uniform: upper end of the box");
  add_real(app, "--spacing", o.spacing, "pdb-like: grid spacing (angstroms)");
  if (auto rc = cl.parse(argc, argv, 2)) return *rc;
  o.exp_set = app.count("--exp") > 0;
  o.step_exp_set = app.count("--step-exp") > 0;
  try {
    const PointSet ps = gen::generate(o);
    const auto fmt = decimal ? io::FloatFormat::decimal : io::FloatFormat::hex;
    if (out_path != "-") {
      std::ofstream out(out_path, std::ios::binary);
      if (!out) throw UsageError("cannot write '" + out_path + "'");
      io::write_points(out, ps, fmt);
      if (!out.flush()) throw UsageError("error writing '" + out_path + "'");
    } else {
      io::write_points(std::cout, ps, fmt);
      std::cout.flush();
    }
    return 0;
  } catch (const UsageError& e) {
    return cl.usage_error(e.what());
  } catch (const std::invalid_argument& e) {
    return cl.usage_error(e.what());
  }
}

}  // namespace dlab::cli
