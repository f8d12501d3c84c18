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
// The run_engine lines compare the exact specular's closed form (integer m) with its adaptive form.
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
  SpecularOptions base_spec{SpecularMethod::kExact};
  base_spec.exact_tolerance = 1e-12;
  LinearDiffuseOptions base_diff;
  base_diff.force_quadrature = true;
  base_diff.quadrature_tolerance = 1e-14;
  for (size_t i = 0; i < cases.size(); ++i) {
    const Response<T> r = shade_linear(lights[i], points[i], spec, diff);
    const LinearLight<double> ld{static_cast<Vec3d>(lights[i].q0), static_cast<Vec3d>(lights[i].q1), falloff};
    const ShadingPoint<double> pd{static_cast<Vec3d>(points[i].p), static_cast<Vec3d>(points[i].n),
                                  static_cast<Vec3d>(points[i].rv), double(points[i].shininess)};
    const Response<double> b = shade_linear(ld, pd, base_spec, base_diff);
    value.push_back(kind == Kind::kDiffuse ? double(r.diffuse) : double(r.specular));
    base.push_back(kind == Kind::kDiffuse ? b.diffuse : b.specular);
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

// The exact specular's two engines on the same cases with integer m log-uniform in [m_lo, m_hi]
// (the random set above otherwise): the closed form where its bound holds, else adaptive
// (linear_specular_exact_dispatch, what `--specular exact` runs), and the adaptive form alone
// (linear_specular_exact_frame, tolerance 1e-9). Both on the frame set up in long double, timed
// with it. Errors against the adaptive form at tolerance 1e-12; closed_fraction = the share of
// cases the closed form answers. The closed_forced lines time the recurrence alone on every case,
// accepted or not (their errors include the refused cases: they show why the bound is needed).
enum class Engine { kDispatch, kAdaptive, kClosedForced };

void run_engine(benchmark::State& state, Engine engine, double m_lo, double m_hi) {
  std::vector<Case> cases = make_cases(2.0);
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u01(0, 1);
  for (Case& c : cases)
    c.sp.shininess = std::round(std::pow(10.0, std::log10(m_lo) + (std::log10(m_hi) - std::log10(m_lo)) * u01(rng)));
  auto eval = [engine](const Case& c) {
    const LinearFrame<double> fr = make_linear_frame_precise(c.light, c.sp);
    if (engine == Engine::kClosedForced) return linear_specular_closed_frame(fr, int(c.sp.shininess)).value;
    return engine == Engine::kDispatch ? linear_specular_exact_dispatch(fr, c.sp.shininess, 1e-9)
                                       : linear_specular_exact_frame(fr, c.sp.shininess, 1e-9);
  };
  for (auto _ : state)
    for (const Case& c : cases) benchmark::DoNotOptimize(eval(c));
  state.SetItemsProcessed(int64_t(state.iterations()) * int64_t(cases.size()));
  std::vector<double> value, base;
  int closed = 0;
  for (const Case& c : cases) {
    const LinearFrame<double> fr = make_linear_frame_precise(c.light, c.sp);
    value.push_back(eval(c));
    base.push_back(linear_specular_exact_frame(fr, c.sp.shininess, 1e-12));
    if (linear_specular_closed_frame(fr, int(c.sp.shininess)).accepted) ++closed;
  }
  report_errors(state, value, base);
  state.counters["closed_fraction"] = engine == Engine::kAdaptive ? 0.0 : double(closed) / double(cases.size());
}

}  // namespace

BENCHMARK_CAPTURE(run_engine, specular_exact_int_m_1_100_closed_or_adaptive, Engine::kDispatch, 1.0, 100.0);
BENCHMARK_CAPTURE(run_engine, specular_exact_int_m_1_100_adaptive_only, Engine::kAdaptive, 1.0, 100.0);
BENCHMARK_CAPTURE(run_engine, specular_exact_int_m_1_100_closed_forced, Engine::kClosedForced, 1.0, 100.0);
BENCHMARK_CAPTURE(run_engine, specular_exact_int_m_100_1e4_closed_forced, Engine::kClosedForced, 100.0, 1e4);
BENCHMARK_CAPTURE(run_engine, specular_exact_int_m_100_1e4_closed_or_adaptive, Engine::kDispatch, 100.0, 1e4);
BENCHMARK_CAPTURE(run_engine, specular_exact_int_m_100_1e4_adaptive_only, Engine::kAdaptive, 100.0, 1e4);
// Where the closed form's O(m) recurrence stops paying (kLinearClosedDispatchMaxShininess): what
// `exact` runs (the dispatch: closed form, or adaptive where it is refused, up to the cap) and the
// recurrence alone on every case, against the adaptive form alone, at one m.
BENCHMARK_CAPTURE(run_engine, specular_exact_m_100_closed_or_adaptive, Engine::kDispatch, 100.0, 100.0);
BENCHMARK_CAPTURE(run_engine, specular_exact_m_100_adaptive_only, Engine::kAdaptive, 100.0, 100.0);
BENCHMARK_CAPTURE(run_engine, specular_exact_m_300_closed_or_adaptive, Engine::kDispatch, 300.0, 300.0);
BENCHMARK_CAPTURE(run_engine, specular_exact_m_300_adaptive_only, Engine::kAdaptive, 300.0, 300.0);
BENCHMARK_CAPTURE(run_engine, specular_exact_m_1000_closed_or_adaptive, Engine::kDispatch, 1000.0, 1000.0);
BENCHMARK_CAPTURE(run_engine, specular_exact_m_1000_adaptive_only, Engine::kAdaptive, 1000.0, 1000.0);
BENCHMARK_CAPTURE(run_engine, specular_exact_m_1000_closed_forced, Engine::kClosedForced, 1000.0, 1000.0);
BENCHMARK_CAPTURE(run_engine, specular_exact_m_3000_closed_forced, Engine::kClosedForced, 3000.0, 3000.0);
BENCHMARK_CAPTURE(run_engine, specular_exact_m_3000_adaptive_only, Engine::kAdaptive, 3000.0, 3000.0);
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
