// atan(t) for t in [0, 1] in double, vectorisable: the double lanes' part of atan2_upper.h
// (area_diffuse_batch.h's double lanes).
//
// For t > tan(pi/8),
// atan(t) = pi/4 + atan((t - 1)/(t + 1)), so the polynomial only sees |u| <= tan(pi/8):
// atan(u) = u P(u^2) with P the degree-11 Chebyshev interpolant of atan(sqrt z)/sqrt z on
// z in [0, tan^2(pi/8)] (near-minimax). Coefficients: `./build/release/bench/fit_atan_polynomial 11
// --double` (bench/fit_atan_polynomial.cpp), which measures a max relative error of 3.9e-16 over
// [0, 1]; tests/kernels/batch/batch_kernels_test.cpp "double atan2" checks 1e-15 over the whole
// range of angles.
#pragma once

namespace vlit::batch_detail {

inline double atan_unit(double t) {  // t in [0, 1]
  constexpr double kTanPiOver8 = 0.41421356237309504880, kQuarterPi = 0.78539816339744830962;
  const bool high = t > kTanPiOver8;
  const double u = high ? (t - 1.) / (t + 1.) : t;
  const double z = u * u;
  double p = -1.783328703476172424e-02;
  p = p * z + 3.799048555584740484e-02;
  p = p * z + -5.036027397523584422e-02;
  p = p * z + 5.847049276208475462e-02;
  p = p * z + -6.662966763529512289e-02;
  p = p * z + 7.692045411952877202e-02;
  p = p * z + -9.090896706484310651e-02;
  p = p * z + 1.111111073589821634e-01;
  p = p * z + -1.428571427892261594e-01;
  p = p * z + 1.999999999993610041e-01;
  p = p * z + -3.333333333333310773e-01;
  p = p * z + 9.999999999999999991e-01;
  const double r = u * p;
  return high ? kQuarterPi + r : r;
}

}  // namespace vlit::batch_detail
