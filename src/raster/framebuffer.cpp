// Band storage, span shading and resolve; see framebuffer.h.
#include "raster/framebuffer.h"

namespace vlit::raster {

void SampleBand::reset(int width, int row_begin, int row_end, const Vec3f& background) {
  width_ = width;
  row_begin_ = row_begin;
  row_end_ = row_end;
  const size_t n = size_t(width) * size_t(row_end - row_begin);
  depth_.assign(n, -1.0f);
  color_.assign(n, background);
}

void SampleBand::shade_span(const SetupTriangle& t, int row, int col_begin, int col_end) {
  // Attribute values at the first sample centre of the span, then one step per sample.
  const double dx = col_begin + 0.5 - t.ref_x, dy = row + 0.5 - t.ref_y;
  const auto start = [&](const Gradient& g) { return g.at_ref + g.ddx * dx + g.ddy * dy; };
  double depth = start(t.depth), inv_w = start(t.inv_w);
  double r_w = start(t.color_over_w[0]), g_w = start(t.color_over_w[1]), b_w = start(t.color_over_w[2]);
  const size_t offset = size_t(row - row_begin_) * size_t(width_);
  for (int col = col_begin; col < col_end; ++col) {
    const float z = float(depth);
    if (z > depth_[offset + col]) {
      depth_[offset + col] = z;
      const double w = 1.0 / inv_w;
      color_[offset + col] = Vec3f{float(r_w * w), float(g_w * w), float(b_w * w)};
    }
    depth += t.depth.ddx;
    inv_w += t.inv_w.ddx;
    r_w += t.color_over_w[0].ddx;
    g_w += t.color_over_w[1].ddx;
    b_w += t.color_over_w[2].ddx;
  }
}

void SampleBand::resolve(int samples_per_side, Image& image) const {
  const int s = samples_per_side;
  const double inv_count = 1.0 / (double(s) * s);
  for (int y = row_begin_ / s; y < row_end_ / s; ++y)
    for (int x = 0; x < image.width; ++x) {
      double sum[3] = {0, 0, 0};
      for (int sy = 0; sy < s; ++sy) {
        const Vec3f* row = color_.data() + size_t(y * s + sy - row_begin_) * size_t(width_) + size_t(x) * s;
        for (int sx = 0; sx < s; ++sx) {
          sum[0] += row[sx].x;
          sum[1] += row[sx].y;
          sum[2] += row[sx].z;
        }
      }
      float* out = image.pixel(x, y);
      for (int k = 0; k < 3; ++k) out[k] = float(sum[k] * inv_count);
    }
}

}  // namespace vlit::raster
