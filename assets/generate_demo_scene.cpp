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
#include "gltf_scene_writer.h"

namespace {

using vlit::MeshData;
using vlit::Vec3d;

using vlit::grid_mesh;

// A surface of revolution around +Y through the profile (radius r(t), height y(t)), t in [0, 1].
template <class Profile>
MeshData lathe(Vec3d center, int rings, int segments, Profile profile) {
  MeshData m;
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

MeshData box(Vec3d lo, Vec3d hi, int cells) {
  MeshData m;
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
    const MeshData g = grid_mesh(f[0], f[1], f[2], cells, cells);
    m.append(g);
  }
  return m;
}

// One object: a mesh with one primitive, its material and a root node.
void add_object(vlit::GltfSceneWriter& scene, const std::string& name, const MeshData& mesh,
                std::array<double, 3> base_color, double roughness) {
  const int material = scene.material({name, base_color, roughness, 0.0});
  scene.node(name, scene.mesh(name, {{mesh, material}}));
}

}  // namespace

int main(int argc, char** argv) {
  return vlit::write_generated_scene(argc, argv, "generate_demo_scene", [](vlit::GltfSceneWriter& scene) {
    add_object(scene, "floor", grid_mesh({-3, 0, 2}, {6, 0, 0}, {0, 0, -5}, 96, 80), {0.8, 0.8, 0.78}, 0.9);
    add_object(scene, "back wall", grid_mesh({-3, 0, -3}, {6, 0, 0}, {0, 3, 0}, 96, 48), {0.7, 0.72, 0.8}, 0.9);
    add_object(scene, "sphere", lathe({-1.2, 0.6, 0}, 48, 96,
                                      [](double t) { const double a = M_PI * t - M_PI / 2;  // bottom to top
                                                     return std::pair{0.6 * std::cos(a), 0.6 * std::sin(a)}; }),
               {0.85, 0.25, 0.2}, 0.35);
    add_object(scene, "box", box({0.3, 0, -1.2}, {1.3, 1, -0.2}, 16), {0.25, 0.45, 0.85}, 0.6);
    add_object(scene, "vase", lathe({1.6, 0, 0.9}, 64, 64,
                                    [](double t) { return std::pair{0.18 + 0.12 * std::sin(M_PI * t * 1.5), 1.1 * t}; }),
               {0.9, 0.75, 0.3}, 0.25);

    // Camera: from the front-right, looking at the middle of the set (a rotation about X then Y).
    tinygltf::Camera camera;
    camera.type = "perspective";
    camera.perspective.yfov = 0.75;
    camera.perspective.znear = 0.05;
    camera.perspective.zfar = 100;  // tinygltf writes zfar even when unset, and 0 is invalid
    scene.model().cameras.push_back(camera);
    tinygltf::Node cam;
    cam.name = "camera";
    cam.camera = 0;
    cam.translation = {1.6, 2.2, 5.6};
    const double yaw = 0.27, pitch = -0.3;  // radians
    const double cy = std::cos(yaw / 2), sy = std::sin(yaw / 2), cp = std::cos(pitch / 2), sp = std::sin(pitch / 2);
    cam.rotation = {cy * sp, sy * cp, -sy * sp, cy * cp};  // q_yaw * q_pitch
    scene.add_root_node(cam);
  });
}
