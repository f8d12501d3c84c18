#include "bake/preview_draw_mesh.h"

namespace vlit {

raster::DrawMesh preview_draw_mesh(const ScenePrimitive& primitive, const Material& material,
                                   std::vector<std::uint32_t> indices) {
  raster::DrawMesh mesh;
  mesh.double_sided = material.double_sided;
  mesh.indices = std::move(indices);
  const Vec3d base = material.base_color, emission = material.emission();
  const bool has_colors = primitive.colors.size() == primitive.positions.size();
  mesh.positions.reserve(primitive.positions.size());
  mesh.colors.reserve(primitive.positions.size());
  for (std::size_t v = 0; v < primitive.positions.size(); ++v) {
    mesh.positions.push_back(static_cast<Vec3f>(primitive.positions[v]));
    const Vec3d color_0 = has_colors ? static_cast<Vec3d>(primitive.colors[v]) : Vec3d{1, 1, 1};
    mesh.colors.push_back(static_cast<Vec3f>(hadamard(color_0, base) + emission));
  }
  return mesh;
}

}  // namespace vlit
