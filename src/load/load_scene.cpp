#include "load/load_scene.h"

#include "core/input_error.h"
#include "gltf/gltf_scene.h"
#include "io/lights_json.h"
#include "mesh/mesh_file.h"
#include "scene/emissive_lights.h"

namespace vlit {

LoadedScene load_scene(const std::string& asset_path, const std::string& lights_path, const SceneOptions& options) {
  LoadedScene loaded;
  if (is_gltf_path(asset_path)) {
    loaded.gltf = load_gltf_file(asset_path);
    loaded.warnings = loaded.gltf->warnings;
    loaded.scene = build_scene(*loaded.gltf, loaded.warnings, options);
  } else if (is_mesh_path(asset_path)) {
    loaded.scene = load_mesh_file(asset_path, loaded.warnings, options.limits.max_vertices);
    // Emissive materials (an OBJ's Ke) become lights exactly as a glTF's emissive triangles.
    if (options.file_lights)
      add_emissive_triangle_lights(loaded.scene, asset_path, options.limits.max_emissive_lights, loaded.warnings);
  } else {
    throw InputError(asset_path, "unsupported file type (expected .gltf, .glb, .obj, .ply, .off or .stl)");
  }
  if (!options.file_lights) loaded.scene.lights.clear();
  if (!lights_path.empty()) {
    auto lights = read_lights_json(lights_path);
    loaded.scene.lights.insert(loaded.scene.lights.end(), lights.begin(), lights.end());
  }
  return loaded;
}

}  // namespace vlit
