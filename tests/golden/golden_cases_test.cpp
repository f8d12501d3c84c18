// Golden images of `vlit render`: each light model alone on a floor with a sphere, glTF features
// that change what is drawn (a mirrored node, a mesh without normals, double-sided materials
// under back-face culling), and the paper's scenes (assets/paper/). Each case runs the real
// executable at 160 x 120 with 4 samples per pixel and compares the PNG with
// tests/golden/images/NAME.png (tolerance: golden/golden_image.h, docs/golden-images.md).
// VLIT_UPDATE_GOLDENS=1 (scripts/update-goldens.sh) rewrites the goldens instead of comparing.
#include <doctest/doctest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <string>
#include <vector>

#include "golden/golden_image.h"
#include "raster/png_writer.h"
#include "support/gltf_builder.h"
#include "support/run_command.h"

namespace fs = std::filesystem;
using vlit::test::run_command;

namespace {

const std::string kVlit = VLIT_BINARY;
const std::string kSource = VLIT_SOURCE_DIR;
const fs::path kGoldenDir = fs::path(kSource) / "tests" / "golden" / "images";
const fs::path kFailureDir = VLIT_GOLDEN_OUT_DIR;
constexpr double kPi = 3.14159265358979323846;

std::string q(const std::string& s) { return "'" + s + "'"; }

bool updating_goldens() {
  const char* v = std::getenv("VLIT_UPDATE_GOLDENS");
  return v && *v && std::string(v) != "0";
}

// --- Small scenes built in code --------------------------------------------------------------

struct Mesh {
  std::vector<float> positions, normals;
  std::vector<std::uint32_t> indices;
};

// (nu x nv) cells of f(u, v) -> {position, normal}; quads wound counter-clockwise seen from
// the normals' side.
Mesh surface(int nu, int nv, const std::function<void(double, double, double*, double*)>& f) {
  Mesh m;
  for (int j = 0; j <= nv; ++j)
    for (int i = 0; i <= nu; ++i) {
      double p[3], n[3];
      f(double(i) / nu, double(j) / nv, p, n);
      for (int k = 0; k < 3; ++k) {
        m.positions.push_back(float(p[k]));
        m.normals.push_back(float(n[k]));
      }
    }
  auto at = [&](std::uint32_t v, int k) { return double(m.positions[3 * v + k]); };
  for (int j = 0; j < nv; ++j)
    for (int i = 0; i < nu; ++i) {
      const std::uint32_t a = j * (nu + 1) + i, b = a + 1, c = a + nu + 2, d = a + nu + 1;
      double e1[3], e2[3], nsum[3];
      for (int k = 0; k < 3; ++k) {
        e1[k] = at(c, k) - at(a, k);
        e2[k] = at(d, k) - at(b, k);
        nsum[k] = m.normals[3 * a + k] + m.normals[3 * b + k] + m.normals[3 * c + k] + m.normals[3 * d + k];
      }
      const double facing[3] = {e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2], e1[0] * e2[1] - e1[1] * e2[0]};
      if (facing[0] * nsum[0] + facing[1] * nsum[1] + facing[2] * nsum[2] >= 0) m.indices.insert(m.indices.end(), {a, b, c, a, c, d});
      else m.indices.insert(m.indices.end(), {a, c, b, a, d, c});
    }
  return m;
}

Mesh floor_mesh(double half, int cells) {
  return surface(cells, cells, [=](double u, double v, double* p, double* n) {
    p[0] = -half + 2 * half * u; p[1] = 0; p[2] = -half + 2 * half * v;
    n[0] = 0; n[1] = 1; n[2] = 0;
  });
}

Mesh sphere_mesh(double cx, double cy, double cz, double r, int rings, int segments) {
  return surface(segments, rings, [=](double u, double v, double* p, double* n) {
    const double theta = kPi * (v - 0.5), phi = 2 * kPi * u;
    n[0] = std::cos(theta) * std::cos(phi); n[1] = std::sin(theta); n[2] = -std::cos(theta) * std::sin(phi);
    p[0] = cx + r * n[0]; p[1] = cy + r * n[1]; p[2] = cz + r * n[2];
  });
}

// A camera at (0, height, distance) looking at the origin (a pitch about X).
void add_camera(vlit::test::GltfBuilder& b, double height, double distance, double yfov) {
  tinygltf::Camera cam;
  cam.type = "perspective";
  cam.perspective.yfov = yfov;
  cam.perspective.znear = 0.05;
  b.model().cameras.push_back(cam);
  tinygltf::Node node;
  node.camera = static_cast<int>(b.model().cameras.size()) - 1;
  node.translation = {0, height, distance};
  const double pitch = -std::atan2(height, distance);
  node.rotation = {std::sin(pitch / 2), 0, 0, std::cos(pitch / 2)};
  b.model().nodes.push_back(node);
  b.model().scenes[0].nodes.push_back(static_cast<int>(b.model().nodes.size()) - 1);
}

// The scenes of this suite, written once per run into a temporary directory.
struct Scenes {
  fs::path dir, lit_floor, mirrored, no_normals, double_sided, coarse;
};

const Scenes& scenes() {
  static const Scenes s = [] {
    Scenes out;
    out.dir = vlit::test::temp_dir("golden");
    {  // Floor and sphere: the stage for every light model.
      vlit::test::GltfBuilder b;
      const int grey = b.add_material({0.8, 0.8, 0.8, 1}, 0, 0.6);
      const int red = b.add_material({0.85, 0.3, 0.25, 1}, 0, 0.35);
      const Mesh floor = floor_mesh(1.5, 48), ball = sphere_mesh(0, 0.45, 0, 0.45, 24, 48);
      b.add_node(b.add_mesh(floor.positions, floor.normals, floor.indices, TINYGLTF_MODE_TRIANGLES, grey));
      b.add_node(b.add_mesh(ball.positions, ball.normals, ball.indices, TINYGLTF_MODE_TRIANGLES, red));
      add_camera(b, 1.6, 3.2, 0.8);
      out.lit_floor = b.write((out.dir / "lit-floor.glb").string());
    }
    {  // A hemisphere and its mirror image (node scale -1 in x): under back-face culling the mirrored
       // copy is drawn only if the loader flips the winding of negative-determinant nodes.
      vlit::test::GltfBuilder b;
      const int grey = b.add_material({0.8, 0.8, 0.8, 1}, 0, 0.6);
      const int green = b.add_material({0.3, 0.75, 0.35, 1}, 0, 0.4);
      const Mesh floor = floor_mesh(1.5, 32);
      // Half a sphere (x >= 0 side) offset to +x, so the mirrored copy lands on -x.
      const Mesh half = surface(24, 16, [](double u, double v, double* p, double* n) {
        const double theta = kPi * (v - 0.5), phi = kPi * (u - 0.5);
        n[0] = std::cos(theta) * std::cos(phi); n[1] = std::sin(theta); n[2] = -std::cos(theta) * std::sin(phi);
        p[0] = 0.25 + 0.45 * n[0]; p[1] = 0.45 + 0.45 * n[1]; p[2] = 0.45 * n[2];
      });
      b.add_node(b.add_mesh(floor.positions, floor.normals, floor.indices, TINYGLTF_MODE_TRIANGLES, grey));
      const int mesh = b.add_mesh(half.positions, half.normals, half.indices, TINYGLTF_MODE_TRIANGLES, green);
      b.add_node(mesh);
      b.add_node(mesh, {}, {-1, 1, 1});
      add_camera(b, 1.6, 3.2, 0.8);
      out.mirrored = b.write((out.dir / "mirrored.glb").string());
    }
    {  // The same sphere without NORMAL: vlit computes smooth vertex normals.
      vlit::test::GltfBuilder b;
      const int grey = b.add_material({0.8, 0.8, 0.8, 1}, 0, 0.6);
      const int blue = b.add_material({0.3, 0.4, 0.85, 1}, 0, 0.35);
      const Mesh floor = floor_mesh(1.5, 32), ball = sphere_mesh(0, 0.45, 0, 0.45, 12, 24);
      b.add_node(b.add_mesh(floor.positions, floor.normals, floor.indices, TINYGLTF_MODE_TRIANGLES, grey));
      b.add_node(b.add_mesh(ball.positions, {}, ball.indices, TINYGLTF_MODE_TRIANGLES, blue));
      add_camera(b, 1.6, 3.2, 0.8);
      out.no_normals = b.write((out.dir / "no-normals.glb").string());
    }
    {  // Two upright panels seen from behind: the left one double-sided (drawn under culling),
       // the right one single-sided (culled), in front of a back wall.
      vlit::test::GltfBuilder b;
      const int grey = b.add_material({0.8, 0.8, 0.8, 1}, 0, 0.6);
      const int two = b.add_material({0.9, 0.6, 0.2, 1}, 0, 0.5);
      const int one = b.add_material({0.2, 0.6, 0.9, 1}, 0, 0.5);
      b.model().materials[two].doubleSided = true;
      const Mesh floor = floor_mesh(1.5, 32);
      auto panel = [](double x0) {
        return surface(8, 8, [=](double u, double v, double* p, double* n) {  // faces -z, away from the camera
          p[0] = x0 + 0.8 * (1 - u); p[1] = 0.1 + 0.8 * v; p[2] = 0;
          n[0] = 0; n[1] = 0; n[2] = -1;
        });
      };
      const Mesh left = panel(-0.95), right = panel(0.15);
      b.add_node(b.add_mesh(floor.positions, floor.normals, floor.indices, TINYGLTF_MODE_TRIANGLES, grey));
      b.add_node(b.add_mesh(left.positions, left.normals, left.indices, TINYGLTF_MODE_TRIANGLES, two));
      b.add_node(b.add_mesh(right.positions, right.normals, right.indices, TINYGLTF_MODE_TRIANGLES, one));
      add_camera(b, 1.6, 3.2, 0.8);
      out.double_sided = b.write((out.dir / "double-sided.glb").string());
    }
    {  // A coarse floor and sphere, so the wireframe view shows separate edges at 160 x 120.
      vlit::test::GltfBuilder b;
      const int grey = b.add_material({0.8, 0.8, 0.8, 1}, 0, 0.6);
      const int red = b.add_material({0.85, 0.3, 0.25, 1}, 0, 0.35);
      const Mesh floor = floor_mesh(1.5, 6), ball = sphere_mesh(0, 0.45, 0, 0.45, 8, 12);
      b.add_node(b.add_mesh(floor.positions, floor.normals, floor.indices, TINYGLTF_MODE_TRIANGLES, grey));
      b.add_node(b.add_mesh(ball.positions, ball.normals, ball.indices, TINYGLTF_MODE_TRIANGLES, red));
      add_camera(b, 1.6, 3.2, 0.8);
      out.coarse = b.write((out.dir / "coarse.glb").string());
    }
    return out;
  }();
  // Removes the directory when the test program exits.
  static const struct Cleanup {
    fs::path dir;
    ~Cleanup() { std::error_code ec; fs::remove_all(dir, ec); }
  } cleanup{s.dir};
  return s;
}

std::string write_lights(const std::string& name, const std::string& json) {
  const fs::path p = scenes().dir / (name + ".json");
  std::ofstream(p) << json;
  return p.string();
}

// Renders `scene` with `lights` (none if empty), compares with the golden NAME.png, or rewrites the golden.
void check_golden(const std::string& name, const std::string& scene, const std::string& lights, const std::string& extra = "") {
  fs::create_directories(kFailureDir);
  const fs::path actual_path = kFailureDir / (name + ".actual.png");
  const fs::path diff_path = kFailureDir / (name + ".diff.png");
  const fs::path golden_path = kGoldenDir / (name + ".png");
  fs::remove(diff_path);
  const std::string lights_option = lights.empty() ? std::string() : " --lights " + q(lights);
  const auto r = run_command(kVlit + " render " + q(scene) + lights_option + " -o " + q(actual_path.string()) +
                             " --width 160 --height 120 --samples 4 -q " + extra);
  REQUIRE_MESSAGE(r.exit_code == 0, "vlit render failed for golden " << name << ": " << r.err);
  if (updating_goldens()) {
    fs::create_directories(kGoldenDir);
    fs::copy_file(actual_path, golden_path, fs::copy_options::overwrite_existing);
    fs::remove(actual_path);
    MESSAGE("updated golden " << golden_path.string());
    return;
  }
  const auto golden = vlit::test::load_png_rgb8(golden_path.string());
  REQUIRE_MESSAGE(golden.has_value(), "no golden " << golden_path.string() << " (the render is at " << actual_path.string()
                                                   << "); run scripts/update-goldens.sh to create it");
  const auto actual = vlit::test::load_png_rgb8(actual_path.string());
  REQUIRE(actual.has_value());
  const vlit::test::GoldenTolerance tolerance;
  const auto c = vlit::test::compare_to_golden(*golden, *actual, tolerance);
  if (c.match) {
    fs::remove(actual_path);
    return;
  }
  const auto diff = vlit::test::diff_image(*golden, *actual, tolerance);
  vlit::raster::write_png(diff_path.string(), diff.width, diff.height, diff.rgb, nullptr);
  FAIL_CHECK("golden " << name << ": " << c.summary() << "\n  golden: " << golden_path.string()
                       << "\n  actual: " << actual_path.string() << "\n  diff:   " << diff_path.string());
}

const std::string kPaper = kSource + "/assets/paper/";

}  // namespace

TEST_CASE("golden: each light model alone on a floor with a sphere") {
  const std::string scene = scenes().lit_floor.string();
  SUBCASE("point") {
    check_golden("light-point", scene, write_lights("point", R"({"lights": [
      {"type": "point", "position": [0.9, 1.4, 0.9], "intensity": 3, "falloff": 2}]})"));
  }
  SUBCASE("directional") {
    check_golden("light-directional", scene, write_lights("directional", R"({"lights": [
      {"type": "directional", "direction": [-0.5, -1, -0.35], "intensity": 1}]})"));
  }
  SUBCASE("spot") {
    check_golden("light-spot", scene, write_lights("spot", R"({"lights": [
      {"type": "spot", "position": [0.3, 2.2, 0.3], "direction": [-0.15, -1, -0.15],
       "inner_cone_angle": 0.3, "outer_cone_angle": 0.45, "intensity": 5, "falloff": 2}]})"));
  }
  SUBCASE("linear") {
    check_golden("light-linear", scene, write_lights("linear", R"({"lights": [
      {"type": "linear", "from": [-0.9, 1.3, 0.6], "to": [0.9, 1.3, 0.6], "intensity": 3, "falloff": 2}]})"));
  }
  SUBCASE("area") {  // a 0.9 m square at 1.4 m, emitting down
    check_golden("light-area", scene, write_lights("area", R"({"lights": [
      {"type": "area", "polygon": [[-0.45, 1.4, 0.15], [0.45, 1.4, 0.15], [0.45, 1.4, 1.05], [-0.45, 1.4, 1.05]],
       "intensity": 6}]})"));
  }
  SUBCASE("disk") {
    check_golden("light-disk", scene, write_lights("disk", R"({"lights": [
      {"type": "disk", "center": [0.4, 1.4, 0.5], "normal": [0, -1, 0], "radius": 0.45, "intensity": 6}]})"));
  }
}

TEST_CASE("golden: shadows (docs/shadows.md)") {
  SUBCASE("area light, the sphere's soft shadow on the floor") {
    check_golden("shadow-area", scenes().lit_floor.string(), write_lights("shadow-area", R"({"lights": [
      {"type": "area", "polygon": [[-0.45, 1.4, 0.15], [0.45, 1.4, 0.15], [0.45, 1.4, 1.05], [-0.45, 1.4, 1.05]],
       "intensity": 6}]})"), "--shadows on");
  }
  SUBCASE("the paper's bowling lane under its spot lights, sharp shadows") {
    check_golden("paper-bowling-spot-shadows", kPaper + "bowling.glb", kPaper + "bowling-spot.json", "--shadows on");
  }
}

TEST_CASE("golden: glTF features that change what is drawn") {
  const std::string key = write_lights("features", R"({"lights": [
    {"type": "point", "position": [1.2, 1.5, 1.4], "intensity": 3, "falloff": 2},
    {"type": "directional", "direction": [0.3, -1, -0.4], "intensity": 0.25},
    {"type": "point", "position": [-0.4, 1.0, -1.2], "intensity": 1.5, "falloff": 2}]})");  // behind the panels
  SUBCASE("mirrored node (negative scale), back faces culled") {
    check_golden("gltf-mirrored-culled", scenes().mirrored.string(), key, "--cull-back-faces");
  }
  SUBCASE("mesh without normals") { check_golden("gltf-no-normals", scenes().no_normals.string(), key); }
  SUBCASE("double-sided and single-sided panels seen from behind, back faces culled") {
    check_golden("gltf-double-sided-culled", scenes().double_sided.string(), key, "--cull-back-faces");
  }
}

TEST_CASE("golden: the paper's scenes (assets/paper/)") {
  for (const std::string scene : {"bowling", "studio"})
    for (const std::string light : {"spot", "linear", "area"}) {
      CAPTURE(scene);
      CAPTURE(light);
      check_golden("paper-" + scene + "-" + light, kPaper + scene + ".glb", kPaper + scene + "-" + light + ".json");
    }
}

TEST_CASE("golden: debug views (wireframe over the shading, world normals)") {
  const std::string scene = scenes().coarse.string();
  const std::string lights = write_lights("views", R"({"lights": [
    {"type": "point", "position": [0.9, 1.4, 0.9], "intensity": 3, "falloff": 2}]})");
  SUBCASE("wireframe") { check_golden("view-wireframe", scene, lights, "--view wireframe"); }
  SUBCASE("normals") { check_golden("view-normals", scene, lights, "--view normals"); }
}

TEST_CASE("golden: the preview of a baked asset (COLOR_0 x base colour unlit, panels drawn with their radiance)") {
  // The paper's studio baked under its panels, then drawn as a viewer shows it, without lights
  // (the default for an asset with COLOR_0 and no lights) and with the panels drawn (--preview
  // --lights).
  const std::string baked = (scenes().dir / "studio-area-baked.glb").string();
  const auto bake = run_command(kVlit + " bake " + q(kPaper + "studio.glb") + " --lights " + q(kPaper + "studio-area.json") +
                                " -o " + q(baked) + " -q");
  REQUIRE_MESSAGE(bake.exit_code == 0, bake.err);
  SUBCASE("no lights") { check_golden("preview-studio-baked", baked, ""); }
  SUBCASE("with the panels") { check_golden("preview-studio-baked-panels", baked, kPaper + "studio-area.json", "--preview"); }
}
