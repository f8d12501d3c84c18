// A light as the user described it (LIGHTS.json or the glTF file), in world space, before any
// per-light constants are computed. The shading layer (src/shading/) turns it into a kernel.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "core/vec3.h"

namespace vlit {

enum class LightType { kPoint, kDirectional, kSpot, kLinear, kArea, kDisk };

const char* light_type_name(LightType type);

struct LightSource {
  LightType type = LightType::kPoint;
  std::string name;                 // for messages: "lights.json: lights[2]" or the glTF node name
  Vec3d color{1, 1, 1};             // linear RGB multiplier
  double intensity = 1;             // scalar Ip (per unit t for linear lights, radiance for area)
  double falloff = 2;               // decay exponent n (point, spot, linear)
  std::optional<double> range;      // glTF KHR_lights_punctual range: no light beyond it

  Vec3d position;                   // point, spot
  Vec3d direction{0, 0, -1};        // directional, spot: unit direction the light travels
  double cos_inner = 1;             // spot cone
  double cos_outer = 0.70710678118654752;

  Vec3d from, to;                   // linear: segment Q0 -> Q1

  std::vector<Vec3d> polygon;       // area: planar, counter-clockwise seen from the emitting side
  bool two_sided = false;           // area, disk

  Vec3d center, normal{0, 0, 1};    // disk: emits toward normal
  double radius = 1;

  // A light made from a primitive's own emissive triangles (scene/emissive_lights.h): index into
  // Scene::primitives of that primitive, which this light does not light; -1 otherwise.
  long emitting_primitive = -1;

  bool casts_shadows = true;        // LIGHTS.json "shadows": false = never shadowed (docs/shadows.md)
};

}  // namespace vlit
