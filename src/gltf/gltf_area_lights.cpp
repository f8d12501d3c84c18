#include "gltf/gltf_area_lights.h"

#include <algorithm>
#include <cmath>

#include "core/input_error.h"
#include "gltf/extension_object.h"

namespace vlit {
namespace {

std::string node_path(int node) { return light_reference_path(node, kExtLightsArea); }

// The polygon with the node's transform applied, counter-clockwise seen from the side it emits
// to. Local polygons are given with their Newell normal along local -Z; a mirroring transform
// reverses their winding, so the order is reversed back: the light then emits into the image of
// its local z < 0 half-space (as a mesh face keeps facing its outside, gltf_scene.cpp).
std::vector<Vec3d> place(const std::vector<Vec3d>& local, const Affine& world) {
  std::vector<Vec3d> out;
  for (const Vec3d& q : local) out.push_back(world.apply_point(q));
  if (world.determinant() < 0) std::reverse(out.begin(), out.end());
  return out;
}

double polygon_area(const std::vector<Vec3d>& polygon) {
  Vec3d newell;
  for (std::size_t i = 0; i < polygon.size(); ++i) newell += cross(polygon[i] - polygon[0], polygon[(i + 1) % polygon.size()] - polygon[0]);
  return 0.5 * length(newell);
}

}  // namespace

std::vector<AreaLightDefinition> read_area_light_definitions(const GltfFile& file, std::vector<std::string>& warnings) {
  // The draft may grow: unknown properties are warnings.
  auto warn_unread = [&](const ExtensionObject& object) {
    for (const std::string& k : object.unread_keys())
      warnings.push_back(file.path + ": " + object.path() + "." + k + ": unknown property; ignored");
  };
  auto read_shape = [&](ExtensionObject& light, AreaLightDefinition& d) {
    const std::string type = light.string("type");
    if (type != "rect" && type != "disk") light.fail("type", "unknown area light type \"" + type + "\" (expected rect or disk)");
    d.rect = type == "rect";
    d.size = light.number("size", 1.0);
    if (!(d.size > 0)) light.fail("size", "size must be > 0");
    if (d.rect) {
      ExtensionObject rect = light.object("rect");
      d.aspect = rect.number("aspect", 1.0);
      if (!(d.aspect > 0)) rect.fail("aspect", "aspect must be > 0");
      warn_unread(rect);
    }
  };
  return read_light_definitions<AreaLightDefinition>(file, kExtLightsArea, 1000.0, "nits", read_shape, warn_unread);
}

std::optional<LightSource> place_area_light(const GltfFile& file, const std::vector<AreaLightDefinition>& definitions,
                                            int node_index, const Affine& world, std::vector<std::string>& warnings) {
  ExtensionObject ref(file.model.nodes[node_index].extensions.at(kExtLightsArea), file.path, node_path(node_index));
  const AreaLightDefinition& d = definitions[referenced_light(ref, definitions.size(), kExtLightsArea)];
  LightSource l = placed_light(d.emission, file, node_index, kExtLightsArea);
  l.intensity = d.emission.intensity;
  l.two_sided = false;
  if (d.rect) {
    const double hw = 0.5 * d.size * d.aspect, hh = 0.5 * d.size;
    // Newell normal along local -Z (counter-clockwise seen from below).
    l.type = LightType::kArea;
    l.polygon = place({{-hw, -hh, 0}, {-hw, hh, 0}, {hw, hh, 0}, {hw, -hh, 0}}, world);
  } else {
    const Vec3d ex = world.apply_vector({1, 0, 0}), ey = world.apply_vector({0, 1, 0});
    const double lx = length(ex), ly = length(ey);
    const bool circle = std::abs(lx - ly) <= 1e-9 * std::max(lx, ly) && std::abs(dot(ex, ey)) <= 1e-9 * lx * ly;
    if (circle) {
      l.type = LightType::kDisk;
      l.center = world.apply_point({0, 0, 0});
      l.normal = normalize(world.apply_normal({0, 0, -1}));
      l.radius = 0.5 * d.size * lx;
    } else {
      // An ellipse: a regular polygon of the same area, stretched by the transform. The inscribed
      // n-gon of radius r has area (n/2) r^2 sin(2 pi/n), so r = R sqrt(pi / ((n/2) sin(2 pi/n))).
      const int n = kEllipseVertices;
      const double r = 0.5 * d.size * std::sqrt(M_PI / (0.5 * n * std::sin(2 * M_PI / n)));
      std::vector<Vec3d> local;
      for (int i = 0; i < n; ++i) {  // clockwise in local XY: Newell normal along -Z
        const double phi = -2 * M_PI * i / n;
        local.push_back({r * std::cos(phi), r * std::sin(phi), 0});
      }
      l.type = LightType::kArea;
      l.polygon = place(local, world);
    }
  }
  const double area = l.type == LightType::kDisk ? M_PI * l.radius * l.radius : polygon_area(l.polygon);
  if (!(area > 0) || !std::isfinite(area) || (l.type == LightType::kDisk && length_squared(l.normal) == 0)) {
    warnings.push_back(file.path + ": " + node_path(node_index) + ": the node's transform gives the light zero area; ignored");
    return std::nullopt;
  }
  return l;
}

}  // namespace vlit
