// `dlab demo`: the default job of the README's first command.
// 1. Kettner, Mehlhorn, Pion, Schirra, Yap, "Classroom examples of robustness
//    problems in geometric computations", CGTA 40 (2008), section 3: the sign
//    of orient2d(p, q, r) for p = (0.5 + x u, 0.5 + y u), u = 2^-53, 0 <= x, y
//    < 256, q = (12, 12), r = (24, 24). Exactly, p is left of, on, or right of
//    the line qr as y > x, y = x, y < x: the exact sign is sign(y - x). Per
//    kernel: how many of the 65536 signs are wrong, and a 32 x 32 sign map.
// 2. Every registered algorithm x kernel on built-in degenerate sets (exactly
//    cocircular points, a 2D grid, a corner of Kettner's grid with q and r,
//    cocircular points moved by 1 ulp, exactly cospherical points, a 3D grid,
//    cospherical points moved by 1 ulp): the exact validator's verdict and the
//    triangulation time. Algorithms not registered yet are left out.
#include <cstdio>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include "algorithms/validate.hpp"
#include "cli/cli_app.hpp"
#include "cli/commands.hpp"
#include "cli/kernels.hpp"
#include "fuzz/generators.hpp"

namespace dlab::cli {
namespace {

constexpr int kSide = 256;

struct SignMap {
  std::string label;
  std::vector<signed char> s;  // kSide * kSide, row y, column x
  int wrong = 0, flipped = 0, false_zero = 0;
  int integer_vs_mp = -1;      // integer kernel: disagreements with mp on its snapped points
};

// The grid points and q, r; the integer kernel is fitted to all of them at
// once, as a triangulation of this set would fit it. `rotate` evaluates
// orient2d(q, r, p) instead of orient2d(p, q, r): the same exact value (a
// cyclic permutation), but Shewchuk's formula det[a-c; b-c] then takes its
// differences from p instead of r, which changes how float rounds.
SignMap sign_map(const std::string& kernel, bool rotate) {
  const std::vector<Point2> pts = gen::kettner_grid(kSide);
  const Point2 q = pts[pts.size() - 2], r = pts.back();
  SignMap m;
  m.label = rotate ? kernel + "(q,r,p)" : kernel;
  m.s.resize(kSide * kSide);
  with_kernel<2>(kernel, std::span<const Point2>(pts), [&](const auto& k) {
    for (int y = 0; y < kSide; ++y)
      for (int x = 0; x < kSide; ++x) {
        const std::size_t i = static_cast<std::size_t>(y * kSide + x);
        const Point2& p = pts[i];
        const int s = to_int(rotate ? k.orient2d(q, r, p) : k.orient2d(p, q, r));
        m.s[i] = static_cast<signed char>(s);
        const int exact = (y > x) - (y < x);
        m.wrong += s != exact;
        m.flipped += s * exact < 0;
        m.false_zero += s == 0 && exact != 0;
      }
    if constexpr (requires { k.snap(q); }) {
      // The integer kernel answers for its snapped points: compare with mp there.
      const MpKernel mp;
      const Point2 sq = k.snap(q), sr = k.snap(r);
      m.integer_vs_mp = 0;
      for (std::size_t i = 0; i < m.s.size(); ++i)
        m.integer_vs_mp += to_int(mp.orient2d(k.snap(pts[i]), sq, sr)) != m.s[i];
    }
    return 0;
  });
  return m;
}

char glyph(int s) { return s > 0 ? '+' : (s < 0 ? '.' : '0'); }

void print_maps(std::ostream& out, const std::vector<SignMap>& maps, int x0, int y0, int step) {
  std::string head;
  for (const auto& m : maps) {
    std::string h = m.label;
    h.resize(34, ' ');
    head += h;
  }
  out << head << "\n";
  for (int y = y0 + 31 * step; y >= y0; y -= step) {
    std::string row;
    for (const auto& m : maps) {
      for (int x = x0; x < x0 + 32 * step; x += step)
        row += glyph(m.s[static_cast<std::size_t>(y * kSide + x)]);
      row += "  ";
    }
    out << row << "\n";
  }
}

void sign_map_experiment(std::ostream& out) {
  out << "== Predicate sign map (Kettner et al. 2008) ==\n"
         "orient2d(p, q, r) with p = (0.5 + x*2^-53, 0.5 + y*2^-53), 0 <= x, y < 256,\n"
         "q = (12, 12), r = (24, 24). Exact sign: sign(y - x) (p left of qr iff y > x).\n"
         "float(q,r,p) asks the same question as orient2d(q, r, p): equal exactly, but\n"
         "rounded differently (Shewchuk's formula takes differences from its last point).\n\n";
  char line[200];
  std::snprintf(line, sizeof line, "%-16s %7s %9s %11s  %s\n", "kernel", "wrong", "opposite",
                "false zero", "(of 65536 signs)");
  out << line;
  std::vector<SignMap> maps;
  for (const auto& name : all_kernel_names()) {
    if (!kernel_available(name)) {
      std::snprintf(line, sizeof line, "%-16s %7s\n", name.c_str(), "(not built)");
      out << line;
      continue;
    }
    for (bool rotate : {false, true}) {
      if (rotate && kernel_is_exact(name)) continue;
      SignMap m = sign_map(name, rotate);
      std::string note;
      if (m.integer_vs_mp >= 0)
        note = "signs of its snapped points: " + std::to_string(m.integer_vs_mp) +
               " differ from mp on the same snapped points";
      std::snprintf(line, sizeof line, "%-16s %7d %9d %11d  %s\n", m.label.c_str(), m.wrong,
                    m.flipped, m.false_zero, note.c_str());
      out << line;
      maps.push_back(std::move(m));
    }
  }
  // The exact kernels all draw the exact map ('+' above the diagonal, '.' below,
  // '0' on it): show the inexact ones.
  std::vector<SignMap> shown;
  for (auto& m : maps)
    if (m.label == "float" || m.label == "float(q,r,p)" || m.label == "epsilon") shown.push_back(m);
  out << "\nSign maps of the inexact kernels ('+' = 1, '.' = -1, '0' = 0; x to the right,\n"
         "y up; exactly: '+' above the diagonal, '.' below, '0' on it), every 8th point:\n";
  print_maps(out, shown, 0, 0, 8);
  out << "\nFull resolution, x and y in [0, 32):\n";
  print_maps(out, shown, 0, 0, 1);
}

struct DemoSet {
  std::string name;
  PointSet points;
};

std::vector<DemoSet> demo_sets() {
  std::vector<DemoSet> sets;
  auto add2 = [&](std::string name, std::vector<Point2> p) {
    DemoSet s{std::move(name), {}};
    s.points.dimension = 2;
    s.points.p2 = std::move(p);
    sets.push_back(std::move(s));
  };
  auto add3 = [&](std::string name, std::vector<Point3> p) {
    DemoSet s{std::move(name), {}};
    s.points.dimension = 3;
    s.points.p3 = std::move(p);
    sets.push_back(std::move(s));
  };
  add2("cocircular 256", gen::cospherical<2>(256, 1));
  add2("2D grid 48x48", gen::lattice<2>(48 * 48));
  add2("Kettner 24x24+2", gen::kettner_grid(24));
  add2("cocircular+-1ulp", gen::perturb_ulps<2>(gen::cospherical<2>(1000, 2), 1, 2));
  add3("cospherical 300", gen::cospherical<3>(300, 1));
  add3("3D grid 10^3", gen::lattice<3>(1000));
  add3("cosphere+-1ulp", gen::perturb_ulps<3>(gen::cospherical<3>(1000, 2), 1, 2));
  return sets;
}

// One cell of the matrix: what happened to one algorithm x kernel x set.
std::string run_cell(const PointSet& points, const std::string& algo, const std::string& kernel,
                     std::vector<std::string>& notes, const std::string& where) {
  RunOptions o;
  o.algorithm = algo;
  o.kernel = kernel;
  o.policy = kernel_is_exact(kernel) ? "sos" : "strict";
  o.order = "brio";
  o.seed = 1;
  char buf[64];
  try {
    const RunResult res = run(points, o);
    std::snprintf(buf, sizeof buf, " %.3fs", res.seconds);
    const std::string secs = buf;
    if (res.outcome == RunResult::Outcome::failed) {
      notes.push_back(where + ": " + res.message);
      return "FAILED [" + std::to_string(notes.size()) + "]";
    }
    if (res.outcome == RunResult::Outcome::lower_dimensional) return "lower-dim" + secs;
    const PointSet& pts = res.points.size() == points.size() ? res.points : points;
    const ValidationReport rep = validate(pts, res.simplices);
    if (!rep.valid()) {
      std::string summary = rep.summary();
      for (char& c : summary)
        if (c == '\n') c = ';';
      notes.push_back(where + ": " + summary);
      return "INVALID [" + std::to_string(notes.size()) + "]";
    }
    if (!rep.delaunay()) return "valid, " + std::to_string(rep.non_delaunay_facets()) + " non-Del";
    return "Delaunay" + secs;
  } catch (const UsageError&) {
    return "-";
  } catch (const std::exception& e) {
    notes.push_back(where + ": exception: " + e.what());
    return "ERROR [" + std::to_string(notes.size()) + "]";
  }
}

void matrix(std::ostream& out) {
  out << "\n== Algorithms x kernels on degenerate sets ==\n"
         "Each cell: the exact validator's verdict on the result (for `integer`, on its\n"
         "snapped points) and the triangulation time. 'Delaunay': valid and Delaunay;\n"
         "'valid, k non-Del': valid, k interior facets not locally Delaunay; INVALID: not a\n"
         "triangulation of the hull; FAILED: the algorithm reported a failure; '-': not built.\n";
  const auto sets = demo_sets();
  std::vector<std::string> algos;
  try {
    algos = algorithm_names();
  } catch (const std::exception&) {
  }
  const auto kernels = all_kernel_names();
  for (const auto& algo : algos) {
    std::vector<std::string> notes;
    std::ostringstream table;
    bool any = false;
    std::string head = "set";
    head.resize(18, ' ');
    for (const auto& k : kernels) {
      std::string h = k;
      h.resize(18, ' ');
      head += h;
    }
    table << head << "\n";
    for (const auto& set : sets) {
      std::string row = set.name;
      row.resize(18, ' ');
      for (const auto& k : kernels) {
        std::string cell = run_cell(set.points, algo, k, notes, set.name + " / " + k);
        any = any || cell != "-";
        cell.resize(std::max<std::size_t>(cell.size() + 1, 18), ' ');
        row += cell;
      }
      table << row << "\n";
    }
    if (!any) continue;  // an algorithm with no instantiation yet
    out << "\nalgorithm: " << algo << "\n" << table.str();
    for (std::size_t i = 0; i < notes.size(); ++i) {
      std::string n = notes[i];
      if (n.size() > 150) n = n.substr(0, 147) + "...";
      out << "  [" << i + 1 << "] " << n << "\n";
    }
    out << std::flush;
  }
}

// The full map of one kernel, for papers/shewchuk-kettner (the picture is drawn
// there; the signs are decided here, by predicates/).
void print_sign_map(std::ostream& out, const SignMap& m) {
  out << "# dlab demo --sign-map: " << m.label
      << ": orient2d signs, p = (0.5 + x*2^-53, 0.5 + y*2^-53), q = (12, 12), r = (24, 24)\n"
         "# line 1 + y (y = 0.." << kSide - 1 << "), column 1 + x (x = 0.." << kSide - 1
      << "); '+' = 1, '-' = -1, '0' = 0\n"
         "# wrong " << m.wrong << ", opposite " << m.flipped << ", false zero " << m.false_zero
      << " of " << kSide * kSide << " (exact sign: sign(y - x))\n";
  for (int y = 0; y < kSide; ++y) {
    std::string row(kSide, '0');
    for (int x = 0; x < kSide; ++x) {
      const int s = m.s[static_cast<std::size_t>(y * kSide + x)];
      row[static_cast<std::size_t>(x)] = s > 0 ? '+' : (s < 0 ? '-' : '0');
    }
    out << row << "\n";
  }
}

}  // namespace

int cmd_demo(int argc, char** argv) {
  std::string map_kernel;
  bool qrp = false;
  CommandLine cl("demo",
                 "usage: dlab demo                        the sign-map experiment and the kernel matrix\n"
                 "       dlab demo --sign-map K [--qrp]   the full 256 x 256 sign map of kernel K\n",
                 "Without options: for each kernel, how many of orient2d's 65536 signs on Kettner et al.'s\n"
                 "grid (CGTA 2008) are wrong, with a 32 x 32 sign map; then every algorithm x kernel on\n"
                 "built-in degenerate sets: the exact validator's verdict and the time.\n",
                 "  dlab demo\n"
                 "  dlab demo --sign-map float > float.map\n"
                 "  dlab demo --sign-map float --qrp > float_qrp.map\n",
                 "Exit status: 0, 2 bad usage.\n");
  CLI::App& app = cl.app();
  app.add_option("--sign-map", map_kernel,
                 "orient2d(p, q, r) by kernel K for p = (0.5 + x*2^-53, 0.5 + y*2^-53), 0 <= x, y < 256,\n"
                 "q = (12, 12), r = (24, 24): three '#' lines, then line 1 + y holds the signs for\n"
                 "x = 0..255 ('+', '-', '0')")
      ->type_name("K");
  app.add_flag("--qrp", qrp,
               "with --sign-map: orient2d(q, r, p) instead, the same exact sign, but the floating-point\n"
               "formula then takes its differences from p, as Kettner et al.'s float_orient does");
  if (auto rc = cl.parse(argc, argv, 2)) return *rc;
  if (qrp && map_kernel.empty()) return cl.usage_error("--qrp needs --sign-map K");
  if (!map_kernel.empty()) {
    try {
      print_sign_map(std::cout, sign_map(map_kernel, qrp));
    } catch (const UsageError& e) {
      return cl.usage_error(e.what());
    }
    return 0;
  }
  sign_map_experiment(std::cout);
  std::cout << std::flush;
  matrix(std::cout);
  return 0;
}

}  // namespace dlab::cli
