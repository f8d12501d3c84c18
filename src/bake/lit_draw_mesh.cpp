#include "bake/lit_draw_mesh.h"

#include "scene/material.h"
#include "shading/shading_policy.h"

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
    const Vec3d specular = light.specular.empty() ? Vec3d{} : static_cast<Vec3d>(light.specular[v]);
    const Vec3d color = shaded_color(phong, static_cast<Vec3d>(light.diffuse[v]), light.specular.empty() ? nullptr : &specular);
    mesh.colors.push_back(static_cast<Vec3f>(color));
  }
  return mesh;
}

}  // namespace vlit
