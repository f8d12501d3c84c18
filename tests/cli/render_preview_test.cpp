// `vlit render --preview`, and the preview as the default for a scene with COLOR_0 and no lights:
// COLOR_0 x base colour unlit (what a glTF viewer shows for a baked asset), panels and tubes with
// their own radiance. Expected pixels come from the glTF definitions (COLOR_0 multiplies
// baseColorFactor; PNG = sRGB OETF of linear RGB, written out here) and a pinhole projection,
// not from vlit's code; the real-file case compares the preview of a baked demo scene with the
// lit render of the same scene.
#include <doctest/doctest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include <stb_image.h>

#include "support/gltf_builder.h"
#include "support/run_command.h"

using vlit::test::run_command;
namespace fs = std::filesystem;

namespace {

const std::string kVlit = VLIT_BINARY;
const std::string kSource = VLIT_SOURCE_DIR;
std::string q(const std::string& s) { return "'" + s + "'"; }

struct Image {
  int width = 0, height = 0;
  std::vector<unsigned char> rgb;
  const unsigned char* at(int x, int y) const { return rgb.data() + 3 * (size_t(y) * width + x); }
};
Image load(const std::string& path) {
  Image image;
  int channels = 0;
  unsigned char* data = stbi_load(path.c_str(), &image.width, &image.height, &channels, 3);
  REQUIRE_MESSAGE(data != nullptr, path);
  image.rgb.assign(data, data + size_t(image.width) * image.height * 3);
  stbi_image_free(data);
  return image;
}

// IEC 61966-2-1 sRGB encoding of a linear value in [0, 1], to 8 bits.
int srgb8(double linear) {
  const double v = linear <= 0.0031308 ? 12.92 * linear : 1.055 * std::pow(linear, 1 / 2.4) - 0.055;
  return int(std::lround(255 * v));
}

void check_pixel(const Image& image, int x, int y, double r, double g, double b) {
  CAPTURE(x);
  CAPTURE(y);
  const unsigned char* c = image.at(x, y);
  CHECK(std::abs(int(c[0]) - srgb8(r)) <= 1);
  CHECK(std::abs(int(c[1]) - srgb8(g)) <= 1);
  CHECK(std::abs(int(c[2]) - srgb8(b)) <= 1);
}

// The quad x, y in [-1, 1] at z = 0 facing +Z with COLOR_0 (0.5, 0.25, 1) and base colour
// (0.5, 1, 0.2); a camera at (0, 0, 5) looking down -Z, yfov 0.8.
std::string write_quad(const fs::path& dir) {
  vlit::test::GltfBuilder b;
  const int material = b.add_material({0.5, 1, 0.2, 1}, 0, 1);
  const int mesh = b.add_mesh({-1, -1, 0, 1, -1, 0, 1, 1, 0, -1, 1, 0}, {0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1}, {0, 1, 2, 0, 2, 3},
                              TINYGLTF_MODE_TRIANGLES, material);
  b.model().meshes[mesh].primitives[0].attributes["COLOR_0"] =
      b.add_floats({0.5, 0.25, 1, 0.5, 0.25, 1, 0.5, 0.25, 1, 0.5, 0.25, 1}, TINYGLTF_TYPE_VEC3);
  b.add_node(mesh);
  tinygltf::Camera cam;
  cam.type = "perspective";
  cam.perspective.yfov = 0.8;
  cam.perspective.znear = 0.1;
  b.model().cameras.push_back(cam);
  tinygltf::Node node;
  node.camera = 0;
  node.translation = {0, 0, 5};
  b.model().nodes.push_back(node);
  b.model().scenes[0].nodes.push_back(int(b.model().nodes.size()) - 1);
  return b.write((dir / "quad.glb").string());
}

constexpr int kW = 160, kH = 120;
// Pixel of a world point (x, y, z) seen by the quad's camera.
std::pair<int, int> pixel_of(double x, double y, double z) {
  const double depth = 5 - z, t = std::tan(0.4);
  return {int((x / (depth * t * kW / kH) + 1) * 0.5 * kW), int((1 - y / (depth * t)) * 0.5 * kH)};
}

}  // namespace

TEST_CASE("render: a scene with COLOR_0 and no lights is previewed as COLOR_0 x base colour, unlit") {
  const auto dir = vlit::test::temp_dir("render-preview");
  const std::string scene = write_quad(dir), out = (dir / "auto.png").string();
  const auto r = run_command(kVlit + " render " + q(scene) + " -o " + q(out) + " --width 160 --height 120 --samples 1");
  REQUIRE_MESSAGE(r.exit_code == 0, r.err);
  CHECK(r.err.find("COLOR_0 x base colour") != std::string::npos);
  CHECK(r.err.find("the image will be black") == std::string::npos);
  const Image image = load(out);
  const auto [x, y] = pixel_of(0.3, -0.4, 0);
  check_pixel(image, x, y, 0.5 * 0.5, 0.25 * 1, 1 * 0.2);
  check_pixel(image, 2, 2, 0, 0, 0);  // background
  // --preview says nothing about why: it was asked for.
  const auto explicit_preview =
      run_command(kVlit + " render " + q(scene) + " -o " + q(out) + " --width 160 --height 120 --samples 1 --preview");
  REQUIRE_MESSAGE(explicit_preview.exit_code == 0, explicit_preview.err);
  CHECK(explicit_preview.err.find("no lights") == std::string::npos);
  CHECK(load(out).rgb == image.rgb);
  fs::remove_all(dir);
}

TEST_CASE("render --preview and --show-lights: panels and tubes drawn with their own radiance, a one-sided panel black from behind") {
  const auto dir = vlit::test::temp_dir("render-preview-emitters");
  const std::string scene = write_quad(dir);
  const std::string lights = (dir / "lights.json").string();
  // At z = 1 in front of the quad: a panel facing the camera (counter-clockwise seen from +Z), one
  // facing away, and a tube of 1 per unit of t over 2 m (0.5 candela per metre).
  std::ofstream(lights) << R"({"lights": [
    {"type": "area", "intensity": 0.5, "polygon": [[-0.8, -0.25, 1], [-0.3, -0.25, 1], [-0.3, 0.25, 1], [-0.8, 0.25, 1]]},
    {"type": "area", "intensity": 0.5, "polygon": [[0.3, -0.25, 1], [0.3, 0.25, 1], [0.8, 0.25, 1], [0.8, -0.25, 1]]},
    {"type": "linear", "intensity": 1, "color": [1, 0.5, 0.25], "from": [-1, 0.7, 1], "to": [1, 0.7, 1]}]})";
  const std::string out = (dir / "emitters.png").string();
  const auto r = run_command(kVlit + " render " + q(scene) + " --lights " + q(lights) + " -o " + q(out) +
                             " --width 160 --height 120 --samples 1 --preview -q");
  REQUIRE_MESSAGE(r.exit_code == 0, r.err);
  const Image image = load(out);
  const auto [fx, fy] = pixel_of(-0.55, 0, 1);
  check_pixel(image, fx, fy, 0.5, 0.5, 0.5);  // the front of a panel: its radiance
  const auto [bx, by] = pixel_of(0.55, 0, 1);
  check_pixel(image, bx, by, 0, 0, 0);  // the back of a one-sided panel
  const auto [tx, ty] = pixel_of(0, 0.7, 1);
  check_pixel(image, tx, ty, 0.5, 0.25, 0.125);  // the tube: colour x intensity / length
  const auto [qx, qy] = pixel_of(0.3, -0.6, 0);
  check_pixel(image, qx, qy, 0.25, 0.25, 0.2);  // the quad, unlit

  // The same scene and lights without --preview is lit, not previewed: the quad's colour differs.
  const std::string lit = (dir / "lit.png").string();
  const auto lit_run = run_command(kVlit + " render " + q(scene) + " --lights " + q(lights) + " -o " + q(lit) +
                                   " --width 160 --height 120 --samples 1 -q");
  REQUIRE_MESSAGE(lit_run.exit_code == 0, lit_run.err);
  const Image lit_image = load(lit);
  const unsigned char* c = lit_image.at(qx, qy);
  CHECK(std::abs(int(c[0]) - srgb8(0.25)) + std::abs(int(c[2]) - srgb8(0.2)) > 4);
  CHECK(std::abs(int(lit_image.at(fx, fy)[0]) - srgb8(0.5)) > 4);  // no panel drawn: the lit quad behind it

  // --show-lights draws the same emitters over the lit render; the quad stays lit.
  const std::string shown = (dir / "shown.png").string();
  const auto shown_run = run_command(kVlit + " render " + q(scene) + " --lights " + q(lights) + " -o " + q(shown) +
                                     " --width 160 --height 120 --samples 1 --show-lights -q");
  REQUIRE_MESSAGE(shown_run.exit_code == 0, shown_run.err);
  const Image with_lights = load(shown);
  check_pixel(with_lights, fx, fy, 0.5, 0.5, 0.5);
  check_pixel(with_lights, tx, ty, 0.5, 0.25, 0.125);
  CHECK(std::equal(with_lights.at(qx, qy), with_lights.at(qx, qy) + 3, lit_image.at(qx, qy)));
  fs::remove_all(dir);
}

TEST_CASE("render: the preview of a baked demo scene is its lit render (diffuse only) without --lights") {
  const auto dir = vlit::test::temp_dir("render-preview-baked");
  const std::string demo = kSource + "/assets/demo/studio.glb", lights = kSource + "/assets/demo/lights.json";
  REQUIRE_MESSAGE(fs::exists(demo), "missing test data: " << demo);
  const std::string baked = (dir / "baked.glb").string();
  // Float colours: nothing clipped or quantized, so COLOR_0 x base colour is the lit diffuse.
  const auto bake = run_command(kVlit + " bake " + q(demo) + " --lights " + q(lights) + " -o " + q(baked) +
                                " --color-format float -q");
  REQUIRE_MESSAGE(bake.exit_code == 0, bake.err);
  const std::string preview = (dir / "preview.png").string(), lit = (dir / "lit.png").string();
  const std::string size = " --width 160 --height 120 --samples 4 -q";
  const auto p = run_command(kVlit + " render " + q(baked) + " -o " + q(preview) + size);
  REQUIRE_MESSAGE(p.exit_code == 0, p.err);
  const auto l = run_command(kVlit + " render " + q(demo) + " --lights " + q(lights) + " -o " + q(lit) + size +
                             " --specular none");
  REQUIRE_MESSAGE(l.exit_code == 0, l.err);
  const Image a = load(preview), b = load(lit);
  REQUIRE(a.rgb.size() == b.rgb.size());
  std::size_t differing = 0, lit_pixels = 0;
  for (std::size_t i = 0; i < a.rgb.size(); i += 3) {
    int worst = 0;
    for (int k = 0; k < 3; ++k) worst = std::max(worst, std::abs(int(a.rgb[i + k]) - int(b.rgb[i + k])));
    if (worst > 2) ++differing;
    if (b.rgb[i] + b.rgb[i + 1] + b.rgb[i + 2] > 30) ++lit_pixels;
  }
  CAPTURE(differing);
  CHECK(lit_pixels > a.rgb.size() / 3 / 4);  // the comparison is about a lit picture, not a black one
  CHECK(differing <= a.rgb.size() / 3 / 100);
  fs::remove_all(dir);
}
