// Light sources for tests and benchmarks, built the way LIGHTS.json describes them
// (docs/lights-json.md): a tube, a planar polygon, a disk.
#pragma once

#include <utility>
#include <vector>

#include "scene/light_source.h"

namespace vlit::test {

// A light of `type` named `name`, the rest at LightSource's defaults.
inline LightSource named_source(LightType type, const char* name, bool two_sided = false) {
  LightSource l;
  l.type = type;
  l.name = name;
  l.two_sided = two_sided;
  return l;
}

inline LightSource linear_source(const Vec3d& q0, const Vec3d& q1, double falloff) {
  LightSource l = named_source(LightType::kLinear, "tube");
  l.from = q0;
  l.to = q1;
  l.falloff = falloff;
  return l;
}

// `polygon` counter-clockwise seen from the emitting side.
inline LightSource area_source(std::vector<Vec3d> polygon, bool two_sided = false) {
  LightSource l = named_source(LightType::kArea, "panel", two_sided);
  l.polygon = std::move(polygon);
  return l;
}

inline LightSource disk_source(const Vec3d& center, const Vec3d& normal, double radius, bool two_sided = false) {
  LightSource l = named_source(LightType::kDisk, "disk", two_sided);
  l.center = center;
  l.normal = normal;
  l.radius = radius;
  return l;
}

}  // namespace vlit::test
