// VLIT_lights_linear: vlit's vendor extension for linear (tube) lights on nodes, so a tube light
// can travel inside a glTF (docs/gltf-lights.md has the schema and an example).
//
// Root `extensions.VLIT_lights_linear.lights[]`: {name, color, intensity, from, to, falloff};
// a node instances one with `extensions.VLIT_lights_linear.light`. `from` and `to` are the
// segment's ends in the node's local space; `intensity` is in candela per metre of the segment's
// world length (each piece dl of the tube is an isotropic point light of intensity x dl), so
// our linear light's Ip = intensity x world length (docs/conventions.md).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "core/affine.h"
#include "gltf/gltf_file.h"
#include "gltf/light_extension.h"
#include "scene/light_source.h"

namespace vlit {

inline constexpr const char* kVlitLightsLinear = "VLIT_lights_linear";

struct LinearLightDefinition {
  LightEmission emission;  // intensity in cd per metre of the tube
  Vec3d from, to;        // node-local segment
  double falloff = 2;    // decay exponent n of paper eq. 1, in [0, 3]
};

// The root definitions; empty without the extension. Throws InputError naming the file and the
// property for malformed data or an unknown property (this is our own extension).
std::vector<LinearLightDefinition> read_linear_light_definitions(const GltfFile& file);

// The light a node instances, placed by its world transform; nullopt with a warning when the
// transform collapses the segment to a point (zero length: no light). Throws InputError for a
// malformed reference.
std::optional<LightSource> place_linear_light(const GltfFile& file, const std::vector<LinearLightDefinition>& definitions,
                                              int node_index, const Affine& world, std::vector<std::string>& warnings);

}  // namespace vlit
