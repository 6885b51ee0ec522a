// `dlab flip INPUT SIMPLICES [-o OUT] [--stats FILE.json]`: flip an existing
// triangulation toward Delaunay (algorithms/flip_existing.hpp, exact perturbed
// adaptive kernel).  Writes the resulting simplices; prints flips, passes and
// the number of non-Delaunay facets left when 3D flipping is stuck.
// Exit 0: the result is Delaunay; 1: stuck (3D) or failed; 2: bad input/usage.
//
// `dlab flip INPUT --make-start [--seed S] [--flips K] [-o OUT]`: writes a
// valid but non-Delaunay triangulation of INPUT (fuzz/non_delaunay.hpp: the
// Delaunay triangulation with K random valid flips, default K = n), the
// starting point for the first form.
#include <cstdint>
#include <fstream>
#include <iostream>
#include <optional>
#include <string>

#include "algorithms/flip_existing.hpp"
#include "cli/args.hpp"
#include "cli/commands.hpp"
#include "cli/point_reader.hpp"
#include "cli/simplex_io.hpp"
#include "fuzz/non_delaunay.hpp"

namespace dlab::cli {

namespace {

// 1-based line of the k-th simplex (0-based) of a SIMPLICES file: its k-th
// line that holds data (blank and '#'-comment lines skipped, as the reader
// does); 0 if it cannot be told (standard input, unreadable).
std::size_t simplex_line(const std::string& path, std::int64_t k) {
  if (path == "-" || k < 0) return 0;
  std::ifstream f(path, std::ios::binary);
  std::string text;
  std::size_t line = 0;
  std::int64_t seen = 0;
  while (std::getline(f, text)) {
    ++line;
    const std::size_t hash = text.find('#');
    if (hash != std::string::npos) text.resize(hash);
    if (text.find_first_not_of(" \t\r,") == std::string::npos) continue;
    if (seen++ == k) return line;
  }
  return 0;
}

void write_out(const std::optional<std::string>& path, const std::vector<std::uint32_t>& s, int dim) {
  if (!path || *path == "-") {
    io::write_simplices(std::cout, s, dim);
    std::cout.flush();
    return;
  }
  std::ofstream f(*path, std::ios::binary);
  if (!f) throw UsageError("cannot write '" + *path + "'");
  io::write_simplices(f, s, dim);
  if (!f.flush()) throw UsageError("error writing '" + *path + "'");
}

}  // namespace

int cmd_flip(int argc, char** argv) {
  try {
    const Args a = parse_args(argc, argv, 2, {"-o", "--seed", "--flips", "--stats"}, {"--make-start"});
    const bool make = a.has("--make-start");
    if (a.positional.size() != (make ? 1u : 2u))
      throw UsageError("usage: dlab flip INPUT SIMPLICES [-o OUT] [--stats FILE.json] | "
                       "dlab flip INPUT --make-start [--seed S] [--flips K] [-o OUT]");
    const PointSet points = io::read_points(a.positional[0]);
    const int dim = points.dimension;
    if (make) {
      const std::uint64_t seed = a.u64("--seed", 1);
      const std::size_t flips = a.u64("--flips", 0, 1ull << 40);
      const std::vector<std::uint32_t> s = dim == 2 ? non_delaunay_start<2>(points.p2, seed, flips)
                                                    : non_delaunay_start<3>(points.p3, seed, flips);
      if (s.empty()) {
        std::cerr << "dlab flip: the points are lower-dimensional: no triangulation\n";
        return 1;
      }
      write_out(a.get("-o"), s, dim);
      return 0;
    }
    const std::vector<std::uint32_t> in = io::read_simplices(a.positional[1], dim, points.size());
    const FlipExistingResult r = dim == 2 ? flip_existing<2>(points.p2, in) : flip_existing<3>(points.p3, in);
    if (r.outcome != RunResult::Outcome::ok) {
      if (r.message.rfind("not a triangulation", 0) != 0) {
        std::cerr << "dlab flip: " << r.message << "\n";
        return 1;
      }
      // Bad input (exit 2): name the file, and the line when one simplex is at fault.
      std::cerr << "dlab flip: " << a.positional[1];
      if (const std::size_t line = simplex_line(a.positional[1], r.bad_simplex)) std::cerr << ":" << line;
      std::cerr << ": " << r.message << "\n";
      return 2;
    }
    write_out(a.get("-o"), r.simplices, dim);
    if (auto st = a.get("--stats")) {
      std::ofstream f(*st);
      f << "{\n  \"counters\": {";
      for (std::size_t i = 0; i < r.counters.size(); ++i)
        f << (i ? "," : "") << "\n    \"" << r.counters[i].first << "\": " << r.counters[i].second;
      f << "\n  }\n}\n";
    }
    std::cerr << "dlab flip: " << r.flips << " flips in " << r.passes << " passes";
    if (r.stuck_facets) {
      std::cerr << "; stuck: " << r.stuck_facets << " non-Delaunay facets left, none flippable\n";
      return 1;
    }
    std::cerr << "; Delaunay\n";
    return 0;
  } catch (const UsageError& e) {
    std::cerr << "dlab flip: " << e.what() << "\n";
    return 2;
  } catch (const io::InputError& e) {
    std::cerr << "dlab flip: " << e.what() << "\n";
    return 2;
  }
}

}  // namespace dlab::cli
