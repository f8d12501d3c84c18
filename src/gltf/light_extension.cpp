// The shared part of the light extensions' readers (light_extension.h).
#include "gltf/light_extension.h"

namespace vlit {

LightEmission read_light_emission(ExtensionObject& light, double default_intensity, const std::string& unit) {
  LightEmission e;
  e.name = light.string("name", "");
  e.color = light.vec3("color", Vec3d{1, 1, 1});
  if (e.color.x < 0 || e.color.y < 0 || e.color.z < 0) light.fail("color", "color components must be >= 0");
  e.intensity = light.number("intensity", default_intensity);
  if (e.intensity < 0) light.fail("intensity", "intensity (" + unit + ") must be >= 0");
  return e;
}

std::optional<ExtensionObject> root_light_extension(const GltfFile& file, const char* extension) {
  const auto ext = file.model.extensions.find(extension);
  if (ext == file.model.extensions.end()) return std::nullopt;
  return ExtensionObject(ext->second, file.path, std::string("extensions.") + extension);
}

std::string light_reference_path(int node_index, const char* extension) {
  return "nodes[" + std::to_string(node_index) + "].extensions." + extension;
}

int referenced_light(ExtensionObject& reference, std::size_t count, const char* extension) {
  const int index = reference.index("light");
  if (static_cast<std::size_t>(index) >= count)
    reference.fail("light", "light " + std::to_string(index) + " does not exist (the file defines " +
                                std::to_string(count) + " " + extension + " lights)");
  return index;
}

LightSource placed_light(const LightEmission& emission, const GltfFile& file, int node_index, const char* extension) {
  const tinygltf::Node& node = file.model.nodes[node_index];
  LightSource l;
  l.name = !emission.name.empty() ? emission.name
           : !node.name.empty()    ? node.name
                                   : file.path + ": " + light_reference_path(node_index, extension);
  l.color = emission.color;
  return l;
}

}  // namespace vlit
