// Reads a glTF, adds a tube light above the scene, bakes the light into COLOR_0, writes the result.
//   bake_tube_light IN.glb OUT.glb
#include <cstdio>

#include <vlit/vlit.h>

int main(int argc, char** argv) {
  if (argc != 3) return std::fprintf(stderr, "usage: %s IN.glb OUT.glb\n", argv[0]), 2;
  try {
    tinygltf::Model model = vlit::load_model(argv[1]);
    vlit::Lights lights;
    lights.add(vlit::Light::tube({-1, 2.5, 0}, {1, 2.5, 0}, 1.5, {1.0, 0.9, 0.8}));  // 2 m, warm white
    const vlit::BakeSummary summary = vlit::bake(model, lights, {}, argv[1]);
    vlit::save_model(model, argv[2], argv[1]);
    std::printf("baked %zu vertices with %zu lights into %s\n", summary.vertices, summary.lights, argv[2]);
  } catch (const vlit::Error& e) {
    return std::fprintf(stderr, "%s\n", e.what()), 1;
  }
  return 0;
}
