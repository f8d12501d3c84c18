// Band storage, span shading and resolve; see framebuffer.h.
#include "raster/framebuffer.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>

#include "raster/fixed_point.h"

namespace vlit::raster {


void SampleBand::reset(int width, int row_begin, int row_end, const Vec3f& background, float* image_rows) {
  width_ = width;
  row_begin_ = row_begin;
  row_end_ = row_end;
  const size_t n = size_t(width) * size_t(row_end - row_begin);
  depth_.assign(n, -1.0f);
  background_ = background;
  if (image_rows) {  // the image is written once: covered samples by shading, the rest by resolve()
    color_ = image_rows;
    return;
  }
  own_color_.resize(3 * n);
  color_ = own_color_.data();
  // The first row element by element, the others copied from it (a plain memcpy is much faster
  // than filling 12-byte elements).
  for (int col = 0; col < width; ++col) store_color(size_t(col), background);
  for (int row = 1; row < row_end - row_begin; ++row)
    std::memcpy(color_ + 3 * size_t(row) * size_t(width), color_, 3 * sizeof(float) * size_t(width));
}

// The span loop of both shade_span variants: attribute values at the first sample centre of the
// span, then one step per sample; where the depth test passes, the sample gets
// color_of(col, Gouraud colour).
template <class ColorOf>
void SampleBand::step_span(const SetupTriangle& t, int row, int col_begin, int col_end, const ColorOf& color_of) {
  const double dx = col_begin + 0.5 - t.ref_x(), dy = row + 0.5 - t.ref_y();
  const auto start = [&](const Gradient& g) { return g.at_ref + g.ddx * dx + g.ddy * dy; };
  double depth = start(t.depth), inv_w = start(t.inv_w);
  double r_w = start(t.color_over_w[0]), g_w = start(t.color_over_w[1]), b_w = start(t.color_over_w[2]);
  const size_t offset = size_t(row - row_begin_) * size_t(width_);
  for (int col = col_begin; col < col_end; ++col) {
    const float z = float(depth);
    if (z > depth_[offset + col]) {
      depth_[offset + col] = z;
      const double w = 1.0 / inv_w;
      store_color(offset + col, color_of(col, Vec3f{float(r_w * w), float(g_w * w), float(b_w * w)}));
    }
    depth += t.depth.ddx;
    inv_w += t.inv_w.ddx;
    r_w += t.color_over_w[0].ddx;
    g_w += t.color_over_w[1].ddx;
    b_w += t.color_over_w[2].ddx;
  }
}

void SampleBand::shade_span(const SetupTriangle& t, int row, int col_begin, int col_end) {
  step_span(t, row, col_begin, col_end, [](int, const Vec3f& gouraud) { return gouraud; });
}

void SampleBand::shade_span_wireframe(const SetupTriangle& t, int row, int col_begin, int col_end,
                                      double wire_width, const Vec3f& wire_color) {
  // Distance of a sample centre to the line through an edge p -> q, as an affine function of the
  // column: |n . (s - p)| with n the unit normal of the edge, stepping by n.x per column.
  struct EdgeDistance {
    double at_begin, step;
  };
  std::array<EdgeDistance, 3> edges;
  int edge_count = 0;
  const double sx = col_begin + 0.5, sy = row + 0.5;
  const auto add = [&](int p, int q) {
    const double px = double(t.x[p]) / kSubpixelOne, py = double(t.y[p]) / kSubpixelOne;
    const double ex = double(t.x[q] - t.x[p]) / kSubpixelOne, ey = double(t.y[q] - t.y[p]) / kSubpixelOne;
    const double inv_length = 1.0 / std::sqrt(ex * ex + ey * ey);
    const double nx = -ey * inv_length, ny = ex * inv_length;
    edges[edge_count++] = {nx * (sx - px) + ny * (sy - py), nx};
  };
  if (t.original_edges & kEdgeTopMid) add(0, 1);
  if (t.original_edges & kEdgeMidBottom) add(1, 2);
  if (t.original_edges & kEdgeTopBottom) add(0, 2);

  // The same stepping as shade_span (bit-identical colours off the wire).
  step_span(t, row, col_begin, col_end, [&](int col, const Vec3f& gouraud) {
    bool on_wire = false;
    for (int e = 0; e < edge_count; ++e)
      on_wire = on_wire || std::abs(edges[e].at_begin + edges[e].step * (col - col_begin)) < wire_width;
    return on_wire ? wire_color : gouraud;
  });
}

void SampleBand::resolve(int samples_per_side, Image& image) {
  const int s = samples_per_side;
  if (s == 1) {  // one sample per pixel: the mean is the sample itself (bit-identical to the loop below)
    if (color_ == own_color_.data()) {
      for (int y = row_begin_; y < row_end_; ++y)
        std::memcpy(image.pixel(0, y), color_ + 3 * size_t(y - row_begin_) * size_t(width_), 3 * sizeof(float) * size_t(image.width));
    } else {  // shaded samples are in the image already; the untouched ones get the background
      const size_t n = size_t(width_) * size_t(row_end_ - row_begin_);
      for (size_t i = 0; i < n; ++i)
        if (depth_[i] == -1.0f) store_color(i, background_);  // no surface stores a depth <= -1
    }
    return;
  }
  const double inv_count = 1.0 / (double(s) * s);
  for (int y = row_begin_ / s; y < row_end_ / s; ++y)
    for (int x = 0; x < image.width; ++x) {
      double sum[3] = {0, 0, 0};
      for (int sy = 0; sy < s; ++sy) {
        const float* row = color_ + 3 * (size_t(y * s + sy - row_begin_) * size_t(width_) + size_t(x) * s);
        for (int sx = 0; sx < s; ++sx) {
          sum[0] += row[3 * sx];
          sum[1] += row[3 * sx + 1];
          sum[2] += row[3 * sx + 2];
        }
      }
      float* out = image.pixel(x, y);
      for (int k = 0; k < 3; ++k) out[k] = float(sum[k] * inv_count);
    }
}

}  // namespace vlit::raster
