// The library API (include/vlit/vlit.h, src/api/): a bake through it equals the command line's
// own path (bake_file) byte for byte, errors name their input and place, cancellation stops the
// work and leaves the model alone, the thread count does not change results, and probe, the
// array path and render give the values their definitions say.
#include <doctest/doctest.h>

#include <vlit/vlit.h>

#include <atomic>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "bake/bake_file.h"
#include "gltf/accessor_reader.h"
#include "support/cornell_obj.h"
#include "support/gltf_builder.h"

namespace {

const std::string kStudio = std::string(VLIT_SOURCE_DIR) + "/assets/demo/studio.glb";
const std::string kStudioLights = std::string(VLIT_SOURCE_DIR) + "/assets/demo/lights.json";

std::string read_bytes(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// The message of the vlit::Error `body` throws (fails the test if it throws nothing or another type).
template <class Body>
vlit::Error error_of(Body&& body) {
  try {
    body();
  } catch (const vlit::Error& e) {
    return e;
  }
  FAIL("no vlit::Error thrown");
  return vlit::Error("", "");
}

// A unit square in z = 0 facing +z, as two triangles.
vlit::Mesh square() {
  vlit::Mesh m;
  m.positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  m.normals = {{0, 0, 1}, {0, 0, 1}, {0, 0, 1}, {0, 0, 1}};
  m.triangles = {0, 1, 2, 0, 2, 3};
  return m;
}

}  // namespace

TEST_CASE("api: bake of a model in memory equals the command line's bake_file, byte for byte") {
  const auto dir = vlit::test::temp_dir("api-bake");
  // The command line's path: bake_file with LIGHTS.json, default options (vlit bake IN --lights L -o OUT).
  vlit::BakeFileOptions cli;
  cli.lights_path = kStudioLights;
  vlit::bake_file(kStudio, (dir / "cli.glb").string(), cli);

  tinygltf::Model model = vlit::load_model(kStudio);
  const vlit::Lights lights = vlit::Lights::read_json(kStudioLights);
  CHECK(lights.size() == 4);
  const vlit::BakeSettings defaults;
  const vlit::BakeSummary summary = vlit::bake(model, lights, defaults, kStudio);
  CHECK(summary.lights == 4);
  CHECK(summary.vertices > 20000);
  vlit::save_model(model, (dir / "api.glb").string(), kStudio);
  const std::string expected = read_bytes(dir / "cli.glb");
  CHECK(expected.size() > 100000);
  CHECK(read_bytes(dir / "api.glb") == expected);

  // The file-to-file call is the same path.
  vlit::bake_asset(kStudio, (dir / "asset.glb").string(), lights, defaults);
  CHECK(read_bytes(dir / "asset.glb") == expected);

  // Lights added in code, equal to the file's, give the same bytes again.
  vlit::Lights same;
  for (std::size_t i = 0; i < lights.size(); ++i) same.add(lights[i]);
  tinygltf::Model again = vlit::load_model(kStudio);
  vlit::bake(again, same, defaults, kStudio);
  vlit::save_model(again, (dir / "in-code.glb").string(), kStudio);
  // (Lights::operator[] gives the spot's cone angles through acos of the stored cosines; on this
  // scene cos(acos(c)) gives back the same doubles, so the bytes are the same.)
  CHECK(read_bytes(dir / "in-code.glb") == expected);
  std::filesystem::remove_all(dir);
}

TEST_CASE("api: an OBJ's .mtl emitter lights the model loaded with load_model, as in vlit bake") {
  const auto dir = vlit::test::temp_dir("api-obj");
  const auto obj = vlit::test::write_cornell_obj(dir).string();
  vlit::BakeFileOptions cli;
  cli.encode.format = vlit::ColorFormat::kFloat;
  vlit::bake_file(obj, (dir / "cli.glb").string(), cli);
  tinygltf::Model model = vlit::load_model(obj);
  vlit::BakeSettings settings;
  settings.encoding = vlit::ColorEncoding::kFloat;
  const vlit::BakeSummary summary = vlit::bake(model, vlit::Lights{}, settings, obj);
  CHECK(summary.lights == 1);  // the lamp's Ke, read back from the glTF's emissive material
  const tinygltf::Model expected = vlit::load_model((dir / "cli.glb").string());
  REQUIRE(model.meshes.size() == 4);
  REQUIRE(expected.meshes.size() == 4);
  const auto& a = model.meshes[0].primitives[0];
  const auto& b = expected.meshes[0].primitives[0];
  const auto ca = vlit::read_accessor_as_doubles(model, a.attributes.at("COLOR_0"), obj);
  const auto cb = vlit::read_accessor_as_doubles(expected, b.attributes.at("COLOR_0"), obj);
  REQUIRE(ca.size() == cb.size());
  double peak = 0;
  for (double c : cb) peak = std::max(peak, c);
  CHECK(peak > 0);
  // Positions pass through float in the model (the CLI lights the OBJ's doubles): equal to float precision.
  for (std::size_t i = 0; i < ca.size(); ++i) CHECK(ca[i] == doctest::Approx(cb[i]).epsilon(1e-5));
}

TEST_CASE("api: the thread count does not change a bake") {
  vlit::Lights lights = vlit::Lights::read_json(kStudioLights);
  tinygltf::Model one = vlit::load_model(kStudio), two = vlit::load_model(kStudio);
  vlit::BakeSettings s1, s2;
  s1.threads = 1;
  s2.threads = 2;
  vlit::bake(one, lights, s1);
  vlit::bake(two, lights, s2);
  CHECK(one.buffers.size() == two.buffers.size());
  for (std::size_t b = 0; b < one.buffers.size(); ++b) CHECK(one.buffers[b].data == two.buffers[b].data);
}

TEST_CASE("api: errors name the input and the place in it") {
  SUBCASE("a LIGHTS.json file") {
    const vlit::Error e = error_of([] { vlit::Lights::read_json("/nonexistent/lights.json"); });
    CHECK(e.input() == "/nonexistent/lights.json");
  }
  SUBCASE("LIGHTS.json text") {
    const vlit::Error e = error_of([] {
      vlit::Lights::parse_json(R"({"lights": [{"type": "disk", "center": [0,0,0], "normal": [0,0,1], "radius": -1}]})",
                               "studio-lights");
    });
    CHECK(e.input() == "studio-lights");
    CHECK(e.where() == "/lights/0/radius");
  }
  SUBCASE("a light built in code names its index and field") {
    vlit::Lights lights;
    lights.add(vlit::Light::point({0, 0, 1}, 1));
    const vlit::Error e = error_of([&] { lights.add(vlit::Light::disk({0, 0, 0}, {0, 0, 1}, 0.0, 1)); });
    CHECK(e.input() == "lights");
    CHECK(e.where() == "/lights/1/radius");
    CHECK(lights.size() == 1);  // the bad light was not added
    const vlit::Error nan = error_of([&] { lights.add(vlit::Light::point({0, std::nan(""), 1}, 1)); });
    CHECK(nan.where() == "/lights/1/position/1");
    const vlit::Error planar = error_of([&] {
      lights.add(vlit::Light::panel({{0, 0, 0}, {1, 0, 0}, {1, 1, 0.5}, {0, 1, 0}}, 1));
    });
    CHECK(planar.where() == "/lights/1/polygon");
  }
  SUBCASE("a model in memory is named by the caller's name") {
    tinygltf::Model model = vlit::load_model(kStudio);
    model.accessors[model.meshes[0].primitives[0].attributes.at("POSITION")].bufferView = 9999;
    const vlit::BakeSettings defaults;
    const vlit::Error e = error_of([&] { vlit::bake(model, vlit::Lights(), defaults, "my-model"); });
    CHECK(e.input() == "my-model");
    CHECK(std::string(e.what()).rfind("my-model: ", 0) == 0);
  }
  SUBCASE("a file that is not glTF") {
    const auto dir = vlit::test::temp_dir("api-errors");
    const std::string path = (dir / "broken.glb").string();
    std::ofstream(path) << "glTF but not really";
    const vlit::Error e = error_of([&] { vlit::load_model(path); });
    CHECK(e.input() == path);
    std::filesystem::remove_all(dir);
  }
  SUBCASE("arrays name the mesh and the index") {
    vlit::Mesh m = square();
    m.name = "floor";
    m.triangles[4] = 7;
    const vlit::Error e = error_of([&] { vlit::light_meshes({m}, vlit::Lights()); });
    CHECK(e.input() == "floor");
    CHECK(e.where() == "triangles[4]");
  }
  SUBCASE("settings") {
    vlit::BakeSettings s;
    s.exposure = 0;
    tinygltf::Model model;
    const vlit::Error e = error_of([&] { vlit::bake(model, vlit::Lights(), s, "m"); });
    CHECK(e.where() == "settings.exposure");
    s.exposure = 1;
    s.target = "NORMAL";  // not a colour attribute: the bake would write an invalid glTF
    const vlit::Error t = error_of([&] { vlit::bake(model, vlit::Lights(), s, "m"); });
    CHECK(t.where() == "settings.target");
    CHECK(std::string(t.what()).find("\"NORMAL\" is not an attribute that can hold a colour") != std::string::npos);
  }
}

TEST_CASE("api: cancellation stops the work, throws Cancelled and leaves the model as it was") {
  const vlit::Lights lights = vlit::Lights::read_json(kStudioLights);
  const tinygltf::Model original = vlit::load_model(kStudio);

  // Not cancelled: count the progress calls of a whole bake.
  std::size_t full_calls = 0;
  {
    tinygltf::Model model = original;
    vlit::BakeSettings s;
    s.progress = [&](std::size_t, std::size_t) { ++full_calls; };
    vlit::bake(model, lights, s);
  }
  REQUIRE(full_calls >= 3);

  // Cancelled from the first progress report: the next chunk is never started.
  std::atomic<bool> cancel{false};
  std::size_t calls = 0;
  tinygltf::Model model = original;
  vlit::BakeSettings s;
  s.cancel = &cancel;
  s.progress = [&](std::size_t, std::size_t) {
    ++calls;
    cancel = true;
  };
  CHECK_THROWS_AS(vlit::bake(model, lights, s, "studio"), vlit::Cancelled);
  CHECK(calls == 1);
  CHECK(model.buffers.size() == original.buffers.size());
  for (std::size_t b = 0; b < model.buffers.size(); ++b) CHECK(model.buffers[b].data == original.buffers[b].data);
  CHECK(model.meshes[0].primitives[0].attributes.count("COLOR_0") ==
        original.meshes[0].primitives[0].attributes.count("COLOR_0"));

  // A file bake cancelled writes nothing.
  const auto dir = vlit::test::temp_dir("api-cancel");
  cancel = true;
  CHECK_THROWS_AS(vlit::bake_asset(kStudio, (dir / "out.glb").string(), lights, s), vlit::Cancelled);
  CHECK(!std::filesystem::exists(dir / "out.glb"));
  std::filesystem::remove_all(dir);

  // Render and probe honour the token too.
  vlit::RenderSettings r;
  r.cancel = &cancel;
  CHECK_THROWS_AS(vlit::render(original, lights, r), vlit::Cancelled);
  vlit::ProbeSettings p;
  p.cancel = &cancel;
  CHECK_THROWS_AS(vlit::probe({vlit::SurfacePoint{}}, lights, p), vlit::Cancelled);
}

TEST_CASE("api: probe of a point light is I cos(theta) / d^2, in double and float, on any thread count") {
  vlit::Lights lights;
  lights.add(vlit::Light::point({0, 0, 2}, 3.0));
  std::vector<vlit::SurfacePoint> points;
  for (int i = 0; i < 5000; ++i) {
    vlit::SurfacePoint p;
    p.position = {0.001 * i, 0, 0};
    p.normal = {0, 0, 1};
    points.push_back(p);
  }
  vlit::ProbeSettings one, two, single;
  one.threads = 1;
  two.threads = 2;
  single.precision = vlit::Precision::kFloat;
  const auto a = vlit::probe(points, lights, one), b = vlit::probe(points, lights, two);
  const auto f = vlit::probe(points, lights, single);
  REQUIRE(a.size() == points.size());
  for (std::size_t i = 0; i < points.size(); i += 499) {
    const double x = points[i].position[0], d2 = x * x + 4, expected = 3.0 * (2 / std::sqrt(d2)) / d2;
    CHECK(a[i].diffuse == doctest::Approx(expected).epsilon(1e-12));
    CHECK(a[i].diffuse == b[i].diffuse);
    CHECK(f[i].diffuse == doctest::Approx(expected).epsilon(1e-5));
  }
}

TEST_CASE("api: plain arrays: a square under a point light, and its shadow") {
  vlit::Lights lights;
  lights.add(vlit::Light::point({0.5, 0.5, 1}, 2.0, {1, 0.5, 0.25}));
  const auto light = vlit::light_meshes({square()}, lights);
  REQUIRE(light.size() == 1);
  REQUIRE(light[0].diffuse.size() == 4);
  CHECK(light[0].specular.empty());
  // Corner (0,0,0): d^2 = 1.5, cos = 1 / sqrt(1.5).
  const double expected = 2.0 / 1.5 / std::sqrt(1.5);
  CHECK(light[0].diffuse[0][0] == doctest::Approx(expected).epsilon(1e-6));
  CHECK(light[0].diffuse[0][1] == doctest::Approx(0.5 * expected).epsilon(1e-6));

  // Normals computed from the triangles when none are given.
  vlit::Mesh no_normals = square();
  no_normals.normals.clear();
  CHECK(vlit::light_meshes({no_normals}, lights)[0].diffuse[0][0] == doctest::Approx(expected).epsilon(1e-6));

  // A second square between them casts a shadow with shadows on.
  vlit::Mesh blocker = square();
  for (auto& p : blocker.positions) p = {p[0] * 4 - 1.5, p[1] * 4 - 1.5, 0.5};
  vlit::Settings shadows;
  shadows.shadows = true;
  const auto shadowed = vlit::light_meshes({square(), blocker}, lights, shadows);
  CHECK(shadowed[0].diffuse[0][0] == 0.0f);
}

TEST_CASE("api: render to memory: size, lit pixels, background, sRGB") {
  const vlit::Lights lights = vlit::Lights::read_json(kStudioLights);
  const tinygltf::Model model = vlit::load_model(kStudio);
  vlit::RenderSettings s;
  s.width = 64;
  s.height = 48;
  s.samples = 1;
  s.background = {0, 0, 1};
  const vlit::Image image = vlit::render(model, lights, s);
  CHECK(image.width == 64);
  CHECK(image.height == 48);
  REQUIRE(image.rgb.size() == 64 * 48 * 3);
  double red = 0;
  for (std::size_t i = 0; i < image.rgb.size(); i += 3) red += image.rgb[i];
  CHECK(red > 0);
  const std::vector<std::uint8_t> srgb = vlit::to_srgb8(image);
  CHECK(srgb.size() == image.rgb.size());

  // Meshes seen from a view: a square facing the eye, lit, in front of the background.
  vlit::Lights front;
  front.add(vlit::Light::directional({0, 0, -1}, 1.0));
  vlit::RenderSettings v = s;
  v.view = vlit::View{{0.5, 0.5, 3}, {0.5, 0.5, 0}, {0, 1, 0}, 0.8};
  vlit::Mesh dielectric = square();
  dielectric.material.metallic = 0;  // ks = 0.04
  const vlit::Image lit = vlit::render({dielectric}, front, v);
  const float* centre = lit.rgb.data() + 3 * (24 * 64 + 32);
  // kd x N.L = 1, plus ks (Rv.L)^1 with Rv.L = N.V in [3 / sqrt(9.5), 1] over the vertices.
  CHECK(centre[0] >= 1.0f + 0.04f * 3 / std::sqrt(9.5f) - 1e-5f);
  CHECK(centre[0] <= 1.04f + 1e-5f);
  CHECK(lit.rgb[2] == 1.0f);                                 // corner pixel: background blue
  CHECK(lit.rgb[0] == 0.0f);
}
