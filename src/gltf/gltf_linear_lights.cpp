#include "gltf/gltf_linear_lights.h"

#include <cmath>

#include "core/input_error.h"
#include "gltf/extension_object.h"

namespace vlit {
namespace {

std::string node_path(int node) { return "nodes[" + std::to_string(node) + "].extensions." + kVlitLightsLinear; }

void reject_unknown(const ExtensionObject& object) {
  for (const std::string& k : object.unread_keys())
    object.fail(k, "unknown property (check the spelling; see docs/gltf-lights.md)");
}

}  // namespace

std::vector<LinearLightDefinition> read_linear_light_definitions(const GltfFile& file) {
  std::vector<LinearLightDefinition> out;
  const auto ext = file.model.extensions.find(kVlitLightsLinear);
  if (ext == file.model.extensions.end()) return out;
  ExtensionObject root(ext->second, file.path, std::string("extensions.") + kVlitLightsLinear);
  for (ExtensionObject& light : root.objects("lights")) {
    LinearLightDefinition d;
    d.name = light.string("name", "");
    d.color = light.vec3("color", Vec3d{1, 1, 1});
    if (d.color.x < 0 || d.color.y < 0 || d.color.z < 0) light.fail("color", "color components must be >= 0");
    d.intensity = light.number("intensity", 1.0);
    if (d.intensity < 0) light.fail("intensity", "intensity (cd per metre) must be >= 0");
    d.from = light.vec3("from");
    d.to = light.vec3("to");
    d.falloff = light.number("falloff", 2.0);
    if (d.falloff < 0 || d.falloff > 3) light.fail("falloff", "falloff must be in [0, 3]");
    reject_unknown(light);
    out.push_back(d);
  }
  reject_unknown(root);
  return out;
}

std::optional<LightSource> place_linear_light(const GltfFile& file, const std::vector<LinearLightDefinition>& definitions,
                                              int node_index, const Affine& world, std::vector<std::string>& warnings) {
  const tinygltf::Node& node = file.model.nodes[node_index];
  ExtensionObject ref(node.extensions.at(kVlitLightsLinear), file.path, node_path(node_index));
  const int index = ref.index("light");
  if (static_cast<std::size_t>(index) >= definitions.size())
    ref.fail("light", "light " + std::to_string(index) + " does not exist (the file defines " +
                          std::to_string(definitions.size()) + " VLIT_lights_linear lights)");
  reject_unknown(ref);
  const LinearLightDefinition& d = definitions[index];
  LightSource l;
  l.type = LightType::kLinear;
  l.name = !d.name.empty() ? d.name : !node.name.empty() ? node.name : file.path + ": " + node_path(node_index);
  l.color = d.color;
  l.falloff = d.falloff;
  l.from = world.apply_point(d.from);
  l.to = world.apply_point(d.to);
  const double world_length = length(l.to - l.from);
  l.intensity = d.intensity * world_length;
  if (!(world_length > 0) || !std::isfinite(l.intensity)) {
    warnings.push_back(file.path + ": " + node_path(node_index) + ": the segment has zero length in world space; ignored");
    return std::nullopt;
  }
  return l;
}

}  // namespace vlit
