// atan2(y, x) for y >= 0, vectorisable (no library call, no branch), in float or double lanes:
// range reduction to t = min(y, |x|) / max(y, |x|) in [0, 1], atan(t) from the polynomial of the
// lane type (atan_unit: float_atan.h, double_atan.h), then atan2 = pi/2 - atan(t) when y > |x|
// and pi - that when x < 0.
#pragma once

#include "batch/double_atan.h"
#include "batch/float_atan.h"

namespace vlit::batch_detail {

// The angle in [0, pi] between (x, y), y >= 0, and the positive x axis.
template <class R>
inline R atan2_upper(R y, R x) {
  constexpr R kHalfPi = R(1.57079632679489661923), kPi = R(3.14159265358979323846);
  const R ax = x < R(0) ? -x : x;
  const R hi = y > ax ? y : ax, lo = y > ax ? ax : y;
  const R t = hi > R(0) ? lo / hi : R(0);
  R r = atan_unit(t);
  r = y > ax ? kHalfPi - r : r;
  return x < R(0) ? kPi - r : r;
}

}  // namespace vlit::batch_detail
