#include "gltf/mesh_to_gltf.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>

namespace vlit {
namespace {

// Appends raw bytes to buffer 0 (4-byte aligned) and returns a new bufferView over them.
int add_view(tinygltf::Model& model, const void* data, std::size_t bytes, int target) {
  std::vector<unsigned char>& buffer = model.buffers[0].data;
  buffer.resize((buffer.size() + 3) & ~std::size_t(3));
  tinygltf::BufferView view;
  view.buffer = 0;
  view.byteOffset = buffer.size();
  view.byteLength = bytes;
  view.target = target;
  const auto* p = static_cast<const unsigned char*>(data);
  buffer.insert(buffer.end(), p, p + bytes);
  model.bufferViews.push_back(view);
  return static_cast<int>(model.bufferViews.size()) - 1;
}

int add_vec3_accessor(tinygltf::Model& model, const std::vector<Vec3d>& values, bool with_bounds) {
  std::vector<float> flat;
  flat.reserve(values.size() * 3);
  std::vector<double> lo(3, std::numeric_limits<double>::max()), hi(3, std::numeric_limits<double>::lowest());
  for (const Vec3d& v : values) {
    const float f[3] = {float(v.x), float(v.y), float(v.z)};
    for (int k = 0; k < 3; ++k) {
      flat.push_back(f[k]);
      lo[k] = std::min(lo[k], double(f[k]));
      hi[k] = std::max(hi[k], double(f[k]));
    }
  }
  tinygltf::Accessor a;
  a.bufferView = add_view(model, flat.data(), flat.size() * sizeof(float), TINYGLTF_TARGET_ARRAY_BUFFER);
  a.componentType = TINYGLTF_COMPONENT_TYPE_FLOAT;
  a.type = TINYGLTF_TYPE_VEC3;
  a.count = values.size();
  if (with_bounds) {  // glTF requires min/max on POSITION
    a.minValues = lo;
    a.maxValues = hi;
  }
  model.accessors.push_back(a);
  return static_cast<int>(model.accessors.size()) - 1;
}

}  // namespace

tinygltf::Model gltf_from_mesh_scene(Scene& scene) {
  tinygltf::Model model;
  model.asset.version = "2.0";
  model.asset.generator = "vlit (from a mesh file)";
  model.buffers.resize(1);
  for (const Material& m : scene.materials) {  // the scene's materials, as glTF metallic-roughness
    tinygltf::Material material;
    material.pbrMetallicRoughness.baseColorFactor = {m.base_color.x, m.base_color.y, m.base_color.z, 1.0};
    material.pbrMetallicRoughness.metallicFactor = m.metallic;
    material.pbrMetallicRoughness.roughnessFactor = m.roughness;
    material.doubleSided = m.double_sided;
    model.materials.push_back(std::move(material));
  }
  tinygltf::Scene gltf_scene;
  for (std::size_t i = 0; i < scene.primitives.size(); ++i) {
    ScenePrimitive& prim = scene.primitives[i];
    tinygltf::Primitive p;
    p.mode = TINYGLTF_MODE_TRIANGLES;
    p.material = prim.material;  // -1: glTF's default material, as in the scene
    p.attributes["POSITION"] = add_vec3_accessor(model, prim.positions, true);
    // glTF requires unit normals: a vertex without one (unreferenced, or only on degenerate faces;
    // it was lit as facing nothing) gets +Z in the file.
    std::vector<Vec3d> normals = prim.normals;
    for (Vec3d& n : normals) {
      const double len = length(n);
      n = len > 0 && std::isfinite(len) ? n / len : Vec3d{0, 0, 1};
    }
    p.attributes["NORMAL"] = add_vec3_accessor(model, normals, false);
    tinygltf::Accessor indices;
    indices.bufferView = add_view(model, prim.triangles.data(), prim.triangles.size() * sizeof(std::uint32_t),
                                  TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER);
    indices.componentType = TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT;
    indices.type = TINYGLTF_TYPE_SCALAR;
    indices.count = prim.triangles.size();
    model.accessors.push_back(indices);
    p.indices = static_cast<int>(model.accessors.size()) - 1;
    tinygltf::Mesh mesh;
    mesh.primitives.push_back(std::move(p));
    model.meshes.push_back(std::move(mesh));
    tinygltf::Node node;
    node.mesh = static_cast<int>(i);
    model.nodes.push_back(std::move(node));
    gltf_scene.nodes.push_back(static_cast<int>(i));
    prim.node = prim.mesh = static_cast<int>(i);
    prim.primitive = 0;
  }
  model.buffers[0].data.resize((model.buffers[0].data.size() + 3) & ~std::size_t(3));
  model.scenes.push_back(std::move(gltf_scene));
  model.defaultScene = 0;
  return model;
}

}  // namespace vlit
