// Named robust primitives used by the kernels. Each has its own test in tests/unit/robust_math_test.cpp.
#pragma once

#include <algorithm>
#include <cmath>

#include "core/vec3.h"

namespace vlit {

// sqrt that treats tiny negative rounding residue as zero instead of returning NaN.
template <class T>
T safe_sqrt(T x) { return std::sqrt(std::max(x, T(0))); }

// a*b - c*d with one rounding error (Kahan's algorithm with FMA): the cancellation-safe form
// of 2x2 determinants such as 4CE - D^2.
template <class T>
T difference_of_products(T a, T b, T c, T d) {
  const T cd = c * d;
  const T err = std::fma(-c, d, cd);
  const T dop = std::fma(a, b, -cd);
  return dop + err;
}

// Angle between two vectors (need not be unit), accurate at 0 and pi, unlike acos(dot):
// atan2(|a x b|, a . b).
template <class T>
T angle_between(const Vec3<T>& a, const Vec3<T>& b) {
  return std::atan2(length(cross(a, b)), dot(a, b));
}

template <class T>
T clamp01(T x) { return std::clamp(x, T(0), T(1)); }

// The Phong lobe max(0, c)^m for m >= 0, with m = 0 taken as its limit m -> 0+: [c > 0] (1 in
// front of the lobe's half-space, 0 on and behind it), so that the lobe is continuous in m
// (docs/conventions.md "Radiometric definitions").
template <class T>
T phong_power(T cos_alpha, T m) {
  if (!(cos_alpha > T(0))) return T(0);
  return std::pow(cos_alpha, m);
}

}  // namespace vlit
