// Limits that protect the machine (docs/robustness.md): counts checked against the file and
// against the scene limits before anything is allocated; deep hierarchies; non-finite positions
// and zero normals reported, never propagated into colours.
#include <doctest/doctest.h>

#include <cmath>
#include <filesystem>
#include <limits>

#include "bake/light_vertices.h"
#include "core/input_error.h"
#include "gltf/accessor_reader.h"
#include "gltf/gltf_memory.h"
#include "gltf/gltf_scene.h"
#include "support/gltf_builder.h"
#include "support/run_command.h"

using namespace vlit;
using vlit::test::GltfBuilder;
using vlit::test::run_command;

namespace {

const std::vector<float> kTriangle = {0, 0, 0, 1, 0, 0, 0, 1, 0};

GltfFile as_file(const tinygltf::Model& model) { return GltfFile{"limits.gltf", model, {}}; }

// The InputError message of f(), or "" if it did not throw.
template <class F>
std::string input_error_of(F&& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return {};
}

std::string q(const std::string& s) { return "'" + s + "'"; }

}  // namespace

TEST_CASE("a node chain as deep as the file is long does not overflow the stack") {
  GltfBuilder b;
  const int mesh = b.add_mesh(kTriangle, {}, {});
  int parent = b.add_node(mesh);
  for (int i = 0; i < 200000; ++i) parent = b.add_node(-1, {0, 0, 0}, {}, {}, parent);
  b.model().nodes.back().mesh = mesh;
  std::vector<std::string> warnings;
  const Scene scene = build_scene(as_file(b.model()), warnings);
  CHECK(scene.primitives.size() == 2);
}

TEST_CASE("node order: parents before children, siblings in file order (the explicit stack keeps it)") {
  GltfBuilder b;
  const int m0 = b.add_mesh(kTriangle, {}, {});
  const int m1 = b.add_mesh(kTriangle, {}, {});
  const int m2 = b.add_mesh(kTriangle, {}, {});
  const int root = b.add_node(m0);
  b.add_node(m1, {}, {}, {}, root);
  b.add_node(m2);
  std::vector<std::string> warnings;
  const Scene scene = build_scene(as_file(b.model()), warnings);
  REQUIRE(scene.primitives.size() == 3);
  CHECK(scene.primitives[0].mesh == m0);
  CHECK(scene.primitives[1].mesh == m1);
  CHECK(scene.primitives[2].mesh == m2);
}

TEST_CASE("vertex limit: counted over every instance, checked before reading") {
  GltfBuilder b;
  std::vector<float> positions;
  for (int i = 0; i < 600; ++i) positions.insert(positions.end(), {float(i), float(i % 7), 0});
  const int mesh = b.add_mesh(positions, {}, {});
  b.add_node(mesh);
  std::vector<std::string> warnings;
  CHECK(build_scene(as_file(b.model()), warnings, {SceneLimits{1000}, true}).primitives.size() == 1);
  b.add_node(mesh, {1, 0, 0});  // a second instance: 1200 vertices in all
  const std::string error = input_error_of([&] { build_scene(as_file(b.model()), warnings, {SceneLimits{1000}, true}); });
  CHECK(error.find("limits.gltf") != std::string::npos);
  CHECK(error.find("--max-vertices") != std::string::npos);
  CHECK(build_scene(as_file(b.model()), warnings, {SceneLimits{1200}, true}).primitives.size() == 2);
}

TEST_CASE("vertex limit: a POSITION accessor without bufferView and a huge count is refused, not allocated") {
  GltfBuilder b;
  const int mesh = b.add_mesh(kTriangle, {}, {});
  b.add_node(mesh);
  tinygltf::Accessor& pos = b.model().accessors[b.model().meshes[mesh].primitives[0].attributes["POSITION"]];
  pos.bufferView = -1;
  pos.count = std::size_t(1) << 40;
  std::vector<std::string> warnings;
  CHECK(input_error_of([&] { build_scene(as_file(b.model()), warnings); }).find("--max-vertices") != std::string::npos);
}

TEST_CASE("triangle corner limit: an index accessor far larger than the vertices is refused before reading") {
  GltfBuilder b;
  const int mesh = b.add_mesh(kTriangle, {}, {0, 1, 2});
  b.add_node(mesh);
  tinygltf::Accessor& idx = b.model().accessors[b.model().meshes[mesh].primitives[0].indices];
  idx.bufferView = -1;
  idx.count = std::size_t(1) << 40;
  std::vector<std::string> warnings;
  CHECK(input_error_of([&] { build_scene(as_file(b.model()), warnings, {SceneLimits{1000}, true}); }).find("corners") != std::string::npos);
}

TEST_CASE("a NORMAL accessor whose count differs from POSITION is refused before it is read") {
  GltfBuilder b;
  const int mesh = b.add_mesh(kTriangle, {0, 0, 1, 0, 0, 1, 0, 0, 1}, {});
  b.add_node(mesh);
  tinygltf::Accessor& nrm = b.model().accessors[b.model().meshes[mesh].primitives[0].attributes["NORMAL"]];
  nrm.bufferView = -1;
  nrm.count = std::size_t(1) << 26;  // 1.6 GB of doubles if it were read first
  std::vector<std::string> warnings;
  CHECK(input_error_of([&] { build_scene(as_file(b.model()), warnings); }).find("NORMAL and POSITION counts differ") !=
        std::string::npos);
}

TEST_CASE("accessor without bufferView: sparse or not, the count is capped before allocating") {
  GltfBuilder b;
  const int acc = b.add_floats({1, 2, 3}, TINYGLTF_TYPE_VEC3);
  tinygltf::Accessor& a = b.model().accessors[acc];
  a.bufferView = -1;
  a.count = std::size_t(1) << 34;
  a.sparse.isSparse = true;
  a.sparse.count = 1;
  CHECK(input_error_of([&] { read_accessor_as_doubles(b.model(), acc, "limits.gltf"); }).find("unreasonably large") !=
        std::string::npos);
  a.sparse.isSparse = false;
  CHECK(input_error_of([&] { read_accessor_as_doubles(b.model(), acc, "limits.gltf"); }).find("unreasonably large") !=
        std::string::npos);
  a.count = 4;  // small: zeros, as the spec says
  CHECK(read_accessor_as_doubles(b.model(), acc, "limits.gltf") == std::vector<double>(12, 0.0));
}

TEST_CASE("non-finite positions and zero normals are reported and get no light, colours stay finite") {
  const double inf = std::numeric_limits<double>::infinity();
  const float nan = std::numeric_limits<float>::quiet_NaN();
  GltfBuilder b;
  // Quad of 2 triangles plus a third triangle on a NaN vertex; vertex 1 has a zero normal.
  const int mesh = b.add_mesh({0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, nan, 0, 0},
                              {0, 0, 1, 0, 0, 0, 0, 0, 1, 0, 0, 1, 0, 0, 1}, {0, 1, 2, 0, 2, 3, 0, 3, 4});
  b.add_node(mesh);
  std::vector<std::string> warnings;
  Scene scene = build_scene(as_file(b.model()), warnings);
  REQUIRE(scene.primitives.size() == 1);
  const ScenePrimitive& prim = scene.primitives[0];
  CHECK(prim.triangles.size() == 6);  // the NaN triangle is dropped
  bool saw_position_warning = false, saw_normal_warning = false;
  for (const auto& w : warnings) {
    saw_position_warning |= w.find("non-finite positions") != std::string::npos;
    saw_normal_warning |= w.find("zero or non-finite normals") != std::string::npos;
  }
  CHECK(saw_position_warning);
  CHECK(saw_normal_warning);
  for (std::size_t i = 0; i < prim.positions.size(); ++i) {
    CHECK(is_finite(prim.positions[i]));
    CHECK(is_finite(prim.normals[i]));
  }
  CHECK(length(prim.normals[1]) == doctest::Approx(1));  // repaired from the triangles

  LightSource point;
  point.type = LightType::kPoint;
  point.position = {0.5, 0.5, 1};
  scene.lights = {point};
  LightingRequest request;
  request.eye = Vec3d{0, 0, 5};
  const auto light = light_scene_vertices(scene, request);
  for (const auto& c : light[0].diffuse) CHECK(is_finite(Vec3d(c)));
  for (const auto& c : light[0].specular) CHECK(is_finite(Vec3d(c)));
  CHECK(length(Vec3d(light[0].diffuse[4])) == 0);  // the NaN vertex receives no light
  (void)inf;
}

TEST_CASE("an asset in memory never reads external files") {
  const std::string gltf = R"({"asset":{"version":"2.0"},"buffers":[{"uri":"/etc/passwd","byteLength":4}]})";
  const std::string error = input_error_of([&] { load_gltf_from_memory(gltf, "memory.gltf"); });
  CHECK(error.find("memory.gltf") != std::string::npos);
}

TEST_CASE("command line: --max-vertices and --max-pixels refuse in one line naming the file") {
  const auto dir = vlit::test::temp_dir("robust-limits");
  GltfBuilder b;
  b.add_node(b.add_mesh(kTriangle, {}, {}));
  const std::string input = b.write((dir / "tri.glb").string());
  const std::string out = (dir / "out.glb").string();
  const std::string vlit = VLIT_BINARY;

  auto r = run_command(vlit + " bake " + q(input) + " -o " + q(out) + " --max-vertices 2");
  CHECK(r.exit_code == 1);
  CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 1);
  CHECK(r.err.find(input) != std::string::npos);
  CHECK(r.err.find("--max-vertices") != std::string::npos);
  CHECK_FALSE(std::filesystem::exists(out));
  r = run_command(vlit + " bake " + q(input) + " -o " + q(out) + " --max-vertices 3 --quiet");
  CHECK_MESSAGE(r.exit_code == 0, r.err);

  const std::string png = (dir / "out.png").string();
  r = run_command(vlit + " render " + q(input) + " -o " + q(png) + " --width 16384 --height 16384 --quiet");
  CHECK(r.exit_code == 1);
  CHECK(r.err.find("--max-pixels") != std::string::npos);
  CHECK(r.err.find(png) != std::string::npos);
  CHECK_FALSE(std::filesystem::exists(png));
  r = run_command(vlit + " render " + q(input) + " -o " + q(png) + " --width 64 --height 64 --max-vertices 2 --quiet");
  CHECK(r.exit_code == 1);
  CHECK(r.err.find("--max-vertices") != std::string::npos);
  std::filesystem::remove_all(dir);
}
