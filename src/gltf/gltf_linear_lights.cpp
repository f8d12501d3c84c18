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
  std::vector<LinearLightDefinition> out;
  std::optional<ExtensionObject> root = root_light_extension(file, kVlitLightsLinear);
  if (!root) return out;
  for (ExtensionObject& light : root->objects("lights")) {
    LinearLightDefinition d;
    d.emission = read_light_emission(light, 1.0, "cd per metre");
    d.from = light.vec3("from");
    d.to = light.vec3("to");
    d.falloff = light.number("falloff", 2.0);
    if (d.falloff < 0 || d.falloff > 3) light.fail("falloff", "falloff must be in [0, 3]");
    reject_unknown(light);
    out.push_back(d);
  }
  reject_unknown(*root);
  return out;
}

std::optional<LightSource> place_linear_light(const GltfFile& file, const std::vector<LinearLightDefinition>& definitions,
                                              int node_index, const Affine& world, std::vector<std::string>& warnings) {
  const tinygltf::Node& node = file.model.nodes[node_index];
  ExtensionObject ref(node.extensions.at(kVlitLightsLinear), file.path, node_path(node_index));
  const LinearLightDefinition& d = definitions[referenced_light(ref, definitions.size(), kVlitLightsLinear)];
  reject_unknown(ref);
  LightSource l = placed_light(d.emission, node, file.path, node_path(node_index));
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
