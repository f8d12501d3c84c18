// OBJ files with their .mtl materials (src/mesh/obj_file.*, src/mesh/mtl_file.*): one primitive
// per material, Kd / Ns / Ke mapped onto the scene's material, Ke emitters as area lights.
#include <doctest/doctest.h>

#include <cmath>
#include <fstream>

#include "bake/light_vertices.h"
#include "core/input_error.h"
#include "gltf/gltf_scene.h"
#include "gltf/mesh_to_gltf.h"
#include "mesh/mesh_file.h"
#include "load/load_scene.h"
#include "support/cornell_obj.h"
#include "support/gltf_builder.h"

using namespace vlit;

namespace {

const Material& material_named(const Scene& s, const std::string& name) {
  for (const auto& m : s.materials)
    if (m.name == name) return m;
  FAIL("no material " << name);
  static const Material none;
  return none;
}

const ScenePrimitive& primitive_of(const Scene& s, const std::string& material) {
  for (const auto& p : s.primitives)
    if (s.material_of(p).name == material) return p;
  FAIL("no primitive with material " << material);
  static const ScenePrimitive none;
  return none;
}

bool has_warning(const std::vector<std::string>& warnings, const std::string& a, const std::string& b = {}) {
  for (const auto& w : warnings)
    if (w.find(a) != std::string::npos && w.find(b) != std::string::npos) return true;
  return false;
}

// Illuminance under the centre of a w x w Lambertian square of luminance 1 at height h, parallel
// to the receiver: four times the corner form factor of a (w/2) x (w/2) rectangle (the classical
// parallel-rectangle formula, e.g. Howell's catalogue C-11), times pi. Independent of vlit's
// contour integral (eq. 9).
double illuminance_under_square_centre(double w, double h) {
  const double X = w / 2 / h, Y = w / 2 / h;
  const double sx = std::sqrt(1 + X * X), sy = std::sqrt(1 + Y * Y);
  const double corner_form_factor = (X / sx * std::atan(Y / sx) + Y / sy * std::atan(X / sy)) / (2 * M_PI);
  return M_PI * 4 * corner_form_factor;
}

}  // namespace

TEST_CASE("an OBJ with a .mtl: one primitive per material, Kd as base colour, Ns as shininess, Ke as emission") {
  const auto dir = vlit::test::temp_dir("obj-mtl");
  const auto obj = vlit::test::write_cornell_obj(dir).string();
  std::vector<std::string> warnings;
  const Scene s = load_mesh_file(obj, warnings);
  CHECK(warnings.empty());
  // white (floor, ceiling and back wall: two usemtl runs of one material), red, green, light.
  REQUIRE(s.primitives.size() == 4);
  REQUIRE(s.materials.size() == 4);
  CHECK(s.material_of(s.primitives[0]).name == "white");  // order of first use
  CHECK(s.material_of(s.primitives[3]).name == "light");
  CHECK(primitive_of(s, "white").triangles.size() == 3 * (8 + 2 + 2));
  CHECK(primitive_of(s, "white").positions.size() == 9 + 4 + 4);
  CHECK(primitive_of(s, "red").triangles.size() == 6);
  CHECK(primitive_of(s, "light").triangles.size() == 6);  // the continued line is one quad
  CHECK(material_named(s, "white").base_color == Vec3d{0.73, 0.73, 0.73});
  CHECK(material_named(s, "red").base_color == Vec3d{0.65, 0.05, 0.05});
  CHECK(material_named(s, "green").base_color == Vec3d{0.12, 0.45, 0.15});
  CHECK(material_named(s, "white").metallic == 0);
  CHECK(phong_from_metallic_roughness(material_named(s, "white")).shininess == doctest::Approx(10).epsilon(1e-12));
  CHECK(phong_from_metallic_roughness(material_named(s, "red")).shininess == doctest::Approx(100).epsilon(1e-12));
  CHECK(material_named(s, "green").roughness == 0.5);  // no Ns: the default grey's roughness
  CHECK(material_named(s, "light").emission() == Vec3d{5, 4, 3});
  CHECK(material_named(s, "white").emission() == Vec3d{0, 0, 0});
  // Normals: from vn on the floor, computed (angle-weighted, facing the box) on the ceiling.
  for (const auto& n : primitive_of(s, "red").normals) CHECK(n == Vec3d{1, 0, 0});
  for (const auto& n : primitive_of(s, "light").normals) CHECK(n == Vec3d{0, -1, 0});
}

TEST_CASE("Ke becomes an area light as a glTF emissive triangle does, --no-file-lights drops it") {
  const auto dir = vlit::test::temp_dir("obj-ke");
  const auto obj = vlit::test::write_cornell_obj(dir).string();
  const LoadedScene loaded = load_scene(obj, "");
  REQUIRE(loaded.scene.lights.size() == 1);
  const LightSource& l = loaded.scene.lights[0];
  CHECK(l.type == LightType::kArea);
  CHECK(l.color == Vec3d{5, 4, 3});
  CHECK(l.intensity == 1);
  CHECK_FALSE(l.two_sided);
  CHECK(l.polygon.size() == 4);  // the two triangles merged into one quad
  CHECK(l.emitting_primitive == 3);
  CHECK(l.name.find("material light") != std::string::npos);
  const LoadedScene no_lights = load_scene(obj, "", SceneOptions{.limits = {}, .file_lights = false});
  CHECK(no_lights.scene.lights.empty());
  CHECK(no_lights.scene.primitives.size() == 4);

  // The same lights as the glTF path: the baked document read back by build_scene.
  Scene scene = loaded.scene;
  GltfFile file{obj, gltf_from_mesh_scene(scene), {}};
  std::vector<std::string> warnings;
  const Scene from_gltf = build_scene(file, warnings);
  REQUIRE(from_gltf.lights.size() == 1);
  CHECK(from_gltf.lights[0].color.x * from_gltf.lights[0].intensity == doctest::Approx(5));
  CHECK(from_gltf.lights[0].color.z * from_gltf.lights[0].intensity == doctest::Approx(3));
}

TEST_CASE("the OBJ emitter lights the floor: the same panel as an explicit light, and a closed form") {
  const auto dir = vlit::test::temp_dir("obj-floor");
  const auto obj = vlit::test::write_cornell_obj(dir).string();
  const LoadedScene with_emitter = load_scene(obj, "");
  // The panel written by hand as a LIGHTS.json area light, the OBJ's own lights off.
  const auto lights_json = dir / "panel.json";
  {
    std::ofstream j(lights_json);
    j << R"({"lights": [{"type": "area", "color": [5, 4, 3], "intensity": 1, "polygon": [)";
    for (int i = 0; i < 4; ++i)
      j << (i ? "," : "") << "[" << vlit::test::kLightCorners[i][0] << "," << vlit::test::kLightCorners[i][1] << ","
        << vlit::test::kLightCorners[i][2] << "]";
    j << "]}]}";
  }
  const LoadedScene explicit_light = load_scene(obj, lights_json.string(), SceneOptions{.limits = {}, .file_lights = false});
  LightingRequest request;
  const auto a = light_scene_vertices(with_emitter.scene, request);
  const auto b = light_scene_vertices(explicit_light.scene, request);
  const std::size_t floor = 0;  // the white primitive; its first 9 vertices are the floor grid
  const auto& floor_prim = with_emitter.scene.primitives[floor];
  for (std::size_t v = 0; v < 9; ++v) {
    INFO("floor vertex " << v);
    CHECK(a[floor].diffuse[v].x > 0);
    CHECK(a[floor].diffuse[v].x == doctest::Approx(b[floor].diffuse[v].x).epsilon(1e-6));
    CHECK(a[floor].diffuse[v].z == doctest::Approx(b[floor].diffuse[v].z).epsilon(1e-6));
  }
  // The floor's centre (1, 0, 1), straight under the panel.
  std::size_t centre = 99;
  for (std::size_t v = 0; v < 9; ++v)
    if (floor_prim.positions[v] == Vec3d{1, 0, 1}) centre = v;
  REQUIRE(centre < 9);
  const double e = illuminance_under_square_centre(vlit::test::kLightSide, vlit::test::kLightHeight);
  INFO("closed form " << e);
  CHECK(a[floor].diffuse[centre].x == doctest::Approx(5 * e).epsilon(1e-5));
  CHECK(a[floor].diffuse[centre].y == doctest::Approx(4 * e).epsilon(1e-5));
  CHECK(a[floor].diffuse[centre].z == doctest::Approx(3 * e).epsilon(1e-5));
  // The emitter does not light itself; the ceiling behind it gets nothing (it faces down).
  for (const auto& c : a[3].diffuse) CHECK(c.x == 0);
}

TEST_CASE("a missing .mtl is a warning naming the OBJ and the .mtl, its faces are grey") {
  const auto dir = vlit::test::temp_dir("obj-no-mtl");
  const auto obj = vlit::test::write_cornell_obj(dir, false).string();
  std::vector<std::string> warnings;
  const Scene s = load_mesh_file(obj, warnings);
  CHECK(s.primitives.size() == 4);
  CHECK(has_warning(warnings, obj, (dir / "cornell.mtl").string()));
  CHECK(material_named(s, "red").base_color == Vec3d{0.8, 0.8, 0.8});
  CHECK(load_scene(obj, "").scene.lights.empty());
}

TEST_CASE("several .mtl files on one mtllib line, relative to the OBJ's folder") {
  const auto dir = vlit::test::temp_dir("obj-two-mtl");
  std::filesystem::create_directories(dir / "sub");
  const auto obj = vlit::test::write_cornell_obj(dir, false, "mtllib walls.mtl  sub/light.mtl").string();
  std::ofstream(dir / "walls.mtl") << "newmtl white\nKd 0.73 0.73 0.73\nnewmtl red\nKd 1 0 0\nnewmtl green\nKd 0 1 0\n";
  std::ofstream(dir / "sub" / "light.mtl") << "newmtl light\nKe 2\n";  // one number: grey
  std::vector<std::string> warnings;
  const Scene s = load_mesh_file(obj, warnings);
  CHECK(warnings.empty());
  CHECK(material_named(s, "red").base_color == Vec3d{1, 0, 0});
  CHECK(material_named(s, "green").base_color == Vec3d{0, 1, 0});
  CHECK(material_named(s, "light").emission() == Vec3d{2, 2, 2});
  // The other file missing: a warning for it alone.
  std::filesystem::remove(dir / "sub" / "light.mtl");
  warnings.clear();
  const Scene t = load_mesh_file(obj, warnings);
  CHECK(material_named(t, "red").base_color == Vec3d{1, 0, 0});
  CHECK(has_warning(warnings, "sub/light.mtl"));
  CHECK(has_warning(warnings, "usemtl light"));
}

TEST_CASE("malformed .mtl and OBJ statements are errors naming the file and the line") {
  const auto dir = vlit::test::temp_dir("obj-bad-mtl");
  const auto obj = vlit::test::write_cornell_obj(dir, false).string();
  const auto mtl = (dir / "cornell.mtl").string();
  auto error_of = [&](const std::string& path) {
    try {
      std::vector<std::string> w;
      load_mesh_file(path, w);
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  std::ofstream(mtl) << "newmtl white\n# comment\nKd 0.5 zero 0.5\n";
  CHECK(error_of(obj) == mtl + ": line 3: Kd: 'zero' is not a finite number");
  std::ofstream(mtl) << "newmtl white\nKd 0.5 0.5\n";
  CHECK(error_of(obj) == mtl + ": line 2: Kd needs 1 or 3 numbers (r [g b]), got 2");
  std::ofstream(mtl) << "newmtl light\nKe 1 -1 1\n";
  CHECK(error_of(obj) == mtl + ": line 2: Ke: -1 is negative");
  std::ofstream(mtl) << "Kd 1 1 1\nnewmtl white\n";
  CHECK(error_of(obj) == mtl + ": line 1: Kd before the first newmtl");
  std::ofstream(mtl) << "newmtl white\nKd 2 1 1\nTf 1 1 1\nd 0.5\n";  // clamped with a warning; the rest ignored
  std::vector<std::string> warnings;
  CHECK(material_named(load_mesh_file(obj, warnings), "white").base_color == Vec3d{1, 1, 1});
  CHECK(has_warning(warnings, mtl + ": line 2: Kd above 1"));

  const auto bad = (dir / "bad.obj").string();
  std::ofstream(bad) << "v 0 0 0\nv 1 0 0\nv 1 1 0\nf 1 2 4\n";
  CHECK(error_of(bad) == bad + ": line 4: f: vertex index 4 is out of range (3 vertices so far)");
  std::ofstream(bad) << "v 0 0 0\nv 1 0 x\n";
  CHECK(error_of(bad) == bad + ": line 2: v: 'x' is not a finite number");
  std::ofstream(bad) << "v 0 0 0\nv 1 0 0\nv 1 1 0\nf 1//1 2 3\n";
  CHECK(error_of(bad) == bad + ": line 4: f: normal index 1 is out of range (0 normals so far)");
  std::ofstream(bad) << "v 0 0 0\nv 1 0 0\nf 1 2\n";
  CHECK(error_of(bad) == bad + ": line 3: f needs at least 3 corners, got 2");
}

TEST_CASE("OBJ normals: a hard edge written with two normals stays hard, vertices without normals are smooth") {
  const auto dir = vlit::test::temp_dir("obj-normals");
  const auto path = (dir / "roof.obj").string();
  // Two faces sharing the edge (0,0,0)-(0,0,1): a roof ridge, once with a normal per face, once
  // without normals.
  std::ofstream(path) << "v -1 -1 0\nv -1 -1 1\nv 0 0 1\nv 0 0 0\nv 1 -1 1\nv 1 -1 0\n"
                         "vn -1 1 0\nvn 1 1 0\n"
                         "usemtl hard\nf 1//1 2//1 3//1 4//1\nf 4//2 3//2 5//2 6//2\n";
  std::vector<std::string> warnings;
  const Scene hard = load_mesh_file(path, warnings);
  REQUIRE(hard.primitives.size() == 1);
  CHECK(hard.primitives[0].positions.size() == 8);  // the ridge's two vertices split
  // Vertex 3 is the ridge's (0, 0, 0) on the first face, vertex 4 the same position on the second.
  const double h = 1 / std::sqrt(2.0);
  CHECK(hard.primitives[0].positions[3] == hard.primitives[0].positions[4]);
  CHECK(hard.primitives[0].normals[3].x == doctest::Approx(-h));
  CHECK(hard.primitives[0].normals[3].y == doctest::Approx(h));
  CHECK(hard.primitives[0].normals[4].x == doctest::Approx(h));
  CHECK(hard.primitives[0].normals[4].y == doctest::Approx(h));
  std::ofstream(path) << "v -1 -1 0\nv -1 -1 1\nv 0 0 1\nv 0 0 0\nv 1 -1 1\nv 1 -1 0\n"
                         "f 1 2 3 4\nf 4 3 5 6\n";
  const Scene smooth = load_mesh_file(path, warnings);
  CHECK(smooth.primitives[0].positions.size() == 6);
  CHECK(smooth.primitives[0].normals[3].x == doctest::Approx(0));
  CHECK(smooth.primitives[0].normals[3].y == doctest::Approx(1));
}
