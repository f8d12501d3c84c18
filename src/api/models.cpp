// Models in and out (load_model, save_model) and meshes given as plain arrays (scene_of_meshes).
#include <cmath>

#include "api/api_internal.h"
#include "gltf/gltf_file.h"
#include "gltf/gltf_writer.h"
#include "gltf/mesh_to_gltf.h"
#include "mesh/mesh_file.h"
#include "mesh/vertex_normals.h"

namespace vlit {

tinygltf::Model load_model(const std::string& path, std::vector<std::string>* warnings) {
  return api::translate_errors(path, [&] {
    std::vector<std::string> found;
    tinygltf::Model model;
    if (is_gltf_path(path)) {
      GltfFile file = load_gltf_file(path);
      found = std::move(file.warnings);
      model = std::move(file.model);
    } else if (is_mesh_path(path)) {
      Scene scene = load_mesh_file(path, found, SceneLimits{}.max_vertices);
      model = gltf_from_mesh_scene(scene);
    } else {
      throw Error(path, "unsupported file type (expected .gltf, .glb, .obj, .ply, .off or .stl)");
    }
    if (warnings) warnings->insert(warnings->end(), found.begin(), found.end());
    return model;
  });
}

void save_model(const tinygltf::Model& model, const std::string& path, const std::string& read_from) {
  api::translate_errors(path, [&] {
    if (!is_gltf_path(path)) throw Error(path, "the output must end in .glb or .gltf");
    write_gltf(model, read_from.empty() ? path : read_from, path);
  });
}

namespace api {

Scene scene_of_meshes(const std::vector<Mesh>& meshes) {
  Scene scene;
  for (std::size_t i = 0; i < meshes.size(); ++i) {
    const Mesh& mesh = meshes[i];
    const std::string name = mesh.name.empty() ? "meshes[" + std::to_string(i) + "]" : mesh.name;
    const std::size_t n = mesh.positions.size();
    if (!mesh.normals.empty() && mesh.normals.size() != n)
      throw Error(name, std::to_string(mesh.normals.size()) + " normals for " + std::to_string(n) + " positions", "normals");
    if (mesh.triangles.size() % 3 != 0) throw Error(name, "the index count is not a multiple of 3", "triangles");
    if (mesh.normals.empty() && mesh.triangles.empty() && n > 0)
      throw Error(name, "needs normals, or triangles to compute them from", "normals");
    ScenePrimitive prim;
    prim.positions.reserve(n);
    for (std::size_t v = 0; v < n; ++v) {
      const Vector3& p = mesh.positions[v];
      if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2]))
        throw Error(name, "position is not finite", "positions[" + std::to_string(v) + "]");
      prim.positions.push_back(to_vec3d(p));
    }
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
      if (mesh.triangles[t] >= n)
        throw Error(name, "index " + std::to_string(mesh.triangles[t]) + " is out of range (" + std::to_string(n) +
                              " positions)", "triangles[" + std::to_string(t) + "]");
    prim.triangles = mesh.triangles;
    if (mesh.normals.empty()) {
      prim.normals = angle_weighted_normals(prim.positions, prim.triangles);
    } else {
      prim.normals.reserve(n);
      for (std::size_t v = 0; v < n; ++v) {
        const Vec3d normal = to_vec3d(mesh.normals[v]);
        const double len = length(normal);
        if (!std::isfinite(len) || !(len > 0))
          throw Error(name, "normal is zero or not finite", "normals[" + std::to_string(v) + "]");
        prim.normals.push_back(normal / len);
      }
    }
    const SurfaceMaterial& m = mesh.material;
    Material material;
    material.base_color = to_vec3d(m.base_color);
    material.metallic = m.metallic;
    material.roughness = m.roughness;
    material.double_sided = m.double_sided;
    auto in_unit = [](double x) { return x >= 0 && x <= 1; };
    if (!in_unit(m.base_color[0]) || !in_unit(m.base_color[1]) || !in_unit(m.base_color[2]))
      throw Error(name, "base_color components must be in [0, 1]", "material.base_color");
    if (!in_unit(m.metallic)) throw Error(name, "metallic must be in [0, 1]", "material.metallic");
    if (!in_unit(m.roughness)) throw Error(name, "roughness must be in [0, 1]", "material.roughness");
    prim.material = static_cast<int>(scene.materials.size());
    scene.materials.push_back(material);
    scene.primitives.push_back(std::move(prim));
  }
  return scene;
}

}  // namespace api
}  // namespace vlit
