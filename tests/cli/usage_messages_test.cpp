// What the command line says when it is used wrongly or a bake clips: a render to a non-PNG name
// is refused, a mistyped option or command gets the nearest real one, and a bake that clips many
// vertices prints the exposure that would fit them (checked by baking again with it).
#include <doctest/doctest.h>

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <filesystem>
#include <regex>

#include <stb_image.h>

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
  CHECK(command.err.find("error: unknown command \"bkae\" (did you mean bake?)") != std::string::npos);
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

TEST_CASE("every error is one line 'error: ...' - usage errors exit 2, input errors 1, --help documents the codes") {
  const fs::path dir = vlit::test::temp_dir("error-style");
  const std::string out = q((dir / "x.glb").string()), png = q((dir / "x.png").string());
  struct Case {
    std::string args;
    int exit_code;
  };
  const std::vector<Case> cases = {
      {"bake " + q(kBox) + " --light l.json -o " + out, 2},                 // unknown option
      {"bkae " + q(kBox) + " -o " + out, 2},                                // unknown command
      {"bake " + q(kBox) + " --mode sideways -o " + out, 2},                // a value the option does not allow
      {"bake " + q(kBox) + " --specular-eye 1,2 -o " + out, 2},             // two numbers for a vector
      {"bake " + q(kBox) + " --specular-eye 1,2,x -o " + out, 2},           // not a number
      {"bake " + q(kBox) + " --specular-eye 1 2 nan -o " + out, 2},         // not finite
      {"bake " + q(kBox) + " --specular-eye 0,2,5 --specular sharp -o " + out, 2},
      {"render " + q(kBox) + " --specular neighborhood:0 -o " + png, 2},
      {"render " + q(kBox) + " --background 1,2 -o " + png, 2},
      {"bake " + q(kBox) + " " + q(kBox) + " -o " + out, 2},               // a batch into a .glb name
      {"bake " + q(kBox) + " --shard 3/3 -o " + q(dir.string()), 2},        // a shard index beyond the count
      {"probe --lights " + q(kBox) + " --points " + q(kBox) + " --snap-to-vertices", 2},  // options that need another
      {"probe --lights " + q(kBox) + " --points " + q(kBox) + " --occluders " + q(kBox) + " --precision float", 2},
      {"bake", 2},                                                          // a missing argument
      {"bake " + q((dir / "missing.glb").string()) + " -o " + out, 1},       // an input that cannot be read
      {"render " + q((dir / "missing.glb").string()) + " -o " + png, 1},
      {"bake " + q(kBox) + " --lights " + q((dir / "missing.json").string()) + " -o " + out, 2},  // an option's file is missing
      {"bake " + q(kBox) + " --lights " + q(kBox) + " -o " + out, 1},       // a LIGHTS.json that cannot be read
  };
  for (const Case& c : cases) {
    CAPTURE(c.args);
    const auto r = run_command(kVlit + " " + c.args);
    CHECK(r.exit_code == c.exit_code);
    CHECK(r.err.rfind("error: ", 0) == 0);
    CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 1);
    CHECK_FALSE(fs::exists(dir / "x.glb"));
    CHECK_FALSE(fs::exists(dir / "x.png"));
  }
  const auto help = run_command(kVlit + " --help");
  CHECK(help.exit_code == 0);
  for (const std::string text : {"Exit status: 0 everything done; 1 an input", "2 usage error", "130 interrupted"})
    CHECK_MESSAGE(help.out.find(text) != std::string::npos, text);
}

TEST_CASE("vectors: 1,2,3 and 1 2 3 are the same for every vector option") {
  const fs::path dir = vlit::test::temp_dir("vector-syntax");
  const std::string demo = std::string(VLIT_SOURCE_DIR) + "/assets/demo/studio.glb";
  const std::string lights = std::string(VLIT_SOURCE_DIR) + "/assets/demo/lights.json";
  // bake --specular-eye: the same bytes either way, and different from another eye.
  const auto eye = [&](const std::string& name, const std::string& value) {
    const fs::path path = dir / name;
    const auto r = run_command(kVlit + " bake " + q(demo) + " --lights " + q(lights) + " -q --specular-eye " + value +
                               " -o " + q(path.string()));
    REQUIRE_MESSAGE(r.exit_code == 0, r.err);
    std::ifstream in(path, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), {});
  };
  const std::string commas = eye("commas.glb", "0,2,5"), spaces = eye("spaces.glb", "0 2 5");
  CHECK(commas == spaces);
  CHECK(commas != eye("other.glb", "0,2,-5"));
  // The option takes three numbers and leaves the input after it alone.
  const auto before_input = run_command(kVlit + " bake --specular-eye 0 2 5 " + q(demo) + " --lights " + q(lights) +
                                        " -q -o " + q((dir / "before.glb").string()));
  CHECK_MESSAGE(before_input.exit_code == 0, before_input.err);
  // render --background: the same picture either way; the corner pixel is the background.
  const auto background = [&](const std::string& name, const std::string& value) {
    const fs::path path = dir / name;
    const auto r = run_command(kVlit + " render " + q(kBox) + " --width 16 --height 12 -q --background " + value + " -o " +
                               q(path.string()));
    REQUIRE_MESSAGE(r.exit_code == 0, r.err);
    int w = 0, h = 0, channels = 0;
    unsigned char* data = stbi_load(path.string().c_str(), &w, &h, &channels, 3);
    REQUIRE(data != nullptr);
    const std::vector<unsigned char> rgb(data, data + std::size_t(w) * h * 3);
    stbi_image_free(data);
    return rgb;
  };
  const auto a = background("commas.png", "1,0.5,0"), b = background("spaces.png", "1 0.5 0");
  CHECK(a == b);
  CHECK(int(a[0]) == 255);
  CHECK(std::abs(int(a[1]) - 188) <= 1);  // sRGB(0.5) = 187.5
  CHECK(int(a[2]) == 0);
}

TEST_CASE("--mode multiply does not warn about what it was asked to do, replace warns that it drops the old colours") {
  const fs::path dir = vlit::test::temp_dir("mode-warning");
  const std::string demo = std::string(VLIT_SOURCE_DIR) + "/assets/demo/studio.glb";
  const std::string lights = " --lights " + q(std::string(VLIT_SOURCE_DIR) + "/assets/demo/lights.json");
  const std::string first = (dir / "first.glb").string();
  REQUIRE(run_command(kVlit + " bake " + q(demo) + lights + " -q -o " + q(first)).exit_code == 0);  // now it has COLOR_0
  const auto multiply =
      run_command(kVlit + " bake " + q(first) + lights + " --mode multiply -q -o " + q((dir / "m.glb").string()));
  REQUIRE_MESSAGE(multiply.exit_code == 0, multiply.err);
  CHECK(multiply.err.find("COLOR_0") == std::string::npos);
  CHECK(multiply.err.find("multipl") == std::string::npos);
  CHECK(multiply.err.find("existing") == std::string::npos);
  const auto replace = run_command(kVlit + " bake " + q(first) + lights + " -q -o " + q((dir / "r.glb").string()));
  REQUIRE_MESSAGE(replace.exit_code == 0, replace.err);
  CHECK(replace.err.find("warning: ") != std::string::npos);
  CHECK(replace.err.find("replaced the existing COLOR_0") != std::string::npos);
}
