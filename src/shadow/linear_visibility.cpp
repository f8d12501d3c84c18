#include "shadow/linear_visibility.h"

#include <algorithm>
#include <cmath>

namespace vlit {
namespace {

constexpr double kCollinear = 1e-12;  // h below this fraction of the distance: P on the line

void merge_to_visible(std::vector<std::pair<double, double>>& hidden, std::vector<std::pair<double, double>>& visible) {
  visible.clear();
  std::sort(hidden.begin(), hidden.end());
  double t = 0;
  for (const auto& [a, b] : hidden) {
    if (a > t) visible.emplace_back(t, std::min(a, 1.0));
    t = std::max(t, b);
    if (t >= 1) break;
  }
  if (t < 1) visible.emplace_back(t, 1.0);
}

}  // namespace

bool linear_shadow_frame(const LinearLight<double>& light, const Vec3d& p, LinearShadowFrame& frame) {
  const Vec3d l0 = light.q0 - p, ld = light.q1 - light.q0;
  const double len = length(ld);
  const double dist = std::max(length(l0), length(light.q1 - p));
  if (!(dist > 0) || !(len > 1e-15 * dist)) return false;
  const Vec3d u = ld / len;
  const double s0 = dot(l0, u);   // position of Q0 along u, from the foot's plane through P
  const Vec3d hvec = l0 - u * s0;  // H = F - P
  const double h = length(hvec);
  if (!(h > kCollinear * dist)) return false;
  frame.u = u;
  frame.m = hvec / h;
  frame.plane_normal = cross(frame.m, u);
  frame.len = len;
  frame.h = h;
  frame.t_foot = -s0 / len;
  const Vec3d& m = frame.m;
  const Vec3d& plane_normal = frame.plane_normal;
  frame.strip[0] = {-m, p + m * (h * (1 - kLinearNearLight))};
  frame.strip[1] = {m, p + m * (h * kLinearNearP)};
  ConvexVolume& volume = frame.volume;
  volume.box = Aabb{};
  volume.planes.clear();
  volume.box.grow(p);
  volume.box.grow(light.q0);
  volume.box.grow(light.q1);
  const double thickness = 1e-9 * dist;
  volume.planes.push_back({plane_normal, p - plane_normal * thickness});
  volume.planes.push_back({-plane_normal, p + plane_normal * thickness});
  volume.planes.push_back({-m, p + m * h});  // not beyond the light's line
  {
    // Wedge sides: the planes through P and each end, containing the normal of Π.
    Vec3d k0 = cross(plane_normal, l0), k1 = cross(light.q1 - p, plane_normal);
    if (dot(k0, ld) < 0) k0 = -k0;
    if (dot(k1, -ld) < 0) k1 = -k1;
    volume.planes.push_back({k0, p});
    volume.planes.push_back({k1, p});
  }
  return true;
}

bool lies_in_plane(const std::array<Vec3d, 3>& tri, const Vec3d& p, const Vec3d& plane_normal) {
  double scale = 0;
  for (const Vec3d& x : tri) scale = std::max(scale, length(x - p));
  for (const Vec3d& x : tri)
    if (!(std::abs(dot(x - p, plane_normal)) <= 1e-12 * scale)) return false;
  return true;
}

LinearVisibility visible_linear_intervals(const LinearLight<double>& light, const Vec3d& p,
                                          const OccluderBvh& occluders, LinearShadowScratch& scratch) {
  scratch.hidden.clear();
  scratch.visible.clear();
  LinearShadowFrame& frame = scratch.frame;
  if (!linear_shadow_frame(light, p, frame)) {
    // P at both ends: nothing to hide. A point light at the midpoint (linear_geometry.h, zero
    // length), or P on the line: every ray runs along it, the shadow ray to the nearer end decides.
    const Vec3d l0 = light.q0 - p, l1 = light.q1 - p;
    const double dist = std::max(length(l0), length(l1));
    if (!(dist > 0)) return LinearVisibility::kUnoccluded;
    const Vec3d target = !(length(light.q1 - light.q0) > 1e-15 * dist) ? (light.q0 + light.q1) * 0.5
                         : length(l0) <= length(l1)                  ? light.q0
                                                                     : light.q1;
    if (!occluders.segment_occluded(p, target, p)) return LinearVisibility::kUnoccluded;
    return LinearVisibility::kIntervals;  // nothing visible
  }
  const Vec3d& plane_normal = frame.plane_normal;
  occluders.triangles_in_volume(frame.volume, p, scratch.candidates);
  if (scratch.candidates.empty()) return LinearVisibility::kUnoccluded;

  for (std::uint32_t index : scratch.candidates) {
    if (culled_back_face(occluders.triangles(), index, p, occluders.plane(index).normal)) continue;
    const auto& tri = occluders.triangles().corners[index];
    const double d[3] = {dot(tri[0] - p, plane_normal), dot(tri[1] - p, plane_normal), dot(tri[2] - p, plane_normal)};
    SmallPolygon in_plane;
    if (lies_in_plane(tri, p, plane_normal)) {
      in_plane.count = 3;  // the whole triangle
      for (int i = 0; i < 3; ++i) in_plane.p[i] = tri[i];
    } else {
      for (int i = 0; i < 3; ++i) {
        const int j = (i + 1) % 3;
        if (d[i] == 0) in_plane.p[in_plane.count++] = tri[i];
        if ((d[i] < 0 && d[j] > 0) || (d[i] > 0 && d[j] < 0)) {
          const bool i_first = lexicographic_less(tri[i], tri[j]);
          const Vec3d& x = i_first ? tri[i] : tri[j];
          const Vec3d& y = i_first ? tri[j] : tri[i];
          const double dx = i_first ? d[i] : d[j], dy = i_first ? d[j] : d[i];
          in_plane.p[in_plane.count++] = x + (y - x) * (dx / (dx - dy));
        }
      }
      if (in_plane.count < 2) continue;  // touches Π at one point: hides nothing
    }
    // Clip to the strip between P and the light (as a polygon; a segment is a 2-gon).
    SmallPolygon a = in_plane, b;
    clip_small(a, frame.strip[1], b);
    clip_small(b, frame.strip[0], a);
    if (a.count == 0) continue;
    double t_lo = 1e300, t_hi = -1e300;
    for (int i = 0; i < a.count; ++i) {
      const double lam = frame.lambda(p, a.p[i]);
      if (!(lam > 0)) continue;
      const double t = frame.t_of(p, a.p[i], lam);
      t_lo = std::min(t_lo, t);
      t_hi = std::max(t_hi, t);
    }
    t_lo = std::max(t_lo, 0.0);
    t_hi = std::min(t_hi, 1.0);
    if (t_hi > t_lo) scratch.hidden.emplace_back(t_lo, t_hi);
  }
  merge_to_visible(scratch.hidden, scratch.visible);
  return LinearVisibility::kIntervals;
}

}  // namespace vlit
