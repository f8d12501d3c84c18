#include "bake/lit_draw_mesh.h"

#include "scene/material.h"

namespace vlit {

raster::DrawMesh lit_draw_mesh(const ScenePrimitive& primitive, const Material& material, const VertexLight& light,
                               std::vector<std::uint32_t> indices) {
  const PhongMaterial phong = phong_from_metallic_roughness(material);
  raster::DrawMesh mesh;
  mesh.double_sided = material.double_sided;
  mesh.indices = std::move(indices);
  mesh.positions.reserve(primitive.positions.size());
  mesh.colors.reserve(primitive.positions.size());
  for (std::size_t v = 0; v < primitive.positions.size(); ++v) {
    mesh.positions.push_back(static_cast<Vec3f>(primitive.positions[v]));
    Vec3d color = hadamard(phong.kd, static_cast<Vec3d>(light.diffuse[v]));
    if (!light.specular.empty()) color += hadamard(phong.ks, static_cast<Vec3d>(light.specular[v]));
    mesh.colors.push_back(static_cast<Vec3f>(color));
  }
  return mesh;
}

}  // namespace vlit
