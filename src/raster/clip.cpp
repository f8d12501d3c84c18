// Sutherland-Hodgman clipping in homogeneous clip space; see clip.h.
#include "raster/clip.h"

#include "raster/fixed_point.h"

namespace vlit::raster {

ClipPlanes make_clip_planes(int grid_width, int grid_height, bool has_far) {
  // Pixel coordinates: x_px = (x/w + 1) W/2, y_px = (1 - y/w) H/2 (top row first).
  // x_px >= -G  <=>  x + (2G/W + 1) w >= 0;   x_px <= G  <=>  (2G/W - 1) w - x >= 0;
  // y_px >= -G  <=>  (2G/H + 1) w - y >= 0;   y_px <= G  <=>  y + (2G/H - 1) w >= 0.
  const double gx = 2.0 * kGuardBandPixels / grid_width;
  const double gy = 2.0 * kGuardBandPixels / grid_height;
  ClipPlanes p;
  p.planes[p.count++] = {0, 0, 1, 1};  // near: z + w >= 0 (first, so later planes see w > 0)
  if (has_far) p.planes[p.count++] = {0, 0, -1, 1};
  p.planes[p.count++] = {1, 0, 0, gx + 1};
  p.planes[p.count++] = {-1, 0, 0, gx - 1};
  p.planes[p.count++] = {0, -1, 0, gy + 1};
  p.planes[p.count++] = {0, 1, 0, gy - 1};
  return p;
}

namespace {

// The point where the edge inside -> outside crosses the plane, computed from the inside end.
// original_edge_to_next is for the caller to set (it depends on the direction of travel).
ClipVertex intersect(const ClipVertex& inside, double d_in, const ClipVertex& outside, double d_out) {
  const double t = d_in / (d_in - d_out);  // d_in >= 0 > d_out, so t in [0, 1)
  return {inside.position + (outside.position - inside.position) * t,
          inside.color + (outside.color - inside.color) * t, false};
}

}  // namespace

int clip_triangle(const ClipVertex& a, const ClipVertex& b, const ClipVertex& c,
                  const ClipPlanes& planes, std::array<ClipVertex, kMaxClipVertices>& out) {
  // Fast paths: entirely inside every plane (most triangles), or entirely outside one.
  bool all_inside = true;
  for (int i = 0; i < planes.count; ++i) {
    const Vec4d& plane = planes.planes[i];
    const double da = dot(plane, a.position), db = dot(plane, b.position), dc = dot(plane, c.position);
    if (da < 0 && db < 0 && dc < 0) return 0;
    all_inside = all_inside && da >= 0 && db >= 0 && dc >= 0;
  }
  out[0] = a;
  out[1] = b;
  out[2] = c;
  if (all_inside) return 3;

  std::array<ClipVertex, kMaxClipVertices> scratch;
  int n = 3;
  for (int i = 0; i < planes.count && n > 0; ++i) {
    const Vec4d& plane = planes.planes[i];
    int m = 0;
    for (int j = 0; j < n; ++j) {
      const ClipVertex& cur = out[j];
      const ClipVertex& next = out[(j + 1) % n];
      const double d_cur = dot(plane, cur.position), d_next = dot(plane, next.position);
      if (m + 2 > kMaxClipVertices) return 0;
      if (d_cur >= 0) scratch[m++] = cur;
      if ((d_cur >= 0) != (d_next >= 0)) {
        // Leaving: the edge from the cut point runs along the plane. Entering: it continues the
        // edge cur -> next.
        scratch[m] = d_cur >= 0 ? intersect(cur, d_cur, next, d_next) : intersect(next, d_next, cur, d_cur);
        scratch[m++].original_edge_to_next = d_cur < 0 && cur.original_edge_to_next;
      }
    }
    for (int j = 0; j < m; ++j) out[j] = scratch[j];
    n = m;
  }
  return n >= 3 ? n : 0;
}

}  // namespace vlit::raster
