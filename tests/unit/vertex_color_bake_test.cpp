// Baking: a single triangle under a known light has a known COLOR_0, read back from the written
// file; instanced meshes get their own colours; everything else passes through.
#include <doctest/doctest.h>

#include <cmath>
#include <fstream>

#include "bake/bake_file.h"
#include "bake/light_vertices.h"
#include "bake/vertex_color_bake.h"
#include "gltf/accessor_reader.h"
#include "gltf/gltf_scene.h"
#include "gltf/gltf_writer.h"
#include "support/gltf_builder.h"
#include "support/run_command.h"

using namespace vlit;
using vlit::test::GltfBuilder;

namespace {

struct Baked {
  tinygltf::Model model;
  BakeReport report;
};

Baked bake_and_reload(GltfBuilder& b, const std::vector<LightSource>& lights, const std::string& name,
                      const std::string& ext, BakeOptions options = {}) {
  const auto dir = vlit::test::temp_dir(name);
  const std::string in = b.write((dir / "in.glb").string());
  GltfFile file = load_gltf_file(in);
  std::vector<std::string> warnings;
  Scene scene = build_scene(file, warnings);
  scene.lights = lights;
  const auto light = light_scene_vertices(scene, LightingRequest{});
  tinygltf::Model model = file.model;
  Baked out;
  out.report = bake_vertex_colors(model, scene, light, options);
  const std::string path = (dir / ("out" + ext)).string();
  write_gltf(model, in, path);
  out.model = load_gltf_file(path).model;
  return out;
}

LightSource point_light(Vec3d position, double intensity) {
  LightSource l;
  l.type = LightType::kPoint;
  l.position = position;
  l.intensity = intensity;
  return l;
}

}  // namespace

TEST_CASE("one triangle under a point light: COLOR_0 = I cos / d^2 per vertex") {
  for (const std::string ext : {".glb", ".gltf"}) {
    CAPTURE(ext);
    GltfBuilder b;
    b.add_node(b.add_mesh({0, 0, 0, 1, 0, 0, 0, 1, 0}, {0, 0, 1, 0, 0, 1, 0, 0, 1}, {0, 1, 2}));
    // Light 2 above the origin with intensity 2: vertex 0 gets 2/4; vertices 1 and 2 are at
    // distance sqrt 5 with cos = 2/sqrt 5: 2 * (2/sqrt 5) / 5.
    const Baked baked = bake_and_reload(b, {point_light({0, 0, 2}, 2)}, "one-triangle", ext);
    const auto& prim = baked.model.meshes[0].primitives[0];
    REQUIRE(prim.attributes.count("COLOR_0"));
    const tinygltf::Accessor& acc = baked.model.accessors[prim.attributes.at("COLOR_0")];
    CHECK(acc.type == TINYGLTF_TYPE_VEC4);
    CHECK(acc.componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT);
    CHECK(acc.normalized);
    const auto c = read_accessor_as_doubles(baked.model, prim.attributes.at("COLOR_0"), "out");
    const double expected[3] = {0.5, 2 * (2 / std::sqrt(5.0)) / 5, 2 * (2 / std::sqrt(5.0)) / 5};
    for (int v = 0; v < 3; ++v) {
      for (int ch = 0; ch < 3; ++ch) CHECK(c[4 * v + ch] == doctest::Approx(expected[v]).epsilon(1.0 / 65535));
      CHECK(c[4 * v + 3] == 1.0);
    }
    CHECK(baked.report.max_quantization_error <= 0.5 / 65535 + 1e-12);
    // Viewers must not light it again.
    REQUIRE(prim.material >= 0);
    CHECK(baked.model.materials[prim.material].extensions.count("KHR_materials_unlit"));
  }
}

TEST_CASE("light above 1 is clipped in unorm formats and counted, float keeps it") {
  GltfBuilder b;
  b.add_node(b.add_mesh({0, 0, 0, 1, 0, 0, 0, 1, 0}, {0, 0, 1, 0, 0, 1, 0, 0, 1}, {0, 1, 2}));
  BakeOptions u8;
  u8.format = ColorFormat::kUnorm8;
  const Baked unorm = bake_and_reload(b, {point_light({0, 0, 1}, 10)}, "clip8", ".glb", u8);
  CHECK(unorm.report.clipped_vertices == 3);
  BakeOptions f;
  f.format = ColorFormat::kFloat;
  const Baked fl = bake_and_reload(b, {point_light({0, 0, 1}, 10)}, "float", ".glb", f);
  const auto& prim = fl.model.meshes[0].primitives[0];
  const auto c = read_accessor_as_doubles(fl.model, prim.attributes.at("COLOR_0"), "out");
  CHECK(c[0] == doctest::Approx(10.0));
}

TEST_CASE("an instanced mesh is duplicated so each instance keeps its own light") {
  GltfBuilder b;
  const int mesh = b.add_mesh({0, 0, 0, 1, 0, 0, 0, 1, 0}, {0, 0, 1, 0, 0, 1, 0, 0, 1}, {0, 1, 2});
  b.add_node(mesh, {0, 0, 0});
  b.add_node(mesh, {0, 0, -1});  // one unit further from the light
  const Baked baked = bake_and_reload(b, {point_light({0, 0, 1}, 1)}, "instanced", ".glb");
  CHECK(baked.report.duplicated_meshes == 1);
  REQUIRE(baked.model.meshes.size() == 2);
  CHECK(baked.model.nodes[0].mesh != baked.model.nodes[1].mesh);
  auto color0 = [&](int node) {
    const auto& prim = baked.model.meshes[baked.model.nodes[node].mesh].primitives[0];
    return read_accessor_as_doubles(baked.model, prim.attributes.at("COLOR_0"), "out")[0];
  };
  CHECK(color0(0) == doctest::Approx(1.0).epsilon(1e-4));   // 1 / 1^2
  CHECK(color0(1) == doctest::Approx(0.25).epsilon(1e-4));  // 1 / 2^2
}

TEST_CASE("everything but the baked attribute passes through") {
  GltfBuilder b;
  const int mat = b.add_material({0.5, 0.25, 1, 1}, 0, 0.5);
  b.add_node(b.add_mesh({0, 0, 0, 1, 0, 0, 0, 1, 0}, {}, {0, 1, 2}, TINYGLTF_MODE_TRIANGLES, mat));
  b.model().nodes[0].name = "keep me";
  b.model().extensionsUsed.push_back("EXT_unknown_to_vlit");
  tinygltf::Value::Object extras;
  extras["answer"] = tinygltf::Value(42);
  b.model().nodes[0].extras = tinygltf::Value(extras);
  const Baked baked = bake_and_reload(b, {point_light({0, 0, 2}, 1)}, "passthrough", ".glb");
  CHECK(baked.model.nodes[0].name == "keep me");
  CHECK(baked.model.nodes[0].extras.Get("answer").Get<int>() == 42);
  CHECK(baked.model.materials[0].pbrMetallicRoughness.baseColorFactor[1] == 0.25);
  const auto& used = baked.model.extensionsUsed;
  CHECK(std::find(used.begin(), used.end(), "EXT_unknown_to_vlit") != used.end());
  // The original POSITION accessor is unchanged.
  const auto pos = read_accessor_as_doubles(baked.model, baked.model.meshes[0].primitives[0].attributes.at("POSITION"), "out");
  CHECK(pos == std::vector<double>{0, 0, 0, 1, 0, 0, 0, 1, 0});
}

TEST_CASE("multiply mode: existing vertex colours times the light, alpha kept") {
  GltfBuilder b;
  const int mesh = b.add_mesh({0, 0, 0, 1, 0, 0, 0, 1, 0}, {0, 0, 1, 0, 0, 1, 0, 0, 1}, {0, 1, 2});
  b.model().meshes[mesh].primitives[0].attributes["COLOR_0"] =
      b.add_floats({0.5f, 1, 0.25f, 0.75f, 1, 1, 1, 1, 1, 1, 1, 1}, TINYGLTF_TYPE_VEC4);
  b.add_node(mesh);
  BakeOptions multiply;
  multiply.mode = BakeMode::kMultiply;
  multiply.format = ColorFormat::kFloat;
  // Light 1 above vertex 0 with intensity 1: vertex 0 gets exactly 1.
  const Baked baked = bake_and_reload(b, {point_light({0, 0, 1}, 1)}, "multiply", ".glb", multiply);
  CHECK(baked.report.replaced_attributes == 1);
  const auto& prim = baked.model.meshes[0].primitives[0];
  const auto c = read_accessor_as_doubles(baked.model, prim.attributes.at("COLOR_0"), "out");
  CHECK(c[0] == doctest::Approx(0.5));
  CHECK(c[1] == doctest::Approx(1.0));
  CHECK(c[2] == doctest::Approx(0.25));
  CHECK(c[3] == doctest::Approx(0.75));
}

TEST_CASE("an infinite perspective camera stays infinite: no zfar = 0 in the output") {
  for (const std::string ext : {".glb", ".gltf"}) {
    CAPTURE(ext);
    GltfBuilder b;
    b.add_node(b.add_mesh({0, 0, 0, 1, 0, 0, 0, 1, 0}, {}, {0, 1, 2}));
    tinygltf::Camera camera;
    camera.type = "perspective";
    camera.perspective.yfov = 0.5;
    camera.perspective.znear = 0.1;  // zfar left at 0: infinite
    b.model().cameras.push_back(camera);
    b.model().nodes[0].camera = 0;
    const auto dir = vlit::test::temp_dir("infinite-camera");
    const std::string in = b.write((dir / "in.glb").string());
    GltfFile file = load_gltf_file(in);
    const std::string out = (dir / ("out" + ext)).string();
    write_gltf(file.model, in, out);
    const std::string text = vlit::test::read_all(out);
    CHECK(text.find("\"zfar\"") == std::string::npos);
    const GltfFile back = load_gltf_file(out);
    REQUIRE(back.model.cameras.size() == 1);
    CHECK(back.model.cameras[0].perspective.yfov == doctest::Approx(0.5));
  }
}

TEST_CASE("--specular-eye: one triangle, specular folded into the multiplier by hand") {
  // Material: base (0.5, 0.25, 1), dielectric (ks = 0.04), roughness 0.5^(1/4) so alpha^2 = 0.5
  // and m = 2 / alpha^2 - 2 = 2. Point light of intensity 2 at (0, 0, 2), eye at (0, 0, 5).
  GltfBuilder b;
  const int mat = b.add_material({0.5, 0.25, 1, 1}, 0, std::pow(0.5, 0.25));
  b.add_node(b.add_mesh({0, 0, 0, 1, 0, 0, 0, 1, 0}, {0, 0, 1, 0, 0, 1, 0, 0, 1}, {0, 1, 2}, TINYGLTF_MODE_TRIANGLES, mat));
  const auto dir = vlit::test::temp_dir("specular-eye");
  const std::string in = b.write((dir / "in.glb").string());
  const std::string lights = (dir / "lights.json").string();
  std::ofstream(lights) << R"({"lights": [{"type": "point", "position": [0, 0, 2], "intensity": 2}]})";
  BakeFileOptions options;
  options.lights_path = lights;
  options.encode.format = ColorFormat::kFloat;
  options.specular_eye = Vec3d{0, 0, 5};
  const std::string out = (dir / "out.glb").string();
  bake_file(in, out, options);
  const GltfFile baked = load_gltf_file(out);
  const auto c = read_accessor_as_doubles(baked.model, baked.model.meshes[0].primitives[0].attributes.at("COLOR_0"), "out");
  const double albedo[3] = {0.5, 0.25, 1};
  // Vertex 0 at the origin: L = V = Rv = +Z; diffuse 2 / 2^2 = 0.5, specular Ip ks (Rv.L)^m / |L|^2
  // = 0.08 / 4 (the default specular carries the diffuse's falloff, docs/conventions.md).
  for (int ch = 0; ch < 3; ++ch) CHECK(c[ch] == doctest::Approx(0.5 + 0.02 / albedo[ch]).epsilon(1e-6));
  // Vertex 1 at (1, 0, 0): L = (-1, 0, 2), |L|^2 = 5, V = (-1, 0, 5)/sqrt 26, Rv = (1, 0, 5)/sqrt 26,
  // Rv.L̂ = 9 / sqrt 130; diffuse 2 (2/sqrt 5) / 5, specular 0.08 (81/130) / 5.
  const double diffuse1 = 2 * (2 / std::sqrt(5.0)) / 5, specular1 = 0.08 * 81.0 / 130.0 / 5;
  for (int ch = 0; ch < 3; ++ch) CHECK(c[4 + ch] == doctest::Approx(diffuse1 + specular1 / albedo[ch]).epsilon(1e-6));
  // What a viewer shows, stored x base = kd diffuse + ks specular:
  CHECK(c[4] * 0.5 == doctest::Approx(0.5 * diffuse1 + 0.04 * 2 * 81.0 / 130.0 / 5).epsilon(1e-6));

  // The paper's eq. 6 by name (--specular exact-no-falloff): no 1/|L|^2 on the specular.
  options.specular.falloff = SpecularFalloff::kNone;
  const std::string paper = (dir / "paper.glb").string();
  bake_file(in, paper, options);
  const GltfFile pb = load_gltf_file(paper);
  const auto cp = read_accessor_as_doubles(pb.model, pb.model.meshes[0].primitives[0].attributes.at("COLOR_0"), "paper");
  for (int ch = 0; ch < 3; ++ch) CHECK(cp[ch] == doctest::Approx(0.5 + 0.08 / albedo[ch]).epsilon(1e-6));
  for (int ch = 0; ch < 3; ++ch) CHECK(cp[4 + ch] == doctest::Approx(diffuse1 + 5 * specular1 / albedo[ch]).epsilon(1e-6));
  options.specular.falloff = SpecularFalloff::kAsDiffuse;

  // Without an eye, no specular: the diffuse alone.
  options.specular_eye.reset();
  const std::string plain = (dir / "plain.glb").string();
  bake_file(in, plain, options);
  const GltfFile p = load_gltf_file(plain);
  const auto d = read_accessor_as_doubles(p.model, p.model.meshes[0].primitives[0].attributes.at("COLOR_0"), "out");
  CHECK(d[0] == doctest::Approx(0.5).epsilon(1e-6));
}

TEST_CASE("--specular-eye: a base colour channel of 0 cannot show specular, it is counted, not divided") {
  GltfBuilder b;
  const int mat = b.add_material({0.5, 0, 1, 1}, 0, 0.5);
  b.add_node(b.add_mesh({0, 0, 0, 1, 0, 0, 0, 1, 0}, {0, 0, 1, 0, 0, 1, 0, 0, 1}, {0, 1, 2}, TINYGLTF_MODE_TRIANGLES, mat));
  const auto dir = vlit::test::temp_dir("specular-black");
  const std::string in = b.write((dir / "in.glb").string());
  const std::string lights = (dir / "lights.json").string();
  std::ofstream(lights) << R"({"lights": [{"type": "point", "position": [0, 0, 2], "intensity": 2}]})";
  BakeFileOptions options;
  options.lights_path = lights;
  options.encode.format = ColorFormat::kFloat;
  options.specular_eye = Vec3d{0, 0, 5};
  const BakeFileResult r = bake_file(in, (dir / "out.glb").string(), options);
  CHECK(r.report.specular_unrepresentable == 3);
  CHECK(std::any_of(r.warnings.begin(), r.warnings.end(), [](const std::string& w) { return w.find("base colour is 0") != std::string::npos; }));
}
