#include "gltf/gltf_linear_lights.h"

#include <cmath>

#include "core/input_error.h"
#include "gltf/extension_object.h"

namespace vlit {
namespace {

std::string node_path(int node) { return light_reference_path(node, kVlitLightsLinear); }

void reject_unknown(const ExtensionObject& object) {
  for (const std::string& k : object.unread_keys())
    object.fail(k, "unknown property (check the spelling; see docs/gltf-lights.md)");
}

}  // namespace

std::vector<LinearLightDefinition> read_linear_light_definitions(const GltfFile& file) {
  auto read_shape = [](ExtensionObject& light, LinearLightDefinition& d) {
    d.from = light.vec3("from");
    d.to = light.vec3("to");
    d.falloff = light.number("falloff", 2.0);
    if (d.falloff < 0 || d.falloff > 3) light.fail("falloff", "falloff must be in [0, 3]");
  };
  // Our own extension: an unknown property is an error (a typo would silently change the light).
  return read_light_definitions<LinearLightDefinition>(file, kVlitLightsLinear, 1.0, "cd per metre", read_shape,
                                                       reject_unknown);
}

std::optional<LightSource> place_linear_light(const GltfFile& file, const std::vector<LinearLightDefinition>& definitions,
                                              int node_index, const Affine& world, std::vector<std::string>& warnings) {
  ExtensionObject ref(file.model.nodes[node_index].extensions.at(kVlitLightsLinear), file.path, node_path(node_index));
  const LinearLightDefinition& d = definitions[referenced_light(ref, definitions.size(), kVlitLightsLinear)];
  reject_unknown(ref);
  LightSource l = placed_light(d.emission, file, node_index, kVlitLightsLinear);
  l.type = LightType::kLinear;
  l.falloff = d.falloff;
  l.from = world.apply_point(d.from);
  l.to = world.apply_point(d.to);
  const double world_length = length(l.to - l.from);
  l.intensity = d.emission.intensity * world_length;
  if (!(world_length > 0) || !std::isfinite(l.intensity)) {
    warnings.push_back(file.path + ": " + node_path(node_index) + ": the segment has zero length in world space; ignored");
    return std::nullopt;
  }
  return l;
}

}  // namespace vlit
