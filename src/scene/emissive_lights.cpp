#include "scene/emissive_lights.h"

#include <algorithm>
#include <cmath>

#include "area_polygon.h"

namespace vlit {

bool emits_light(const Material& material) {
  const Vec3d e = material.emission();
  return !material.emissive_texture && (e.x > 0 || e.y > 0 || e.z > 0) && is_finite(e);
}

std::vector<LightSource> emissive_line_lights(const std::vector<Vec3d>& positions, const std::vector<std::uint32_t>& segments,
                                              const Material& material, const std::string& name) {
  std::vector<LightSource> out;
  for (std::size_t s = 0; s + 1 < segments.size(); s += 2) {
    LightSource l;
    l.type = LightType::kLinear;
    l.from = positions[segments[s]];
    l.to = positions[segments[s + 1]];
    const double world_length = length(l.to - l.from);
    if (!(world_length > 0) || !std::isfinite(world_length)) continue;
    l.name = name + " segment " + std::to_string(s / 2);
    l.color = material.emissive_factor;
    l.intensity = material.emissive_strength * world_length;  // candela per metre x length
    l.falloff = 2;
    out.push_back(l);
  }
  return out;
}

std::vector<LightSource> emissive_triangle_lights(const ScenePrimitive& primitive, std::size_t index, const Material& material,
                                                  const std::string& name, PlanarMergeStats* stats) {
  std::vector<LightSource> out;
  const auto polygons = merge_coplanar_triangles(primitive.positions, primitive.triangles, kMaxAreaVertices, stats);
  for (std::size_t i = 0; i < polygons.size(); ++i) {
    LightSource l;
    l.type = LightType::kArea;
    l.name = name + " polygon " + std::to_string(i);
    l.polygon = polygons[i];
    l.two_sided = material.double_sided;
    l.color = material.emissive_factor;
    l.intensity = material.emissive_strength;  // nits
    l.emitting_primitive = static_cast<long>(index);
    out.push_back(std::move(l));
  }
  return out;
}

double luminous_flux(const LightSource& l) {
  const Vec3d radiance = l.color * l.intensity;
  const double peak = std::max({radiance.x, radiance.y, radiance.z});
  if (l.type == LightType::kLinear) return 4 * M_PI * peak;
  if (l.type == LightType::kDisk) return M_PI * peak * M_PI * l.radius * l.radius * (l.two_sided ? 2 : 1);
  if (l.type == LightType::kArea) {
    Vec3d newell;
    for (std::size_t i = 0; i < l.polygon.size(); ++i) newell += cross(l.polygon[i], l.polygon[(i + 1) % l.polygon.size()]);
    return M_PI * peak * 0.5 * length(newell) * (l.two_sided ? 2 : 1);
  }
  return 4 * M_PI * peak;
}

void EmissiveLightSet::add(LightSource light) {
  Ranked r{luminous_flux(light), seen_++, std::move(light)};
  if (kept_.size() < limit_) {
    kept_.push_back(std::move(r));
    std::push_heap(kept_.begin(), kept_.end(), stronger);
  } else if (!kept_.empty() && stronger(r, kept_.front())) {
    std::pop_heap(kept_.begin(), kept_.end(), stronger);
    kept_.back() = std::move(r);
    std::push_heap(kept_.begin(), kept_.end(), stronger);
  }
}

void EmissiveLightSet::add_triangles(const ScenePrimitive& primitive, std::size_t index, const Material& material,
                                     const std::string& name) {
  PlanarMergeStats merge;
  for (auto& l : emissive_triangle_lights(primitive, index, material, name, &merge)) add(std::move(l));
  merge_.triangles += merge.triangles;
  merge_.regions += merge.regions;
  merge_.merged_regions += merge.merged_regions;
}

void EmissiveLightSet::finish(const std::string& file, std::vector<LightSource>& lights, std::vector<std::string>& warnings) {
  if (seen_ > limit_)
    warnings.push_back(file + ": emissive geometry makes " + std::to_string(seen_) + " lights; kept the " +
                       std::to_string(limit_) +
                       " brightest (the limit that keeps a bake fast; raise it with --max-emissive-lights)");
  if (merge_.regions > merge_.merged_regions)
    warnings.push_back(file + ": " + std::to_string(merge_.regions - merge_.merged_regions) +
                       " coplanar emissive regions have holes, pinched or long boundaries; their triangles are lit "
                       "as separate area lights (exact, slower)");
  if (seen_ > limit_) std::sort(kept_.begin(), kept_.end(), stronger);
  else std::sort(kept_.begin(), kept_.end(), [](const Ranked& a, const Ranked& b) { return a.order < b.order; });
  for (auto& r : kept_) lights.push_back(std::move(r.light));
  kept_.clear();
}

void add_emissive_triangle_lights(Scene& scene, const std::string& file, std::size_t limit,
                                  std::vector<std::string>& warnings) {
  EmissiveLightSet set(limit);
  for (std::size_t i = 0; i < scene.primitives.size(); ++i) {
    const Material& material = scene.material_of(scene.primitives[i]);
    if (emits_light(material))
      set.add_triangles(scene.primitives[i], i, material,
                        file + ": " + (material.name.empty() ? "primitive " + std::to_string(i) : "material " + material.name));
  }
  set.finish(file, scene.lights, warnings);
}

}  // namespace vlit
