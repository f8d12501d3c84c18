// Lights that reach no vertex: a warning for each with why, and --explain counts their pairs as
// skipped, on a real file baked by the executable.
#include <doctest/doctest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>

#include "support/gltf_builder.h"
#include "support/run_command.h"

using vlit::test::run_command;
namespace fs = std::filesystem;

namespace {

const std::string kVlit = VLIT_BINARY;

std::string q(const std::string& s) { return "'" + s + "'"; }

std::size_t count(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

}  // namespace

TEST_CASE("bake warns about every light that reaches no vertex, with why, and --explain counts it right") {
  const fs::path dir = vlit::test::temp_dir("light-reach");
  // A 1 x 1 floor in z = 0 facing +Z.
  vlit::test::GltfBuilder b;
  b.add_node(b.add_mesh({0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0}, {0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1}, {0, 1, 2, 0, 2, 3}));
  // A KHR_lights_punctual point light 2 above the floor whose range ends 0.5 above it (LIGHTS.json
  // has no range).
  tinygltf::Light point;
  point.name = "short";
  point.type = "point";
  point.range = 1.5;
  b.model().lights.push_back(point);
  const int node = b.add_node(-1, {0.5, 0.5, 2});
  tinygltf::Value::Object ref;
  ref["light"] = tinygltf::Value(0);
  b.model().nodes[node].extensions["KHR_lights_punctual"] = tinygltf::Value(ref);
  b.model().extensionsUsed.push_back("KHR_lights_punctual");
  const std::string scene = b.write((dir / "floor.glb").string());
  std::ofstream(dir / "lights.json") << R"({"lights": [
    {"name": "good", "type": "point", "position": [0.5, 0.5, 2]},
    {"name": "flipped", "type": "area", "polygon": [[0, 0, 2], [1, 0, 2], [1, 1, 2], [0, 1, 2]]},
    {"name": "below", "type": "area", "polygon": [[0, 0, -1], [1, 0, -1], [1, 1, -1], [0, 1, -1]]},
    {"name": "sideways", "type": "spot", "position": [0.5, 0.5, 2], "direction": [1, 0, 0], "outer_cone_angle": 0.3}
  ]})";
  const std::string bake = kVlit + " bake " + q(scene) + " --lights " + q((dir / "lights.json").string()) + " -o " +
                           q((dir / "out.glb").string());
  const auto r = run_command(bake);
  REQUIRE_MESSAGE(r.exit_code == 0, r.err);
  // "flipped" is counter-clockwise seen from above, so it emits upward, away from the floor;
  // "below" emits up at the floor's back; "short" ends 0.5 above the floor's centre (its bounding
  // sphere is within range, no vertex is); "sideways" points along it.
  CHECK(r.err.find("light flipped reaches no vertex: the box is behind the emitting side (it emits toward the side from "
                   "which its polygon runs counter-clockwise") != std::string::npos);
  CHECK(r.err.find("light below reaches no vertex: every vertex facing away from the light") != std::string::npos);
  CHECK(r.err.find("light short reaches no vertex: every vertex beyond the light's range") != std::string::npos);
  CHECK(r.err.find("light sideways reaches no vertex: outside the spot cone") != std::string::npos);
  CHECK(count(r.err, "reaches no vertex") == 4);  // not "good"

  const auto explain = run_command(bake + " --explain -q");
  REQUIRE_MESSAGE(explain.exit_code == 0, explain.err);
  CHECK(explain.out.find("1 of 5 light x primitive pairs lit") != std::string::npos);
  CHECK(explain.out.find("plan: light good: point (eq. 1), 4 vertices") != std::string::npos);
  CHECK(explain.out.find("plan: light below: area contour integral (eq. 9), 0 vertices") != std::string::npos);
  CHECK(count(explain.out, "reaches no vertex") == 4);
}
