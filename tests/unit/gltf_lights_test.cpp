// Lights from the glTF file itself: EXT_lights_area (rect, disk), VLIT_lights_linear, emissive
// lines and triangles. Expected values are closed forms written here (form factors of a
// rectangle and a disk, the integral of a line source) or the equivalent LIGHTS.json light.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>

#include "bake/bake_file.h"
#include "bake/light_vertices.h"
#include "core/input_error.h"
#include "gltf/accessor_reader.h"
#include "gltf/gltf_scene.h"
#include "io/lights_json.h"
#include "support/gltf_builder.h"

using namespace vlit;
using vlit::test::GltfBuilder;
using Value = tinygltf::Value;

namespace {

Value num(double x) { return Value(x); }
Value str(const std::string& s) { return Value(s); }
Value arr(std::vector<Value> v) { return Value(Value::Array(std::move(v))); }
Value vec3(double x, double y, double z) { return arr({num(x), num(y), num(z)}); }
Value obj(std::map<std::string, Value> kv) { return Value(Value::Object(kv.begin(), kv.end())); }

// A large receiver triangle in z = 0 facing +Z, with vertex 0 at the origin.
int add_receiver(GltfBuilder& b) {
  return b.add_node(b.add_mesh({0, 0, 0, 10, 0, 0, 0, 10, 0}, {0, 0, 1, 0, 0, 1, 0, 0, 1}, {0, 1, 2}));
}

void add_root_lights(GltfBuilder& b, const std::string& ext, std::vector<Value> lights) {
  b.model().extensions[ext] = obj({{"lights", arr(std::move(lights))}});
  b.model().extensionsUsed.push_back(ext);
}

int add_light_node(GltfBuilder& b, const std::string& ext, int light, std::vector<double> translation,
                   std::vector<double> scale = {}, std::vector<double> rotation = {}) {
  const int node = b.add_node(-1, std::move(translation), std::move(scale), std::move(rotation));
  b.model().nodes[node].extensions[ext] = obj({{"light", Value(light)}});
  return node;
}

Scene load(GltfBuilder& b, const std::string& name, std::vector<std::string>* warnings_out = nullptr,
           SceneLimits limits = {}, bool file_lights = true) {
  const auto dir = vlit::test::temp_dir(name);
  const std::string path = b.write((dir / "scene.glb").string());
  std::vector<std::string> warnings;
  Scene s = build_scene(load_gltf_file(path), warnings, {limits, file_lights});
  if (warnings_out) *warnings_out = warnings;
  return s;
}

// Diffuse light (kd = 1) at vertex v of primitive p.
Vec3d diffuse_at(const Scene& scene, std::size_t p = 0, std::size_t v = 0) {
  const auto light = light_scene_vertices(scene, LightingRequest{});
  return static_cast<Vec3d>(light[p].diffuse[v]);
}

// Form factor from a point to a parallel rectangle [0, a] x [0, b] at height h whose corner is
// straight above the point (the classic closed form): E = pi L F.
double corner_form_factor(double a, double b, double h) {
  const double x = a / h, y = b / h;
  return (x / std::sqrt(1 + x * x) * std::atan(y / std::sqrt(1 + x * x)) +
          y / std::sqrt(1 + y * y) * std::atan(x / std::sqrt(1 + y * y))) / (2 * M_PI);
}

// Illuminance per unit luminance under the centre of a w x hgt rectangle at height h.
double centered_rect(double w, double hgt, double h) { return M_PI * 4 * corner_form_factor(w / 2, hgt / 2, h); }

Value rect_light(double intensity, double size, double aspect) {
  return obj({{"type", str("rect")}, {"intensity", num(intensity)}, {"size", num(size)},
              {"rect", obj({{"aspect", num(aspect)}})}});
}

}  // namespace

TEST_CASE("EXT_lights_area rect above a triangle: closed form and the equivalent LIGHTS.json light") {
  GltfBuilder b;
  add_receiver(b);
  add_root_lights(b, "EXT_lights_area", {rect_light(3, 1, 2)});  // 2 wide (x), 1 high (y), 3 nits
  add_light_node(b, "EXT_lights_area", 0, {0, 0, 2});
  const Scene s = load(b, "rect");
  REQUIRE(s.lights.size() == 1);
  CHECK(s.lights[0].type == LightType::kArea);
  const double expected = 3 * centered_rect(2, 1, 2);
  CHECK(diffuse_at(s).x == doctest::Approx(expected).epsilon(1e-6));

  Scene json = s;
  json.lights = parse_lights_json(
      R"({"lights": [{"type": "area", "intensity": 3, "polygon": [[-1,-0.5,2],[-1,0.5,2],[1,0.5,2],[1,-0.5,2]]}]})", "l.json");
  CHECK(diffuse_at(json).x == doctest::Approx(diffuse_at(s).x).epsilon(1e-9));
}

TEST_CASE("EXT_lights_area: defaults, rotation, non-uniform scale and mirrors") {
  SUBCASE("defaults: 1000 nits, size 1, aspect 1") {
    GltfBuilder b;
    add_receiver(b);
    add_root_lights(b, "EXT_lights_area", {obj({{"type", str("rect")}})});
    add_light_node(b, "EXT_lights_area", 0, {0, 0, 1});
    const Scene s = load(b, "rect-defaults");
    CHECK(diffuse_at(s).x == doctest::Approx(1000 * centered_rect(1, 1, 1)).epsilon(1e-6));
  }
  SUBCASE("a non-uniform scale stretches the rect: scale (2, 3, 1) on a unit square is 2 x 3") {
    GltfBuilder b;
    add_receiver(b);
    add_root_lights(b, "EXT_lights_area", {rect_light(1, 1, 1)});
    add_light_node(b, "EXT_lights_area", 0, {0, 0, 1.5}, {2, 3, 1});
    const Scene s = load(b, "rect-scale");
    CHECK(diffuse_at(s).x == doctest::Approx(centered_rect(2, 3, 1.5)).epsilon(1e-6));
  }
  SUBCASE("a light below the receiver turned up by a 180 degree rotation about X lights it from below") {
    GltfBuilder b;
    add_receiver(b);
    add_root_lights(b, "EXT_lights_area", {rect_light(1, 1, 1)});
    // Receiver faces +Z; the light 1 below it, emitting toward +Z after the rotation: the
    // receiver's vertex is behind it... and the receiver faces away, so 0. The same light
    // at +1 without rotation gives the closed form.
    add_light_node(b, "EXT_lights_area", 0, {0, 0, -1}, {}, {1, 0, 0, 0});
    CHECK(diffuse_at(load(b, "rect-rot")).x == 0);
  }
  SUBCASE("mirrors: the light emits into the image of its local -Z half-space") {
    // Mirror across the light's own plane (scale z = -1): it now emits toward +Z, away from the
    // receiver below. Mirror across X (scale x = -1): still toward -Z, unchanged.
    GltfBuilder b;
    add_receiver(b);
    add_root_lights(b, "EXT_lights_area", {rect_light(1, 1, 1)});
    add_light_node(b, "EXT_lights_area", 0, {0, 0, 1}, {1, 1, -1});
    std::vector<std::string> warnings;
    CHECK(diffuse_at(load(b, "mirror-z")).x == 0);
    GltfBuilder c;
    add_receiver(c);
    add_root_lights(c, "EXT_lights_area", {rect_light(1, 1, 1)});
    add_light_node(c, "EXT_lights_area", 0, {0, 0, 1}, {-1, 1, 1});
    CHECK(diffuse_at(load(c, "mirror-x")).x == doctest::Approx(centered_rect(1, 1, 1)).epsilon(1e-6));
  }
}

TEST_CASE("EXT_lights_area disk: a circle stays a disk light, an ellipse becomes a polygon of the same area") {
  GltfBuilder b;
  add_receiver(b);
  add_root_lights(b, "EXT_lights_area", {obj({{"type", str("disk")}, {"intensity", num(2)}, {"size", num(1)}})});
  add_light_node(b, "EXT_lights_area", 0, {0, 0, 1}, {3, 3, 3});  // radius 1.5 at height 1
  add_light_node(b, "EXT_lights_area", 0, {0, 0, 1}, {3, 1, 1});  // ellipse, semi-axes 1.5 x 0.5
  const Scene s = load(b, "disk");
  REQUIRE(s.lights.size() == 2);
  CHECK(s.lights[0].type == LightType::kDisk);
  CHECK(s.lights[0].radius == doctest::Approx(1.5));
  CHECK(s.lights[0].normal.z == doctest::Approx(-1));
  CHECK(s.lights[1].type == LightType::kArea);
  Vec3d newell;
  const auto& poly = s.lights[1].polygon;
  for (std::size_t i = 0; i < poly.size(); ++i) newell += cross(poly[i], poly[(i + 1) % poly.size()]);
  CHECK(0.5 * length(newell) == doctest::Approx(M_PI * 1.5 * 0.5).epsilon(1e-12));
  CHECK(newell.z < 0);  // emits down
  // Disk of radius R at height h, on axis: E = pi L R^2 / (R^2 + h^2).
  Scene disk_only = s;
  disk_only.lights.resize(1);
  CHECK(diffuse_at(disk_only).x == doctest::Approx(2 * M_PI * 2.25 / (2.25 + 1)).epsilon(1e-4));
}

TEST_CASE("VLIT_lights_linear: the segment in node-local space, intensity in cd per metre") {
  GltfBuilder b;
  add_receiver(b);
  add_root_lights(b, "VLIT_lights_linear",
                  {obj({{"intensity", num(3)}, {"from", vec3(-0.5, 0, 0)}, {"to", vec3(0.5, 0, 0)}, {"color", vec3(1, 0.5, 0.25)}})});
  add_light_node(b, "VLIT_lights_linear", 0, {0, 0, 1}, {2, 1, 1});  // world segment (-1,0,1) -> (1,0,1)
  const Scene s = load(b, "linear");
  REQUIRE(s.lights.size() == 1);
  CHECK(s.lights[0].type == LightType::kLinear);
  CHECK(s.lights[0].intensity == doctest::Approx(6));  // 3 cd/m x 2 m
  // Line source at height h over [-1, 1]: E = (I/m) * integral h / (h^2 + x^2)^(3/2) dx
  //   = 3 * [x / (h sqrt(h^2 + x^2))] from -1 to 1 = 3 * 2 / sqrt 2.
  const Vec3d d = diffuse_at(s);
  CHECK(d.x == doctest::Approx(3 * std::sqrt(2.0)).epsilon(1e-6));
  CHECK(d.z == doctest::Approx(0.25 * 3 * std::sqrt(2.0)).epsilon(1e-6));
}

TEST_CASE("emissive lines are linear lights: the same light as LIGHTS.json, a strip sums its segments") {
  for (const int mode : {TINYGLTF_MODE_LINE, TINYGLTF_MODE_LINE_STRIP}) {
    CAPTURE(mode);
    GltfBuilder b;
    add_receiver(b);
    const int mat = b.add_material({1, 1, 1, 1}, 0, 1);
    b.model().materials[mat].emissiveFactor = {1, 0.5, 0.25};
    b.model().materials[mat].extensions["KHR_materials_emissive_strength"] = obj({{"emissiveStrength", num(3)}});
    // LINES: one segment (-1,0,1)-(1,0,1); LINE_STRIP: the same line in two pieces through (0.2,0,1).
    if (mode == TINYGLTF_MODE_LINE)
      b.add_node(b.add_mesh({-1, 0, 1, 1, 0, 1}, {}, {0, 1}, mode, mat));
    else
      b.add_node(b.add_mesh({-1, 0, 1, 0.2f, 0, 1, 1, 0, 1}, {}, {0, 1, 2}, mode, mat));
    std::vector<std::string> warnings;
    const Scene s = load(b, "emissive-line", &warnings);
    REQUIRE(s.primitives.size() == 1);  // the line is a light, not a receiver
    CHECK(s.lights.size() == (mode == TINYGLTF_MODE_LINE ? 1u : 2u));
    Scene json = s;
    json.lights = parse_lights_json(
        R"({"lights": [{"type": "linear", "from": [-1,0,1], "to": [1,0,1], "intensity": 6, "color": [1, 0.5, 0.25]}]})", "l.json");
    const Vec3d got = diffuse_at(s), want = diffuse_at(json);
    CHECK(got.x == doctest::Approx(want.x).epsilon(1e-6));
    CHECK(got.z == doctest::Approx(want.z).epsilon(1e-6));
    CHECK(got.x == doctest::Approx(3 * std::sqrt(2.0)).epsilon(1e-6));
  }
}

TEST_CASE("emissive triangles: a coplanar quad is one polygon, lights others but not itself") {
  GltfBuilder b;
  add_receiver(b);
  const int mat = b.add_material({1, 1, 1, 1}, 0, 1);
  b.model().materials[mat].emissiveFactor = {0.5, 0.5, 0.5};
  // A 2 x 1 quad at z = 2 facing down (-Z), as two triangles with split vertices (as exporters
  // write flat faces): the merge matches vertices by position.
  b.add_node(b.add_mesh({-1, -0.5f, 2, 1, 0.5f, 2, 1, -0.5f, 2,   -1, -0.5f, 2, -1, 0.5f, 2, 1, 0.5f, 2}, {},
                        {0, 1, 2, 3, 4, 5}, TINYGLTF_MODE_TRIANGLES, mat));
  const Scene s = load(b, "emissive-quad");
  REQUIRE(s.primitives.size() == 2);
  REQUIRE(s.lights.size() == 1);
  CHECK(s.lights[0].polygon.size() == 4);
  CHECK(s.lights[0].emitting_primitive == 1);
  const auto light = light_scene_vertices(s, LightingRequest{});
  CHECK(light[0].diffuse[0].x == doctest::Approx(0.5 * centered_rect(2, 1, 2)).epsilon(1e-6));
  for (const Vec3f& c : light[1].diffuse) CHECK(c == Vec3f{0, 0, 0});  // not lit by itself, no NaN
}

TEST_CASE("emissive triangles: a square ring (a hole) falls back to its triangles, the sum stays exact") {
  // Outer square [-2, 2]^2, inner hole [-1, 1]^2, at z = 1 facing down; 8 triangles.
  GltfBuilder b;
  add_receiver(b);
  const int mat = b.add_material({1, 1, 1, 1}, 0, 1);
  b.model().materials[mat].emissiveFactor = {1, 1, 1};
  const std::vector<float> p = {-2, -2, 1, 2, -2, 1, 2, 2, 1, -2, 2, 1,   -1, -1, 1, 1, -1, 1, 1, 1, 1, -1, 1, 1};
  // Between outer edge (o_i, o_i+1) and inner edge (n_i, n_i+1), clockwise seen from above.
  std::vector<std::uint32_t> idx;
  for (std::uint32_t i = 0; i < 4; ++i) {
    const std::uint32_t o0 = i, o1 = (i + 1) % 4, n0 = 4 + i, n1 = 4 + (i + 1) % 4;
    idx.insert(idx.end(), {o0, n1, o1, o0, n0, n1});
  }
  b.add_node(b.add_mesh(p, {}, idx, TINYGLTF_MODE_TRIANGLES, mat));
  std::vector<std::string> warnings;
  const Scene s = load(b, "emissive-ring", &warnings);
  CHECK(s.lights.size() == 8);
  CHECK(std::any_of(warnings.begin(), warnings.end(), [](const std::string& w) { return w.find("holes") != std::string::npos; }));
  CHECK(diffuse_at(s).x == doctest::Approx(centered_rect(4, 4, 1) - centered_rect(2, 2, 1)).epsilon(1e-6));
}

TEST_CASE("emissive geometry: a material with an emissive texture is not a light, the limit keeps the brightest") {
  SUBCASE("emissive texture") {
    GltfBuilder b;
    add_receiver(b);
    const int mat = b.add_material({1, 1, 1, 1}, 0, 1);
    b.model().materials[mat].emissiveFactor = {1, 1, 1};
    b.model().materials[mat].emissiveTexture.index = 0;
    b.model().textures.resize(1);
    b.model().textures[0].name = "glow";
    b.add_node(b.add_mesh({0, 0, 1, 0, 1, 1, 1, 0, 1}, {}, {0, 1, 2}, TINYGLTF_MODE_TRIANGLES, mat));
    std::vector<std::string> warnings;
    const Scene s = load(b, "emissive-texture", &warnings);
    CHECK(s.lights.empty());
    CHECK(std::any_of(warnings.begin(), warnings.end(), [](const std::string& w) { return w.find("texture") != std::string::npos; }));
  }
  SUBCASE("limit") {
    GltfBuilder b;
    add_receiver(b);
    const int dim = b.add_material({1, 1, 1, 1}, 0, 1), bright = b.add_material({1, 1, 1, 1}, 0, 1);
    b.model().materials[dim].emissiveFactor = {0.1, 0.1, 0.1};
    b.model().materials[bright].emissiveFactor = {1, 1, 1};
    for (int i = 0; i < 5; ++i)
      b.add_node(b.add_mesh({-1, 0, 1, 1, 0, 1}, {}, {0, 1}, TINYGLTF_MODE_LINE, i == 3 ? bright : dim), {0, 0, double(i)});
    SceneLimits limits;
    limits.max_emissive_lights = 2;
    std::vector<std::string> warnings;
    const Scene s = load(b, "emissive-limit", &warnings, limits);
    REQUIRE(s.lights.size() == 2);
    CHECK(s.lights[0].intensity * s.lights[0].color.x == doctest::Approx(2));  // the bright one first
    CHECK(std::any_of(warnings.begin(), warnings.end(), [](const std::string& w) { return w.find("kept the 2 brightest") != std::string::npos; }));
  }
}

TEST_CASE("file lights off: no light of the file is read, not even a malformed one") {
  GltfBuilder b;
  add_receiver(b);
  add_root_lights(b, "EXT_lights_area", {obj({{"type", str("sphere")}})});
  add_light_node(b, "EXT_lights_area", 0, {0, 0, 1});
  const int mat = b.add_material({1, 1, 1, 1}, 0, 1);
  b.model().materials[mat].emissiveFactor = {1, 1, 1};
  b.add_node(b.add_mesh({-1, 0, 1, 1, 0, 1}, {}, {0, 1}, TINYGLTF_MODE_LINE, mat));
  std::vector<std::string> warnings;
  const Scene s = load(b, "no-file-lights", &warnings, {}, false);
  CHECK(s.lights.empty());
  CHECK_THROWS_AS(load(b, "file-lights-bad"), InputError);
}

TEST_CASE("malformed light extensions: one-line errors naming the file and the property") {
  struct Case {
    const char* name;
    const char* ext;
    Value light;
    int node_light;
    const char* message;
  };
  const std::vector<Case> cases = {
      {"bad-size", "EXT_lights_area", obj({{"type", str("rect")}, {"size", num(-1)}}), 0,
       "extensions.EXT_lights_area.lights[0].size: size must be > 0"},
      {"bad-type", "EXT_lights_area", obj({{"type", str("sphere")}}), 0, "unknown area light type \"sphere\""},
      {"no-type", "EXT_lights_area", obj({{"size", num(1)}}), 0, "lights[0].type: missing required string"},
      {"bad-aspect", "EXT_lights_area", obj({{"type", str("rect")}, {"rect", obj({{"aspect", num(0)}})}}), 0,
       "lights[0].rect.aspect: aspect must be > 0"},
      {"bad-color", "EXT_lights_area", obj({{"type", str("disk")}, {"color", vec3(1, -1, 0)}}), 0, "color components must be >= 0"},
      {"missing-light", "EXT_lights_area", obj({{"type", str("disk")}}), 3, "nodes[1].extensions.EXT_lights_area.light: light 3 does not exist"},
      {"linear-no-to", "VLIT_lights_linear", obj({{"from", vec3(0, 0, 0)}}), 0, "lights[0].to: missing required [x, y, z]"},
      {"linear-typo", "VLIT_lights_linear", obj({{"from", vec3(0, 0, 0)}, {"to", vec3(1, 0, 0)}, {"intensty", num(2)}}), 0,
       "lights[0].intensty: unknown property"},
      {"linear-falloff", "VLIT_lights_linear", obj({{"from", vec3(0, 0, 0)}, {"to", vec3(1, 0, 0)}, {"falloff", num(4)}}), 0,
       "falloff must be in [0, 3]"},
      // The shared part of both extensions (gltf/light_extension.h), with each one's unit and name.
      {"bad-intensity", "EXT_lights_area", obj({{"type", str("disk")}, {"intensity", num(-1)}}), 0,
       "lights[0].intensity: intensity (nits) must be >= 0"},
      {"linear-bad-intensity", "VLIT_lights_linear",
       obj({{"from", vec3(0, 0, 0)}, {"to", vec3(1, 0, 0)}, {"intensity", num(-1)}}), 0,
       "lights[0].intensity: intensity (cd per metre) must be >= 0"},
      {"linear-missing-light", "VLIT_lights_linear", obj({{"from", vec3(0, 0, 0)}, {"to", vec3(1, 0, 0)}}), 1,
       "nodes[1].extensions.VLIT_lights_linear.light: light 1 does not exist (the file defines 1 VLIT_lights_linear lights)"},
  };
  for (const Case& c : cases) {
    INFO(c.name);
    GltfBuilder b;
    add_receiver(b);
    add_root_lights(b, c.ext, {c.light});
    add_light_node(b, c.ext, c.node_light, {0, 0, 1});
    try {
      load(b, c.name);
      FAIL("no error");
    } catch (const InputError& e) {
      const std::string what = e.what();
      INFO(what);
      CHECK(what.find("scene.glb: ") != std::string::npos);
      CHECK(what.find(c.message) != std::string::npos);
      CHECK(what.find('\n') == std::string::npos);
    }
  }
}

TEST_CASE("receivers on an emissive polygon's corner, edge or plane, or on an emissive line: finite light") {
  // Vertices of another primitive touching the lights: at a corner, on an edge, inside in the
  // plane, each with normals along, against and across the emission; and on the line.
  Scene s;
  ScenePrimitive p;
  const std::vector<Vec3d> points = {{0, 0, 0}, {0.5, 0, 0}, {0.5, 0.5, 0}, {2, 0, 0}, {0.25, 0, 0}};
  const std::vector<Vec3d> normals = {{0, 0, 1}, {0, 0, -1}, {1, 0, 0}, {0, std::sqrt(0.5), -std::sqrt(0.5)}};
  for (const Vec3d& q : points)
    for (const Vec3d& n : normals) {
      p.positions.push_back(q);
      p.normals.push_back(n);
    }
  s.primitives.push_back(p);
  LightSource area;
  area.type = LightType::kArea;
  area.polygon = {{0, 0, 0}, {0, 1, 0}, {1, 1, 0}, {1, 0, 0}};  // emits toward -Z
  LightSource line;
  line.type = LightType::kLinear;
  line.from = {0, 0, 0};
  line.to = {1, 0, 0};
  for (bool two_sided : {false, true}) {
    area.two_sided = two_sided;
    s.lights = {area, line};
    LightingRequest request;
    request.eye = Vec3d{0.3, 0.2, -1};
    request.shade.specular.method = SpecularMethod::kExact;
    const auto light = light_scene_vertices(s, request);
    for (std::size_t v = 0; v < light[0].diffuse.size(); ++v) {
      CAPTURE(v);
      CHECK(is_finite(light[0].diffuse[v]));
      CHECK(is_finite(light[0].specular[v]));
    }
  }
}

TEST_CASE("real assets: Box under an EXT_lights_area rect equals LIGHTS.json, LightsPunctualLamp's textured emission is no light") {
  const std::string samples = std::string(VLIT_ASSETS_DIR) + "/samples";
  REQUIRE_MESSAGE(std::filesystem::exists(samples + "/Box/Box.gltf"), "missing test data: " << samples);
  GltfFile box = load_gltf_file(samples + "/Box/Box.gltf");
  // A 1.5 x 1 rect 2 above the box's centre, turned to face down (-90 degrees about X), 5 nits.
  box.model.extensions["EXT_lights_area"] = obj({{"lights", arr({rect_light(5, 1, 1.5)})}});
  tinygltf::Node node;
  node.translation = {0, 2, 0};
  node.rotation = {-std::sqrt(0.5), 0, 0, std::sqrt(0.5)};
  node.extensions["EXT_lights_area"] = obj({{"light", Value(0)}});
  box.model.nodes.push_back(node);
  box.model.scenes[0].nodes.push_back(static_cast<int>(box.model.nodes.size()) - 1);
  std::vector<std::string> warnings;
  const Scene s = build_scene(box, warnings);
  REQUIRE(s.lights.size() == 1);
  Scene json = s;
  // Local (x, y) -> world (x, -z) after the rotation; counter-clockwise seen from below.
  json.lights = parse_lights_json(R"({"lights": [{"type": "area", "intensity": 5,
      "polygon": [[-0.75, 2, 0.5], [-0.75, 2, -0.5], [0.75, 2, -0.5], [0.75, 2, 0.5]]}]})", "l.json");
  const auto a = light_scene_vertices(s, LightingRequest{}), b = light_scene_vertices(json, LightingRequest{});
  REQUIRE(a[0].diffuse.size() == 24);
  double lit = 0;
  for (std::size_t v = 0; v < 24; ++v) {
    CAPTURE(v);
    CHECK(a[0].diffuse[v].x == doctest::Approx(b[0].diffuse[v].x).epsilon(1e-9));
    lit += a[0].diffuse[v].x;
  }
  CHECK(lit > 0);

  warnings.clear();
  const Scene lamp = build_scene(load_gltf_file(samples + "/LightsPunctualLamp/LightsPunctualLamp.gltf"), warnings);
  CHECK(lamp.lights.size() == 5);  // its KHR_lights_punctual lights only
  CHECK(std::count_if(warnings.begin(), warnings.end(), [](const std::string& w) { return w.find("emission comes from a texture") != std::string::npos; }) == 2);
}

TEST_CASE("baked COLOR_0: a file's rect light and emissive line equal their LIGHTS.json twins, code for code") {
  // The same triangle baked twice: once lit by the file's EXT_lights_area rect and emissive line,
  // once by LIGHTS.json with the equivalent area and linear lights (--no-file-lights).
  GltfBuilder b;
  add_receiver(b);
  add_root_lights(b, "EXT_lights_area", {rect_light(0.2, 1, 2)});
  add_light_node(b, "EXT_lights_area", 0, {0, 0, 2});
  const int mat = b.add_material({1, 1, 1, 1}, 0, 1);
  b.model().materials[mat].emissiveFactor = {0.1, 0.05, 0.025};
  b.add_node(b.add_mesh({-1, 0, 1, 1, 0, 1}, {}, {0, 1}, TINYGLTF_MODE_LINE, mat));
  const auto dir = vlit::test::temp_dir("baked-twins");
  const std::string in = b.write((dir / "in.glb").string());
  const std::string lights = (dir / "lights.json").string();
  std::ofstream(lights) << R"({"lights": [
    {"type": "area", "intensity": 0.2, "polygon": [[-1,-0.5,2],[-1,0.5,2],[1,0.5,2],[1,-0.5,2]]},
    {"type": "linear", "from": [-1,0,1], "to": [1,0,1], "intensity": 2, "color": [0.1, 0.05, 0.025]}]})";
  BakeFileOptions file_lights, json_lights;
  json_lights.lights_path = lights;
  json_lights.use_file_lights = false;
  const auto a = bake_file(in, (dir / "a.glb").string(), file_lights);
  const auto c = bake_file(in, (dir / "b.glb").string(), json_lights);
  CHECK(a.lights == 2);
  CHECK(c.lights == 2);
  auto colors = [](const std::string& path) {
    const GltfFile f = load_gltf_file(path);
    return read_accessor_as_doubles(f.model, f.model.meshes[0].primitives[0].attributes.at("COLOR_0"), path);
  };
  const auto ca = colors((dir / "a.glb").string()), cb = colors((dir / "b.glb").string());
  REQUIRE(ca.size() == 12);
  CHECK(ca == cb);
  CHECK(ca[0] > 0.1);  // lit, well inside (0, 1)
  CHECK(ca[0] < 1);
}
