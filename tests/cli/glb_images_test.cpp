// A .glb output embeds the image files its input refers to, so it can be moved on its own;
// --keep-image-links keeps them as links relative to the output (gltf/gltf_writer.h).
#include <doctest/doctest.h>

#include <filesystem>
#include <fstream>

#include "gltf/gltf_file.h"
#include "support/gltf_builder.h"
#include "support/run_command.h"

using namespace vlit;
using vlit::test::run_command;
namespace fs = std::filesystem;

namespace {

std::string q(const fs::path& p) { return "'" + p.string() + "'"; }

// The bytes of an image as stored in a loaded model's buffer.
std::string buffer_view_bytes(const tinygltf::Model& model, int view_index) {
  const auto& view = model.bufferViews.at(view_index);
  const auto& data = model.buffers.at(view.buffer).data;
  return std::string(data.begin() + static_cast<long>(view.byteOffset),
                     data.begin() + static_cast<long>(view.byteOffset + view.byteLength));
}

}  // namespace

TEST_CASE(".glb output embeds the input's image files, --keep-image-links keeps links") {
  const fs::path dir = vlit::test::temp_dir("cli-glb-images");
  fs::create_directories(dir / "in/tex");
  fs::create_directories(dir / "out");
  // Not decoded by vlit, only copied: a PNG signature and some bytes are enough.
  const std::string png = std::string("\x89PNG\r\n\x1a\n", 8) + "pixels of the base colour";
  const std::string jpeg = std::string("\xff\xd8\xff\xe0", 4) + "pixels of the roughness";
  std::ofstream(dir / "in/tex/base colour.png", std::ios::binary) << png;
  std::ofstream(dir / "in/tex/rough.jpg", std::ios::binary) << jpeg;
  vlit::test::GltfBuilder b;
  b.add_node(b.add_mesh({0, 0, 0, 1, 0, 0, 0, 1, 0}, {}, {0, 1, 2}));
  for (const char* uri : {"tex/base%20colour.png", "tex/rough.jpg", "tex/base%20colour.png", "tex/missing.png"}) {
    tinygltf::Image image;
    image.uri = uri;
    b.model().images.push_back(image);
  }
  b.write((dir / "in/scene.gltf").string());
  std::ofstream(dir / "lights.json") << R"({"lights": [{"type": "point", "position": [0, 0, 1], "intensity": 1}]})";
  const std::string bake = std::string(VLIT_BINARY) + " bake " + q(dir / "in/scene.gltf") + " --lights " + q(dir / "lights.json") + " -q";

  const auto r = run_command(bake + " -o " + q(dir / "out/scene.glb"));
  REQUIRE_MESSAGE(r.exit_code == 0, r.err);
  // Moved away from the input's folder, the output still has its images.
  fs::create_directories(dir / "moved");
  fs::rename(dir / "out/scene.glb", dir / "moved/scene.glb");
  const tinygltf::Model embedded = load_gltf_file((dir / "moved/scene.glb").string()).model;
  REQUIRE(embedded.images.size() == 4);
  CHECK(embedded.images[0].uri.empty());
  CHECK(embedded.images[0].mimeType == "image/png");
  CHECK(embedded.images[1].mimeType == "image/jpeg");
  CHECK(buffer_view_bytes(embedded, embedded.images[0].bufferView) == png);
  CHECK(buffer_view_bytes(embedded, embedded.images[1].bufferView) == jpeg);
  CHECK(embedded.images[2].bufferView == embedded.images[0].bufferView);  // one file, stored once
  CHECK(embedded.images[3].uri == "../in/tex/missing.png");  // missing in the input too: still a link
  for (const auto& view : embedded.bufferViews) CHECK(view.byteOffset % 4 == 0);

  const auto links = run_command(bake + " --keep-image-links -o " + q(dir / "out/links.glb"));
  REQUIRE_MESSAGE(links.exit_code == 0, links.err);
  const tinygltf::Model linked = load_gltf_file((dir / "out/links.glb").string()).model;
  REQUIRE(linked.images.size() == 4);
  CHECK(linked.images[0].bufferView == -1);
  CHECK(linked.images[0].uri == "../in/tex/base%20colour.png");
  CHECK(linked.images[1].uri == "../in/tex/rough.jpg");
  // A .gltf output keeps links (its buffers are data URIs; images stay files).
  const auto gltf = run_command(bake + " -o " + q(dir / "out/scene.gltf"));
  REQUIRE_MESSAGE(gltf.exit_code == 0, gltf.err);
  CHECK(load_gltf_file((dir / "out/scene.gltf").string()).model.images[1].uri == "../in/tex/rough.jpg");
}
