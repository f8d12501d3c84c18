// `vlit render --view normals|wireframe` end to end: an axis-aligned cube with one normal per face
// seen from its (+X, +Y, +Z) corner has the colour 0.5 n + 0.5 (written without sRGB encoding) at
// the centre of each visible face; the face centres are projected here with the glTF perspective
// definition (camera frame from the node's rotation, tan(yfov/2)), not with vlit's matrices.
#include <doctest/doctest.h>

#include <array>
#include <cmath>
#include <filesystem>

#include <stb_image.h>

#include "support/gltf_builder.h"
#include "support/run_command.h"

using vlit::test::run_command;

namespace {

const std::string kVlit = VLIT_BINARY;
std::string q(const std::string& s) { return "'" + s + "'"; }

using V3 = std::array<double, 3>;

// Quaternion (x, y, z, w) product and rotation of a vector.
std::array<double, 4> quat_mul(const std::array<double, 4>& a, const std::array<double, 4>& b) {
  return {a[3] * b[0] + a[0] * b[3] + a[1] * b[2] - a[2] * b[1], a[3] * b[1] - a[0] * b[2] + a[1] * b[3] + a[2] * b[0],
          a[3] * b[2] + a[0] * b[1] - a[1] * b[0] + a[2] * b[3], a[3] * b[3] - a[0] * b[0] - a[1] * b[1] - a[2] * b[2]};
}
V3 rotate(const std::array<double, 4>& q4, const V3& v) {
  const auto r = quat_mul(quat_mul(q4, {v[0], v[1], v[2], 0}), {-q4[0], -q4[1], -q4[2], q4[3]});
  return {r[0], r[1], r[2]};
}
double dot3(const V3& a, const V3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

struct Png {
  int width = 0, height = 0;
  std::vector<unsigned char> rgb;
  const unsigned char* at(int x, int y) const { return rgb.data() + 3 * (size_t(y) * width + x); }
};
Png load(const std::string& path) {
  Png p;
  int channels = 0;
  unsigned char* data = stbi_load(path.c_str(), &p.width, &p.height, &channels, 3);
  REQUIRE(data != nullptr);
  p.rgb.assign(data, data + size_t(p.width) * p.height * 3);
  stbi_image_free(data);
  return p;
}

}  // namespace

TEST_CASE("render --view normals: an axis-aligned cube shows 0.5 n + 0.5 at its face centres") {
  const auto dir = vlit::test::temp_dir("render-views");
  // Cube [-1, 1]^3, 4 vertices per face with the face's normal (split normals), CCW from outside.
  std::vector<float> positions, normals;
  std::vector<std::uint32_t> indices;
  for (int axis = 0; axis < 3; ++axis)
    for (int sign : {1, -1}) {
      const int u = (axis + 1) % 3, v = (axis + 2) % 3;
      const std::uint32_t base = std::uint32_t(positions.size() / 3);
      for (auto [a, b] : {std::pair{-1, -1}, {1, -1}, {1, 1}, {-1, 1}}) {
        float p[3], n[3] = {0, 0, 0};
        p[axis] = float(sign);
        p[u] = float(a);
        p[v] = float(b * sign);  // flips the winding on the negative face
        n[axis] = float(sign);
        positions.insert(positions.end(), p, p + 3);
        normals.insert(normals.end(), n, n + 3);
      }
      indices.insert(indices.end(), {base, base + 1, base + 2, base, base + 2, base + 3});
    }
  vlit::test::GltfBuilder b;
  b.add_node(b.add_mesh(positions, normals, indices));
  // Camera at (4, 4, 4) looking at the origin: yaw 45 degrees about Y, then pitch down about X.
  const double yaw = M_PI / 4, pitch = -std::atan(1 / std::sqrt(2.0)), yfov = 0.7;
  const std::array<double, 4> rotation =
      quat_mul({0, std::sin(yaw / 2), 0, std::cos(yaw / 2)}, {std::sin(pitch / 2), 0, 0, std::cos(pitch / 2)});
  tinygltf::Camera cam;
  cam.type = "perspective";
  cam.perspective.yfov = yfov;
  cam.perspective.znear = 0.1;
  b.model().cameras.push_back(cam);
  tinygltf::Node node;
  node.camera = 0;
  node.translation = {4, 4, 4};
  node.rotation = {rotation[0], rotation[1], rotation[2], rotation[3]};
  b.model().nodes.push_back(node);
  b.model().scenes[0].nodes.push_back(int(b.model().nodes.size()) - 1);
  const std::string scene = b.write((dir / "cube.glb").string());

  constexpr int kW = 200, kH = 150;
  const std::string out = (dir / "normals.png").string();
  const auto r = run_command(kVlit + " render " + q(scene) + " -o " + q(out) + " --view normals --width 200 --height 150 -q");
  REQUIRE_MESSAGE(r.exit_code == 0, r.err);
  CHECK(r.err.find("no lights") == std::string::npos);  // the normals view needs none
  const Png image = load(out);
  REQUIRE(image.width == kW);

  // The camera frame and an independent pinhole projection.
  const V3 right = rotate(rotation, {1, 0, 0}), up = rotate(rotation, {0, 1, 0}), back = rotate(rotation, {0, 0, 1});
  CHECK(std::abs(back[0] - 1 / std::sqrt(3.0)) < 1e-12);  // the camera does look at the origin
  const double tan_half = std::tan(yfov / 2), aspect = double(kW) / kH;
  for (int axis = 0; axis < 3; ++axis) {
    CAPTURE(axis);
    V3 centre{0, 0, 0};
    centre[axis] = 1;
    const V3 rel{centre[0] - 4, centre[1] - 4, centre[2] - 4};
    const double depth = -dot3(rel, back);
    const double px = (dot3(rel, right) / (depth * tan_half * aspect) + 1) * 0.5 * kW;
    const double py = (1 - dot3(rel, up) / (depth * tan_half)) * 0.5 * kH;
    const int x = int(px), y = int(py);
    for (int dy = -1; dy <= 1; ++dy)
      for (int dx = -1; dx <= 1; ++dx) {
        const unsigned char* c = image.at(x + dx, y + dy);
        for (int k = 0; k < 3; ++k) {
          // 255 (0.5 n + 0.5): 255 on the face's own axis, 127.5 elsewhere; the perspective-correct
          // interpolation of a constant may round 127.5 either way.
          const double expected = 255 * (0.5 + 0.5 * centre[k]);
          CHECK(std::abs(c[k] - expected) <= 0.5 + 1e-9);
        }
      }
  }
  CHECK(image.at(0, 0)[0] == 0);  // background, unlit
  std::filesystem::remove_all(dir);
}

TEST_CASE("render --view: wireframe changes the picture, a bad view or line width is refused") {
  const auto dir = vlit::test::temp_dir("render-views-cli");
  const std::string demo = std::string(VLIT_SOURCE_DIR) + "/assets/demo/studio.glb";
  const std::string lights = std::string(VLIT_SOURCE_DIR) + "/assets/demo/lights.json";
  const std::string shaded = (dir / "shaded.png").string(), wire = (dir / "wire.png").string();
  const std::string size = " --width 64 --height 48 -q";
  REQUIRE(run_command(kVlit + " render " + q(demo) + " --lights " + q(lights) + " -o " + q(shaded) + size).exit_code == 0);
  REQUIRE(run_command(kVlit + " render " + q(demo) + " --lights " + q(lights) + " -o " + q(wire) + size +
                      " --view wireframe --wire-width 1")
              .exit_code == 0);
  CHECK(load(shaded).rgb != load(wire).rgb);
  const auto bad = run_command(kVlit + " render " + q(demo) + " -o " + q((dir / "x.png").string()) + " --view sketch");
  CHECK(bad.exit_code != 0);
  CHECK(!std::filesystem::exists(dir / "x.png"));
  const auto bad_width =
      run_command(kVlit + " render " + q(demo) + " -o " + q((dir / "x.png").string()) + " --view wireframe --wire-width 0");
  CHECK(bad_width.exit_code != 0);
  CHECK(!std::filesystem::exists(dir / "x.png"));
  std::filesystem::remove_all(dir);
}
