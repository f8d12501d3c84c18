// libFuzzer target: bytes -> glTF loader (tinygltf, compiled into this target so it is
// instrumented) -> world-space scene -> per-vertex lighting -> COLOR_0 bake -> GLB serialization.
// The contract under test (docs/robustness.md): bad input ends in an InputError, never in a
// crash, a sanitizer report, an unbounded allocation or another exception type; every baked
// colour is finite; the written GLB loads back.
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstdio>
#include <filesystem>
#include <string>

#include <unistd.h>

#include "bake/light_vertices.h"
#include "bake/vertex_color_bake.h"
#include "core/input_error.h"
#include "gltf/gltf_memory.h"
#include "gltf/gltf_scene.h"
#include "gltf/gltf_writer.h"

namespace {

// Where each baked output goes: RAM-backed when /dev/shm exists (the writer fsyncs).
const std::string& output_path() {
  static const std::string path =
      (std::filesystem::is_directory("/dev/shm") ? std::string("/dev/shm") : std::filesystem::temp_directory_path().string()) +
      "/vlit-fuzz-" + std::to_string(::getpid()) + ".glb";
  return path;
}

std::vector<vlit::LightSource> fuzz_lights() {
  using vlit::LightSource;
  using vlit::LightType;
  std::vector<LightSource> lights(4);
  lights[0].type = LightType::kPoint;
  lights[0].position = {0.5, 2, 1};
  lights[1].type = LightType::kDirectional;
  lights[1].direction = vlit::normalize(vlit::Vec3d{-1, -2, -0.5});
  lights[2].type = LightType::kSpot;
  lights[2].position = {0, 0, 3};
  lights[2].direction = {0, 0, -1};
  lights[3].type = LightType::kLinear;
  lights[3].from = {-1, 1.5, 0};
  lights[3].to = {1, 1.5, 0};
  return lights;
}

}  // namespace

// The scene's vertex cap, scaled down so that the fuzzer's 2 GB malloc limit finds allocations
// that the cap does not bound (the default 50 M vertices needs ~3 GB by design).
const vlit::SceneOptions kFuzzSceneOptions{vlit::SceneLimits{/*max_vertices=*/1u << 20}, true};

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  try {
    vlit::GltfFile file = vlit::load_gltf_from_memory({reinterpret_cast<const char*>(data), size}, "fuzz.glb");
    std::vector<std::string> warnings;
    vlit::Scene scene = vlit::build_scene(file, warnings, kFuzzSceneOptions);
    scene.lights = fuzz_lights();
    vlit::LightingRequest request;
    request.shade.with_specular = false;
    const auto light = vlit::light_scene_vertices(scene, request);
    for (const auto& prim : light)
      for (const auto& c : prim.diffuse)
        if (!std::isfinite(c.x) || !std::isfinite(c.y) || !std::isfinite(c.z)) std::abort();
    vlit::BakeOptions options;
    options.format = (size & 1) ? vlit::ColorFormat::kFloat : vlit::ColorFormat::kUnorm16;
    vlit::bake_vertex_colors(file.model, scene, light, options);
    // The real writer (atomic write to a RAM-backed file), and the output must load back.
    vlit::write_gltf(std::move(file.model), "fuzz.glb", output_path());
    try {
      vlit::load_gltf_file(output_path());
    } catch (const vlit::InputError& e) {
      std::fprintf(stderr, "baked output does not load back: %s\n", e.what());
      std::abort();
    }
  } catch (const vlit::InputError&) {
    // the expected outcome for bad input
  }
  return 0;
}
