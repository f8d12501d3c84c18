#include "shadow/sweep_axes.h"

#include <algorithm>
#include <array>

namespace vlit {
namespace {

double bounding_area(const PreparedAreaLight<double>& light, const Vec3d& u, const Vec3d& v) {
  Rect2 r;
  for (int k = 0; k < light.count; ++k) r.grow(dot(u, light.d[k]), dot(v, light.d[k]));
  return (r.x1 - r.x0) * (r.y1 - r.y0);
}

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
    const double area = bounding_area(light, u, v);
    if (!found || area < best_area) best = {u, v}, best_area = area, found = true;
  }
  // The light's own frame where it is about as tight (kSweepAxesMinGain).
  if (!(best_area < (1 - kSweepAxesMinGain) * bounding_area(light, light.u, light.v))) return {light.u, light.v};
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
