// libFuzzer target: bytes -> an OBJ file and its .mtl (the same bytes written as both: each reader
// ignores the other's statements, so one input can carry `mtllib fuzz.mtl`, `newmtl`, `Kd`, `Ke`,
// `v`, `usemtl` and `f` lines) -> load_obj_file -> the emissive lights of its materials.
// The contract under test (docs/robustness.md, docs/mesh-files.md): bad input ends in an
// InputError; an accepted scene has indices in range, one finite normal per vertex (unit or zero),
// base colours in [0, 1] and finite, non-negative emission.
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include <unistd.h>

#include "core/input_error.h"
#include "mesh/obj_file.h"
#include "scene/emissive_lights.h"

namespace {

const std::filesystem::path& folder() {
  static const std::filesystem::path path = [] {
    const std::filesystem::path base = std::filesystem::is_directory("/dev/shm") ? std::filesystem::path("/dev/shm")
                                                                                : std::filesystem::temp_directory_path();
    const auto dir = base / ("vlit-fuzz-obj-" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir);
    return dir;
  }();
  return path;
}

bool in_unit_range(double v) { return std::isfinite(v) && v >= 0 && v <= 1; }

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string bytes(reinterpret_cast<const char*>(data), size);
  const std::string obj = (folder() / "fuzz.obj").string();
  std::ofstream(obj, std::ios::binary) << bytes;
  std::ofstream(folder() / "fuzz.mtl", std::ios::binary) << bytes;
  try {
    std::vector<std::string> warnings;
    vlit::Scene scene = vlit::load_obj_file(obj, warnings, /*max_vertices=*/1u << 20);
    for (const auto& p : scene.primitives) {
      if (p.normals.size() != p.positions.size() || p.triangles.size() % 3 != 0) std::abort();
      for (std::uint32_t i : p.triangles)
        if (i >= p.positions.size()) std::abort();
      for (const auto& n : p.normals) {
        const double len = vlit::length(n);
        if (!vlit::is_finite(n) || !(len == 0 || std::abs(len - 1) < 1e-9)) std::abort();
      }
      for (const auto& x : p.positions)
        if (!vlit::is_finite(x)) std::abort();
    }
    for (const auto& m : scene.materials) {
      if (!in_unit_range(m.base_color.x) || !in_unit_range(m.base_color.y) || !in_unit_range(m.base_color.z)) std::abort();
      if (!in_unit_range(m.roughness)) std::abort();
      const vlit::Vec3d e = m.emission();
      if (!vlit::is_finite(e) || e.x < 0 || e.y < 0 || e.z < 0) std::abort();
    }
    vlit::add_emissive_triangle_lights(scene, obj, 8, warnings);
    for (const auto& l : scene.lights)
      for (const auto& q : l.polygon)
        if (!vlit::is_finite(q)) std::abort();
  } catch (const vlit::InputError&) {
  }
  return 0;
}
