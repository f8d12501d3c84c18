// Writes a large test scene for the rasterizer's memory measurement (docs/rasterizer.md,
// scripts/raster-memory.sh): one (grid x grid) terrain mesh with normals, 2 (grid - 1)^2
// triangles, as a .glb; no camera (vlit frames it). Made on demand, never committed.
// Usage: vlit_make_terrain_scene GRID OUT.glb
#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "../assets/gltf_scene_writer.h"

int main(int argc, char** argv) {
  if (argc != 3 || std::atoi(argv[1]) < 2) {
    std::fprintf(stderr, "usage: %s GRID OUT.glb   (2 (GRID-1)^2 triangles)\n", argv[0]);
    return 2;
  }
  const int grid = std::atoi(argv[1]);
  vlit::MeshData mesh;
  mesh.positions.reserve(size_t(grid) * grid);
  mesh.normals.reserve(size_t(grid) * grid);
  const auto height = [](double x, double z) { return 0.08 * std::sin(7 * x + 1.3) * std::cos(5 * z) + 0.05 * std::sin(13 * x * z); };
  for (int j = 0; j < grid; ++j)
    for (int i = 0; i < grid; ++i) {
      const double x = 2.0 * i / (grid - 1) - 1, z = 2.0 * j / (grid - 1) - 1, e = 1e-4;
      const double dhdx = (height(x + e, z) - height(x - e, z)) / (2 * e), dhdz = (height(x, z + e) - height(x, z - e)) / (2 * e);
      mesh.positions.push_back({x, height(x, z), z});
      mesh.normals.push_back(vlit::normalize(vlit::Vec3d{-dhdx, 1, -dhdz}));
    }
  mesh.indices.reserve(size_t(grid - 1) * (grid - 1) * 6);
  for (std::uint32_t j = 0; j + 1 < std::uint32_t(grid); ++j)
    for (std::uint32_t i = 0; i + 1 < std::uint32_t(grid); ++i) {
      const std::uint32_t a = j * grid + i, b = a + 1, c = a + grid + 1, d = a + grid;
      mesh.indices.insert(mesh.indices.end(), {a, c, b, a, d, c});
    }
  vlit::GltfSceneWriter writer("vlit_make_terrain_scene");
  const int material = writer.material({"terrain", {0.7, 0.7, 0.7}, 0.8, 0.0});
  writer.node("terrain", writer.mesh("terrain", {{mesh, material}}));
  return writer.write(argv[2]) ? 0 : 1;
}
