// Coefficients of the float atan polynomial of shaders_cpu/batch/float_atan.h, and its error.
//
//   ./build/release/bench/fit_atan_polynomial 8
//
// atan(x) = x P(x^2) on [0, 1]: P (degree DEG in z = x^2) interpolates f(z) = atan(sqrt z)/sqrt z
// at the DEG + 1 Chebyshev nodes of [0, 1] (near-minimax; bench/chebyshev_fit.h). Prints the
// coefficients (z^0 first) and the maximum relative error of the float Horner evaluation against
// long-double atan on 2e6 + 1 points of [0, 1].
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <vector>

#include "chebyshev_fit.h"

using vlit::fit::LD;

int main(int argc, char** argv) {
  const int deg = argc > 1 ? std::atoi(argv[1]) : 8;
  if (deg < 1 || deg > 20) {
    std::fprintf(stderr, "usage: fit_atan_polynomial [DEGREE 1..20]\n");
    return 2;
  }
  const int n = deg + 1;
  auto f = [](LD z) { return z == 0 ? LD(1) : std::atan(std::sqrt(z)) / std::sqrt(z); };
  const std::vector<LD> mono = vlit::fit::chebyshev_interpolant(f, 0, 1, deg);
  for (int i = 0; i < n; ++i) std::printf("z^%d: %.9Le\n", i, mono[i]);
  double worst = 0;
  for (int i = 0; i <= 2000000; ++i) {
    const float x = float(i) / 2000000.f, z = x * x;
    float p = float(mono[n - 1]);
    for (int k = n - 2; k >= 0; --k) p = p * z + float(mono[k]);
    const LD ref = std::atan(LD(x));
    if (ref > 0) worst = std::max(worst, double(std::fabs((x * p - ref) / ref)));
  }
  std::printf("degree %d: max relative error of the float evaluation on [0, 1]: %.3e\n", deg, worst);
  return 0;
}
