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
#include <benchmark/benchmark.h>

#include <array>
#include <cmath>
#include <cstdint>
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

template <class K>
int call(const K& k, Pred pred, const Call& c) {
  switch (pred) {
    case kOrient2d: return to_int(k.orient2d(xy(c[0]), xy(c[1]), xy(c[2])));
    case kIncircle: return to_int(k.incircle(xy(c[0]), xy(c[1]), xy(c[2]), xy(c[3])));
    case kOrient3d: return to_int(k.orient3d(c[0], c[1], c[2], c[3]));
    case kInsphere: return to_int(k.insphere(c[0], c[1], c[2], c[3], c[4]));
  }
  return 0;
}

Staged staged(Pred pred, const Call& c) {
  switch (pred) {
    case kOrient2d: return AdaptiveKernel::orient2d_staged(xy(c[0]), xy(c[1]), xy(c[2]));
    case kIncircle: return AdaptiveKernel::incircle_staged(xy(c[0]), xy(c[1]), xy(c[2]), xy(c[3]));
    case kOrient3d: return AdaptiveKernel::orient3d_staged(c[0], c[1], c[2], c[3]);
    case kInsphere: return AdaptiveKernel::insphere_staged(c[0], c[1], c[2], c[3], c[4]);
  }
  return {};
}

// The switch on `pred` is outside the timed loop: one instantiation per predicate.
template <class K, Pred P>
void bench(benchmark::State& state, Set set) {
  const std::vector<Call> calls = make_inputs(P, set);
  const K k{};
  std::size_t i = 0;
  int acc = 0;
  for (auto _ : state) {
    acc += call(k, P, calls[i]);
    i = (i + 1) & (kCalls - 1);
    benchmark::DoNotOptimize(acc);
  }
  if constexpr (std::is_same_v<K, AdaptiveKernel>) {
    std::array<int, 6> n{};
    for (const Call& c : calls) ++n[staged(P, c).stage];
    for (std::size_t s = 0; s < n.size(); ++s)
      if (n[s] > 0)
        state.counters[std::string("stage_") + std::string(AdaptiveKernel::stage_names[s])] =
            static_cast<double>(n[s]) / kCalls;
  }
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
  register_kernel<FloatKernel>();
  register_kernel<AdaptiveKernel>();
  register_kernel<MpKernel>();
  register_kernel<EpsilonKernel>();
  register_kernel<IntegerKernel>();
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
