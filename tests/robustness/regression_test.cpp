// Regression tests for what the corpus, the fuzzers and the property tests found
// (docs/robustness.md, "Findings"). Every input in tests/robustness/fuzz-findings/ goes through
// the same pipeline as fuzz/fuzz_gltf.cpp: load from memory, build the scene, light, bake, write
// with the real writer, read back.
#include <doctest/doctest.h>

#include <filesystem>
#include <fstream>

#include "bake/light_vertices.h"
#include "bake/vertex_color_bake.h"
#include "core/input_error.h"
#include "gltf/gltf_memory.h"
#include "gltf/gltf_scene.h"
#include "gltf/gltf_writer.h"
#include "io/lights_json.h"
#include "io/points_csv.h"
#include "support/gltf_builder.h"
#include "support/run_command.h"

using namespace vlit;
namespace fs = std::filesystem;

namespace {

const fs::path kFindings = fs::path(VLIT_SOURCE_DIR) / "tests" / "robustness" / "fuzz-findings";
// How many files fuzz-findings/ holds; update it when a finding is added.
constexpr std::size_t kFindingCount = 2;

// The fuzz_gltf pipeline. Returns "" when the asset baked and the output loaded back, the
// InputError message when the asset was refused; anything else escapes and fails the test.
std::string bake_from_memory(const std::string& bytes, const fs::path& out_dir) {
  try {
    GltfFile file = load_gltf_from_memory(bytes, "memory.glb");
    std::vector<std::string> warnings;
    Scene scene = build_scene(file, warnings);
    LightSource point;
    point.position = {0.5, 2, 1};
    scene.lights = {point};
    LightingRequest request;
    request.shade.with_specular = false;
    const auto light = light_scene_vertices(scene, request);
    bake_vertex_colors(file.model, scene, light, BakeOptions{});
    const std::string out = (out_dir / "out.glb").string();
    write_gltf(std::move(file.model), "memory.glb", out);
    load_gltf_file(out);  // must not throw: a baked output always loads back
    fs::remove(out);
    return {};
  } catch (const InputError& e) {
    const std::string message = e.what();
    CHECK_MESSAGE(message.rfind("memory.glb", 0) == 0, message);  // refused ones name the input
    return message;
  }
}

}  // namespace

TEST_CASE("writer: an object with no properties is written as {} (tinygltf 2.7 wrote null)") {
  const auto dir = vlit::test::temp_dir("robust-writer-null");
  // A node, a scene and a sampler that are just {}: the baked output used to hold "nodes": [null]
  // and could not be read back (corpus: node/custom_property.gltf and 35 others).
  const std::string gltf = R"({"asset":{"version":"2.0"},"scene":0,"scenes":[{}],"nodes":[{}],"samplers":[{}]})";
  CHECK(bake_from_memory(gltf, dir) == "");
  fs::remove_all(dir);
}

TEST_CASE("writer: a skin with \"joints\": [] keeps its (required) joints array") {
  const auto dir = vlit::test::temp_dir("robust-writer-skin");
  const std::string gltf = R"({"asset":{"version":"2.0"},"skins":[{"joints":[]}]})";
  CHECK(bake_from_memory(gltf, dir) == "");
  fs::remove_all(dir);
}

TEST_CASE("every saved fuzz finding is baked or refused cleanly") {
  REQUIRE_MESSAGE(fs::is_directory(kFindings), "missing test data: " << kFindings.string());
  const auto dir = vlit::test::temp_dir("robust-findings");
  std::size_t n = 0;
  for (const auto& entry : fs::directory_iterator(kFindings)) {
    const std::string name = entry.path().filename().string();
    CAPTURE(name);
    const std::string bytes = vlit::test::read_all(entry.path());
    if (name.rfind("gltf-", 0) == 0) {
      bake_from_memory(bytes, dir);
    } else if (name.rfind("lights-", 0) == 0) {
      try { parse_lights_json(bytes, "memory.json"); } catch (const InputError&) {}
    } else if (name.rfind("points-", 0) == 0) {
      try { parse_points_csv(bytes, "memory.csv"); } catch (const InputError&) {}
    }
    ++n;
  }
  MESSAGE(n << " saved findings replayed");
  CHECK(n == kFindingCount);  // every file of fuzz-findings/, so a lost or unread finding fails
  fs::remove_all(dir);
}

TEST_CASE("LIGHTS.json: a number beyond double is an InputError naming the file (was json out_of_range 406)") {
  const std::string text = R"({"lights": [{"type": "point", "position": [1e999, 0, 0]}]})";
  try {
    parse_lights_json(text, "lights.json");
    FAIL("accepted a number beyond double");
  } catch (const InputError& e) {
    CHECK(std::string(e.what()).rfind("lights.json: ", 0) == 0);
  }
  const auto dir = vlit::test::temp_dir("robust-lights-406");
  const std::string path = (dir / "lights.json").string();
  { std::ofstream(path) << text; }
  const std::string points = (dir / "points.csv").string();
  { std::ofstream(points) << "px,py,pz,nx,ny,nz,ex,ey,ez,m\n0,0,0,0,0,1,0,0,1,1\n"; }
  const auto r = vlit::test::run_command(std::string(VLIT_BINARY) + " probe --lights '" + path + "' --points '" + points + "'");
  CHECK(r.exit_code == 1);
  CHECK(r.err.find(path) != std::string::npos);
  fs::remove_all(dir);
}
