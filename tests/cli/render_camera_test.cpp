// `vlit render` cameras: the image's aspect wins over a glTF camera's aspectRatio (the vertical
// field of view is kept, as in three.js), and --camera INDEX|NAME|auto picks the view. A quad
// facing two cameras is drawn with --view normals (constant colour, no lights); its extent in the
// image is predicted here with the pinhole definition of glTF's perspective camera
// (x_ndc = x / (depth tan(yfov / 2) aspect)), not with vlit's matrices.
#include <doctest/doctest.h>

#include <cmath>
#include <filesystem>

#include <stb_image.h>

#include "support/gltf_builder.h"
#include "support/run_command.h"

using vlit::test::run_command;

namespace {

const std::string kVlit = VLIT_BINARY;
std::string q(const std::string& s) { return "'" + s + "'"; }

constexpr double kYfov = 0.5, kDistance = 5;

// Quad x in [-1, 1], y in [-0.5, 0.5] at z = 0 facing +Z; cameras 0 "Front" at (0, 0, 5) and 1
// "Left" at (-1, 0, 5), both looking down -Z with aspectRatio 1.
std::string write_scene(const std::filesystem::path& dir) {
  vlit::test::GltfBuilder b;
  b.add_node(b.add_mesh({-1, -0.5f, 0, 1, -0.5f, 0, 1, 0.5f, 0, -1, 0.5f, 0}, {0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1},
                        {0, 1, 2, 0, 2, 3}));
  for (const auto& [name, x] : {std::pair{"Front", 0.0}, std::pair{"Left", -1.0}}) {
    tinygltf::Camera cam;
    cam.type = "perspective";
    cam.name = name;
    cam.perspective.yfov = kYfov;
    cam.perspective.aspectRatio = 1;
    cam.perspective.znear = 0.1;
    b.model().cameras.push_back(cam);
    tinygltf::Node node;
    node.camera = int(b.model().cameras.size()) - 1;
    node.translation = {x, 0, kDistance};
    b.model().nodes.push_back(node);
    b.model().scenes[0].nodes.push_back(int(b.model().nodes.size()) - 1);
  }
  return b.write((dir / "quad.glb").string());
}

struct Extent {
  int first = -1, last = -1;  // columns of the quad (non-background) on a row
};

// The quad's columns on row y and its rows on column x of a --view normals image.
struct Image {
  int width = 0, height = 0;
  std::vector<unsigned char> rgb;
  bool covered(int x, int y) const { return rgb[3 * (size_t(y) * width + x) + 2] > 0; }  // +Z normal: blue 255
  Extent columns(int y) const {
    Extent e;
    for (int x = 0; x < width; ++x)
      if (covered(x, y)) { if (e.first < 0) e.first = x; e.last = x; }
    return e;
  }
  Extent rows(int x) const {
    Extent e;
    for (int y = 0; y < height; ++y)
      if (covered(x, y)) { if (e.first < 0) e.first = y; e.last = y; }
    return e;
  }
};

Image load(const std::string& path) {
  Image image;
  int channels = 0;
  unsigned char* data = stbi_load(path.c_str(), &image.width, &image.height, &channels, 3);
  REQUIRE(data != nullptr);
  image.rgb.assign(data, data + size_t(image.width) * image.height * 3);
  stbi_image_free(data);
  return image;
}

// Pixel column of world x (camera at camera_x, quad at depth kDistance) in an image `width` wide of
// aspect `aspect`.
double column_of(double x, double camera_x, int width, double aspect) {
  const double ndc = (x - camera_x) / (kDistance * std::tan(kYfov / 2) * aspect);
  return (ndc + 1) * 0.5 * width;
}

}  // namespace

TEST_CASE("render: the image's aspect wins over the camera's aspectRatio and --camera picks by index, name or auto") {
  const auto dir = vlit::test::temp_dir("render-camera");
  const std::string scene = write_scene(dir);
  constexpr int kW = 200, kH = 100;
  const double aspect = double(kW) / kH;
  auto render = [&](const std::string& name, const std::string& extra) {
    const std::string out = (dir / name).string();
    const auto r = run_command(kVlit + " render " + q(scene) + " -o " + q(out) +
                               " --view normals --width 200 --height 100 --samples 1 -q" + extra);
    REQUIRE_MESSAGE(r.exit_code == 0, r.err);
    return load(out);
  };

  SUBCASE("the default camera (the first) keeps yfov and takes the image's aspect") {
    const Image image = render("front.png", "");
    const Extent cols = image.columns(kH / 2), rows = image.rows(kW / 2);
    CAPTURE(cols.first);
    CAPTURE(cols.last);
    // Pixel centres inside [left, right): the first and last covered columns.
    const double left = column_of(-1, 0, kW, aspect), right = column_of(1, 0, kW, aspect);
    CHECK(std::abs(cols.first - (left - 0.5)) <= 1.0);
    CHECK(std::abs(cols.last - (right - 0.5)) <= 1.0);
    // The vertical extent from yfov alone: 0.5 / (5 tan(0.25)) of the half height.
    const double half_rows = 0.5 / (kDistance * std::tan(kYfov / 2)) * kH / 2;
    CHECK(std::abs((rows.last - rows.first + 1) - 2 * half_rows) <= 2.0);
    // With the file's aspectRatio (1) the quad would be twice as wide.
    CHECK(std::abs((cols.last - cols.first + 1) - (right - left)) <= 2.0);
  }
  SUBCASE("--camera by index and by name draw from the same camera, auto from neither") {
    const Image by_index = render("left-index.png", " --camera 1");
    const Image by_name = render("left-name.png", " --camera Left");
    CHECK(by_index.rgb == by_name.rgb);
    const Extent cols = by_index.columns(kH / 2);
    CHECK(std::abs(cols.first - (column_of(-1, -1, kW, aspect) - 0.5)) <= 1.0);
    CHECK(std::abs(cols.last - (column_of(1, -1, kW, aspect) - 0.5)) <= 1.0);
    const Image first = render("front-index.png", " --camera 0");
    const Image framed = render("auto.png", " --camera auto");
    CHECK(first.rgb != by_index.rgb);
    CHECK(framed.rgb != first.rgb);
    CHECK(framed.rgb != by_index.rgb);
  }
  SUBCASE("a camera the file does not have is a usage error naming the cameras it has") {
    for (const std::string choice : {"Back", "7"}) {
      CAPTURE(choice);
      const std::string out = (dir / "none.png").string();
      const auto r = run_command(kVlit + " render " + q(scene) + " -o " + q(out) + " --view normals --camera " + choice);
      CHECK(r.exit_code == 2);
      CHECK(r.err.rfind("error: ", 0) == 0);
      CHECK(r.err.find("quad.glb") != std::string::npos);
      CHECK(r.err.find("0 \"Front\"") != std::string::npos);
      CHECK(r.err.find("1 \"Left\"") != std::string::npos);
      CHECK(!std::filesystem::exists(out));
    }
  }
  std::filesystem::remove_all(dir);
}
