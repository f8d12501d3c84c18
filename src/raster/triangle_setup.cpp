// Perspective divide, snapping, and per-triangle edge and gradient setup; see triangle_setup.h.
#include "raster/triangle_setup.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "raster/fixed_point.h"

namespace vlit::raster {

std::optional<ScreenVertex> project_to_screen(const ClipVertex& v, int grid_width, int grid_height) {
  const Vec4d& p = v.position;
  const double inv_w = 1.0 / p.w;
  const double x_px = (p.x * inv_w + 1.0) * 0.5 * grid_width;
  const double y_px = (1.0 - p.y * inv_w) * 0.5 * grid_height;
  const double depth = 0.5 * (1.0 - p.z * inv_w);
  const Vec3d color_over_w = v.color * inv_w;
  if (!(std::isfinite(x_px) && std::isfinite(y_px) && std::isfinite(depth) && std::isfinite(inv_w) &&
        is_finite(color_over_w)))
    return std::nullopt;
  return ScreenVertex{snap_to_fixed(x_px), snap_to_fixed(y_px), depth, inv_w, color_over_w};
}

namespace {

// Plane through (0, 0, a0), (x1, y1, a1), (x2, y2, a2) in coordinates relative to vertex 0;
// inv_area2 = 1 / (x1 y2 - x2 y1).
Gradient plane(double a0, double a1, double a2, double x1, double y1, double x2, double y2, double inv_area2) {
  const double d1 = a1 - a0, d2 = a2 - a0;
  return {a0, (d1 * y2 - d2 * y1) * inv_area2, (d2 * x1 - d1 * x2) * inv_area2};
}

}  // namespace

std::optional<SetupTriangle> setup_triangle(const ScreenVertex& a, const ScreenVertex& b,
                                            const ScreenVertex& c, bool cull_back_face,
                                            int grid_width, int grid_height, uint8_t original_edges) {
  // Twice the signed area with y down: negative = counter-clockwise on screen with y up = front.
  const int64_t area2 = (b.x - a.x) * (c.y - a.y) - (c.x - a.x) * (b.y - a.y);
  if (area2 == 0) return std::nullopt;
  if (cull_back_face && area2 > 0) return std::nullopt;

  const std::array<const ScreenVertex*, 3> input = {&a, &b, &c};
  std::array<int, 3> order = {0, 1, 2};  // order[k] = input index of the k-th vertex from the top
  // Stable sort by y (ties keep the input order): insertion sort of three.
  for (int i = 1; i < 3; ++i)
    for (int j = i; j > 0 && input[order[j]]->y < input[order[j - 1]]->y; --j) std::swap(order[j], order[j - 1]);
  const std::array<const ScreenVertex*, 3> v = {input[order[0]], input[order[1]], input[order[2]]};
  const ScreenVertex& top = *v[0];
  const ScreenVertex& mid = *v[1];
  const ScreenVertex& bot = *v[2];

  SetupTriangle t;
  t.row_begin = int(std::clamp<int64_t>(first_center_at_or_after(top.y), 0, grid_height));
  t.row_end = int(std::clamp<int64_t>(first_center_at_or_after(bot.y), 0, grid_height));
  if (t.row_begin >= t.row_end) return std::nullopt;
  const int64_t x_min = std::min({a.x, b.x, c.x}), x_max = std::max({a.x, b.x, c.x});
  const int64_t col_begin = std::max<int64_t>(first_center_at_or_after(x_min), 0);
  const int64_t col_end = std::min<int64_t>(first_center_at_or_after(x_max), grid_width);
  if (col_begin >= col_end) return std::nullopt;

  for (int i = 0; i < 3; ++i) {
    t.x[i] = int32_t(v[i]->x);
    t.y[i] = int32_t(v[i]->y);
  }
  // Which side of the long edge top -> bot the middle vertex lies on (y down: negative = right).
  const int64_t side = (bot.x - top.x) * (mid.y - top.y) - (bot.y - top.y) * (mid.x - top.x);
  t.long_edge_on_left = side < 0;
  std::array<int, 3> rank{};  // rank[input index] = position from the top
  for (int k = 0; k < 3; ++k) rank[order[k]] = k;
  for (int e = 0; e < 3; ++e) {  // input edge e runs from input vertex e to input vertex (e + 1) % 3
    if (!(original_edges & (1 << e))) continue;
    const int lo = std::min(rank[e], rank[(e + 1) % 3]), hi = std::max(rank[e], rank[(e + 1) % 3]);
    t.original_edges |= lo == 0 ? (hi == 1 ? kEdgeTopMid : kEdgeTopBottom) : kEdgeMidBottom;
  }

  static_assert(kSubpixelBits == 8, "SetupTriangle::ref_x() assumes 8 sub-pixel bits");
  const double one = double(kSubpixelOne);
  const double x1 = double(mid.x - top.x) / one, y1 = double(mid.y - top.y) / one;
  const double x2 = double(bot.x - top.x) / one, y2 = double(bot.y - top.y) / one;
  const double inv_area2 = 1.0 / (x1 * y2 - x2 * y1);
  t.depth = plane(top.depth, mid.depth, bot.depth, x1, y1, x2, y2, inv_area2);
  t.inv_w = plane(top.inv_w, mid.inv_w, bot.inv_w, x1, y1, x2, y2, inv_area2);
  for (int k = 0; k < 3; ++k)
    t.color_over_w[k] = plane(top.color_over_w[k], mid.color_over_w[k], bot.color_over_w[k], x1, y1, x2, y2, inv_area2);
  return t;
}

}  // namespace vlit::raster
