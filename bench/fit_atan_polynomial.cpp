// Coefficients of the atan polynomials of shaders_cpu/batch/float_atan.h (float) and
// shaders_cpu/batch/double_atan.h (double), and their errors.
//
//   ./build/release/bench/fit_atan_polynomial 8            (float, on [0, 1])
//   ./build/release/bench/fit_atan_polynomial 11 --double  (double, on [0, tan(pi/8)])
//
// atan(x) = x P(x^2) on [0, X] (X = 1 for float; X = tan(pi/8) for double, whose kernel first
// reduces larger arguments by atan(t) = pi/4 + atan((t - 1)/(t + 1))): P (degree DEG in z = x^2)
// interpolates f(z) = atan(sqrt z)/sqrt z at the DEG + 1 Chebyshev nodes of [0, X^2]
// (near-minimax; bench/chebyshev_fit.h). Prints the coefficients (z^0 first) and the maximum
// relative error of the Horner evaluation in the target precision against long-double atan: float
// on 2e6 + 1 points of [0, 1]; double on 2e6 + 1 points of [0, 1] through the same reduction as
// double_atan.h.
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <vector>

#include "chebyshev_fit.h"

using vlit::fit::LD;

namespace {

// Monomial coefficients (in z) of the degree-`deg` Chebyshev interpolant of f on [0, zmax].
std::vector<LD> chebyshev_fit(int deg, LD zmax) {
  auto f = [](LD z) { return z == 0 ? LD(1) : std::atan(std::sqrt(z)) / std::sqrt(z); };
  return vlit::fit::chebyshev_interpolant(f, 0, zmax, deg);
}

template <class R>
R horner(const std::vector<LD>& mono, R z) {
  R p = R(mono.back());
  for (int k = int(mono.size()) - 2; k >= 0; --k) p = p * z + R(mono[k]);
  return p;
}

}  // namespace

int main(int argc, char** argv) {
  const auto args = vlit::fit::fit_arguments(argc, argv, "fit_atan_polynomial", 8, 20);
  if (!args) return 2;
  const int deg = args->degree;
  const bool dbl = args->double_range;
  const LD xmax = dbl ? std::tan(M_PIl / 8) : LD(1);
  const std::vector<LD> mono = chebyshev_fit(deg, xmax * xmax);
  for (int i = 0; i <= deg; ++i) std::printf("z^%d: %.21Le\n", i, mono[i]);
  double worst = 0;
  for (int i = 0; i <= 2000000; ++i) {
    LD ref_x;
    double got;
    if (dbl) {
      const double t = double(i) / 2000000.0;
      const bool high = t > double(xmax);
      const double u = high ? (t - 1) / (t + 1) : t;
      const double r = u * horner(mono, u * u);
      got = high ? double(M_PIl / 4) + r : r;
      ref_x = t;
    } else {
      const float x = float(i) / 2000000.f;
      got = x * horner(mono, x * x);
      ref_x = x;
    }
    const LD ref = std::atan(ref_x);
    if (ref > 0) worst = std::max(worst, double(std::fabs((got - ref) / ref)));
  }
  std::printf("degree %d: max relative error of the %s evaluation on [0, 1]: %.3e\n", deg, dbl ? "double" : "float", worst);
  return 0;
}
