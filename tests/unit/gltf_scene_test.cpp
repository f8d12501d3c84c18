// The glTF loader: node transforms, primitive modes, indices, normals, instancing, bad input.
#include <doctest/doctest.h>

#include <cmath>
#include <fstream>

#include "core/input_error.h"
#include "gltf/gltf_scene.h"
#include "support/gltf_builder.h"

using namespace vlit;
using vlit::test::GltfBuilder;

namespace {

// A unit right triangle in the XY plane, counter-clockwise seen from +Z.
const std::vector<float> kTriangle = {0, 0, 0, 1, 0, 0, 0, 1, 0};

Scene load(GltfBuilder& b, const std::string& name, std::vector<std::string>* warnings_out = nullptr) {
  const auto dir = vlit::test::temp_dir(name);
  const std::string path = b.write((dir / "scene.glb").string());
  std::vector<std::string> warnings;
  Scene s = build_scene(load_gltf_file(path), warnings);
  if (warnings_out) *warnings_out = warnings;
  return s;
}

void check_vec(const Vec3d& a, const Vec3d& b, double tol = 1e-6) {
  CHECK(a.x == doctest::Approx(b.x).epsilon(tol));
  CHECK(a.y == doctest::Approx(b.y).epsilon(tol));
  CHECK(a.z == doctest::Approx(b.z).epsilon(tol));
}

}  // namespace

TEST_CASE("node transforms compose parent then child: T, R, S") {
  GltfBuilder b;
  const int mesh = b.add_mesh(kTriangle, {0, 0, 1, 0, 0, 1, 0, 0, 1}, {0, 1, 2});
  // Parent translates by (10, 0, 0); child rotates 90 degrees about Z and scales x by 2.
  const int parent = b.add_node(-1, {10, 0, 0});
  const double h = std::sqrt(0.5);
  b.add_node(mesh, {}, {2, 1, 1}, {0, 0, h, h}, parent);
  const Scene s = load(b, "transforms");
  REQUIRE(s.primitives.size() == 1);
  const auto& p = s.primitives[0].positions;
  // (1,0,0) scaled to (2,0,0), rotated to (0,2,0), translated to (10,2,0).
  check_vec(p[1], {10, 2, 0});
  // (0,1,0) -> (0,1,0) -> (-1,0,0) -> (9,0,0).
  check_vec(p[2], {9, 0, 0});
  check_vec(s.primitives[0].normals[0], {0, 0, 1});
}

TEST_CASE("negative scale flips winding and keeps normals facing out") {
  GltfBuilder b;
  const int mesh = b.add_mesh(kTriangle, {}, {0, 1, 2});  // no normals: computed from the winding
  b.add_node(mesh, {}, {1, 1, -1});                        // mirror in z: still in the XY plane
  b.add_node(mesh, {}, {-1, 1, 1});                        // mirror in x
  const Scene s = load(b, "mirror");
  REQUIRE(s.primitives.size() == 2);
  // Mirroring z maps +Z normals to -Z; mirroring x keeps a +Z normal but reverses the winding.
  check_vec(s.primitives[0].normals[0], {0, 0, -1});
  check_vec(s.primitives[1].normals[0], {0, 0, 1});
  for (const auto& prim : s.primitives) {
    const auto& t = prim.triangles;
    const Vec3d face = cross(prim.positions[t[1]] - prim.positions[t[0]], prim.positions[t[2]] - prim.positions[t[0]]);
    CHECK(dot(face, prim.normals[0]) > 0);  // counter-clockwise around the outward normal
  }
}

TEST_CASE("triangle strips and fans become triangle lists with consistent winding") {
  const std::vector<std::uint32_t> idx = {0, 1, 2, 3, 4};
  CHECK(triangle_list(TINYGLTF_MODE_TRIANGLE_STRIP, idx) == std::vector<std::uint32_t>{0, 1, 2, 2, 1, 3, 2, 3, 4});
  CHECK(triangle_list(TINYGLTF_MODE_TRIANGLE_FAN, idx) == std::vector<std::uint32_t>{1, 2, 0, 2, 3, 0, 3, 4, 0});
  CHECK(triangle_list(TINYGLTF_MODE_TRIANGLES, {0, 1, 2, 3}) == std::vector<std::uint32_t>{0, 1, 2});
}

TEST_CASE("computed normals respect the file's vertex split") {
  // Two triangles folded 90 degrees along the x axis, not sharing vertices: each keeps its own
  // face normal. A shared-vertex version gets the angle-weighted average on the fold.
  GltfBuilder b;
  const std::vector<float> split = {0, 0, 0, 1, 0, 0, 0, 1, 0,   0, 0, 0, 0, 0, 1, 1, 0, 0};
  const int m1 = b.add_mesh(split, {}, {0, 1, 2, 3, 4, 5});
  const std::vector<float> shared = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1};
  const int m2 = b.add_mesh(shared, {}, {0, 1, 2, 0, 3, 1});
  b.add_node(m1);
  b.add_node(m2);
  const Scene s = load(b, "normals");
  check_vec(s.primitives[0].normals[0], {0, 0, 1});
  check_vec(s.primitives[0].normals[3], {0, 1, 0});
  // Shared vertex 0: both faces meet it at 90 degrees, so the average is (0, 1, 1)/sqrt 2.
  check_vec(s.primitives[1].normals[0], {0, std::sqrt(0.5), std::sqrt(0.5)});
  check_vec(s.primitives[1].normals[2], {0, 0, 1});
}

TEST_CASE("a mesh instanced twice gives two world-space primitives") {
  GltfBuilder b;
  const int mesh = b.add_mesh(kTriangle, {}, {0, 1, 2});
  b.add_node(mesh, {0, 0, 0});
  b.add_node(mesh, {0, 0, 5});
  const Scene s = load(b, "instances");
  REQUIRE(s.primitives.size() == 2);
  CHECK(s.primitives[0].mesh == s.primitives[1].mesh);
  CHECK(s.primitives[1].positions[0].z == 5);
}

TEST_CASE("bad input: index out of range, node cycle, non-triangle primitives") {
  SUBCASE("index out of range is an error naming the accessor") {
    GltfBuilder b;
    b.add_node(b.add_mesh(kTriangle, {}, {0, 1, 3}));
    CHECK_THROWS_WITH_AS(load(b, "badindex"), doctest::Contains("is not below the vertex count 3"), InputError);
  }
  SUBCASE("a node cycle is an error") {
    GltfBuilder b;
    const int a = b.add_node(b.add_mesh(kTriangle, {}, {0, 1, 2}));
    const int c = b.add_node(-1, {}, {}, {}, a);
    b.model().nodes[c].children.push_back(a);
    CHECK_THROWS_WITH_AS(load(b, "cycle"), doctest::Contains("reached twice"), InputError);
  }
  SUBCASE("lines are skipped with a warning") {
    GltfBuilder b;
    b.add_node(b.add_mesh(kTriangle, {}, {0, 1}, TINYGLTF_MODE_LINE));
    std::vector<std::string> warnings;
    const Scene s = load(b, "lines", &warnings);
    CHECK(s.primitives.empty());
    REQUIRE(warnings.size() == 1);
    CHECK(warnings[0].find("skipped") != std::string::npos);
  }
  SUBCASE("a required extension vlit does not support is named before the file is parsed") {
    // The index accessor loses its bufferView, as in a compressed asset: a parser that ran first
    // would fail on it ("accessor[0] invalid bufferView") instead of naming the extension.
    GltfBuilder b;
    b.add_node(b.add_mesh(kTriangle, {}, {0, 1, 2}));
    b.model().accessors[b.model().meshes[0].primitives[0].indices].bufferView = -1;
    b.model().extensionsRequired.push_back("EXT_mesh_gpu_instancing");
    b.model().extensionsUsed.push_back("EXT_mesh_gpu_instancing");
    CHECK_THROWS_WITH_AS(load(b, "unsupported-extension"),
                         doctest::Contains("scene.glb: requires extension EXT_mesh_gpu_instancing, which vlit does not support"),
                         InputError);
  }
  SUBCASE("a compression extension that is required but stores nothing is dropped, the asset loads") {
    GltfBuilder b;
    b.add_node(b.add_mesh(kTriangle, {}, {0, 1, 2}));
    b.model().extensionsRequired.push_back("KHR_draco_mesh_compression");
    b.model().extensionsUsed.push_back("KHR_draco_mesh_compression");
    const auto dir = vlit::test::temp_dir("unused-draco");
    const GltfFile file = load_gltf_file(b.write((dir / "scene.glb").string()));
    CHECK(file.model.extensionsRequired.empty());
    CHECK(file.model.extensionsUsed.empty());
    std::vector<std::string> warnings;
    CHECK(build_scene(file, warnings).primitives.size() == 1);
  }
}

TEST_CASE("real assets load: Box and its interleaved variant") {
  const std::string samples = std::string(VLIT_ASSETS_DIR) + "/samples";
  REQUIRE_MESSAGE(std::filesystem::exists(samples + "/Box/Box.gltf"), "missing test data: " << samples);
  std::vector<std::string> warnings;
  const Scene box = build_scene(load_gltf_file(samples + "/Box/Box.gltf"), warnings);
  REQUIRE(box.primitives.size() == 1);
  CHECK(box.primitives[0].positions.size() == 24);
  CHECK(box.primitives[0].triangles.size() == 36);
  const Scene inter = build_scene(load_gltf_file(samples + "/BoxInterleaved/BoxInterleaved.gltf"), warnings);
  REQUIRE(inter.primitives.size() == 1);
  // Same box, interleaved storage: same world-space vertices.
  for (std::size_t i = 0; i < 24; ++i) check_vec(inter.primitives[0].positions[i], box.primitives[0].positions[i]);
}

TEST_CASE("KHR_lights_punctual lights are placed by their node's transform") {
  GltfBuilder b;
  b.add_node(b.add_mesh(kTriangle, {}, {0, 1, 2}));
  tinygltf::Light spot;
  spot.type = "spot";
  spot.intensity = 7;
  spot.color = {1, 0.5, 0.25};
  spot.range = 3;
  spot.spot.innerConeAngle = 0.1;
  spot.spot.outerConeAngle = 0.3;
  b.model().lights.push_back(spot);
  // The node sits at (0, 0, 4) rotated 180 degrees about X: local -Z points to world +Z... and a
  // parent moves it by (1, 0, 0). Expected: position (1, 0, 4), direction (0, 0, 1).
  const int parent = b.add_node(-1, {1, 0, 0});
  const int node = b.add_node(-1, {0, 0, 4}, {}, {1, 0, 0, 0}, parent);
  tinygltf::Value::Object ref;
  ref["light"] = tinygltf::Value(0);
  b.model().nodes[node].extensions["KHR_lights_punctual"] = tinygltf::Value(ref);
  b.model().extensionsUsed.push_back("KHR_lights_punctual");
  const Scene s = load(b, "punctual");
  REQUIRE(s.lights.size() == 1);
  const LightSource& l = s.lights[0];
  CHECK(l.type == LightType::kSpot);
  CHECK(l.intensity == 7);
  CHECK(l.color.y == 0.5);
  REQUIRE(l.range.has_value());
  CHECK(*l.range == 3);
  check_vec(l.position, {1, 0, 4});
  check_vec(l.direction, {0, 0, 1});
  CHECK(l.cos_inner == doctest::Approx(std::cos(0.1)));
  CHECK(l.cos_outer == doctest::Approx(std::cos(0.3)));
}

TEST_CASE("external URIs are used literally: no shell expansion, no reading directories") {
  const auto dir = vlit::test::temp_dir("uri");
  const auto marker = dir / "expanded";
  // If the loader ran the URI through shell expansion, this would create the marker file.
  const std::string uri = "$(touch " + marker.string() + ").bin";
  std::ofstream(dir / "shell.gltf") << R"({"asset": {"version": "2.0"}, "buffers": [{"uri": ")" + uri +
                                           R"(", "byteLength": 4}]})";
  CHECK_THROWS_AS(load_gltf_file((dir / "shell.gltf").string()), InputError);
  CHECK_FALSE(std::filesystem::exists(marker));
  // A buffer URI naming a directory is refused, not read as a file of absurd size.
  std::filesystem::create_directories(dir / "folder");
  std::ofstream(dir / "dir.gltf") << R"({"asset": {"version": "2.0"}, "buffers": [{"uri": "folder", "byteLength": 4}]})";
  CHECK_THROWS_WITH_AS(load_gltf_file((dir / "dir.gltf").string()), doctest::Contains("dir.gltf"), InputError);
}
