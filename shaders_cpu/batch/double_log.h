// Natural logarithm and ln(1 + x) in double, vectorisable (no library call, no branch): the double
// lanes' counterpart of float_log.h (disk_diffuse_batch.h's arc lanes).
//
// log_positive(x), x > 0 finite: x = 2^k m with m in [sqrt(1/2), sqrt(2)), read from the double's
// bits (subnormals first scaled by 2^54), ln x = k ln 2 + ln m, ln m = 2 atanh(s) = s R(s^2),
// s = (m - 1)/(m + 1), |s| <= 3 - 2 sqrt 2, R the degree-7 Chebyshev interpolant of
// 2 atanh(sqrt z)/sqrt z on z in [0, (3 - 2 sqrt 2)^2]. Coefficients: `./build/release/bench/fit_log_polynomial
// 7 --double` (bench/fit_log_polynomial.cpp), which measures 4.2e-16 relative error for ln m. k ln 2 is
// added as k ln2_hi + (ln m + k ln2_lo), ln2_hi = ln 2 rounded to 32 fractional bits, so k ln2_hi is
// exact for every double exponent.
//
// log1p_double(x), x > -1: ln(1 + x) = ln(u) x / (u - 1) with u = 1 + x rounded (or x when
// u = 1), full relative precision for small x (Goldberg 1991, theorem 4), as float_log.h.
//
// Measured: tests/kernels/batch/batch_kernels_test.cpp "double log and log1p".
#pragma once

#include <bit>
#include <cstdint>

namespace vlit::batch_detail {

inline double log_positive(double x) {
  constexpr double kTwoTo54 = 18014398509481984.0, kSmallestNormal = 2.2250738585072014e-308;
  constexpr double kLn2Hi = 0.69314718060195446014404296875;     // 2977044472 / 2^32
  constexpr double kLn2Lo = -4.2009150726810846e-11;             // ln 2 - kLn2Hi
  constexpr std::int64_t kSqrtHalfBits = 0x3fe6a09e667f3bcd;     // bits of sqrt(1/2) rounded to double
  const bool subnormal = x < kSmallestNormal;
  const double xs = subnormal ? x * kTwoTo54 : x;
  const std::int64_t bits = std::bit_cast<std::int64_t>(xs);
  const std::int64_t k = (bits - kSqrtHalfBits) >> 52;  // floor: arithmetic shift
  const double m = std::bit_cast<double>(bits - k * (std::int64_t(1) << 52));
  const double kd = double(k) - (subnormal ? 54. : 0.);
  const double s = (m - 1.) / (m + 1.);
  const double z = s * s;
  double r = 1.480562773902996944e-01;
  r = r * z + 1.531337983228732149e-01;
  r = r * z + 1.818357539388466842e-01;
  r = r * z + 2.222219874962245931e-01;
  r = r * z + 2.857142873542939422e-01;
  r = r * z + 3.999999999948034029e-01;
  r = r * z + 6.666666666666715987e-01;
  r = r * z + 2.000000000000000000e+00;
  return kd * kLn2Hi + (s * r + kd * kLn2Lo);
}

// ln(1 + x) for x > -1.
inline double log1p_double(double x) {
  const double u = 1. + x;
  const double d = u - 1.;
  const double d_safe = d == 0. ? 1. : d;
  const double r = log_positive(u) * (x / d_safe);
  return d == 0. ? x : r;
}

}  // namespace vlit::batch_detail
