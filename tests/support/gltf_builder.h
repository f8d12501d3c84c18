// Builds small glTF models in memory for tests, so expectations can be derived by hand from a
// few vertices instead of from a stored file.
#pragma once

#include <cstring>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include <tiny_gltf.h>
#include <unistd.h>

namespace vlit::test {

class GltfBuilder {
 public:
  GltfBuilder() {
    model_.asset.version = "2.0";
    model_.buffers.resize(1);
    model_.scenes.resize(1);
    model_.defaultScene = 0;
  }

  // Adds an accessor of float VECn (n = components) or of scalar uint32/uint16 indices.
  int add_floats(const std::vector<float>& values, int type) {
    return add_accessor(values.data(), values.size() * 4, TINYGLTF_COMPONENT_TYPE_FLOAT, type,
                        values.size() / (type == TINYGLTF_TYPE_VEC3 ? 3 : type == TINYGLTF_TYPE_VEC4 ? 4 : 1));
  }
  int add_indices(const std::vector<std::uint32_t>& values) {
    return add_accessor(values.data(), values.size() * 4, TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT, TINYGLTF_TYPE_SCALAR,
                        values.size());
  }
  int add_accessor(const void* data, std::size_t bytes, int component_type, int type, std::size_t count) {
    auto& buf = model_.buffers[0].data;
    while (buf.size() % 4) buf.push_back(0);
    tinygltf::BufferView view;
    view.buffer = 0;
    view.byteOffset = buf.size();
    view.byteLength = bytes;
    const auto* b = static_cast<const unsigned char*>(data);
    buf.insert(buf.end(), b, b + bytes);
    model_.bufferViews.push_back(view);
    tinygltf::Accessor acc;
    acc.bufferView = static_cast<int>(model_.bufferViews.size()) - 1;
    acc.componentType = component_type;
    acc.type = type;
    acc.count = count;
    model_.accessors.push_back(acc);
    return static_cast<int>(model_.accessors.size()) - 1;
  }

  // A mesh with one primitive; returns the mesh index. normals may be empty.
  int add_mesh(const std::vector<float>& positions, const std::vector<float>& normals,
               const std::vector<std::uint32_t>& indices, int mode = TINYGLTF_MODE_TRIANGLES, int material = -1) {
    tinygltf::Primitive prim;
    prim.mode = mode;
    prim.material = material;
    prim.attributes["POSITION"] = add_floats(positions, TINYGLTF_TYPE_VEC3);
    if (!normals.empty()) prim.attributes["NORMAL"] = add_floats(normals, TINYGLTF_TYPE_VEC3);
    if (!indices.empty()) prim.indices = add_indices(indices);
    tinygltf::Mesh mesh;
    mesh.primitives.push_back(prim);
    model_.meshes.push_back(mesh);
    return static_cast<int>(model_.meshes.size()) - 1;
  }

  int add_material(std::vector<double> base_color, double metallic, double roughness) {
    tinygltf::Material m;
    m.pbrMetallicRoughness.baseColorFactor = std::move(base_color);
    m.pbrMetallicRoughness.metallicFactor = metallic;
    m.pbrMetallicRoughness.roughnessFactor = roughness;
    model_.materials.push_back(m);
    return static_cast<int>(model_.materials.size()) - 1;
  }

  // Adds a node (a root of the scene unless parent >= 0); returns its index.
  int add_node(int mesh, std::vector<double> translation = {}, std::vector<double> scale = {},
               std::vector<double> rotation = {}, int parent = -1) {
    tinygltf::Node node;
    node.mesh = mesh;
    node.translation = std::move(translation);
    node.scale = std::move(scale);
    node.rotation = std::move(rotation);
    model_.nodes.push_back(node);
    const int index = static_cast<int>(model_.nodes.size()) - 1;
    if (parent >= 0) model_.nodes[parent].children.push_back(index);
    else model_.scenes[0].nodes.push_back(index);
    return index;
  }

  tinygltf::Model& model() { return model_; }

  // Writes the model as .glb or .gltf (by extension) and returns the path.
  std::string write(const std::string& path) const {
    tinygltf::TinyGLTF writer;
    const bool binary = path.size() > 4 && path.substr(path.size() - 4) == ".glb";
    if (!writer.WriteGltfSceneToFile(&model_, path, false, true, true, binary)) throw std::runtime_error("cannot write " + path);
    return path;
  }

 private:
  tinygltf::Model model_;
};

// A fresh, empty temporary directory for one test.
inline std::filesystem::path temp_dir(const std::string& name) {
  const auto dir = std::filesystem::temp_directory_path() / ("vlit-test-" + name + "-" + std::to_string(::getpid()));
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

}  // namespace vlit::test
