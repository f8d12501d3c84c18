// Building a glTF scene for the bundled asset generators (generate_demo_scene.cpp,
// generate_paper_scenes.cpp): indexed triangle meshes with normals in one buffer, PBR materials,
// root nodes and cameras, written as .glb atomically. Output bytes are deterministic.
#pragma once

#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <exception>
#include <functional>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include <tiny_gltf.h>

#include "core/vec3.h"
#include "gltf/gltf_append.h"
#include "io/atomic_write.h"

namespace vlit {

// An indexed triangle mesh with per-vertex normals.
struct MeshData {
  std::vector<Vec3d> positions, normals;
  std::vector<std::uint32_t> indices;

  void append(const MeshData& other) {
    const auto base = static_cast<std::uint32_t>(positions.size());
    positions.insert(positions.end(), other.positions.begin(), other.positions.end());
    normals.insert(normals.end(), other.normals.begin(), other.normals.end());
    for (auto i : other.indices) indices.push_back(base + i);
  }
};

// A flat (nu x nv)-cell grid over origin + s*u + t*v, s, t in [0, 1], facing cross(u, v); each
// cell split along its a-d diagonal.
inline MeshData grid_mesh(Vec3d origin, Vec3d u, Vec3d v, int nu, int nv) {
  MeshData m;
  const Vec3d n = normalize(cross(u, v));
  for (int j = 0; j <= nv; ++j)
    for (int i = 0; i <= nu; ++i) {
      m.positions.push_back(origin + u * (double(i) / nu) + v * (double(j) / nv));
      m.normals.push_back(n);
    }
  for (int j = 0; j < nv; ++j)
    for (int i = 0; i < nu; ++i) {
      const std::uint32_t a = j * (nu + 1) + i, b = a + 1, c = a + (nu + 1), d = c + 1;
      m.indices.insert(m.indices.end(), {a, b, d, a, d, c});
    }
  return m;
}

struct MaterialSpec {
  std::string name;
  std::array<double, 3> base_color;
  double roughness, metallic;
  std::array<double, 3> emissive{0, 0, 0};  // emissiveFactor
  double emissive_strength = 1;             // KHR_materials_emissive_strength when not 1
};

class GltfSceneWriter {
 public:
  GltfSceneWriter(const std::string& generator) {
    model_.asset.version = "2.0";
    model_.asset.generator = generator;
    model_.buffers.resize(1);
    model_.scenes.resize(1);
    model_.defaultScene = 0;
  }

  // Several materials, added in order; their indices in the same order.
  template <std::size_t N>
  std::array<int, N> materials(const MaterialSpec (&specs)[N]) {
    std::array<int, N> out;
    for (std::size_t i = 0; i < N; ++i) out[i] = material(specs[i]);
    return out;
  }

  int material(const MaterialSpec& spec) {
    tinygltf::Material m;
    m.name = spec.name;
    m.pbrMetallicRoughness.baseColorFactor = {spec.base_color[0], spec.base_color[1], spec.base_color[2], 1};
    m.pbrMetallicRoughness.metallicFactor = spec.metallic;
    m.pbrMetallicRoughness.roughnessFactor = spec.roughness;
    if (spec.emissive != std::array<double, 3>{0, 0, 0}) m.emissiveFactor = {spec.emissive[0], spec.emissive[1], spec.emissive[2]};
    if (spec.emissive_strength != 1) {
      tinygltf::Value::Object strength;
      strength["emissiveStrength"] = tinygltf::Value(spec.emissive_strength);
      m.extensions["KHR_materials_emissive_strength"] = tinygltf::Value(strength);
      uses("KHR_materials_emissive_strength");
    }
    model_.materials.push_back(m);
    return static_cast<int>(model_.materials.size()) - 1;
  }

  // A mesh with one primitive per (geometry, material) part.
  int mesh(const std::string& name, const std::vector<std::pair<MeshData, int>>& parts) {
    tinygltf::Mesh mesh;
    mesh.name = name;
    for (const auto& [data, material] : parts) {
      tinygltf::Primitive prim;
      prim.mode = TINYGLTF_MODE_TRIANGLES;
      prim.attributes["POSITION"] = vec3_accessor(data.positions, true);
      prim.attributes["NORMAL"] = vec3_accessor(data.normals, false);
      tinygltf::Accessor idx;
      idx.bufferView = view(data.indices.data(), data.indices.size() * 4, TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER);
      idx.componentType = TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT;
      idx.type = TINYGLTF_TYPE_SCALAR;
      idx.count = data.indices.size();
      model_.accessors.push_back(idx);
      prim.indices = static_cast<int>(model_.accessors.size()) - 1;
      prim.material = material;
      mesh.primitives.push_back(prim);
    }
    model_.meshes.push_back(mesh);
    return static_cast<int>(model_.meshes.size()) - 1;
  }

  // A mesh of one LINES primitive (2 positions per segment), e.g. an emissive tube.
  int line_mesh(const std::string& name, const std::vector<Vec3d>& positions, int material) {
    tinygltf::Primitive prim;
    prim.mode = TINYGLTF_MODE_LINE;
    prim.attributes["POSITION"] = vec3_accessor(positions, true);
    prim.material = material;
    tinygltf::Mesh mesh;
    mesh.name = name;
    mesh.primitives.push_back(prim);
    model_.meshes.push_back(mesh);
    return static_cast<int>(model_.meshes.size()) - 1;
  }

  // Adds `name` to extensionsUsed once.
  void uses(const std::string& name) {
    for (const auto& e : model_.extensionsUsed)
      if (e == name) return;
    model_.extensionsUsed.push_back(name);
  }

  void node(const std::string& name, int mesh, Vec3d translation = {}) {
    tinygltf::Node n;
    n.name = name;
    n.mesh = mesh;
    if (!(translation == Vec3d{})) n.translation = {translation.x, translation.y, translation.z};
    add_root(n);
  }

  // A perspective camera at eye looking at target, +Y up (glTF cameras look down their local -Z).
  void camera(Vec3d eye, Vec3d target, double yfov, double aspect) {
    tinygltf::Camera c;
    c.type = "perspective";
    c.perspective.yfov = yfov;
    c.perspective.aspectRatio = aspect;
    c.perspective.znear = 0.05;
    c.perspective.zfar = 50;  // finite: tinygltf would otherwise write the invalid zfar = 0
    model_.cameras.push_back(c);
    const Vec3d back = normalize(eye - target);
    const Vec3d right = normalize(cross(Vec3d{0, 1, 0}, back));
    const Vec3d up = cross(back, right);
    tinygltf::Node n;
    n.name = "camera";
    n.camera = static_cast<int>(model_.cameras.size()) - 1;
    n.translation = {eye.x, eye.y, eye.z};
    n.rotation = quaternion_from_columns(right, up, back);
    add_root(n);
  }

  // For what the writer has no verb for (e.g. a camera node with a given rotation).
  tinygltf::Model& model() { return model_; }
  void add_root_node(const tinygltf::Node& n) { add_root(n); }

  bool write(const std::string& path) {
    tinygltf::TinyGLTF writer;
    std::ostringstream out;
    if (!writer.WriteGltfSceneToStream(&model_, out, false, true)) {
      std::fprintf(stderr, "%s: cannot serialize the scene\n", path.c_str());
      return false;
    }
    write_file_atomically(path, out.str());
    return true;
  }

 private:
  void add_root(const tinygltf::Node& n) {
    model_.nodes.push_back(n);
    model_.scenes[0].nodes.push_back(static_cast<int>(model_.nodes.size()) - 1);
  }

  int view(const void* data, std::size_t bytes, int target) { return append_buffer_view(model_, data, bytes, target); }
  int vec3_accessor(const std::vector<Vec3d>& values, bool with_bounds) {
    return append_vec3_accessor(model_, values, with_bounds);
  }

  // The unit quaternion [x, y, z, w] of the rotation whose matrix has columns x, y, z
  // (Shepperd's method: the largest of the four candidates keeps it well conditioned).
  static std::vector<double> quaternion_from_columns(Vec3d x, Vec3d y, Vec3d z) {
    const double m00 = x.x, m10 = x.y, m20 = x.z, m01 = y.x, m11 = y.y, m21 = y.z, m02 = z.x, m12 = z.y, m22 = z.z;
    const double trace = m00 + m11 + m22;
    double qx, qy, qz, qw;
    if (trace > 0) {
      const double s = 2 * std::sqrt(1 + trace);
      qw = s / 4; qx = (m21 - m12) / s; qy = (m02 - m20) / s; qz = (m10 - m01) / s;
    } else if (m00 > m11 && m00 > m22) {
      const double s = 2 * std::sqrt(1 + m00 - m11 - m22);
      qw = (m21 - m12) / s; qx = s / 4; qy = (m01 + m10) / s; qz = (m02 + m20) / s;
    } else if (m11 > m22) {
      const double s = 2 * std::sqrt(1 + m11 - m00 - m22);
      qw = (m02 - m20) / s; qx = (m01 + m10) / s; qy = s / 4; qz = (m12 + m21) / s;
    } else {
      const double s = 2 * std::sqrt(1 + m22 - m00 - m11);
      qw = (m10 - m01) / s; qx = (m02 + m20) / s; qy = (m12 + m21) / s; qz = s / 4;
    }
    return {qx, qy, qz, qw};
  }

  tinygltf::Model model_;
};

// The main of a generator that writes one scene: `PROGRAM OUT.glb`; `build` fills the writer
// (whose asset.generator is "vlit " + name). Exit status 2 for a wrong command line, 1 when the
// file cannot be written (the message names it).
inline int write_generated_scene(int argc, char** argv, const std::string& name,
                                 const std::function<void(GltfSceneWriter&)>& build) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: %s OUT.glb\n", argv[0]);
    return 2;
  }
  GltfSceneWriter scene("vlit " + name);
  build(scene);
  try {
    return scene.write(argv[1]) ? 0 : 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "%s\n", e.what());
    return 1;
  }
}

}  // namespace vlit
