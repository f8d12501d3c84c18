// Linear-light kernels: run time and error per method, from one process.
//
//   cmake --build build/linear --target linear_light_bench -j2 && ./build/linear/bench/linear_light_bench
//
// Each benchmark evaluates one method on the same 1024 seeded random configurations (log-uniform
// distance/length in [1e-3, 1e3], m log-uniform in [1, 1e3], normals biased towards the light) and
// reports, besides the time per evaluation, the mean and max relative error against a baseline:
// - diffuse methods against the forced quadrature at tolerance 1e-14 (checked against Boost.Math
//   references in tests/kernels/linear);
// - specular methods against the exact lobe integral at tolerance 1e-12. For the peak and the
//   neighbourhood this is the error of the paper's approximation itself (eq. 7-8), not a bug.
// Errors are relative to max(|baseline|, 1e-12 * max baseline over the set).
// The run_engine lines compare the exact specular's closed forms (the recurrence for integer m, the
// incomplete-beta form for n = 2) with its adaptive form.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "linear_light.h"

namespace {

using namespace vlit;

struct Case {
  LinearLight<double> light;
  ShadingPoint<double> sp;
};

Vec3d random_unit(std::mt19937_64& rng) {
  std::normal_distribution<double> g;
  for (;;) {
    const Vec3d v{g(rng), g(rng), g(rng)};
    if (length(v) > 1e-3) return normalize(v);
  }
}

std::vector<Case> make_cases(double falloff) {
  std::mt19937_64 rng(42);
  std::uniform_real_distribution<double> u01(0, 1);
  auto log_uniform = [&](double lo, double hi) { return std::pow(10.0, lo + (hi - lo) * u01(rng)); };
  std::vector<Case> cases;
  for (int i = 0; i < 1024; ++i) {
    const double len = 1 / log_uniform(-3, 3);
    const Vec3d centre = random_unit(rng), dir = random_unit(rng);
    Case c;
    c.light = {centre - dir * (0.5 * len), centre + dir * (0.5 * len), falloff};
    c.sp.p = {0, 0, 0};
    c.sp.n = normalize(centre + random_unit(rng) * 0.7);
    c.sp.rv = normalize(centre + random_unit(rng) * 0.3);
    c.sp.shininess = log_uniform(0, 3);
    cases.push_back(c);
  }
  return cases;
}

enum class Kind { kDiffuse, kSpecular };

void report_errors(benchmark::State& state, const std::vector<double>& value, const std::vector<double>& base) {
  double max_base = 0;
  for (double b : base) max_base = std::max(max_base, std::fabs(b));
  double sum = 0, worst = 0;
  for (size_t i = 0; i < value.size(); ++i) {
    const double e = std::fabs(value[i] - base[i]) / std::max(std::fabs(base[i]), 1e-12 * max_base);
    sum += e;
    worst = std::max(worst, e);
  }
  state.counters["mean_rel_err"] = sum / double(value.size());
  state.counters["max_rel_err"] = worst;
}

template <class T>
void run(benchmark::State& state, Kind kind, double falloff, SpecularOptions spec, LinearDiffuseOptions diff) {
  const std::vector<Case> cases = make_cases(falloff);
  std::vector<LinearLight<T>> lights;
  std::vector<ShadingPoint<T>> points;
  for (const Case& c : cases) {
    lights.push_back({static_cast<Vec3<T>>(c.light.q0), static_cast<Vec3<T>>(c.light.q1), T(falloff)});
    points.push_back({static_cast<Vec3<T>>(c.sp.p), static_cast<Vec3<T>>(c.sp.n), static_cast<Vec3<T>>(c.sp.rv),
                      T(c.sp.shininess)});
  }
  for (auto _ : state) {
    for (size_t i = 0; i < cases.size(); ++i) benchmark::DoNotOptimize(shade_linear(lights[i], points[i], spec, diff));
  }
  state.SetItemsProcessed(int64_t(state.iterations()) * int64_t(cases.size()));
  // Errors, outside the timed loop; the baseline is computed in double from the same inputs.
  std::vector<double> value, base;
  const SpecularOptions base_spec{SpecularMethod::kNone};
  LinearDiffuseOptions base_diff;
  base_diff.force_quadrature = true;
  base_diff.quadrature_tolerance = 1e-14;
  for (size_t i = 0; i < cases.size(); ++i) {
    const Response<T> r = shade_linear(lights[i], points[i], spec, diff);
    const LinearLight<double> ld{static_cast<Vec3d>(lights[i].q0), static_cast<Vec3d>(lights[i].q1), falloff};
    const ShadingPoint<double> pd{static_cast<Vec3d>(points[i].p), static_cast<Vec3d>(points[i].n),
                                  static_cast<Vec3d>(points[i].rv), double(points[i].shininess)};
    // The specular's baseline is the adaptive form itself (the dispatch would pick a closed form).
    const double b = kind == Kind::kDiffuse ? shade_linear(ld, pd, base_spec, base_diff).diffuse
                                            : linear_specular_exact(ld, pd, 1e-12, spec.falloff);
    value.push_back(kind == Kind::kDiffuse ? double(r.diffuse) : double(r.specular));
    base.push_back(b);
  }
  report_errors(state, value, base);
}

const SpecularOptions kNoSpec{SpecularMethod::kNone};
const LinearDiffuseOptions kClosed{};
LinearDiffuseOptions forced() { LinearDiffuseOptions o; o.force_quadrature = true; return o; }
SpecularOptions spec(SpecularMethod m, int k = 4, double tol = 1e-9) {
  SpecularOptions o;
  o.method = m;
  o.neighborhood_samples = k;
  o.exact_tolerance = tol;
  return o;
}

void run_d(benchmark::State& s, Kind k, double n, SpecularOptions sp, LinearDiffuseOptions d) { run<double>(s, k, n, sp, d); }
void run_f(benchmark::State& s, Kind k, double n, SpecularOptions sp, LinearDiffuseOptions d) { run<float>(s, k, n, sp, d); }

// The exact specular's engines on the same cases with m log-uniform in [m_lo, m_hi] (rounded to
// integers unless `real_m`; the random set above otherwise), falloff n on the specular (0: the
// paper's form; 2: the default definition), all on the frame set up in long double, timed with it:
// - dispatch: linear_specular_exact_dispatch, what `--specular exact` runs (n = 2: the recurrence
//   where its bound holds up to kLinearRecurrenceMaxShininess, the incomplete-beta form where its
//   bound holds, the adaptive form for the rest; n = 0: the recurrence or the adaptive form);
// - recurrence_or_adaptive: the dispatch before the incomplete-beta form, as a baseline in the
//   same process (the recurrence for integer m <= kLinearClosedDispatchMaxShininess where its bound
//   holds, else the adaptive form);
// - adaptive_only: linear_specular_exact_frame at tolerance 1e-9;
// - closed_forced / beta_forced: the recurrence (integer m) or the incomplete-beta form alone on
//   every case, accepted or not (their errors include the refused cases: why the bounds are needed).
// Errors against the adaptive form at tolerance 1e-12; closed_fraction / beta_fraction = the share
// of cases each form accepts.
enum class Engine { kDispatch, kRecurrenceOrAdaptive, kAdaptive, kClosedForced, kBetaForced };

void run_engine(benchmark::State& state, Engine engine, double m_lo, double m_hi, int n, bool real_m) {
  std::vector<Case> cases = make_cases(double(n));
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u01(0, 1);
  for (Case& c : cases) {
    const double m = std::pow(10.0, std::log10(m_lo) + (std::log10(m_hi) - std::log10(m_lo)) * u01(rng));
    c.sp.shininess = real_m ? m : std::round(m);
  }
  const double nf = double(n);
  auto eval = [engine, n, nf](const Case& c) {
    const LinearFrame<double> fr = make_linear_frame_precise(c.light, c.sp);
    const double m = c.sp.shininess;
    switch (engine) {
      case Engine::kDispatch: return linear_specular_exact_dispatch(fr, m, 1e-9, nf);
      case Engine::kRecurrenceOrAdaptive:
        if (m == std::floor(m) && m <= kLinearClosedDispatchMaxShininess) {
          const LinearSpecularClosed<double> k = linear_specular_closed_frame(fr, int(m), n);
          if (k.accepted) return k.value;
        }
        return linear_specular_exact_frame(fr, m, 1e-9, nf);
      case Engine::kAdaptive: return linear_specular_exact_frame(fr, m, 1e-9, nf);
      case Engine::kClosedForced: return linear_specular_closed_frame(fr, int(m), n).value;
      case Engine::kBetaForced: return linear_specular_beta_frame(fr, m).value;
    }
    return 0.0;
  };
  for (auto _ : state)
    for (const Case& c : cases) benchmark::DoNotOptimize(eval(c));
  state.SetItemsProcessed(int64_t(state.iterations()) * int64_t(cases.size()));
  std::vector<double> value, base;
  int closed = 0, beta = 0;
  for (const Case& c : cases) {
    const LinearFrame<double> fr = make_linear_frame_precise(c.light, c.sp);
    const double m = c.sp.shininess;
    value.push_back(eval(c));
    base.push_back(linear_specular_exact_frame(fr, m, 1e-12, nf));
    if (m == std::floor(m) && linear_specular_closed_frame(fr, int(m), n).accepted) ++closed;
    if (n == 2 && linear_specular_beta_frame(fr, m).accepted) ++beta;
  }
  report_errors(state, value, base);
  state.counters["closed_fraction"] = double(closed) / double(cases.size());
  if (n == 2) state.counters["beta_fraction"] = double(beta) / double(cases.size());
}

}  // namespace

// n = 0 (the paper's form, `--specular exact-no-falloff`): the recurrence or the adaptive form.
BENCHMARK_CAPTURE(run_engine, specular_exact_n0_int_m_1_100_closed_or_adaptive, Engine::kDispatch, 1.0, 100.0, 0, false);
BENCHMARK_CAPTURE(run_engine, specular_exact_n0_int_m_1_100_adaptive_only, Engine::kAdaptive, 1.0, 100.0, 0, false);
BENCHMARK_CAPTURE(run_engine, specular_exact_n0_int_m_1_100_closed_forced, Engine::kClosedForced, 1.0, 100.0, 0, false);
BENCHMARK_CAPTURE(run_engine, specular_exact_n0_int_m_100_1e4_closed_forced, Engine::kClosedForced, 100.0, 1e4, 0, false);
BENCHMARK_CAPTURE(run_engine, specular_exact_n0_int_m_100_1e4_closed_or_adaptive, Engine::kDispatch, 100.0, 1e4, 0, false);
BENCHMARK_CAPTURE(run_engine, specular_exact_n0_int_m_100_1e4_adaptive_only, Engine::kAdaptive, 100.0, 1e4, 0, false);
// Where the recurrence's O(m) stops paying (kLinearClosedDispatchMaxShininess, n = 0).
BENCHMARK_CAPTURE(run_engine, specular_exact_n0_m_100_closed_or_adaptive, Engine::kDispatch, 100.0, 100.0, 0, false);
BENCHMARK_CAPTURE(run_engine, specular_exact_n0_m_100_adaptive_only, Engine::kAdaptive, 100.0, 100.0, 0, false);
BENCHMARK_CAPTURE(run_engine, specular_exact_n0_m_300_closed_or_adaptive, Engine::kDispatch, 300.0, 300.0, 0, false);
BENCHMARK_CAPTURE(run_engine, specular_exact_n0_m_300_adaptive_only, Engine::kAdaptive, 300.0, 300.0, 0, false);
BENCHMARK_CAPTURE(run_engine, specular_exact_n0_m_1000_closed_or_adaptive, Engine::kDispatch, 1000.0, 1000.0, 0, false);
BENCHMARK_CAPTURE(run_engine, specular_exact_n0_m_1000_adaptive_only, Engine::kAdaptive, 1000.0, 1000.0, 0, false);
BENCHMARK_CAPTURE(run_engine, specular_exact_n0_m_1000_closed_forced, Engine::kClosedForced, 1000.0, 1000.0, 0, false);
BENCHMARK_CAPTURE(run_engine, specular_exact_n0_m_3000_closed_forced, Engine::kClosedForced, 3000.0, 3000.0, 0, false);
BENCHMARK_CAPTURE(run_engine, specular_exact_n0_m_3000_adaptive_only, Engine::kAdaptive, 3000.0, 3000.0, 0, false);
// n = 2 (the default): the dispatch with the incomplete-beta form against the dispatch before it.
BENCHMARK_CAPTURE(run_engine, specular_exact_n2_int_m_1_100_dispatch, Engine::kDispatch, 1.0, 100.0, 2, false);
BENCHMARK_CAPTURE(run_engine, specular_exact_n2_int_m_1_100_recurrence_or_adaptive, Engine::kRecurrenceOrAdaptive, 1.0, 100.0, 2, false);
BENCHMARK_CAPTURE(run_engine, specular_exact_n2_int_m_1_100_adaptive_only, Engine::kAdaptive, 1.0, 100.0, 2, false);
BENCHMARK_CAPTURE(run_engine, specular_exact_n2_real_m_1_100_dispatch, Engine::kDispatch, 1.0, 100.0, 2, true);
BENCHMARK_CAPTURE(run_engine, specular_exact_n2_real_m_1_100_recurrence_or_adaptive, Engine::kRecurrenceOrAdaptive, 1.0, 100.0, 2, true);
BENCHMARK_CAPTURE(run_engine, specular_exact_n2_int_m_100_1e4_dispatch, Engine::kDispatch, 100.0, 1e4, 2, false);
BENCHMARK_CAPTURE(run_engine, specular_exact_n2_int_m_100_1e4_recurrence_or_adaptive, Engine::kRecurrenceOrAdaptive, 100.0, 1e4, 2, false);
BENCHMARK_CAPTURE(run_engine, specular_exact_n2_real_m_100_1e4_dispatch, Engine::kDispatch, 100.0, 1e4, 2, true);
BENCHMARK_CAPTURE(run_engine, specular_exact_n2_real_m_100_1e4_adaptive_only, Engine::kAdaptive, 100.0, 1e4, 2, true);
// Where the W recurrence stops paying against the incomplete-beta form (kLinearRecurrenceMaxShininess).
BENCHMARK_CAPTURE(run_engine, specular_exact_n2_m_10_closed_forced, Engine::kClosedForced, 10.0, 10.0, 2, false);
BENCHMARK_CAPTURE(run_engine, specular_exact_n2_m_10_beta_forced, Engine::kBetaForced, 10.0, 10.0, 2, false);
BENCHMARK_CAPTURE(run_engine, specular_exact_n2_m_30_closed_forced, Engine::kClosedForced, 30.0, 30.0, 2, false);
BENCHMARK_CAPTURE(run_engine, specular_exact_n2_m_30_beta_forced, Engine::kBetaForced, 30.0, 30.0, 2, false);
BENCHMARK_CAPTURE(run_engine, specular_exact_n2_m_100_closed_forced, Engine::kClosedForced, 100.0, 100.0, 2, false);
BENCHMARK_CAPTURE(run_engine, specular_exact_n2_m_100_beta_forced, Engine::kBetaForced, 100.0, 100.0, 2, false);
BENCHMARK_CAPTURE(run_engine, specular_exact_n2_m_300_closed_forced, Engine::kClosedForced, 300.0, 300.0, 2, false);
BENCHMARK_CAPTURE(run_engine, specular_exact_n2_m_300_beta_forced, Engine::kBetaForced, 300.0, 300.0, 2, false);
BENCHMARK_CAPTURE(run_engine, specular_exact_n2_m_1000_closed_forced, Engine::kClosedForced, 1000.0, 1000.0, 2, false);
BENCHMARK_CAPTURE(run_engine, specular_exact_n2_m_1000_beta_forced, Engine::kBetaForced, 1000.0, 1000.0, 2, false);
BENCHMARK_CAPTURE(run_d, diffuse_closed_n2_double, Kind::kDiffuse, 2.0, kNoSpec, kClosed);
BENCHMARK_CAPTURE(run_f, diffuse_closed_n2_float, Kind::kDiffuse, 2.0, kNoSpec, kClosed);
BENCHMARK_CAPTURE(run_d, diffuse_closed_n1_double, Kind::kDiffuse, 1.0, kNoSpec, kClosed);
BENCHMARK_CAPTURE(run_d, diffuse_quadrature_n2_tol1e10, Kind::kDiffuse, 2.0, kNoSpec, forced());
BENCHMARK_CAPTURE(run_d, diffuse_quadrature_n2p5_tol1e10, Kind::kDiffuse, 2.5, kNoSpec, kClosed);
BENCHMARK_CAPTURE(run_d, specular_peak, Kind::kSpecular, 2.0, spec(SpecularMethod::kPeak), kClosed);
BENCHMARK_CAPTURE(run_d, specular_neighborhood_k4, Kind::kSpecular, 2.0, spec(SpecularMethod::kNeighborhood), kClosed);
BENCHMARK_CAPTURE(run_d, specular_neighborhood_k16, Kind::kSpecular, 2.0, spec(SpecularMethod::kNeighborhood, 16), kClosed);
BENCHMARK_CAPTURE(run_d, specular_exact_tol1e9, Kind::kSpecular, 2.0, spec(SpecularMethod::kExact), kClosed);
BENCHMARK_CAPTURE(run_d, specular_exact_tol1e4, Kind::kSpecular, 2.0, spec(SpecularMethod::kExact, 4, 1e-4), kClosed);
BENCHMARK_CAPTURE(run_f, specular_exact_tol1e9_float, Kind::kSpecular, 2.0, spec(SpecularMethod::kExact), kClosed);

BENCHMARK_MAIN();
