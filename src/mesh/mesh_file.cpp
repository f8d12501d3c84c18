#include "mesh/mesh_file.h"

#include <algorithm>
#include <filesystem>

#include <OpenMesh/Core/IO/MeshIO.hh>

#include "core/input_error.h"
#include "gltf/gltf_scene.h"
#include "mesh/obj_file.h"
#include "mesh/openmesh_mesh.h"
#include "mesh/vertex_normals.h"

namespace vlit {
namespace {

std::string extension_of(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext;
}

}  // namespace

bool is_mesh_path(const std::string& path) {
  const std::string ext = extension_of(path);
  return ext == ".obj" || ext == ".ply" || ext == ".off" || ext == ".stl";
}

Scene load_mesh_file(const std::string& path, std::vector<std::string>& warnings) {
  return load_mesh_file(path, warnings, default_scene_limits().max_vertices);
}

Scene load_mesh_file(const std::string& path, std::vector<std::string>& warnings, std::size_t max_vertices) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) throw InputError(path, "cannot open: not a regular file");
  if (extension_of(path) == ".obj") return load_obj_file(path, warnings, max_vertices);
  TriMesh mesh;
  OpenMesh::IO::Options options = OpenMesh::IO::Options::VertexNormal;
  // OpenMesh reports problems on its own log streams; keep them off the user's terminal and
  // report one line of our own instead.
  omlog().disable();
  omerr().disable();
  omout().disable();
  const bool ok = OpenMesh::IO::read_mesh(mesh, path, options);
  if (!ok) throw InputError(path, "cannot read this " + extension_of(path) + " file (OpenMesh reader failed)");
  if (mesh.n_faces() == 0) throw InputError(path, "the mesh has no faces");
  // Same vertex limit as glTF scenes (gltf/gltf_scene.h); OpenMesh's own memory is bounded by the file.
  if (const std::size_t limit = max_vertices; mesh.n_vertices() > limit)
    throw InputError(path, "the mesh has more than " + std::to_string(limit) +
                               " vertices (the limit that protects the machine; raise it with --max-vertices)");

  ScenePrimitive prim;
  prim.positions.reserve(mesh.n_vertices());
  for (const auto v : mesh.vertices()) {
    const auto& p = mesh.point(v);
    prim.positions.push_back({p[0], p[1], p[2]});
  }
  std::size_t non_finite = 0;
  for (auto& p : prim.positions)
    if (!is_finite(p)) { p = {}; ++non_finite; }
  for (const auto f : mesh.faces()) {
    std::uint32_t idx[3];
    int k = 0;
    for (const auto v : mesh.fv_range(f)) if (k < 3) idx[k++] = static_cast<std::uint32_t>(v.idx());
    if (k == 3) prim.triangles.insert(prim.triangles.end(), idx, idx + 3);
  }
  if (non_finite > 0)
    warnings.push_back(path + ": " + std::to_string(non_finite) + " vertices have non-finite positions; they receive no light");

  if (options.check(OpenMesh::IO::Options::VertexNormal)) {
    for (const auto v : mesh.vertices()) {
      const auto& n = mesh.normal(v);
      prim.normals.push_back(normalize(Vec3d{n[0], n[1], n[2]}));
    }
  } else {
    // Angle-weighted, as for glTF primitives without normals (mesh/vertex_normals.h).
    prim.normals = angle_weighted_normals(prim.positions, prim.triangles);
  }
  for (auto& n : prim.normals)
    if (!is_finite(n)) n = {};
  Scene scene;
  // Mesh files carry no PBR material: a neutral grey dielectric (docs/conventions.md).
  Material grey;
  grey.base_color = {0.8, 0.8, 0.8};
  grey.metallic = 0;
  grey.roughness = 0.5;
  scene.materials.push_back(grey);
  prim.material = 0;
  scene.primitives.push_back(std::move(prim));
  return scene;
}

}  // namespace vlit
