// pso_bench: wall time and final cost of Strider's particle swarm
// (kinematics/pso.h) on seed 003's problem, for the side-by-side comparison
// with pyswarms (tools/pso_bench/pso_compare.py, docs/results.md).
//
// Seed 003 (section 4, table 3): a 2-joint leg, a1 = a2 = 70 mm, cost = the
// distance of FK(q) to the target (eq 15), swarm 20, 1000 iterations,
// c1 = c2 = 1.5, w = 0.5. Two readings of its bounds (docs/kinematics.md,
// test/chain/test_pso.cpp):
//   a: bounds 0..20 rad, target (100, 0) mm: the numbers the paper printed;
//   b: bounds 0..20 deg, target FK(13.34156399 deg, 17.29916917 deg): its intent.
//
// The cost, in double, two ways (docs/results.md shows both):
//   each:  ParticleSwarm::minimize, one call per particle, libm's sin and cos;
//   swarm: ParticleSwarm::minimize_swarm, one call per iteration for the whole
//          swarm, as pyswarms calls its numpy cost; sin and cos four (AVX2) or
//          two (SSE2) particles at a time from glibc's vector math library
//          (libmvec, max 4 ulp) where it is linked, else as `each`.
// Float and fixed point run the library's own math per particle (as the
// firmware would).
//
// usage: pso_bench [--runs N] [--seed N] [--iterations N] [--case a|b|all]
//                  [--scalar double|float|fixed|all] [--cost each|swarm|all]
// Seeds are N, N + 1, ... (default 1).
// Output: one JSON object per case and scalar on stdout; times are medians
// of thread CPU time ("median_ms", "median_ms_to_1e-6") and of wall time
// ("median_wall_ms", ...), after one untimed warm-up run. Exit 1 when a run
// misses the cost bound of its scalar (so a smoke test can fail).
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <type_traits>
#include <vector>

#include <time.h>

#include "kinematics/pso.h"

#if defined(STRIDER_HAVE_LIBMVEC) && defined(__x86_64__)
#include <immintrin.h>
extern "C" __m128d _ZGVbN2v_sin(__m128d);  // libmvec, SSE2 (any x86-64)
extern "C" __m128d _ZGVbN2v_cos(__m128d);
#pragma GCC push_options
#pragma GCC target("avx2")
extern "C" __m256d _ZGVdN4v_sin(__m256d);  // libmvec, AVX2
extern "C" __m256d _ZGVdN4v_cos(__m256d);
#pragma GCC pop_options
#define STRIDER_PSO_BENCH_SIMD 1
#endif

namespace {

using strider::Fixed;
using strider::JointVector;
using strider::ParticleSwarm;
using strider::PsoParams;
using strider::PsoResult;
using strider::Vec3;

constexpr double kPi = 3.14159265358979323846;
constexpr double kLinkMm = 70.0;
constexpr double kSeedT1Deg = 13.34156399, kSeedT2Deg = 17.29916917;
constexpr double kTargetCostMm = 1e-6;  // "converged" for the time-to-target figure

struct Case {
  const char* name;
  const char* what;
  double hi;  // upper bound of both joints [rad]
  double tx, tz;
};

Case make_case(char c) {
  if (c == 'a') return {"a", "bounds 0..20 rad, target (100, 0) mm", 20.0, 100.0, 0.0};
  const double t1 = kSeedT1Deg * kPi / 180.0, t2 = kSeedT2Deg * kPi / 180.0;
  return {"b", "bounds 0..20 deg, target FK(13.34156399, 17.29916917 deg)", 20.0 * kPi / 180.0,
          kLinkMm * (std::cos(t1) + std::cos(t1 + t2)), kLinkMm * (std::sin(t1) + std::sin(t1 + t2))};
}

// Eq 3 and eq 15 in double: the same arithmetic numpy does for pyswarms.
struct CostDouble {
  double tx, tz;
  double operator()(const JointVector<double, 2>& q) const {
    const double x = kLinkMm * std::cos(q[0]) + kLinkMm * std::cos(q[0] + q[1]);
    const double z = kLinkMm * std::sin(q[0]) + kLinkMm * std::sin(q[0] + q[1]);
    return std::sqrt((x - tx) * (x - tx) + (z - tz) * (z - tz));
  }
};

// The same cost for the whole swarm at once, on joint arrays padded to
// kPad (structure of arrays, as numpy holds the swarm's columns).
constexpr int kPad = 24;

#ifdef STRIDER_PSO_BENCH_SIMD
void fk_cost_sse2(const double* a, const double* b, int n, double tx, double tz, double* c) {
  const __m128d l = _mm_set1_pd(kLinkMm), vtx = _mm_set1_pd(tx), vtz = _mm_set1_pd(tz);
  for (int i = 0; i < n; i += 2) {
    const __m128d q0 = _mm_load_pd(a + i), q01 = _mm_add_pd(q0, _mm_load_pd(b + i));
    const __m128d dx = _mm_sub_pd(
        _mm_add_pd(_mm_mul_pd(l, _ZGVbN2v_cos(q0)), _mm_mul_pd(l, _ZGVbN2v_cos(q01))), vtx);
    const __m128d dz = _mm_sub_pd(
        _mm_add_pd(_mm_mul_pd(l, _ZGVbN2v_sin(q0)), _mm_mul_pd(l, _ZGVbN2v_sin(q01))), vtz);
    _mm_store_pd(c + i, _mm_sqrt_pd(_mm_add_pd(_mm_mul_pd(dx, dx), _mm_mul_pd(dz, dz))));
  }
}

#pragma GCC push_options
#pragma GCC target("avx2")
void fk_cost_avx2(const double* a, const double* b, int n, double tx, double tz, double* c) {
  const __m256d l = _mm256_set1_pd(kLinkMm), vtx = _mm256_set1_pd(tx), vtz = _mm256_set1_pd(tz);
  for (int i = 0; i < n; i += 4) {
    const __m256d q0 = _mm256_load_pd(a + i), q01 = _mm256_add_pd(q0, _mm256_load_pd(b + i));
    const __m256d dx = _mm256_sub_pd(
        _mm256_add_pd(_mm256_mul_pd(l, _ZGVdN4v_cos(q0)), _mm256_mul_pd(l, _ZGVdN4v_cos(q01))), vtx);
    const __m256d dz = _mm256_sub_pd(
        _mm256_add_pd(_mm256_mul_pd(l, _ZGVdN4v_sin(q0)), _mm256_mul_pd(l, _ZGVdN4v_sin(q01))), vtz);
    _mm256_store_pd(c + i, _mm256_sqrt_pd(_mm256_add_pd(_mm256_mul_pd(dx, dx), _mm256_mul_pd(dz, dz))));
  }
}
#pragma GCC pop_options
#else
void fk_cost_scalar(const double* a, const double* b, int n, double tx, double tz, double* c) {
  for (int i = 0; i < n; ++i) c[i] = CostDouble{tx, tz}(JointVector<double, 2>{{a[i], b[i]}});
}
#endif

using FkCostFn = void (*)(const double*, const double*, int, double, double, double*);

FkCostFn pick_fk_cost(const char** what) {
#ifdef STRIDER_PSO_BENCH_SIMD
  if (__builtin_cpu_supports("avx2")) {
    *what = "libmvec AVX2, 4 lanes";
    return fk_cost_avx2;
  }
  *what = "libmvec SSE2, 2 lanes";
  return fk_cost_sse2;
#else
  *what = "libm, no vector math library";
  return fk_cost_scalar;
#endif
}

struct SwarmCostDouble {
  double tx, tz;
  FkCostFn fn;
  void operator()(const JointVector<double, 2>* q, uint8_t n, double* c) const {
    alignas(32) double a[kPad] = {}, b[kPad] = {}, out[kPad];
    for (uint8_t i = 0; i < n; ++i) {
      a[i] = q[i][0];
      b[i] = q[i][1];
    }
    fn(a, b, n, tx, tz, out);
    for (uint8_t i = 0; i < n; ++i) c[i] = out[i];
  }
};

// The library's own scalar math (float or Fixed), as the firmware runs it.
template <typename S>
struct CostLib {
  Vec3<S> target;
  S operator()(const JointVector<S, 2>& q) const {
    const S a = strider::scalar<S>(kLinkMm);
    const Vec3<S> foot(a * strider::cos(q[0]) + a * strider::cos(q[0] + q[1]), S(0),
                       a * strider::sin(q[0]) + a * strider::sin(q[0] + q[1]));
    return strider::units::distance(foot, target);
  }
};

template <typename S>
struct Traits;
template <>
struct Traits<double> {
  static const char* name() { return "double"; }
  static double bound_mm() { return 1e-6; }
  static CostDouble cost(const Case& c) { return CostDouble{c.tx, c.tz}; }
};
static_assert(kPad >= 20 + 3, "the swarm's 20 particles, padded to whole AVX2 vectors");
template <>
struct Traits<float> {
  static const char* name() { return "float"; }
  static double bound_mm() { return 5e-4; }  // float ulp near 20 rad (test_pso.cpp)
  static CostLib<float> cost(const Case& c) {
    return CostLib<float>{Vec3<float>(float(c.tx), 0.0f, float(c.tz))};
  }
};
template <>
struct Traits<Fixed> {
  static const char* name() { return "fixed"; }
  static double bound_mm() { return 0.05; }  // Q16.16 trig on 70 mm links (test_pso.cpp)
  static CostLib<Fixed> cost(const Case& c) { return CostLib<Fixed>{Vec3<Fixed>(Fixed(c.tx), Fixed(0), Fixed(c.tz))}; }
};

double to_d(double v) { return v; }
double to_d(float v) { return double(v); }
double to_d(Fixed v) { return v.to_double(); }

// Thread CPU time [ms]: what the run itself cost, without the time other
// processes held the core (pso_compare.py times pyswarms the same way; under
// load a 10 ms pyswarms run is preempted far more often than a 0.1 ms one,
// so wall time would skew the ratio).
double cpu_ms() {
  timespec ts;
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return double(ts.tv_sec) * 1e3 + double(ts.tv_nsec) * 1e-6;
}

double wall_ms() {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

// One timed call: CPU and wall time [ms].
struct Timed {
  double cpu = 0, wall = 0;
};
template <typename F>
Timed timed(F&& f) {
  const double c0 = cpu_ms(), w0 = wall_ms();
  f();
  const double w1 = wall_ms(), c1 = cpu_ms();
  return Timed{c1 - c0, w1 - w0};
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

// minimize() with the per-particle cost, or (swarm = true, double only)
// minimize_swarm() with the vectorised one.
template <typename S>
struct Solver {
  const Case& c;
  bool swarm_cost;
  PsoResult<S, 2> operator()(ParticleSwarm<S, 2, 20>& swarm, const PsoParams<S, 2>& p) const {
    return swarm.minimize(p, Traits<S>::cost(c));
  }
};
template <>
PsoResult<double, 2> Solver<double>::operator()(ParticleSwarm<double, 2, 20>& swarm,
                                                const PsoParams<double, 2>& p) const {
  if (!swarm_cost) return swarm.minimize(p, Traits<double>::cost(c));
  const char* what = nullptr;
  static const FkCostFn fn = pick_fk_cost(&what);
  return swarm.minimize_swarm(p, SwarmCostDouble{c.tx, c.tz, fn});
}

template <typename S>
bool run(const Case& c, int runs, int first_seed, int iterations, bool swarm_cost) {
  static ParticleSwarm<S, 2, 20> swarm;
  const Solver<S> solve{c, swarm_cost};
  const char* cost_what = "the library's math";
  if (std::is_same<S, double>::value) {
    cost_what = "libm";
    if (swarm_cost) pick_fk_cost(&cost_what);
  }
  std::vector<double> ms, wall, costs, ms_to, wall_to, it_to;
  double best = 1e300;
  JointVector<double, 2> best_q{{0, 0}};
  int reached = 0;
  auto params = [&](int r) {
    PsoParams<S, 2> p;  // table 3 defaults
    p.set_bounds(S(0), S(c.hi));
    p.max_iterations = uint16_t(iterations);
    p.seed = uint32_t(first_seed + r);
    return p;
  };
  {  // warm-up, untimed: page faults, lazy binding of libm, caches
    const PsoParams<S, 2> p = params(runs);
    volatile double sink = to_d(solve(swarm, p).cost);
    (void)sink;
  }
  for (int r = 0; r < runs; ++r) {
    PsoParams<S, 2> p = params(r);
    PsoResult<S, 2> res;
    const Timed t = timed([&] { res = solve(swarm, p); });
    ms.push_back(t.cpu);
    wall.push_back(t.wall);
    costs.push_back(to_d(res.cost));
    if (to_d(res.cost) < best) {
      best = to_d(res.cost);
      best_q = JointVector<double, 2>{{to_d(res.position[0]), to_d(res.position[1])}};
    }
    // The same seed again, stopping at the target cost: time to converge.
    if (Traits<S>::bound_mm() <= kTargetCostMm) {
      p.cost_threshold = S(kTargetCostMm);
      PsoResult<S, 2> early;
      const Timed te = timed([&] { early = solve(swarm, p); });
      if (early.status == strider::PsoStatus::kConverged) {
        ++reached;
        ms_to.push_back(te.cpu);
        wall_to.push_back(te.wall);
        it_to.push_back(early.iterations);
      }
    }
  }
  const double worst = *std::max_element(costs.begin(), costs.end());
  std::printf("{\"impl\":\"strider\",\"scalar\":\"%s\",\"cost\":\"%s\",\"cost_math\":\"%s\",\"case\":\"%s\","
              "\"problem\":\"%s\",\"runs\":%d,\"first_seed\":%d,\"swarm\":20,\"iterations\":%d,\"median_ms\":%.5g,\"min_ms\":%.5g,\"max_ms\":%.5g,"
              "\"median_wall_ms\":%.5g,\"median_cost_mm\":%.3g,\"worst_cost_mm\":%.3g,"
              "\"best_joints_deg\":[%.8f,%.8f]",
              Traits<S>::name(), swarm_cost ? "swarm" : "each", cost_what, c.name, c.what, runs, first_seed,
              iterations, median(ms),
              *std::min_element(ms.begin(), ms.end()), *std::max_element(ms.begin(), ms.end()), median(wall),
              median(costs), worst, best_q[0] * 180.0 / kPi, best_q[1] * 180.0 / kPi);
  if (!ms_to.empty())
    std::printf(",\"reached_1e-6\":%d,\"median_iterations_to_1e-6\":%.4g,\"median_ms_to_1e-6\":%.5g,"
                "\"min_ms_to_1e-6\":%.5g,\"median_wall_ms_to_1e-6\":%.5g",
                reached, median(it_to), median(ms_to), *std::min_element(ms_to.begin(), ms_to.end()),
                median(wall_to));
  std::printf("}\n");
  std::fflush(stdout);
  // A run may stall on a bound (pso.h: 0.35 % of seeds for case a), so
  // the median, not the worst, must meet the scalar's bound.
  return median(costs) < Traits<S>::bound_mm();
}

int usage() {
  std::fprintf(stderr,
               "usage: pso_bench [--runs N] [--seed N] [--iterations N] [--case a|b|all]"
               " [--scalar double|float|fixed|all] [--cost each|swarm|all]\n");
  return 2;
}

}  // namespace

int main(int argc, char** argv) {
  int runs = 21, first_seed = 1, iterations = 1000;
  std::string which_case = "all", which_scalar = "all", which_cost = "all";
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (i + 1 >= argc) return usage();
    const std::string v = argv[++i];
    if (a == "--runs") runs = std::atoi(v.c_str());
    else if (a == "--seed") first_seed = std::atoi(v.c_str());
    else if (a == "--iterations") iterations = std::atoi(v.c_str());
    else if (a == "--case") which_case = v;
    else if (a == "--scalar") which_scalar = v;
    else if (a == "--cost") which_cost = v;
    else return usage();
  }
  if (runs < 1 || first_seed < 1 || iterations < 1 || iterations > 65535) return usage();
  if (which_cost != "all" && which_cost != "each" && which_cost != "swarm") return usage();
  bool ok = true;
  for (char cn : {'a', 'b'}) {
    if (which_case != "all" && which_case != std::string(1, cn)) continue;
    const Case c = make_case(cn);
    if (which_scalar == "all" || which_scalar == "double") {
      if (which_cost != "swarm") ok = run<double>(c, runs, first_seed, iterations, false) && ok;
      if (which_cost != "each") ok = run<double>(c, runs, first_seed, iterations, true) && ok;
    }
    if (which_scalar == "all" || which_scalar == "float") ok = run<float>(c, runs, first_seed, iterations, false) && ok;
    if (which_scalar == "all" || which_scalar == "fixed") ok = run<Fixed>(c, runs, first_seed, iterations, false) && ok;
  }
  return ok ? 0 : 1;
}
