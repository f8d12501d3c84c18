// The fixed-point screen coordinates of the rasterizer and their bit budget.
//
// Vertices are snapped to 1/256 of a sample-grid pixel (kSubpixelBits = 8) and stored as
// integers. Everything that decides coverage (edge positions at row centres, facing, row and
// column ranges) is then exact integer arithmetic, so two triangles sharing an edge agree on it
// to the last bit, and the fill rule is exact.
//
// Bit budget (int64_t arithmetic, all bounds are magnitudes):
//   snapped coordinate          |v|            <= 2^28   (kMaxFixed: +-2^20 pixels x 2^8)
//   sample-grid size            W, H           <= 2^19   (kMaxGridSize), so centres <= 2^27
//   coordinate difference       |dx|, |dy|     <= 2^29
//   edge numerator (scan_triangle)  (x0 - half) dy + (yc - y0) dx  <= 2^57 + 2^58 < 2^59
//   twice the signed area       dx1 dy2 - dx2 dy1                   <= 2^59
//   edge denominator            dy * 2^8                           <= 2^37
// all well inside 2^63. Vertices outside the guard band [-2^20, 2^20] pixels are removed by
// homogeneous clipping before snapping (clip.h), so the budget holds for any input.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace vlit::raster {

constexpr int kSubpixelBits = 8;
constexpr int64_t kSubpixelOne = int64_t{1} << kSubpixelBits;   // one pixel
constexpr int64_t kSubpixelHalf = kSubpixelOne / 2;              // the offset of a pixel centre
constexpr int kMaxGridSize = 1 << 19;                            // sample grid width/height limit
constexpr double kGuardBandPixels = double(1 << 20);             // clip range: [-2^20, 2^20] px
constexpr int64_t kMaxFixed = int64_t{1} << 28;                  // kGuardBandPixels in fixed point

// Nearest fixed-point value of a pixel coordinate, clamped to the budget (the clamp only ever
// moves clipped vertices by their rounding error). Precondition: pixel is finite.
// Rounds half away from zero, exactly like std::llround (inline: it is called three times per
// triangle); x - trunc(x) is exact for |x| <= 2^28.
inline int64_t snap_to_fixed(double pixel) {
  const double scaled = std::clamp(pixel * double(kSubpixelOne), -double(kMaxFixed), double(kMaxFixed));
  const int64_t truncated = int64_t(scaled);
  const double fraction = scaled - double(truncated);
  return truncated + (fraction >= 0.5 ? 1 : 0) - (fraction <= -0.5 ? 1 : 0);
}

// Fixed-point coordinate of the centre of pixel (or row) `index`.
constexpr int64_t pixel_center(int64_t index) { return index * kSubpixelOne + kSubpixelHalf; }

// ceil(num / den) for den > 0, exact for any int64 operands.
constexpr int64_t ceil_div(int64_t num, int64_t den) {
  const int64_t q = num / den;   // truncates towards zero
  return q + ((num % den) > 0 ? 1 : 0);
}

// First pixel index whose centre is at or after the fixed-point coordinate v.
constexpr int64_t first_center_at_or_after(int64_t v) { return ceil_div(v - kSubpixelHalf, kSubpixelOne); }

}  // namespace vlit::raster
