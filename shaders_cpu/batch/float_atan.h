// atan(t) for t in [0, 1] in float, vectorisable: the float lanes' part of atan2_upper.h.
//
// atan(t) = t P(t^2) with P the degree-8 Chebyshev interpolant of atan(sqrt z)/sqrt z on z in
// [0, 1] (interpolation at the Chebyshev nodes, near-minimax). Coefficients: `./build/release/bench/fit_atan_polynomial 8` (bench/fit_atan_polynomial.cpp).
// Measured by that program: max relative error 1.4e-7 over [0, 1] in float (truncation is below
// float rounding); tests/kernels/batch/batch_kernels_test.cpp "float atan2" checks 4e-7 over
// the whole range of angles.
#pragma once

namespace vlit::batch_detail {

inline float atan_unit(float t) {  // t in [0, 1]
  const float z = t * t;
  float p = 2.766283502e-03f;
  p = p * z + -1.573124912e-02f;
  p = p * z + 4.213762359e-02f;
  p = p * z + -7.456854826e-02f;
  p = p * z + 1.061837064e-01f;
  p = p * z + -1.419779779e-01f;
  p = p * z + 1.999187203e-01f;
  p = p * z + -3.333303671e-01f;
  p = p * z + 9.999999818e-01f;
  return t * p;
}

}  // namespace vlit::batch_detail
