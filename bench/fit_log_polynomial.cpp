// Coefficients of the log polynomials of shaders_cpu/batch/float_log.h (float) and
// shaders_cpu/batch/double_log.h (double), and their errors.
//
//   ./build/release/bench/fit_log_polynomial 3            (float)
//   ./build/release/bench/fit_log_polynomial 9 --double   (double)
//
// ln(m) for m in [sqrt(1/2), sqrt(2)) is written ln(m) = s R(s^2) with s = (m - 1)/(m + 1)
// (ln m = 2 atanh s), s^2 <= z_max = (3 - 2 sqrt 2)^2. R (degree DEG in z = s^2) interpolates
// f(z) = 2 atanh(sqrt z)/sqrt z at the DEG + 1 Chebyshev nodes of [0, z_max] (near-minimax;
// bench/chebyshev_fit.h). Prints the coefficients (z^0 first) and the maximum relative error of the
// float (double) evaluation of s R(s^2) (with s computed in that precision, as in float_log.h and
// double_log.h) against long-double log on 2e6 + 1 points m of [sqrt(1/2), sqrt(2)].
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <vector>

#include "chebyshev_fit.h"

using vlit::fit::LD;

int main(int argc, char** argv) {
  const auto args = vlit::fit::fit_arguments(argc, argv, "fit_log_polynomial", 3, 12);
  if (!args) return 2;
  const int deg = args->degree;
  const bool dbl = args->double_range;
  const int n = deg + 1;
  const LD z_max = (3 - 2 * std::sqrt(LD(2))) * (3 - 2 * std::sqrt(LD(2)));
  auto f = [](LD z) { return z == 0 ? LD(2) : 2 * std::atanh(std::sqrt(z)) / std::sqrt(z); };
  const std::vector<LD> mono = vlit::fit::chebyshev_interpolant(f, 0, z_max, deg);
  for (int i = 0; i < n; ++i) std::printf(dbl ? "z^%d: %.21Le\n" : "z^%d: %.9Le\n", i, mono[i]);
  auto eval = [&](auto m) {  // s R(s^2) in the precision of m
    using R = decltype(m);
    const R s = (m - R(1)) / (m + R(1)), z = s * s;
    R r = R(mono[n - 1]);
    for (int k = n - 2; k >= 0; --k) r = r * z + R(mono[k]);
    return s * r;
  };
  double worst = 0;
  for (int i = 0; i <= 2000000; ++i) {
    LD m_ref;
    LD got;
    if (dbl) {
      const double lo = std::sqrt(0.5), hi = std::sqrt(2.0), m = lo + (hi - lo) * double(i) / 2000000.0;
      got = eval(m);
      m_ref = m;
    } else {
      const float lo = std::sqrt(0.5f), hi = std::sqrt(2.f), m = lo + (hi - lo) * float(i) / 2000000.f;
      got = eval(m);
      m_ref = m;
    }
    const LD ref = std::log(m_ref);
    if (ref != 0) worst = std::max(worst, double(std::fabs((got - ref) / ref)));
  }
  std::printf("degree %d: max relative error of the %s evaluation on [sqrt(1/2), sqrt(2)]: %.3e\n", deg,
              dbl ? "double" : "float", worst);
  return 0;
}
