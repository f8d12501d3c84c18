// Generates assets/demo/studio.glb, the bundled demo scene: a floor and a back wall (finely
// tessellated, so per-vertex light shows its gradients), a sphere, a box and a lathed vase, each
// with its own base colour, and a camera. Every vertex comes from the formulas below; nothing is
// typed by hand. Usage: vlit_make_demo_scene OUT.glb
#include <cmath>
#include <cstdio>
#include <cstring>
#include <sstream>
#include <string>
#include <vector>

#include <tiny_gltf.h>

#include "core/vec3.h"
#include "io/atomic_write.h"

namespace {

using vlit::Vec3d;

struct MeshData {
  std::string name;
  std::vector<Vec3d> positions, normals;
  std::vector<std::uint32_t> indices;
};

// A (nu x nv)-cell grid over origin + s*u + t*v, s, t in [0, 1], facing cross(u, v).
MeshData grid(const std::string& name, Vec3d origin, Vec3d u, Vec3d v, int nu, int nv) {
  MeshData m{name, {}, {}, {}};
  const Vec3d n = vlit::normalize(vlit::cross(u, v));
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

// A surface of revolution around +Y through the profile (radius r(t), height y(t)), t in [0, 1].
template <class Profile>
MeshData lathe(const std::string& name, Vec3d center, int rings, int segments, Profile profile) {
  MeshData m{name, {}, {}, {}};
  const double dt = 1e-4;
  for (int j = 0; j <= rings; ++j) {
    const double t = double(j) / rings;
    const auto [r, y] = profile(t);
    // Profile tangent by central differences, clamped to [0, 1]; the normal is its perpendicular.
    const auto [r0, y0] = profile(std::max(0.0, t - dt));
    const auto [r1, y1] = profile(std::min(1.0, t + dt));
    const double dr = r1 - r0, dy = y1 - y0;
    for (int i = 0; i <= segments; ++i) {
      const double phi = 2 * M_PI * i / segments;
      const double c = std::cos(phi), s = std::sin(phi);
      m.positions.push_back(center + Vec3d{r * c, y, -r * s});
      m.normals.push_back(vlit::normalize(Vec3d{dy * c, -dr, -dy * s}));
    }
  }
  for (int j = 0; j < rings; ++j)
    for (int i = 0; i < segments; ++i) {
      const std::uint32_t a = j * (segments + 1) + i, b = a + 1, c = a + (segments + 1), d = c + 1;
      m.indices.insert(m.indices.end(), {a, b, d, a, d, c});
    }
  return m;
}

MeshData box(const std::string& name, Vec3d lo, Vec3d hi, int cells) {
  MeshData m{name, {}, {}, {}};
  const Vec3d e = hi - lo;
  const Vec3d faces[6][3] = {
      {{lo.x, lo.y, hi.z}, {e.x, 0, 0}, {0, e.y, 0}},   // +Z
      {{hi.x, lo.y, lo.z}, {-e.x, 0, 0}, {0, e.y, 0}},  // -Z
      {{hi.x, lo.y, hi.z}, {0, 0, -e.z}, {0, e.y, 0}},  // +X
      {{lo.x, lo.y, lo.z}, {0, 0, e.z}, {0, e.y, 0}},   // -X
      {{lo.x, hi.y, hi.z}, {e.x, 0, 0}, {0, 0, -e.z}},  // +Y
      {{lo.x, lo.y, lo.z}, {e.x, 0, 0}, {0, 0, e.z}},   // -Y
  };
  for (const auto& f : faces) {
    const MeshData g = grid(name, f[0], f[1], f[2], cells, cells);
    const auto base = static_cast<std::uint32_t>(m.positions.size());
    m.positions.insert(m.positions.end(), g.positions.begin(), g.positions.end());
    m.normals.insert(m.normals.end(), g.normals.begin(), g.normals.end());
    for (auto i : g.indices) m.indices.push_back(base + i);
  }
  return m;
}

void add_mesh(tinygltf::Model& model, const MeshData& mesh, std::vector<double> base_color, double roughness) {
  tinygltf::Buffer& buffer = model.buffers[0];
  auto add_view = [&](const void* data, std::size_t bytes, int target) {
    while (buffer.data.size() % 4) buffer.data.push_back(0);
    tinygltf::BufferView view;
    view.buffer = 0;
    view.byteOffset = buffer.data.size();
    view.byteLength = bytes;
    view.target = target;
    const auto* b = static_cast<const unsigned char*>(data);
    buffer.data.insert(buffer.data.end(), b, b + bytes);
    model.bufferViews.push_back(view);
    return static_cast<int>(model.bufferViews.size()) - 1;
  };
  auto add_vec3 = [&](const std::vector<Vec3d>& values, bool with_bounds) {
    std::vector<float> f;
    std::vector<double> lo(3, 1e30), hi(3, -1e30);
    for (const Vec3d& v : values)
      for (int c = 0; c < 3; ++c) {
        const float x = static_cast<float>(v[c]);
        f.push_back(x);
        lo[c] = std::min<double>(lo[c], x);
        hi[c] = std::max<double>(hi[c], x);
      }
    tinygltf::Accessor acc;
    acc.bufferView = add_view(f.data(), f.size() * 4, TINYGLTF_TARGET_ARRAY_BUFFER);
    acc.componentType = TINYGLTF_COMPONENT_TYPE_FLOAT;
    acc.type = TINYGLTF_TYPE_VEC3;
    acc.count = values.size();
    if (with_bounds) { acc.minValues = lo; acc.maxValues = hi; }
    model.accessors.push_back(acc);
    return static_cast<int>(model.accessors.size()) - 1;
  };
  tinygltf::Primitive prim;
  prim.mode = TINYGLTF_MODE_TRIANGLES;
  prim.attributes["POSITION"] = add_vec3(mesh.positions, true);
  prim.attributes["NORMAL"] = add_vec3(mesh.normals, false);
  tinygltf::Accessor idx;
  idx.bufferView = add_view(mesh.indices.data(), mesh.indices.size() * 4, TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER);
  idx.componentType = TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT;
  idx.type = TINYGLTF_TYPE_SCALAR;
  idx.count = mesh.indices.size();
  model.accessors.push_back(idx);
  prim.indices = static_cast<int>(model.accessors.size()) - 1;

  tinygltf::Material material;
  material.name = mesh.name;
  material.pbrMetallicRoughness.baseColorFactor = base_color;
  material.pbrMetallicRoughness.metallicFactor = 0;
  material.pbrMetallicRoughness.roughnessFactor = roughness;
  model.materials.push_back(material);
  prim.material = static_cast<int>(model.materials.size()) - 1;

  tinygltf::Mesh m;
  m.name = mesh.name;
  m.primitives.push_back(prim);
  model.meshes.push_back(m);
  tinygltf::Node node;
  node.name = mesh.name;
  node.mesh = static_cast<int>(model.meshes.size()) - 1;
  model.nodes.push_back(node);
  model.scenes[0].nodes.push_back(static_cast<int>(model.nodes.size()) - 1);
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: %s OUT.glb\n", argv[0]);
    return 2;
  }
  tinygltf::Model model;
  model.asset.version = "2.0";
  model.asset.generator = "vlit generate_demo_scene";
  model.buffers.resize(1);
  model.scenes.resize(1);
  model.defaultScene = 0;

  add_mesh(model, grid("floor", {-3, 0, 2}, {6, 0, 0}, {0, 0, -5}, 96, 80), {0.8, 0.8, 0.78, 1}, 0.9);
  add_mesh(model, grid("back wall", {-3, 0, -3}, {6, 0, 0}, {0, 3, 0}, 96, 48), {0.7, 0.72, 0.8, 1}, 0.9);
  add_mesh(model, lathe("sphere", {-1.2, 0.6, 0}, 48, 96,
                        [](double t) { const double a = M_PI * t - M_PI / 2;  // bottom to top
                                       return std::pair{0.6 * std::cos(a), 0.6 * std::sin(a)}; }),
           {0.85, 0.25, 0.2, 1}, 0.35);
  add_mesh(model, box("box", {0.3, 0, -1.2}, {1.3, 1, -0.2}, 16), {0.25, 0.45, 0.85, 1}, 0.6);
  add_mesh(model, lathe("vase", {1.6, 0, 0.9}, 64, 64,
                        [](double t) { return std::pair{0.18 + 0.12 * std::sin(M_PI * t * 1.5), 1.1 * t}; }),
           {0.9, 0.75, 0.3, 1}, 0.25);

  // Camera: from the front-right, looking at the middle of the set (a rotation about X then Y).
  tinygltf::Camera camera;
  camera.type = "perspective";
  camera.perspective.yfov = 0.75;
  camera.perspective.znear = 0.05;
  camera.perspective.zfar = 100;  // tinygltf writes zfar even when unset, and 0 is invalid
  model.cameras.push_back(camera);
  tinygltf::Node cam;
  cam.name = "camera";
  cam.camera = 0;
  cam.translation = {1.6, 2.2, 5.6};
  const double yaw = 0.27, pitch = -0.3;  // radians
  const double cy = std::cos(yaw / 2), sy = std::sin(yaw / 2), cp = std::cos(pitch / 2), sp = std::sin(pitch / 2);
  cam.rotation = {cy * sp, sy * cp, -sy * sp, cy * cp};  // q_yaw * q_pitch
  model.nodes.push_back(cam);
  model.scenes[0].nodes.push_back(static_cast<int>(model.nodes.size()) - 1);

  tinygltf::TinyGLTF writer;
  std::ostringstream out;
  if (!writer.WriteGltfSceneToStream(&model, out, false, true)) {
    std::fprintf(stderr, "%s: cannot serialize the scene\n", argv[1]);
    return 1;
  }
  try {
    vlit::write_file_atomically(argv[1], out.str());
  } catch (const std::exception& e) {
    std::fprintf(stderr, "%s\n", e.what());
    return 1;
  }
  return 0;
}
