#include "gltf/mesh_to_gltf.h"

#include <algorithm>
#include <cmath>

#include "gltf/gltf_append.h"

namespace vlit {

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
    material.name = m.name;
    // Emission E = emissiveFactor x emissiveStrength with the factor at most 1 (glTF's range):
    // the strength carries what exceeds 1 (KHR_materials_emissive_strength).
    const Vec3d e = m.emission();
    const double peak = std::max({e.x, e.y, e.z});
    if (peak > 0 && std::isfinite(peak)) {
      const double strength = std::max(peak, 1.0);
      material.emissiveFactor = {e.x / strength, e.y / strength, e.z / strength};
      if (strength > 1) {
        tinygltf::Value::Object ext;
        ext["emissiveStrength"] = tinygltf::Value(strength);
        material.extensions["KHR_materials_emissive_strength"] = tinygltf::Value(ext);
        if (std::find(model.extensionsUsed.begin(), model.extensionsUsed.end(), "KHR_materials_emissive_strength") ==
            model.extensionsUsed.end())
          model.extensionsUsed.push_back("KHR_materials_emissive_strength");
      }
    }
    model.materials.push_back(std::move(material));
  }
  tinygltf::Scene gltf_scene;
  for (std::size_t i = 0; i < scene.primitives.size(); ++i) {
    ScenePrimitive& prim = scene.primitives[i];
    tinygltf::Primitive p;
    p.mode = TINYGLTF_MODE_TRIANGLES;
    p.material = prim.material;  // -1: glTF's default material, as in the scene
    p.attributes["POSITION"] = append_vec3_accessor(model, prim.positions, true);
    // glTF requires unit normals: a vertex without one (unreferenced, or only on degenerate faces;
    // it was lit as facing nothing) gets +Z in the file.
    std::vector<Vec3d> normals = prim.normals;
    for (Vec3d& n : normals) {
      const double len = length(n);
      n = len > 0 && std::isfinite(len) ? n / len : Vec3d{0, 0, 1};
    }
    p.attributes["NORMAL"] = append_vec3_accessor(model, normals, false);
    tinygltf::Accessor indices;
    indices.bufferView = append_buffer_view(model, prim.triangles.data(), prim.triangles.size() * sizeof(std::uint32_t),
                                  TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER);
    indices.componentType = TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT;
    indices.type = TINYGLTF_TYPE_SCALAR;
    indices.count = prim.triangles.size();
    model.accessors.push_back(indices);
    p.indices = static_cast<int>(model.accessors.size()) - 1;
    tinygltf::Mesh mesh;
    mesh.name = scene.material_of(prim).name;  // an OBJ's usemtl, so a viewer lists its parts
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
