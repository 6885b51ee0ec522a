// Nanoseconds per predicate call, for each predicate x kernel, on random and on
// near-degenerate inputs (Google Benchmark). Issue 2's target: adaptive within
// 1.5x of float on random inputs. Results and the command: papers/predicate_costs.md.
//
// Inputs (fixed seed, 4096 calls per set, cycled):
//   random:     coordinates uniform in [0, 1)
//   degenerate: points on a line / circle / plane / sphere (coordinates rounded
//               to doubles), the query point then moved by -1, 0 or +1 ulp in one
//               coordinate: the exact stages decide most of these.
// For the adaptive kernel, counters give the share of calls each stage answered.
// `adaptive-static` is the adaptive kernel fitted to the set's points
// (AdaptiveKernel::fit_static_filter, as the driver fits it for Bowyer-Watson,
// Lawson and George): orient3d then starts with the static filter.
// --dlab_tight=PRED/KERNEL[/PASSES[/SET]] runs the same loop body without Google
// Benchmark, in one function (tight_pass) for callgrind: see the comment there.
// --dlab_ratio=ROUNDS prints adaptive (and adaptive-static) / float per predicate from interleaved tight
// passes.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cstdio>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "predicates/adaptive_kernel.hpp"
#include "predicates/float_kernel.hpp"
#include "predicates/mp_kernel.hpp"
#include "predicates/epsilon_kernel.hpp"
#include "predicates/integer_kernel.hpp"

namespace {

using namespace dlab;

constexpr int kCalls = 4096;
enum Pred { kOrient2d, kIncircle, kOrient3d, kInsphere };
enum Set { kRandom, kDegenerate };

struct Rng {
  std::mt19937_64 g;
  explicit Rng(std::uint64_t s) : g(s) {}
  double unit() { return static_cast<double>(g() >> 11) * 0x1p-53; }
};

double nudge(double x, int k) {
  if (k > 0) return std::nextafter(x, std::numeric_limits<double>::infinity());
  if (k < 0) return std::nextafter(x, -std::numeric_limits<double>::infinity());
  return x;
}

// 5 points per call (2D predicates use the x, y of the first 3 or 4).
using Call = std::array<Point3, 5>;

std::vector<Call> make_inputs(Pred pred, Set set) {
  Rng r(1000 + 10 * pred + set);
  std::vector<Call> calls(kCalls);
  for (Call& c : calls) {
    if (set == kRandom) {
      for (Point3& p : c) p = {r.unit(), r.unit(), r.unit()};
      continue;
    }
    const double cx = 0.25 + 0.5 * r.unit(), cy = 0.25 + 0.5 * r.unit(), cz = 0.25 + 0.5 * r.unit();
    const double rad = 0.2 * r.unit() + 0.01;
    int query = 0;
    switch (pred) {
      case kOrient2d: {  // on the line through two random points
        const Point3 a{r.unit(), r.unit(), 0}, b{r.unit(), r.unit(), 0};
        for (Point3& p : c) {
          const double t = r.unit();
          p = {a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1]), 0};
        }
        query = 2;
        break;
      }
      case kIncircle:  // on a circle
        for (Point3& p : c) {
          const double th = 6.283185307179586 * r.unit();
          p = {cx + rad * std::cos(th), cy + rad * std::sin(th), 0};
        }
        query = 3;
        break;
      case kOrient3d: {  // on a plane through three random points
        const Point3 a{r.unit(), r.unit(), r.unit()}, u{r.unit() - 0.5, r.unit() - 0.5, r.unit() - 0.5},
            v{r.unit() - 0.5, r.unit() - 0.5, r.unit() - 0.5};
        for (Point3& p : c) {
          const double s = r.unit(), t = r.unit();
          for (int j = 0; j < 3; ++j) p[j] = a[j] + s * u[j] + t * v[j];
        }
        query = 3;
        break;
      }
      case kInsphere:  // on a sphere
        for (Point3& p : c) {
          const double th = 6.283185307179586 * r.unit(), ph = 3.141592653589793 * r.unit();
          p = {cx + rad * std::sin(ph) * std::cos(th), cy + rad * std::sin(ph) * std::sin(th),
               cz + rad * std::cos(ph)};
        }
        query = 4;
        break;
    }
    const int axis = static_cast<int>(r.g() % (pred == kOrient2d || pred == kIncircle ? 2 : 3));
    c[query][axis] = nudge(c[query][axis], static_cast<int>(r.g() % 3) - 1);
  }
  return calls;
}

Point2 xy(const Point3& p) { return {p[0], p[1]}; }

// The adaptive kernel fitted to the points of the set it is timed on.
struct AdaptiveStatic : AdaptiveKernel {
  static constexpr std::string_view name = "adaptive-static";
};

// The calls of one (predicate, set): 2D predicates read stored Point2s (as an
// algorithm reads its point array), 3D ones Point3s; no temporaries per call.
struct Inputs {
  std::vector<std::array<Point2, 4>> c2;
  std::vector<Call> c3;
};

Inputs make_set(Pred pred, Set set) {
  Inputs in;
  in.c3 = make_inputs(pred, set);
  for (const Call& c : in.c3) in.c2.push_back({xy(c[0]), xy(c[1]), xy(c[2]), xy(c[3])});
  return in;
}

// One call of predicate P on call i: the full sign, fresh inputs every call.
template <Pred P, class K>
inline int call(const K& k, const Inputs& in, std::size_t i) {
  if constexpr (P == kOrient2d) {
    const auto& c = in.c2[i];
    return to_int(k.orient2d(c[0], c[1], c[2]));
  } else if constexpr (P == kIncircle) {
    const auto& c = in.c2[i];
    return to_int(k.incircle(c[0], c[1], c[2], c[3]));
  } else if constexpr (P == kOrient3d) {
    const auto& c = in.c3[i];
    return to_int(k.orient3d(c[0], c[1], c[2], c[3]));
  } else {
    const auto& c = in.c3[i];
    return to_int(k.insphere(c[0], c[1], c[2], c[3], c[4]));
  }
}

// K{}, or for AdaptiveStatic an adaptive kernel fitted to every point of the set.
template <class K>
K make_kernel(const Inputs& in) {
  K k{};
  if constexpr (std::is_same_v<K, AdaptiveStatic>) {
    std::vector<Point3> pts;
    for (const Call& c : in.c3) pts.insert(pts.end(), c.begin(), c.end());
    k.fit_static_filter(pts);
  }
  return k;
}

Staged staged(const AdaptiveKernel& k, Pred pred, const Inputs& in, std::size_t i) {
  const auto& d = in.c2[i];
  const auto& c = in.c3[i];
  switch (pred) {
    case kOrient2d: return k.orient2d_staged(d[0], d[1], d[2]);
    case kIncircle: return k.incircle_staged(d[0], d[1], d[2], d[3]);
    case kOrient3d: return k.orient3d_staged(c[0], c[1], c[2], c[3]);
    case kInsphere: return k.insphere_staged(c[0], c[1], c[2], c[3], c[4]);
  }
  return {};
}

// The switch on `pred` is outside the timed loop: one instantiation per predicate.
// DoNotOptimize(acc) (an asm barrier with a memory clobber) after every call keeps
// the compiler from hoisting, merging or vectorising calls across iterations, for
// every kernel alike.
template <class K, Pred P>
void bench(benchmark::State& state, Set set) {
  const Inputs in = make_set(P, set);
  const K k = make_kernel<K>(in);
  std::size_t i = 0;
  int acc = 0;
  for (auto _ : state) {
    acc += call<P>(k, in, i);
    i = (i + 1) & (kCalls - 1);
    benchmark::DoNotOptimize(acc);
  }
  if constexpr (std::is_base_of_v<AdaptiveKernel, K>) {
    std::array<int, AdaptiveKernel::stage_names.size()> n{};
    for (std::size_t j = 0; j < kCalls; ++j) ++n[staged(k, P, in, j).stage];
    for (std::size_t s = 0; s < n.size(); ++s)
      if (n[s] > 0)
        state.counters[std::string("stage_") + std::string(AdaptiveKernel::stage_names[s])] =
            static_cast<double>(n[s]) / kCalls;
  }
}

// ---- Tight loop (--dlab_tight=PRED/KERNEL[/PASSES]) -------------------------------
// The same loop body as bench(), over all kCalls calls once, in a function of its
// own so that callgrind can count its instructions exactly:
//   valgrind --tool=callgrind --toggle-collect='*tight_pass*'
//            bench_predicates --dlab_tight=orient3d/adaptive/20
// (instructions per call = Ir / (PASSES * 4096)). Run alone, it prints the best
// of PASSES timed passes in ns per call.
template <class K, Pred P>
[[gnu::noinline]] int tight_pass(const K& k, const Inputs& in) {
  int acc = 0;
  for (std::size_t i = 0; i < kCalls; ++i) {
    acc += call<P>(k, in, i);
    benchmark::DoNotOptimize(acc);
  }
  return acc;
}

// The fastest of `passes` timed passes over `in`, in ns per call; adds the signs to *sum.
template <class K, Pred P>
double best_pass(const Inputs& in, int passes, long* sum) {
  const K k = make_kernel<K>(in);
  double best = 1e300;
  for (int p = 0; p < passes; ++p) {
    const auto t0 = std::chrono::steady_clock::now();
    *sum += tight_pass<K, P>(k, in);
    const auto t1 = std::chrono::steady_clock::now();
    best = std::min(best, std::chrono::duration<double, std::nano>(t1 - t0).count() / kCalls);
  }
  return best;
}

template <class K, Pred P>
int run_tight(Set set, int passes) {
  const Inputs in = make_set(P, set);
  long sum = 0;
  const double best = best_pass<K, P>(in, passes, &sum);
  std::printf("tight %s: best of %d passes %.3f ns/call (sum of signs %ld)\n",
              std::string(K::name).c_str(), passes, best, sum);
  return 0;
}

// ---- Ratio (--dlab_ratio=ROUNDS) ---------------------------------------------------
// kernel / float on random inputs, per predicate: ROUNDS rounds, each a best-of-20
// pass of float then one of the kernel (interleaved, so that a change in the
// machine's load or clock hits both alike). Printed: the fastest pass of each, their
// ratio, and the median and quartiles of the per-round ratios (each round pairs the
// two kernels under the same machine state: the steadier figure on a shared machine).
template <Pred P, class K>
void ratio_row(const char* name, int rounds) {
  const Inputs in = make_set(P, kRandom);
  long sum_float = 0, sum_k = 0;
  double t_float = 1e300, t_k = 1e300;
  std::vector<double> per_round;
  for (int r = 0; r < rounds; ++r) {
    const double f = best_pass<FloatKernel, P>(in, 20, &sum_float);
    const double k = best_pass<K, P>(in, 20, &sum_k);
    t_float = std::min(t_float, f);
    t_k = std::min(t_k, k);
    per_round.push_back(k / f);
  }
  std::sort(per_round.begin(), per_round.end());
  const std::size_t n = per_round.size();
  std::printf("| %s | %s | %.2f | %.2f | %.2f | %.2f (%.2f-%.2f) |\n", name,
              std::string(K::name).c_str(), t_float, t_k, t_k / t_float, per_round[n / 2],
              per_round[n / 4], per_round[(3 * n) / 4]);
}

int ratio(const std::string& arg) {
  const int rounds = std::atoi(arg.c_str());
  if (rounds < 1) {
    std::fprintf(stderr, "bad --dlab_ratio=%s (a number of rounds)\n", arg.c_str());
    return 2;
  }
  std::printf(
      "| predicate | kernel | float ns | kernel ns | fastest / fastest | per-round median "
      "(quartiles) |\n|---|---|---:|---:|---:|---:|\n");
  ratio_row<kOrient2d, AdaptiveKernel>("orient2d", rounds);
  ratio_row<kIncircle, AdaptiveKernel>("incircle", rounds);
  ratio_row<kOrient3d, AdaptiveKernel>("orient3d", rounds);
  ratio_row<kOrient3d, AdaptiveStatic>("orient3d", rounds);
  ratio_row<kInsphere, AdaptiveKernel>("insphere", rounds);
  return 0;
}

template <class K>
int tight_kernel(Pred pred, Set set, int passes) {
  switch (pred) {
    case kOrient2d: return run_tight<K, kOrient2d>(set, passes);
    case kIncircle: return run_tight<K, kIncircle>(set, passes);
    case kOrient3d: return run_tight<K, kOrient3d>(set, passes);
    case kInsphere: return run_tight<K, kInsphere>(set, passes);
  }
  return 1;
}

// spec = PRED/KERNEL[/PASSES[/SET]], e.g. orient3d/adaptive/200/random.
int tight(const std::string& spec) {
  std::vector<std::string> f;
  std::size_t at = 0;
  while (true) {
    const std::size_t slash = spec.find('/', at);
    f.push_back(spec.substr(at, slash - at));
    if (slash == std::string::npos) break;
    at = slash + 1;
  }
  const char* preds[] = {"orient2d", "incircle", "orient3d", "insphere"};
  int pi = -1;
  for (int j = 0; j < 4; ++j)
    if (f[0] == preds[j]) pi = j;
  const int passes = f.size() > 2 ? std::stoi(f[2]) : 200;
  const Set set = (f.size() > 3 && f[3] == "degenerate") ? kDegenerate : kRandom;
  if (pi < 0 || f.size() < 2 || passes < 1) {
    std::fprintf(stderr, "bad --dlab_tight=%s\n", spec.c_str());
    return 2;
  }
  const Pred pred = static_cast<Pred>(pi);
  if (f[1] == "float") return tight_kernel<FloatKernel>(pred, set, passes);
  if (f[1] == "adaptive") return tight_kernel<AdaptiveKernel>(pred, set, passes);
  if (f[1] == "adaptive-static") return tight_kernel<AdaptiveStatic>(pred, set, passes);
  std::fprintf(stderr, "--dlab_tight: kernel must be float, adaptive or adaptive-static\n");
  return 2;
}

template <class K>
void register_kernel() {
  const char* preds[] = {"orient2d", "incircle", "orient3d", "insphere"};
  const char* sets[] = {"random", "degenerate"};
  for (int s = 0; s < 2; ++s) {
    const std::string tail = std::string("/") + std::string(K::name) + "/" + sets[s];
    const Set set = static_cast<Set>(s);
    benchmark::RegisterBenchmark((preds[0] + tail).c_str(), bench<K, kOrient2d>, set);
    benchmark::RegisterBenchmark((preds[1] + tail).c_str(), bench<K, kIncircle>, set);
    benchmark::RegisterBenchmark((preds[2] + tail).c_str(), bench<K, kOrient3d>, set);
    benchmark::RegisterBenchmark((preds[3] + tail).c_str(), bench<K, kInsphere>, set);
  }
}

}  // namespace

int main(int argc, char** argv) {
  for (int j = 1; j < argc; ++j) {
    const std::string a = argv[j];
    if (a.rfind("--dlab_tight=", 0) == 0) return tight(a.substr(13));
    if (a.rfind("--dlab_ratio=", 0) == 0) return ratio(a.substr(13));
  }
  register_kernel<FloatKernel>();
  register_kernel<AdaptiveKernel>();
  register_kernel<AdaptiveStatic>();
  register_kernel<MpKernel>();
  register_kernel<EpsilonKernel>();
  register_kernel<IntegerKernel>();
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
