// Loading what a command works on: an asset (glTF now; mesh formats through OpenMesh) plus the
// lights of an optional LIGHTS.json, into one world-space Scene.
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

// Throws InputError naming the file for anything it cannot read.
// The file's own lights (glTF light extensions, emissive glTF triangles, emissive .mtl materials
// of an OBJ) are kept unless use_file_lights is false; the lights of LIGHTS.json are added to them.
LoadedScene load_scene(const std::string& asset_path, const std::string& lights_path, bool use_file_lights = true);
// Same with explicit limits instead of default_scene_limits() (the library API, src/api/).
LoadedScene load_scene(const std::string& asset_path, const std::string& lights_path, bool use_file_lights,
                       const SceneLimits& limits);

}  // namespace vlit
