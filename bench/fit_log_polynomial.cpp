// Coefficients of the float log polynomial of shaders_cpu/batch/float_log.h, and its error.
//
//   ./build/release/bench/fit_log_polynomial 3
//
// ln(m) for m in [sqrt(1/2), sqrt(2)) is written ln(m) = s R(s^2) with s = (m - 1)/(m + 1)
// (ln m = 2 atanh s), s^2 <= z_max = (3 - 2 sqrt 2)^2. R (degree DEG in z = s^2) interpolates
// f(z) = 2 atanh(sqrt z)/sqrt z at the DEG + 1 Chebyshev nodes of [0, z_max] (near-minimax;
// bench/chebyshev_fit.h). Prints the coefficients (z^0 first) and the maximum relative error of the
// float evaluation of s R(s^2) (with s computed in float, as in float_log.h) against long-double
// log on 2e6 + 1 points m of [sqrt(1/2), sqrt(2)].
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <vector>

#include "chebyshev_fit.h"

using vlit::fit::LD;

int main(int argc, char** argv) {
  const int deg = argc > 1 ? std::atoi(argv[1]) : 3;
  if (deg < 1 || deg > 12) {
    std::fprintf(stderr, "usage: fit_log_polynomial [DEGREE 1..12]\n");
    return 2;
  }
  const int n = deg + 1;
  const LD z_max = (3 - 2 * std::sqrt(LD(2))) * (3 - 2 * std::sqrt(LD(2)));
  auto f = [](LD z) { return z == 0 ? LD(2) : 2 * std::atanh(std::sqrt(z)) / std::sqrt(z); };
  const std::vector<LD> mono = vlit::fit::chebyshev_interpolant(f, 0, z_max, deg);
  for (int i = 0; i < n; ++i) std::printf("z^%d: %.9Le\n", i, mono[i]);
  double worst = 0;
  const float lo = std::sqrt(0.5f), hi = std::sqrt(2.f);
  for (int i = 0; i <= 2000000; ++i) {
    const float m = lo + (hi - lo) * float(i) / 2000000.f;
    const float s = (m - 1.f) / (m + 1.f), z = s * s;
    float r = float(mono[n - 1]);
    for (int k = n - 2; k >= 0; --k) r = r * z + float(mono[k]);
    const LD ref = std::log(LD(m));
    if (ref != 0) worst = std::max(worst, double(std::fabs((s * r - ref) / ref)));
  }
  std::printf("degree %d: max relative error of the float evaluation on [sqrt(1/2), sqrt(2)]: %.3e\n", deg, worst);
  return 0;
}
