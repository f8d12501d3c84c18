// What the command line says when it is used wrongly or a bake clips: a render to a non-PNG name
// is refused, a mistyped option or command gets the nearest real one, and a bake that clips many
// vertices prints the exposure that would fit them (checked by baking again with it).
#include <doctest/doctest.h>

#include <cstdlib>
#include <filesystem>
#include <regex>

#include "support/gltf_builder.h"
#include "support/run_command.h"

using vlit::test::run_command;
namespace fs = std::filesystem;

namespace {

const std::string kVlit = VLIT_BINARY;
const std::string kBox = std::string(VLIT_ASSETS_DIR) + "/samples/Box/Box.gltf";
const std::string kLamp = std::string(VLIT_ASSETS_DIR) + "/samples/LightsPunctualLamp/LightsPunctualLamp.gltf";

std::string q(const std::string& s) { return "'" + s + "'"; }

// The counts of the bake summary line "... N vertices clipped above 1)" and "baked V vertices".
std::size_t summary_number(const std::string& err, const std::string& pattern) {
  std::smatch m;
  REQUIRE_MESSAGE(std::regex_search(err, m, std::regex(pattern)), err);
  return std::stoul(m[1]);
}

}  // namespace

TEST_CASE("render -o accepts only a .png name, anything else is a usage error before any work") {
  const fs::path dir = vlit::test::temp_dir("render-ext");
  for (const std::string name : {"out.jpg", "out.png.tmp", "out"}) {
    CAPTURE(name);
    const auto r = run_command(kVlit + " render " + q(kBox) + " --width 8 --height 8 -o " + q((dir / name).string()));
    CHECK(r.exit_code == 2);
    CHECK(r.err.find("render writes PNG images only") != std::string::npos);
    CHECK(r.err.find(name) != std::string::npos);
    CHECK_FALSE(fs::exists(dir / name));
  }
  const auto upper = run_command(kVlit + " render " + q(kBox) + " --width 8 --height 8 -q -o " + q((dir / "OUT.PNG").string()));
  CHECK_MESSAGE(upper.exit_code == 0, upper.err);
  CHECK(fs::exists(dir / "OUT.PNG"));
}

TEST_CASE("a mistyped option or command is answered with the nearest real one") {
  const fs::path dir = vlit::test::temp_dir("did-you-mean");
  const std::string out = q((dir / "x.glb").string());
  const auto light = run_command(kVlit + " bake " + q(kBox) + " --light l.json -o " + out);
  CHECK(light.exit_code == 2);
  CHECK(light.err.find("--light (did you mean --lights?)") != std::string::npos);
  const auto width = run_command(kVlit + " render " + q(kBox) + " --widht 10 -o " + q((dir / "x.png").string()));
  CHECK(width.exit_code == 2);
  CHECK(width.err.find("(did you mean --width?)") != std::string::npos);
  const auto swapped = run_command(kVlit + " bake " + q(kBox) + " --expsoure 2 -o " + out);
  CHECK(swapped.err.find("(did you mean --exposure?)") != std::string::npos);
  const auto command = run_command(kVlit + " bkae " + q(kBox) + " -o " + out);
  CHECK(command.exit_code == 2);
  CHECK(command.err.find("Unknown command \"bkae\" (did you mean bake?)") != std::string::npos);
  const auto far = run_command(kVlit + " bake " + q(kBox) + " --zzzzzz -o " + out);
  CHECK(far.exit_code == 2);
  CHECK(far.err.find("did you mean") == std::string::npos);  // nothing is near: no guess
  CHECK_FALSE(fs::exists(dir / "x.glb"));
}

TEST_CASE("a bake that clips many vertices says so and prints the exposures that fit them") {
  const fs::path dir = vlit::test::temp_dir("clipping");
  auto bake = [&](const std::string& exposure) {
    return run_command(kVlit + " bake " + q(kLamp) + " --exposure " + exposure + " -o " + q((dir / "lamp.glb").string()));
  };
  // LightsPunctualLamp's own lights clip most of its vertices at exposure 1.
  const auto r = bake("1");
  REQUIRE_MESSAGE(r.exit_code == 0, r.err);
  const std::size_t vertices = summary_number(r.err, "baked ([0-9]+) vertices");
  const std::size_t clipped = summary_number(r.err, "; ([0-9]+) vertices clipped above 1");
  REQUIRE(clipped > vertices / 50);
  std::smatch m;
  REQUIRE_MESSAGE(std::regex_search(r.err, m, std::regex(std::to_string(clipped) + " of " + std::to_string(vertices) +
                                                         " vertices \\([0-9.]+ %\\) clipped above 1 at exposure 1; "
                                                         "--exposure ([0-9.e+-]+) fits them all, ([0-9.e+-]+) fits 99 %")),
                  r.err);
  const std::string all = m[1], most = m[2];
  CHECK(std::stod(all) < std::stod(most));
  // Baking again with the advice: the first fits every vertex, the second all but at most 1 %.
  const auto fit = bake(all);
  REQUIRE_MESSAGE(fit.exit_code == 0, fit.err);
  CHECK(summary_number(fit.err, "; ([0-9]+) vertices clipped above 1") == 0);
  CHECK(fit.err.find("clipped above 1 at exposure") == std::string::npos);
  const auto fit99 = bake(most);
  REQUIRE_MESSAGE(fit99.exit_code == 0, fit99.err);
  CHECK(summary_number(fit99.err, "; ([0-9]+) vertices clipped above 1") <= vertices / 100);
  CHECK(fit99.err.find("clipped above 1 at exposure") == std::string::npos);
  // A bake that clips nothing, or stores floats, says nothing about it.
  const auto box = run_command(kVlit + " bake " + q(kBox) + " -o " + q((dir / "box.glb").string()));
  CHECK(box.err.find("clipped above 1 at exposure") == std::string::npos);
  const auto floats = run_command(kVlit + " bake " + q(kLamp) + " --color-format float -o " + q((dir / "f.glb").string()));
  CHECK(floats.err.find("clipped above 1 at exposure") == std::string::npos);
}
