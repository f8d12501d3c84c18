// Natural logarithm and ln(1 + x) in float, vectorisable (no library call, no branch).
//
// log_positive(x), x > 0 finite (subnormals included): x = 2^k m with m in [sqrt(1/2), sqrt(2)),
// read from the float's bits (subtracting the bit pattern of sqrt(1/2) and shifting by 23 gives k,
// subtracting k from the exponent field gives m; subnormals are first scaled by 2^24). Then
// ln x = k ln 2 + ln m, ln m = 2 atanh(s) = s R(s^2) with s = (m - 1)/(m + 1) (m - 1 is exact:
// Sterbenz), |s| <= 3 - 2 sqrt 2, and R the degree-3 Chebyshev interpolant of 2 atanh(sqrt z)/sqrt z
// on z in [0, (3 - 2 sqrt 2)^2] (near-minimax). Coefficients: `./build/release/bench/fit_log_polynomial 3`
// (bench/fit_log_polynomial.cpp), which measures 2.2e-7 relative error for ln m in float. k ln 2 is
// added as k ln2_hi + (ln m + k ln2_lo) with ln2_hi holding 15 significant bits, so k ln2_hi is
// exact for every float exponent.
//
// log1p_float(x), x > -1: u = 1 + x rounded, then ln(1 + x) = ln(u) x / (u - 1) (or x when u = 1),
// which keeps full relative precision for small x (Goldberg 1991, "What every computer scientist
// should know about floating-point arithmetic", theorem 4). log1p_or_log_ratio takes the ratio
// 1 + x computed independently, for x near -1 where 1 + x from x has lost its digits.
//
// Measured over the whole positive float range: tests/kernels/batch/batch_kernels_test.cpp
// "float log and log1p".
#pragma once

#include <bit>
#include <cstdint>

namespace vlit::batch_detail {

inline float log_positive(float x) {
  constexpr float kTwoTo24 = 16777216.f, kSmallestNormal = 1.17549435e-38f;
  constexpr float kLn2Hi = 0.693145751953125f;        // 22713 / 2^15
  constexpr float kLn2Lo = 1.42860682030941723e-06f;  // ln 2 - kLn2Hi
  constexpr std::int32_t kSqrtHalfBits = 0x3f3504f3;  // bits of sqrt(1/2) rounded to float
  const bool subnormal = x < kSmallestNormal;
  const float xs = subnormal ? x * kTwoTo24 : x;
  const std::int32_t bits = std::bit_cast<std::int32_t>(xs);
  const std::int32_t k = (bits - kSqrtHalfBits) >> 23;  // floor: arithmetic shift
  const float m = std::bit_cast<float>(bits - k * (std::int32_t(1) << 23));
  const float kf = float(k) - (subnormal ? 24.f : 0.f);
  const float s = (m - 1.f) / (m + 1.f);
  const float z = s * s;
  float r = 2.992439048e-01f;
  r = r * z + 3.997485052e-01f;
  r = r * z + 6.666681534e-01f;
  r = r * z + 1.999999999e+00f;
  return kf * kLn2Hi + (s * r + kf * kLn2Lo);
}

// ln(1 + x) for x > -1, where ratio = 1 + x computed independently of x; ratio is used for
// x <= -1/2 (there 1 + x in float is exact, but x itself may carry an absolute error that is large
// relative to 1 + x).
inline float log1p_or_log_ratio(float x, float ratio) {
  // Selects between floats only: a select between two masks stops GCC 12's vectoriser.
  const bool near_one = x > -0.5f;
  const float u = near_one ? 1.f + x : ratio;
  const float d = u - 1.f;  // exact (Sterbenz) for u in [1/2, 2]; u's rounding error shows up here
  const float d_safe = d == 0.f ? 1.f : d;
  const float correction = near_one ? x / d_safe : 1.f;
  const float r = log_positive(u) * correction;
  const float at_one = near_one ? x : 0.f;  // u = 1: ln(1 + x) = x within rounding (or ln ratio = 0)
  return d == 0.f ? at_one : r;
}

// ln(1 + x) for x > -1/2 (and for x > -1 when x is exact).
inline float log1p_float(float x) { return log1p_or_log_ratio(x, 1.f + x); }

}  // namespace vlit::batch_detail
