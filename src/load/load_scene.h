// The loading stage: what a command works on, read into one world-space Scene. An asset (glTF, or
// an OBJ, PLY, OFF or STL mesh) plus the lights of an optional LIGHTS.json. This stage sits above
// the world model (src/scene/, which knows no file format) and calls the readers: gltf/, mesh/,
// io/lights_json.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "gltf/gltf_file.h"
#include "gltf/gltf_scene.h"
#include "scene/scene.h"

namespace vlit {

struct LoadedScene {
  Scene scene;
  std::optional<GltfFile> gltf;        // present when the asset is glTF (the bake writes it back)
  std::vector<std::string> warnings;   // one line each, already prefixed with the file name
};

// Throws InputError naming the file for anything it cannot read, or for an asset beyond
// options.limits. The lights stored in the asset (KHR_lights_punctual, EXT_lights_area,
// VLIT_lights_linear, emissive geometry, emissive .mtl materials of an OBJ: docs/gltf-lights.md)
// are kept unless options.file_lights is false; the lights of LIGHTS.json (lights_path, may be
// empty) are added after them.
LoadedScene load_scene(const std::string& asset_path, const std::string& lights_path, const SceneOptions& options = {});

}  // namespace vlit
