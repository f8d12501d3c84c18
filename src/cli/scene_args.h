// The options that bake and render share, declared once: what to load (--lights,
// --no-file-lights, --max-vertices, --max-emissive-lights), --shadows and --explain.
#pragma once

#include <cstddef>
#include <string>

#include <CLI/CLI.hpp>

#include "gltf/gltf_scene.h"

namespace vlit::cli {

struct SceneArgs {
  std::string lights;  // LIGHTS.json, may be empty
  bool no_file_lights = false;
  std::size_t max_vertices = SceneLimits{}.max_vertices;
  std::size_t max_emissive_lights = SceneLimits{}.max_emissive_lights;
  std::string shadows = "off";
  bool explain = false;

  SceneOptions scene_options() const { return {{max_vertices, max_emissive_lights}, !no_file_lights}; }
  bool shadows_on() const { return shadows == "on"; }
};

// Adds the options above to `cmd`, stored in `args` (which must outlive the parse).
void add_scene_options(CLI::App& cmd, SceneArgs& args);

}  // namespace vlit::cli
