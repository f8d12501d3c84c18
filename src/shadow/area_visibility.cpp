#include "shadow/area_visibility.h"

#include <algorithm>
#include <cmath>

namespace vlit {
namespace {

double twice_area(const Vec3d* d, int n) {
  Vec3d a{};
  for (int i = 0; i < n; ++i) a += cross(d[i], d[(i + 1) % n]);
  return length(a);
}

}  // namespace

AreaSlab area_slab(const PreparedAreaLight<double>& light, const AreaView<double>& view, const Vec3d& p) {
  const double margin = kLightPlaneMargin * (view.height + light.radius);
  AreaSlab s;
  s.beyond_light = {view.normal, light.center + view.normal * margin};
  s.before_p = {-view.normal, p - view.normal * (view.height * kApexMargin)};
  return s;
}

Rect2 light_rectangle(const AreaView<double>& view, const ClipPolygon<double>& horizon_clipped) {
  Rect2 r;
  for (int i = 0; i < horizon_clipped.count; ++i)
    r.grow(dot(view.u, horizon_clipped.d[i]), dot(view.v, horizon_clipped.d[i]));
  return r;
}

bool is_occluder(const OccluderBvh& occluders, std::uint32_t index, const Vec3d& p, bool* front) {
  const OccluderTriangles& triangles = occluders.triangles();
  const OccluderBvh::TrianglePlane& plane = occluders.plane(index);
  if (culled_back_face(triangles, index, p, plane.normal)) return false;
  // A needle: no area, and no reliable plane.
  if (!(plane.normal_length > kSliver * plane.longest_squared)) return false;
  const int facing = facing_from_plane(plane.normal, plane.normal_length, triangles.corners[index][0], p);
  if (facing == 0) return false;  // edge-on or zero area
  if (front) *front = facing > 0;
  return true;
}

ConvexVolume area_shadow_volume(const PreparedAreaLight<double>& light, const AreaView<double>& view,
                                const Rect2& rect, const Vec3d& p) {
  const double x0 = rect.x0, x1 = rect.x1, y0 = rect.y0, y1 = rect.y1;
  const Vec3d corner[4] = {light.center + view.u * x0 + view.v * y0, light.center + view.u * x1 + view.v * y0,
                           light.center + view.u * x1 + view.v * y1, light.center + view.u * x0 + view.v * y1};
  const Vec3d middle = light.center + view.u * (0.5 * (x0 + x1)) + view.v * (0.5 * (y0 + y1));
  ConvexVolume volume;
  volume.box.grow(p);
  for (const Vec3d& c : corner) volume.box.grow(c);
  for (int k = 0; k < 4; ++k) {
    Vec3d normal = cross(corner[k] - p, corner[(k + 1) % 4] - p);
    if (dot(normal, middle - p) < 0) normal = -normal;
    if (length_squared(normal) > 0) volume.planes.push_back({normal, p});
  }
  const AreaSlab slab = area_slab(light, view, p);
  volume.planes.push_back(slab.beyond_light);
  volume.planes.push_back(slab.before_p);
  return volume;
}

ConvexVolume area_shadow_volume(const PreparedAreaLight<double>& light, const AreaView<double>& view,
                                const ClipPolygon<double>& horizon_clipped, const Vec3d& p) {
  return area_shadow_volume(light, view, light_rectangle(view, horizon_clipped), p);
}

bool subtract_cone(const LightPieces& pieces, const Vec3d* cone_normal, int planes, const Rect2& shadow,
                   const AreaView<double>& view, double area_floor, LightPieces& next) {
  ClipPolygon<double> buffer_a, buffer_b, outside;
  bool cut = false;
  next.clear();
  for (std::size_t i = 0; i < pieces.size(); ++i) {
    const Vec3d* d = pieces.points.data() + pieces.start[i];
    const int n = pieces.start[i + 1] - pieces.start[i];
    // A piece that does not meet the cone is kept whole: first the cheap tests (disjoint
    // rectangles; all its corners outside one plane), then the exact one (its part inside
    // every plane is empty or of negligible area). Cutting a piece the cone misses would
    // only fragment it.
    bool untouched = !pieces.rect[i].overlaps(shadow);
    for (int j = 0; j < planes && !untouched; ++j) {
      const double offset = dot(cone_normal[j], view.D);
      bool all_out = true;
      for (int v = 0; v < n && all_out; ++v) all_out = dot(cone_normal[j], d[v]) + offset <= 0;
      untouched = all_out;
    }
    if (!untouched) {
      ClipPolygon<double>* rest = &buffer_a;
      ClipPolygon<double>* tmp = &buffer_b;
      rest->count = n;
      std::copy(d, d + n, rest->d.begin());
      for (int j = 0; j < planes && rest->count >= 3; ++j) {
        clip_halfspace(rest->d.data(), rest->count, cone_normal[j], dot(cone_normal[j], view.D), *tmp);
        std::swap(rest, tmp);
      }
      untouched = rest->count < 3 || !(twice_area(rest->d.data(), rest->count) > area_floor);
    }
    if (untouched) {
      next.add(d, n, pieces.rect[i]);
      continue;
    }
    cut = true;
    ClipPolygon<double>* rest = &buffer_a;
    ClipPolygon<double>* tmp = &buffer_b;
    rest->count = n;
    std::copy(d, d + n, rest->d.begin());
    for (int j = 0; j < planes && rest->count >= 3; ++j) {
      const double offset = dot(cone_normal[j], view.D);
      clip_halfspace(rest->d.data(), rest->count, -cone_normal[j], -offset, outside);
      if (outside.count >= 3 && twice_area(outside.d.data(), outside.count) > area_floor)
        next.add(outside.d.data(), outside.count, view.u, view.v);
      clip_halfspace(rest->d.data(), rest->count, cone_normal[j], offset, *tmp);
      std::swap(rest, tmp);
    }
    // What is left in `rest` is inside the cone: hidden.
  }
  return cut;
}

AreaVisibility visible_area_pieces(const PreparedAreaLight<double>& light, const AreaView<double>& view,
                                   const ClipPolygon<double>& horizon_clipped, const Vec3d& p,
                                   const OccluderBvh& occluders, AreaShadowScratch& scratch) {
  const ConvexVolume volume = area_shadow_volume(light, view, horizon_clipped, p);
  occluders.triangles_in_volume(volume, p, scratch.candidates);
  if (scratch.candidates.empty()) return AreaVisibility::kUnoccluded;

  const AreaSlab slab = area_slab(light, view, p);
  const std::vector<HalfSpace> slab_planes{slab.beyond_light, slab.before_p};
  const double area_floor = piece_area_floor(light);
  LightPieces& pieces = scratch.pieces;
  LightPieces& next = scratch.next;
  pieces.clear();
  pieces.add(horizon_clipped.d.data(), horizon_clipped.count, view.u, view.v);
  const Vec3d foot{dot(view.u, -view.D), dot(view.v, -view.D), 0};  // P's foot on the light, in (u, v)

  // The cones of the occluders, front faces (as seen from P) first and larger shadows first:
  // pieces are then consumed by the big and near occluders before the others can cut them, so
  // they fragment less. The order depends only on the candidates (BVH on or off alike).
  std::vector<OccluderCone>& cones = scratch.cones;
  cones.clear();
  for (std::uint32_t index : scratch.candidates) {
    bool front = false;
    if (!is_occluder(occluders, index, p, &front)) continue;
    const auto& tri = occluders.triangles().corners[index];
    const double sigma = front ? -1.0 : 1.0;
    const SmallPolygon part = clip_triangle(tri, slab_planes);
    if (part.count < 3) continue;
    // One plane through P per edge of the clipped occluder; inside the cone: dot(k, x - P) >= 0.
    OccluderCone cone;
    for (int j = 0; j < part.count; ++j) {
      const Vec3d a = part.p[j] - p, b = part.p[(j + 1) % part.count] - p;
      const Vec3d k = cross(a, b) * sigma;
      if (length(k) > 1e-14 * length(a) * length(b)) cone.normal[cone.planes++] = k;
    }
    if (cone.planes < 3) continue;
    // The occluder's central projection from P onto the light's plane, as a rectangle in (u, v):
    // x - P = w projects to P + w h / z, z = -n.w > 0 inside the slab.
    for (int j = 0; j < part.count; ++j) {
      const Vec3d w = part.p[j] - p;
      const double scale = view.height / -dot(view.normal, w);
      cone.shadow.grow(foot.x + dot(view.u, w) * scale, foot.y + dot(view.v, w) * scale);
    }
    const double pad = 1e-9 * (light.radius + std::abs(foot.x) + std::abs(foot.y));
    cone.shadow.x0 -= pad; cone.shadow.x1 += pad; cone.shadow.y0 -= pad; cone.shadow.y1 += pad;
    cone.front = front;
    cone.size = (cone.shadow.x1 - cone.shadow.x0) * (cone.shadow.y1 - cone.shadow.y0);
    cone.index = index;
    cones.push_back(cone);
  }
  std::sort(cones.begin(), cones.end(), [](const OccluderCone& a, const OccluderCone& b) {
    if (a.front != b.front) return a.front;
    if (a.size != b.size) return a.size > b.size;
    return a.index < b.index;
  });

  for (const OccluderCone& cone : cones) {
    if (pieces.size() == 0) break;  // fully hidden
    subtract_cone(pieces, cone.normal.data(), cone.planes, cone.shadow, view, area_floor, next);
    std::swap(pieces, next);
  }
  return AreaVisibility::kPieces;
}

}  // namespace vlit
