// e^x for x <= 0 in double, vectorisable (no library call, no branch): with double_log.h, the
// Phong power c^m = e^(m ln c) of the batch specular kernels (punctual_specular_batch.h).
//
// exp_nonpositive(x), x <= 0: x = k ln 2 + r with k = round(x / ln 2) (the 1.5 x 2^52 rounding
// trick, exact for |x / ln 2| < 2^51), r = (x - k ln2_hi) - k ln2_lo, |r| <= ln 2 / 2 + tiny;
// ln2_hi is ln 2 rounded to 32 fractional bits, so k ln2_hi is exact for |k| < 2^21 and the first
// subtraction is exact (Sterbenz). e^r by its Taylor polynomial of degree 13, whose truncation
// error is below (ln 2 / 2)^14 / 14! < 5e-18 relative; 2^k is put into the exponent bits.
// Below x = -708 (e^x < 3.3e-308, the normal range's end) the result is 0: no subnormal output,
// callers compare with an absolute floor far above that.
//
// Measured: tests/kernels/batch/batch_specular_test.cpp "double exp against std::exp" (relative
// error against std::exp over [-708, 0]).
#pragma once

#include <bit>
#include <cstdint>

namespace vlit::batch_detail {

inline double exp_nonpositive(double x) {
  constexpr double kInvLn2 = 1.4426950408889634074;
  constexpr double kLn2Hi = 0.69314718060195446014404296875;  // 2977044472 / 2^32
  constexpr double kLn2Lo = -4.2009150726810846e-11;          // ln 2 - kLn2Hi
  constexpr double kRound = 6755399441055744.0;               // 1.5 x 2^52
  const double xc = x < -708. ? -708. : x;
  const double kd = (xc * kInvLn2 + kRound) - kRound;  // round to nearest integer
  const double r = (xc - kd * kLn2Hi) - kd * kLn2Lo;
  // Taylor coefficients 1/j!, j = 13 down to 0.
  double p = 1.6059043836821614599e-10;
  p = p * r + 2.0876756987868098979e-09;
  p = p * r + 2.5052108385441718775e-08;
  p = p * r + 2.7557319223985890653e-07;
  p = p * r + 2.7557319223985890653e-06;
  p = p * r + 2.4801587301587301587e-05;
  p = p * r + 1.9841269841269841270e-04;
  p = p * r + 1.3888888888888888889e-03;
  p = p * r + 8.3333333333333333333e-03;
  p = p * r + 4.1666666666666666667e-02;
  p = p * r + 1.6666666666666666667e-01;
  p = p * r + 0.5;
  p = p * r + 1.;
  p = p * r + 1.;
  const std::int64_t k = std::int64_t(kd);
  const double scaled = std::bit_cast<double>(std::bit_cast<std::int64_t>(p) + k * (std::int64_t(1) << 52));
  return x < -708. ? 0. : scaled;
}

}  // namespace vlit::batch_detail
