#include "plan/shadow_plan.h"

#include <algorithm>
#include <cmath>

#include "shadow/convex_volume.h"

namespace vlit {
namespace {

Aabb bounds_of(const ScenePrimitive& p) {
  Aabb b;
  for (const Vec3d& v : p.positions) b.grow(v);
  return b;
}

// All positions on one plane (to 1e-9 of the primitive's size): it cannot shadow itself.
bool is_planar(const ScenePrimitive& p, const Aabb& box) {
  const double size = length(box.hi - box.lo);
  const std::size_t n = p.positions.size();
  for (std::size_t t = 0; t + 2 < p.triangles.size(); t += 3) {
    const std::uint32_t a = p.triangles[t], b = p.triangles[t + 1], c = p.triangles[t + 2];
    if (a >= n || b >= n || c >= n) continue;
    const Vec3d normal = cross(p.positions[b] - p.positions[a], p.positions[c] - p.positions[a]);
    const double len = length(normal);
    if (!(len > 1e-12 * size * size)) continue;
    const Vec3d unit = normal / len;
    for (const Vec3d& v : p.positions)
      if (std::abs(dot(v - p.positions[a], unit)) > 1e-9 * size) return false;
    return true;
  }
  return true;  // no triangle of non-zero area: hides nothing
}

// The box holding every segment from a point of `receiver` to the light.
Aabb between(const LightSource& l, const Aabb& receiver, const Aabb& scene) {
  Aabb b = receiver;
  switch (l.type) {
    case LightType::kPoint:
    case LightType::kSpot: b.grow(l.position); break;
    case LightType::kLinear: b.grow(l.from); b.grow(l.to); break;
    case LightType::kArea: for (const Vec3d& q : l.polygon) b.grow(q); break;
    case LightType::kDisk: {
      const Vec3d r{l.radius, l.radius, l.radius};
      b.grow(l.center - r);
      b.grow(l.center + r);
      break;
    }
    case LightType::kDirectional: {
      // Swept toward the light past the whole scene.
      const double reach = length(scene.hi - scene.lo) + length(receiver.center() - scene.center()) + 1;
      const Vec3d shift = -l.direction * reach;
      b.grow(receiver.lo + shift);
      b.grow(receiver.hi + shift);
      break;
    }
  }
  const double pad = 1e-9 * (length(b.hi - b.lo) + length(b.center()));
  b.lo = b.lo - Vec3d{pad, pad, pad};
  b.hi = b.hi + Vec3d{pad, pad, pad};
  return b;
}

}  // namespace

void plan_shadows(const Scene& scene, const std::vector<const LightSource*>& kept, bool shadows_on, ScenePlan& plan) {
  plan.shadows_requested = shadows_on;
  plan.occluder_triangles = 0;
  for (const ScenePrimitive& p : scene.primitives) plan.occluder_triangles += p.triangles.size() / 3;
  plan.shadowed_of_primitive.assign(scene.primitives.size(), {});
  for (std::size_t p = 0; p < scene.primitives.size(); ++p)
    plan.shadowed_of_primitive[p].assign(plan.lights_of_primitive[p].size(), 0);
  if (!shadows_on) return;
  std::vector<Aabb> boxes;
  std::vector<char> planar;
  Aabb scene_box;
  for (const ScenePrimitive& prim : scene.primitives) {
    boxes.push_back(bounds_of(prim));
    planar.push_back(is_planar(prim, boxes.back()));
    if (!boxes.back().empty()) scene_box.grow(boxes.back());
  }
  for (std::size_t p = 0; p < scene.primitives.size(); ++p) {
    for (std::size_t k = 0; k < plan.lights_of_primitive[p].size(); ++k) {
      const LightSource& light = *kept[plan.lights_of_primitive[p][k]];
      if (!light.casts_shadows) continue;  // reported once per light below
      const Aabb volume = between(light, boxes[p], scene_box);
      bool may_occlude = false;
      for (std::size_t q = 0; q < scene.primitives.size() && !may_occlude; ++q) {
        if (boxes[q].empty() || scene.primitives[q].triangles.empty()) continue;
        if (q == p) may_occlude = !planar[p];
        else may_occlude = boxes[q].overlaps(volume);
      }
      if (may_occlude) {
        plan.shadowed_of_primitive[p][k] = 1;
        ++plan.shadowed_pairs;
        plan.needs_occluders = true;
      } else {
        plan.skipped.add("nothing can lie between them",
                         [&] { return "shadows of light " + light.name + " on primitive " + std::to_string(p); });
      }
    }
  }
  for (const LightSource* light : kept)
    if (!light->casts_shadows) plan.skipped.add("\"shadows\": false", [&] { return "shadows of light " + light->name; });
}

}  // namespace vlit
