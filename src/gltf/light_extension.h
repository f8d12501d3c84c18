// What the node-instanced light extensions (EXT_lights_area, gltf_area_lights.h;
// VLIT_lights_linear, gltf_linear_lights.h) share: a root `extensions.<name>.lights[]` array of
// definitions, each with a name, a colour and an intensity, and nodes that instance one by index
// with `extensions.<name>.light`. Errors are InputErrors naming the file and the JSON path.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <tiny_gltf.h>

#include "core/vec3.h"
#include "gltf/extension_object.h"
#include "gltf/gltf_file.h"
#include "scene/light_source.h"

namespace vlit {

// The emission of a light definition: colour components >= 0, intensity >= 0 in the extension's
// unit (nits for an area light, cd per metre for a tube).
struct LightEmission {
  std::string name;
  Vec3d color{1, 1, 1};
  double intensity = 1;
};

// Reads "name", "color" and "intensity" (default `default_intensity`, unit `unit` for the message).
LightEmission read_light_emission(ExtensionObject& light, double default_intensity, const std::string& unit);

// The root object `extensions.<extension>` of the file; nothing when the file has none.
std::optional<ExtensionObject> root_light_extension(const GltfFile& file, const char* extension);

// The definitions of the root `extensions.<extension>.lights[]` array, empty without the
// extension: each one's emission (read_light_emission with the extension's default intensity and
// unit), then read_shape(light, definition) reads the rest; unread(object) deals with the
// properties left unread, of each light and then of the root (a warning or an error).
template <class Definition, class ReadShape, class Unread>
std::vector<Definition> read_light_definitions(const GltfFile& file, const char* extension, double default_intensity,
                                               const std::string& unit, const ReadShape& read_shape, const Unread& unread) {
  std::vector<Definition> out;
  std::optional<ExtensionObject> root = root_light_extension(file, extension);
  if (!root) return out;
  for (ExtensionObject& light : root->objects("lights")) {
    Definition d;
    d.emission = read_light_emission(light, default_intensity, unit);
    read_shape(light, d);
    unread(light);
    out.push_back(d);
  }
  unread(*root);
  return out;
}

// "nodes[i].extensions.<extension>", the JSON path of a node's reference.
std::string light_reference_path(int node_index, const char* extension);

// The definition index a node's reference names, checked against the `count` definitions.
int referenced_light(ExtensionObject& reference, std::size_t count, const char* extension);

// The light node `node_index` instances, before its shape: named by the definition, else by the
// node, else by file and JSON path; the definition's colour. (The intensity depends on the shape.)
LightSource placed_light(const LightEmission& emission, const GltfFile& file, int node_index, const char* extension);

}  // namespace vlit
