#include "gltf/emissive_lights.h"

#include <algorithm>
#include <cmath>

#include "area_polygon.h"

namespace vlit {

bool emits_light(const Material& material) {
  const Vec3d e = material.emission();
  return !material.emissive_texture && (e.x > 0 || e.y > 0 || e.z > 0) && is_finite(e);
}

std::vector<std::uint32_t> line_segments(int mode, const std::vector<std::uint32_t>& idx) {
  std::vector<std::uint32_t> out;
  if (mode == 1) {  // LINES
    for (std::size_t i = 0; i + 1 < idx.size(); i += 2) out.insert(out.end(), {idx[i], idx[i + 1]});
  } else if (mode == 3 || mode == 2) {  // LINE_STRIP, LINE_LOOP
    for (std::size_t i = 0; i + 1 < idx.size(); ++i) out.insert(out.end(), {idx[i], idx[i + 1]});
    if (mode == 2 && idx.size() > 2) out.insert(out.end(), {idx.back(), idx.front()});
  }
  return out;
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

}  // namespace vlit
