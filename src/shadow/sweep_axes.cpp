#include "shadow/sweep_axes.h"

#include <algorithm>
#include <array>

namespace vlit {
namespace {

SweepAxes smallest_bounding_rectangle_axes(const PreparedAreaLight<double>& light) {
  SweepAxes best{light.u, light.v};
  double best_area = 0;
  bool found = false;
  const int n = light.count;
  for (int i = 0; i < n; ++i) {
    const Vec3d e = light.d[(i + 1) % n] - light.d[i];
    const Vec3d in_plane = e - light.normal * dot(light.normal, e);
    const double len = length(in_plane);
    if (!(len > 0)) continue;
    const Vec3d u = in_plane / len;
    const Vec3d v = cross(light.normal, u);
    Rect2 r;
    for (int k = 0; k < n; ++k) r.grow(dot(u, light.d[k]), dot(v, light.d[k]));
    const double area = (r.x1 - r.x0) * (r.y1 - r.y0);
    if (!found || area < best_area) best = {u, v}, best_area = area, found = true;
  }
  return best;
}

}  // namespace

SweepAxes sweep_axes(const PreparedAreaLight<double>& light) {
  thread_local struct {
    int count = 0;
    std::array<Vec3d, kMaxAreaVertices> d{};
    Vec3d normal{};
    SweepAxes axes{};
  } last;
  const bool same = last.count == light.count && last.normal == light.normal &&
                    std::equal(light.d.begin(), light.d.begin() + light.count, last.d.begin());
  if (!same) {
    last.count = light.count;
    std::copy(light.d.begin(), light.d.begin() + light.count, last.d.begin());
    last.normal = light.normal;
    last.axes = smallest_bounding_rectangle_axes(light);
  }
  return last.axes;
}

}  // namespace vlit
