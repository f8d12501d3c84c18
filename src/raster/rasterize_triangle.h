// The scanline loop: walks the edges of a set-up triangle row by row and hands each run of
// covered sample centres to the caller. It knows nothing about colours, depth or lighting.
//
// Fill rule (top-left, as in Direct3D and OpenGL): a sample centre exactly on an edge belongs to
// the triangle when the edge is a left edge or a horizontal top edge. In row/column terms:
// rows whose centre yc satisfies y_top <= yc < y_bottom, and in each row the columns whose centre
// xc satisfies x_left(yc) <= xc < x_right(yc). The edge positions are exact rationals evaluated
// with integer arithmetic (fixed_point.h), so triangles sharing an edge split its row at the same
// column and a mesh covers every interior sample centre exactly once.
#pragma once

#include <algorithm>
#include <cstdint>

#include "raster/fixed_point.h"
#include "raster/triangle_setup.h"

namespace vlit::raster {

// First column whose centre is at or right of the edge (x0, y0) -> (x1, y1) at row centre yc.
// Precondition: y0 <= yc < y1. x(yc) = x0 + (yc - y0)(x1 - x0)/(y1 - y0), and the result is
// ceil((x(yc) - half) / one) computed as one exact integer division.
inline int64_t edge_first_column(int64_t x0, int64_t y0, int64_t x1, int64_t y1, int64_t yc) {
  const int64_t dy = y1 - y0;
  return ceil_div((x0 - kSubpixelHalf) * dy + (yc - y0) * (x1 - x0), dy * kSubpixelOne);
}

// Calls emit(row, col_begin, col_end) for every row in [row_begin, row_end) of the sample grid
// where the triangle covers the centres of columns [col_begin, col_end), clamped to [0, width).
template <class EmitSpan>
void scan_triangle(const SetupTriangle& t, int row_begin, int row_end, int width, EmitSpan&& emit) {
  const int first = std::max(row_begin, t.row_begin), last = std::min(row_end, t.row_end);
  for (int row = first; row < last; ++row) {
    const int64_t yc = pixel_center(row);
    const int64_t on_long = edge_first_column(t.x[0], t.y[0], t.x[2], t.y[2], yc);
    const int64_t on_short = yc < t.y[1] ? edge_first_column(t.x[0], t.y[0], t.x[1], t.y[1], yc)
                                         : edge_first_column(t.x[1], t.y[1], t.x[2], t.y[2], yc);
    const int64_t left = std::max<int64_t>(t.long_edge_on_left ? on_long : on_short, 0);
    const int64_t right = std::min<int64_t>(t.long_edge_on_left ? on_short : on_long, width);
    if (left < right) emit(row, int(left), int(right));
  }
}

}  // namespace vlit::raster
