// One complete bake: read an asset and its lights, light every vertex, store the light as vertex
// colours, write the result atomically. The command line runs this once per input file.
#pragma once

#include <atomic>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "bake/vertex_color_bake.h"
#include "gltf/gltf_scene.h"

namespace vlit {

struct BakeFileOptions {
  std::string lights_path;        // LIGHTS.json, may be empty
  std::vector<LightSource> lights;  // added after those of lights_path (the library API, src/api/)
  SceneLimits limits;             // --max-vertices, --max-emissive-lights
  bool use_file_lights = true;    // keep the lights stored in the asset (docs/gltf-lights.md)
  bool float_batch = true;        // diffuse in the float SIMD batch kernels where they apply (LightingRequest)
  bool shadows = false;           // --shadows on (docs/shadows.md)
  bool embed_images = true;       // a .glb output embeds the input's image files (--keep-image-links: false)
  bool meshopt = false;           // --meshopt: vertex and index data written with EXT_meshopt_compression
  BakeOptions encode;             // target attribute, format, exposure, unlit
  // Bake specular for this eye (world space), folded into the stored multiplier
  // (vertex_color_bake.h); no specular without an eye.
  std::optional<Vec3d> specular_eye;
  SpecularOptions specular;       // method for linear and area lights (--specular)
  // Polled between chunks of vertices; when it becomes true the bake stops with an error and
  // writes nothing. May be null.
  const std::atomic<bool>* cancel = nullptr;
  std::function<void(std::size_t, std::size_t)> progress;  // (vertices done, total), may be empty
};

struct StageTimes {
  double load = 0, plan = 0, light = 0, encode = 0, write = 0;  // seconds
};

struct BakeFileResult {
  BakeReport report;
  std::string plan;   // describe(plan): what runs, what was skipped and why (for --explain)
  StageTimes seconds;
  std::vector<std::string> warnings;  // one line each, prefixed with the file name
  std::size_t lights = 0;
};

// Throws InputError naming the file for any problem; on failure no output file exists (an
// existing one is left as it was).
BakeFileResult bake_file(const std::string& input, const std::string& output, const BakeFileOptions& options);

}  // namespace vlit
