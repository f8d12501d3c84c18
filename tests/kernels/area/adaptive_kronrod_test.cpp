// The adaptive Gauss-Kronrod driver of the exact specular kernels (adaptive_kronrod.h) on its own:
// integrands whose integrals are known in closed form, derived by hand (not by another quadrature).
#include <doctest/doctest.h>

#include <cmath>
#include <cstdio>

#include "adaptive_kronrod.h"

using namespace vlit;

namespace {

// eps / (t^2 + eps^2) on [-1, 1]: a peak of width eps at 0, integral 2 atan(1 / eps).
struct Peak {
  double eps;
  double operator()(int, double t) const { return eps / (t * t + eps * eps); }
};

}  // namespace

TEST_CASE("adaptive Gauss-Kronrod: a narrow peak in one piece is refined to its closed form") {
  for (const double eps : {1e-2, 1e-4, 1e-7}) {
    for (const double weight : {1.0, -3.0}) {
      const Peak f{eps};
      AdaptiveKronrod<double, 2048> quad;
      // One piece with the peak off its centre: the first K15 estimate is far off, only bisection helps.
      quad.add([&](double t) { return f(0, t); }, 0, -1.0, 1.3, weight);
      const double value = quad.refine(f, [&](int) { return weight; }, 1e-12);
      const double exact = weight * (std::atan(1.0 / eps) + std::atan(1.3 / eps));
      INFO("eps " << eps << " weight " << weight << ": " << value << " vs " << exact);
      CHECK(std::abs(value - exact) <= 1e-10 * std::abs(exact));
    }
  }
}

TEST_CASE("adaptive Gauss-Kronrod: graded cuts resolve a peak, a full work list stops the refinement") {
  const double eps = 1e-12;
  const Peak f{eps};
  const double exact = 2 * std::atan(1.0 / eps);
  // Cuts graded around the peak (centre near 0, width eps): 45 cut points, then bisection.
  const double centers[1] = {0.3e-13}, widths[1] = {eps};
  AdaptiveKronrod<double, 64> graded;
  graded.add_graded<48>([&](double t) { return f(0, t); }, 0, -1.0, 1.0, centers, widths, 1, 1.0);
  const double with_cuts = graded.refine(f, [](int) { return 1.0; }, 1e-12);
  // Four pieces cannot resolve a peak 1e-12 wide: the driver stops when the list is full.
  AdaptiveKronrod<double, 4> small;
  small.add([&](double t) { return f(0, t); }, 0, -1.0, 1.0 + 1e-3, 1.0);
  const double coarse = small.refine(f, [](int) { return 1.0; }, 1e-12);
  INFO("graded " << with_cuts << " vs " << exact << "; four pieces " << coarse);
  CHECK(std::abs(with_cuts - exact) <= 1e-9 * exact);
  CHECK(std::isfinite(coarse));
  CHECK(std::abs(coarse - exact) > 1e-3 * exact);
}

TEST_CASE("adaptive Gauss-Kronrod: a piece too narrow to bisect stops the refinement, sums kept") {
  // [1, nextafter(1, 2)] has no representable midpoint; its integrand jumps between the two ends, so
  // its error estimate is the largest and the driver must stop there with that piece's value kept.
  const double lo = 1.0, hi = std::nextafter(1.0, 2.0);
  const auto f = [&](int c, double t) { return c == 0 ? 1.0 : (t == lo ? 0.0 : 1e10); };
  AdaptiveKronrod<double, 64> quad;
  quad.add([&](double t) { return f(0, t); }, 0, 0.0, 1.0, 1.0);  // constant 1: exact, no error
  quad.add([&](double t) { return f(1, t); }, 1, lo, hi, 1.0);
  const double value = quad.refine(f, [](int) { return 1.0; }, 1e-12);
  // The narrow piece contributes at most 1e10 x its width (2.2e-16); the constant piece exactly 1.
  CHECK(std::isfinite(value));
  CHECK(value >= 1.0);
  CHECK(value <= 1.0 + 1e10 * (hi - lo) * 1.0000001);
}

TEST_CASE("adaptive Gauss-Kronrod: a deferred piece is evaluated whole when its bound matters, never otherwise") {
  // Curve 0: 1 on [0, 1], evaluated. Curve 1: 1e-3 on [0, 1], deferred with the bound 2e-3.
  // Curve 2: deferred with bound 0, its integrand must never run.
  int calls_1 = 0, calls_2 = 0;
  const auto f = [&](int c, double) {
    if (c == 1) ++calls_1;
    if (c == 2) ++calls_2;
    return c == 0 ? 1.0 : 1e-3;
  };
  for (const double tolerance : {1e-2, 1e-6}) {
    calls_1 = calls_2 = 0;
    AdaptiveKronrod<double, 64> quad;
    quad.add([&](double t) { return f(0, t); }, 0, 0.0, 1.0, 1.0);
    quad.add_deferred(1, 0.0, 1.0, 2e-3);
    quad.add_deferred(2, 0.0, 1.0, 0.0);
    const double value = quad.refine(f, [](int) { return 1.0; }, tolerance);
    INFO("tolerance " << tolerance << ": " << value << ", curve 1 evaluated " << calls_1 << " times");
    CHECK(calls_2 == 0);
    if (tolerance == 1e-2) {  // 2e-3 <= 1e-2 x 1: left out, within the tolerance
      CHECK(calls_1 == 0);
      CHECK(value == 1.0);
    } else {  // needed: one 15-point evaluation of the whole piece, not a bisection
      CHECK(calls_1 == 15);
      CHECK(std::abs(value - 1.001) <= 1e-15);
    }
  }
}
