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

// Twice the signed area of the triangle (a, b, c): positive when c lies left of a -> b. The
// coordinate differences are rounded; their 2x2 determinant is not (difference_of_products), so
// the sign is that of the exact determinant of the rounded differences.
inline double orient2(double ax, double ay, double bx, double by, double cx, double cy) {
  return difference_of_products(bx - ax, cy - ay, by - ay, cx - ax);
}

// The sign of orient2 where plain products decide it (the determinant farther from 0 than 3 eps
// times the products' sum, a bound of their rounding that also holds when the compiler fuses a
// product into the subtraction, plus a floor for underflow), 0 where they do not: then
// orient2_sign decides, and its sign may be 0 or not. No branch: callers that test many pairs
// combine several of these before they branch.
inline int fast_orient2_sign(double ax, double ay, double bx, double by, double cx, double cy) {
  const double p = (bx - ax) * (cy - ay), q = (by - ay) * (cx - ax);
  const double det = p - q;
  const double bound = 3.4e-16 * (std::abs(p) + std::abs(q)) + 1e-300;
  return (det > bound) - (det < -bound);
}

// The sign of orient2 (-1, 0, +1): fast_orient2_sign's where it decides, otherwise orient2's.
// Always orient2's sign; cheaper when the determinant is not close to 0.
inline int orient2_sign(double ax, double ay, double bx, double by, double cx, double cy) {
  if (const int fast = fast_orient2_sign(ax, ay, bx, by, cx, cy)) return fast;
  const double o = orient2(ax, ay, bx, by, cx, cy);
  return (o > 0) - (o < 0);
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
