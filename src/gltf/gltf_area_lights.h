// EXT_lights_area: rect and disk area lights on nodes, from the draft vendor extension
// (KhronosGroup/glTF pull request #2525, extensions/2.0/Vendor/EXT_lights_area/README.md at
// commit 174a2ab; docs/gltf-lights.md says what vlit follows and where it departs).
//
// A light emits uniformly (Lambertian) from one face, toward its node's local -Z, with luminance
// `intensity` in nits: our area light of Ip = intensity (docs/conventions.md "Lights from the
// glTF file"). The shape is placed by the node's full world transform.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "core/affine.h"
#include "gltf/gltf_file.h"
#include "gltf/light_extension.h"
#include "scene/light_source.h"

namespace vlit {

inline constexpr const char* kExtLightsArea = "EXT_lights_area";

struct AreaLightDefinition {
  LightEmission emission;   // intensity in nits (the draft's default: 1000)
  bool rect = true;         // else disk
  double size = 1;          // rect: height (local Y); disk: diameter
  double aspect = 1;        // rect: width / height
};

// The root `extensions.EXT_lights_area.lights` array; empty without the extension. Throws
// InputError naming the file and the property for malformed data; unknown properties are
// warnings (the draft may grow).
std::vector<AreaLightDefinition> read_area_light_definitions(const GltfFile& file, std::vector<std::string>& warnings);

// The light a node instances (its `extensions.EXT_lights_area.light`), placed by the node's world
// transform, or nullopt with a warning when the transform collapses it to zero area. Throws
// InputError for a malformed reference.
std::optional<LightSource> place_area_light(const GltfFile& file, const std::vector<AreaLightDefinition>& definitions,
                                            int node_index, const Affine& world, std::vector<std::string>& warnings);

// Number of vertices of the polygon that stands for a disk the transform turns into an ellipse.
inline constexpr int kEllipseVertices = 64;

}  // namespace vlit
