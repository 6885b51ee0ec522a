// `dlab`: subcommand dispatch only (the contract is design.md section 5).
#include <cstdio>
#include <cstring>
#include <exception>
#include <iostream>
#include <string_view>

#include "cli/commands.hpp"
#include "cli/outcome_report.hpp"

namespace {

const char* const kUsage =
    "usage:\n"
    "  dlab triangulate INPUT [-o SIMPLICES] [--algo A] [--kernel K] [--policy sos|strict]\n"
    "                   [--order input|random|brio|hilbert] [--seed N] [--points-out FILE [--decimal]]\n"
    "                   [--location walk|scan] [--stats FILE.json] [--validate]\n"
    "  dlab check INPUT SIMPLICES [--orientation positive|any]\n"
    "                                   exact validity + Delaunay check (exit 0 iff valid Delaunay)\n"
    "  dlab convert POINTS OUT [--simplices SIMPLICES]  to Triangle/TetGen .node, .vtu or .off\n"
    "                                   by OUT's extension (dlab convert --help)\n"
    "  dlab predicate NAME K COORD...   NAME: orient2d incircle orient3d insphere; prints -1, 0 or 1\n"
    "  dlab gen GENERATOR [--decimal] [options]  a point set (dlab gen --help lists generators)\n"
    "  dlab flip INPUT SIMPLICES [-o OUT] [--kernel K] [--stats FILE.json]\n"
    "                                   flip a triangulation of INPUT toward Delaunay\n"
    "  dlab flip INPUT --make-start [--seed S] [--flips K] [-o OUT]  a non-Delaunay start\n"
    "  dlab draw POINTS SIMPLICES -o FILE.svg [--circles] [--labels]  2D picture, faults marked\n"
    "                                   by the exact validator (dlab draw --help)\n"
    "  dlab voronoi POINTS [SIMPLICES] -o OUT.svg|OUT.vtu [--box B]  the Voronoi dual, cells cut\n"
    "                                   by a box, exactly rounded centres (dlab voronoi --help)\n"
    "  dlab demo                        the predicate sign-map experiment and the kernel matrix\n"
    "  dlab plot STUDY_DIR [--out DIR]  SVG + PNG figures of a study's runs.csv (dlab plot --help)\n"
    "  dlab fuzz --out DIR (--cases C | --budget T) [--algo LIST] [--kernel LIST] [--gen LIST]\n"
    "            [--dim 2|3] [--n N|LO..HI] [--seed S] [--jobs J] [--shard k/n]\n"
    "                                   classified robustness campaign (dlab fuzz --help)\n"
    "  dlab fuzz merge DIR... --out DIR shards -> exactly the unsharded campaign\n"
    "  dlab shrink INPUT --algo A --kernel K [--seed S] [-o OUT]  a failing point set -> a minimal\n"
    "                                   one with the same failure (dlab shrink --help)\n"
    "  dlab corpus replay DIR|FILE... [--jobs J]  replay the regression corpus (dlab corpus --help)\n"
    "  dlab corpus add INPUT --to DIR [--name NAME] [--replace]  a point file -> a corpus case\n"
    "  dlab study CONFIG.json --out DIR [--shard k/n] [--jobs J]  an algorithm comparison study:\n"
    "                                   DIR/runs.csv + meta.json (--default: the built-in matrix)\n"
    "  dlab study merge DIR... --out DIR shards -> exactly the unsharded study\n"
    "  dlab --version                   version, git commit (at configure time) and compiler\n"
    "A: bowyer-watson (default), lawson, tanemura, george. K: adaptive (default), integer, mp,\n"
    "float, epsilon. INPUT: one point per line (2 or 3 coordinates, decimal or hex floats), or a\n"
    "Triangle/TetGen .node file, or the vertices of a .xyz, .off or ASCII .ply file; '-' is\n"
    "standard input.\n"
    "SIMPLICES: d+1 indices per line, each simplex positively oriented: det[v1-v0; ...; vd-v0] > 0,\n"
    "i.e. Shewchuk's orient2d(v0,v1,v2) > 0 in 2D (counterclockwise) and orient3d(v0,v1,v2,v3) < 0\n"
    "in 3D (CGAL's cells); --orientation any also takes the opposite (scipy's are mixed).\n"
    "--decimal: coordinates as shortest round-trip decimals (numpy.loadtxt) instead of hex floats.\n"
    "Exit status: 0 success, 1 any other outcome, 2 bad input or usage.\n"
    "dlab COMMAND --help: the command's synopsis, every option, examples.\n";

}  // namespace

int main(int argc, char** argv) {
  std::ios::sync_with_stdio(false);
  if (argc < 2) {
    std::cerr << kUsage;
    return 2;
  }
  const std::string_view cmd = argv[1];
  try {
    if (cmd == "triangulate") return dlab::cli::cmd_triangulate(argc, argv);
    if (cmd == "check") return dlab::cli::cmd_check(argc, argv);
    if (cmd == "convert") return dlab::cli::cmd_convert(argc, argv);
    if (cmd == "predicate") return dlab::cli::cmd_predicate(argc, argv);
    if (cmd == "gen") return dlab::cli::cmd_gen(argc, argv);
    if (cmd == "demo") return dlab::cli::cmd_demo(argc, argv);
    if (cmd == "draw") return dlab::cli::cmd_draw(argc, argv);
    if (cmd == "voronoi") return dlab::cli::cmd_voronoi(argc, argv);
    if (cmd == "flip") return dlab::cli::cmd_flip(argc, argv);
    if (cmd == "plot") return dlab::cli::cmd_plot(argc, argv);
    if (cmd == "fuzz") return dlab::cli::cmd_fuzz(argc, argv);
    if (cmd == "corpus") return dlab::cli::cmd_corpus(argc, argv);
    if (cmd == "shrink") return dlab::cli::cmd_shrink(argc, argv);
    if (cmd == "study") return dlab::cli::cmd_study(argc, argv);
    if (cmd == "--version" || cmd == "version") return dlab::cli::cmd_version(argc, argv);
    if (cmd == "help" || cmd == "--help" || cmd == "-h") {
      std::cout << kUsage << dlab::cli::kOutcomeHelp;
      return 0;
    }
  } catch (const std::exception& e) {  // each command reports its own errors; this is a backstop
    std::cerr << "dlab " << cmd << ": internal error: " << e.what() << "\n";
    return 1;
  }
  std::cerr << "dlab: unknown command '" << cmd << "'\n" << kUsage;
  return 2;
}
