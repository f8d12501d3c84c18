// End-to-end tests of the vlit executable: what users type, what they get back.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <stb_image.h>

#include "core/version.h"
#include "gltf/accessor_reader.h"
#include "gltf/gltf_file.h"
#include "support/gltf_builder.h"
#include "support/run_command.h"

using namespace vlit;
using vlit::test::run_command;

namespace {

const std::string kVlit = VLIT_BINARY;
const std::string kSource = VLIT_SOURCE_DIR;
const std::string kDemo = kSource + "/assets/demo/studio.glb";
const std::string kDemoLights = kSource + "/assets/demo/lights.json";

std::string q(const std::string& s) { return "'" + s + "'"; }

std::size_t count_lines(const std::string& s) { return static_cast<std::size_t>(std::count(s.begin(), s.end(), '\n')); }

}  // namespace

TEST_CASE("--version and --help") {
  const auto v = run_command(kVlit + " --version");
  CHECK(v.exit_code == 0);
  CHECK(v.out.find(kVersion) != std::string::npos);
  const auto h = run_command(kVlit + " --help");
  CHECK(h.exit_code == 0);
  for (const char* cmd : {"bake", "render", "probe"}) CHECK(h.out.find(cmd) != std::string::npos);
  for (const char* cmd : {"bake", "render", "probe"}) {
    const auto c = run_command(kVlit + " " + cmd + " --help");
    CHECK(c.exit_code == 0);
    CHECK(c.out.find("--lights") != std::string::npos);
  }
  CHECK(run_command(kVlit).exit_code != 0);  // a command is required
}

TEST_CASE("bake the demo scene: every primitive gets COLOR_0, the input is untouched") {
  const auto dir = vlit::test::temp_dir("cli-bake");
  const std::string before = vlit::test::read_all(kDemo);
  const std::string out = (dir / "demo.glb").string();
  const auto r = run_command(kVlit + " bake " + q(kDemo) + " --lights " + q(kDemoLights) + " -o " + q(out));
  CHECK_MESSAGE(r.exit_code == 0, r.err);
  CHECK(vlit::test::read_all(kDemo) == before);
  const GltfFile baked = load_gltf_file(out);
  std::size_t primitives = 0;
  for (const auto& mesh : baked.model.meshes)
    for (const auto& prim : mesh.primitives) {
      ++primitives;
      REQUIRE(prim.attributes.count("COLOR_0"));
      const auto colors = read_accessor_as_doubles(baked.model, prim.attributes.at("COLOR_0"), out);
      CHECK(colors.size() == 4 * baked.model.accessors[prim.attributes.at("POSITION")].count);
      CHECK(*std::max_element(colors.begin(), colors.end()) > 0);  // lit, not black
    }
  CHECK(primitives == 5);
  CHECK(std::distance(std::filesystem::directory_iterator(dir), {}) == 1);  // no temporary left
}

TEST_CASE("bake refuses to overwrite its input") {
  const auto dir = vlit::test::temp_dir("cli-self");
  const auto copy = dir / "scene.glb";
  std::filesystem::copy_file(kDemo, copy);
  const std::string before = vlit::test::read_all(copy);
  const auto r = run_command(kVlit + " bake " + q(copy.string()) + " --lights " + q(kDemoLights) + " -o " +
                             q((dir / "." / "scene.glb").string()));
  CHECK(r.exit_code != 0);
  CHECK(r.err.find("refusing to overwrite the input") != std::string::npos);
  CHECK(vlit::test::read_all(copy) == before);
}

TEST_CASE("bad inputs: one error line naming the file, non-zero exit, no output") {
  const auto dir = vlit::test::temp_dir("cli-bad");
  const std::string out = (dir / "out.glb").string();
  SUBCASE("bad lights file") {
    const auto lights = dir / "lights.json";
    std::ofstream(lights) << R"({"lights": [{"type": "point", "position": [0, 0]}]})";
    const auto r = run_command(kVlit + " bake " + q(kDemo) + " --lights " + q(lights.string()) + " -o " + q(out));
    CHECK(r.exit_code == 1);
    CHECK(count_lines(r.err) == 1);
    CHECK(r.err.find(lights.string() + ": /lights/0/position: expected an array of 3 numbers") != std::string::npos);
  }
  SUBCASE("not a glTF") {
    const auto junk = dir / "junk.glb";
    std::ofstream(junk) << "this is not glTF";
    const auto r = run_command(kVlit + " bake " + q(junk.string()) + " -o " + q(out));
    CHECK(r.exit_code == 1);
    CHECK(count_lines(r.err) == 1);
    CHECK(r.err.find(junk.string() + ": not a valid glTF 2.0 file") != std::string::npos);
  }
  SUBCASE("index out of range (malformed corpus)") {
    const std::string bad = std::string(VLIT_ASSETS_DIR) + "/bad-gltf/assimp/IndexOutOfRange/IndexOutOfRange.gltf";
    REQUIRE_MESSAGE(std::filesystem::exists(bad), "missing test data: " << bad);
    const auto r = run_command(kVlit + " bake " + q(bad) + " -o " + q(out));
    CHECK(r.exit_code == 1);
    CHECK(r.err.find(bad + ": ") != std::string::npos);
  }
  CHECK_FALSE(std::filesystem::exists(out));
  CHECK(std::distance(std::filesystem::directory_iterator(dir), {}) <= 2);  // only the inputs made above
}

TEST_CASE("render writes a PNG of the requested size") {
  const auto dir = vlit::test::temp_dir("cli-render");
  const std::string out = (dir / "demo.png").string();
  const auto r = run_command(kVlit + " render " + q(kDemo) + " --lights " + q(kDemoLights) +
                             " -o " + q(out) + " --width 64 --height 48 --samples 1");
  CHECK_MESSAGE(r.exit_code == 0, r.err);
  int w = 0, h = 0, comp = 0;
  REQUIRE(stbi_info(out.c_str(), &w, &h, &comp) == 1);
  CHECK(w == 64);
  CHECK(h == 48);
  CHECK(comp == 3);
}

TEST_CASE("probe prints the point light's value at each point, 17 digits") {
  const auto dir = vlit::test::temp_dir("cli-probe");
  const auto lights = dir / "lights.json";
  std::ofstream(lights) << R"({"lights": [{"type": "point", "position": [3, 0, 4], "intensity": 2, "color": [9, 9, 9]}]})";
  const auto points = dir / "points.csv";
  std::ofstream(points) << "px,py,pz,nx,ny,nz,ex,ey,ez,m\n0,0,0,0,0,2,0,0,10,8\n0,0,0,0,0,-1,0,0,10,8\n";
  const auto r = run_command(kVlit + " probe --lights " + q(lights.string()) + " --points " + q(points.string()));
  REQUIRE_MESSAGE(r.exit_code == 0, r.err);
  std::istringstream in(r.out);
  std::string header, row0, row1;
  std::getline(in, header);
  std::getline(in, row0);
  std::getline(in, row1);
  CHECK(header == "index,diffuse,specular");
  // Hand values: |L| = 5, cos = 4/5 (normal normalized by vlit), intensity 2 (colour ignored):
  // diffuse = 2 * 0.8 / 25, specular = 2 * 0.8^8 / 25 (Rv = +Z; the default --specular exact has
  // the diffuse's falloff 1/|L|^2, docs/conventions.md).
  double index = -1, diffuse = -1, specular = -1;
  REQUIRE(std::sscanf(row0.c_str(), "%lf,%lf,%lf", &index, &diffuse, &specular) == 3);
  CHECK(diffuse == doctest::Approx(2 * 0.8 / 25).epsilon(1e-15));
  CHECK(specular == doctest::Approx(2 * std::pow(0.8, 8) / 25).epsilon(1e-14));
  CHECK(row1 == "1,0,0");  // facing away: nothing
  CHECK(row0.size() > 20);   // 17 significant digits, not a rounded print
  // The paper's eq. 6, by name: no falloff on the specular, 2 * 0.8^8.
  const auto paper = run_command(kVlit + " probe --specular exact-no-falloff --lights " + q(lights.string()) +
                                 " --points " + q(points.string()));
  REQUIRE_MESSAGE(paper.exit_code == 0, paper.err);
  std::istringstream paper_in(paper.out);
  std::getline(paper_in, header);
  std::getline(paper_in, row0);
  REQUIRE(std::sscanf(row0.c_str(), "%lf,%lf,%lf", &index, &diffuse, &specular) == 3);
  CHECK(diffuse == doctest::Approx(2 * 0.8 / 25).epsilon(1e-15));
  CHECK(specular == doctest::Approx(2 * std::pow(0.8, 8)).epsilon(1e-14));

  const auto bad = dir / "bad.csv";
  std::ofstream(bad) << "px,py,pz,nx,ny,nz,ex,ey,ez,m\n0,0,0,0,0,1,0,0,1\n";
  const auto e = run_command(kVlit + " probe --lights " + q(lights.string()) + " --points " + q(bad.string()));
  CHECK(e.exit_code == 1);
  CHECK(e.err.find(bad.string() + ": line 2: expected 10 comma-separated numbers") != std::string::npos);
}

TEST_CASE("the bundled demo scene is exactly what its generator makes") {
  const auto dir = vlit::test::temp_dir("cli-demo-scene");
  const std::string out = (dir / "studio.glb").string();
  const auto r = run_command(std::string(VLIT_DEMO_GENERATOR) + " " + q(out));
  REQUIRE_MESSAGE(r.exit_code == 0, r.err);
  CHECK(vlit::test::read_all(out) == vlit::test::read_all(kDemo));
}

TEST_CASE("batch bake: a directory of inputs into a directory, failures reported, others baked") {
  const auto dir = vlit::test::temp_dir("cli-batch");
  const auto in = dir / "in";
  std::filesystem::create_directories(in / "sub");
  std::filesystem::copy_file(kDemo, in / "a.glb");
  std::filesystem::copy_file(kDemo, in / "sub" / "b.glb");
  std::ofstream(in / "broken.gltf") << "{ not json";
  const auto out = dir / "out";
  const auto r = run_command(kVlit + " bake " + q(in.string()) + " --lights " + q(kDemoLights) + " -o " + q(out.string()));
  CHECK(r.exit_code == 1);  // one file failed
  CHECK(r.err.find((in / "broken.gltf").string() + ": not a valid glTF 2.0 file") != std::string::npos);
  CHECK(r.err.find("2 of 3 files baked") != std::string::npos);
  CHECK(std::filesystem::exists(out / "a.glb"));
  CHECK(std::filesystem::exists(out / "sub" / "b.glb"));
  CHECK_FALSE(std::filesystem::exists(out / "broken.gltf"));
  CHECK(load_gltf_file((out / "sub" / "b.glb").string()).model.meshes[0].primitives[0].attributes.count("COLOR_0"));
}

TEST_CASE("bake of a mesh file writes a new glTF with its light in COLOR_0") {
  const auto dir = vlit::test::temp_dir("cli-obj");
  const auto obj = dir / "tri.obj";
  std::ofstream(obj) << "v 0 0 0\nv 1 0 0\nv 1 1 0\nf 1 2 3\n";
  const auto lights = dir / "lights.json";
  std::ofstream(lights) << R"({"lights": [{"type": "point", "position": [0, 0, 1], "intensity": 0.5}]})";
  const auto out = dir / "out.glb";
  const auto r = run_command(kVlit + " bake " + q(obj.string()) + " --lights " + q(lights.string()) + " -o " +
                             q(out.string()) + " --color-format float -q");
  REQUIRE_MESSAGE(r.exit_code == 0, r.err);
  const tinygltf::Model model = load_gltf_file(out.string()).model;
  REQUIRE(model.meshes.size() == 1);
  const auto& prim = model.meshes[0].primitives[0];
  REQUIRE(prim.attributes.count("COLOR_0"));
  const std::vector<double> c = vlit::read_accessor_as_doubles(model, prim.attributes.at("COLOR_0"), out.string());
  const std::size_t comps = c.size() / 3;  // RGB or RGBA per vertex
  // By hand, Lambert with inverse-square falloff: vertex (0,0,0) is 1 below the light (cos 1,
  // d^2 = 1), vertex (1,0,0) sees it at cos 1/sqrt(2) from d^2 = 2, so E1 / E0 = 1 / (2 sqrt 2).
  // The ratio does not depend on the intensity's radiometric scale.
  REQUIRE(c[0] > 0);
  CHECK(c[comps] / c[0] == doctest::Approx(1 / (2 * std::sqrt(2.0))).epsilon(1e-6));
  CHECK(c[0] == c[1]);  // white light: grey
  // In a batch a mesh file's output is named .glb.
  std::filesystem::copy_file(obj, dir / "tri2.obj");
  const auto batch = dir / "batch";
  const auto rb = run_command(kVlit + " bake " + q((dir / "*.obj").string()) + " --lights " + q(lights.string()) +
                              " -o " + q(batch.string()) + " -q");
  CHECK_MESSAGE(rb.exit_code == 0, rb.err);
  CHECK(std::filesystem::exists(batch / "tri.glb"));
  CHECK(std::filesystem::exists(batch / "tri2.glb"));
  // A directory of mesh files is a batch too (it was refused as holding no glTF).
  const auto meshes = dir / "meshes";
  std::filesystem::create_directories(meshes / "sub");
  std::filesystem::copy_file(obj, meshes / "a.obj");
  std::filesystem::copy_file(obj, meshes / "sub" / "b.obj");
  const auto from_dir = dir / "from-dir";
  const auto rd = run_command(kVlit + " bake " + q(meshes.string()) + " --lights " + q(lights.string()) + " -o " +
                              q(from_dir.string()) + " -q");
  CHECK_MESSAGE(rd.exit_code == 0, rd.err);
  CHECK(std::filesystem::exists(from_dir / "a.glb"));
  CHECK(std::filesystem::exists(from_dir / "sub" / "b.glb"));
}

TEST_CASE("--explain prints the plan and per-stage times") {
  const auto dir = vlit::test::temp_dir("cli-explain");
  const auto r = run_command(kVlit + " bake " + q(kDemo) + " --lights " + q(kDemoLights) + " -o " +
                             q((dir / "out.glb").string()) + " --explain -q");
  REQUIRE_MESSAGE(r.exit_code == 0, r.err);
  CHECK(r.out.find("plan: specular none") != std::string::npos);  // a bake is diffuse only
  CHECK(r.out.find("area contour integral (eq. 9)") != std::string::npos);
  CHECK(r.out.find("linear closed form (eq. 4)") != std::string::npos);
  CHECK(r.out.find("time: load") != std::string::npos);
  // vlit restarts itself with a passive OpenMP wait policy unless the user chose one.
  const std::string unset = "env -u OMP_WAIT_POLICY ";
  CHECK(r.out.find("(OpenMP wait policy ") != std::string::npos);
  const auto passive = run_command(unset + kVlit + " bake " + q(kDemo) + " --lights " + q(kDemoLights) + " -o " +
                                   q((dir / "out.glb").string()) + " --explain -q");
  CHECK(passive.out.find("(OpenMP wait policy passive)") != std::string::npos);
  const auto active = run_command("OMP_WAIT_POLICY=active " + kVlit + " bake " + q(kDemo) + " --lights " + q(kDemoLights) +
                                  " -o " + q((dir / "out.glb").string()) + " --explain -q");
  CHECK(active.out.find("(OpenMP wait policy active)") != std::string::npos);
  const auto render = run_command(kVlit + " render " + q(kDemo) + " --lights " + q(kDemoLights) + " -o " +
                                  q((dir / "out.png").string()) + " --width 32 --height 24 --explain -q --specular neighborhood:2");
  REQUIRE_MESSAGE(render.exit_code == 0, render.err);
  CHECK(render.out.find("plan: specular neighborhood") != std::string::npos);  // not exact: that lights the whole demo for seconds
  CHECK(render.out.find("rasterize") != std::string::npos);
  const auto bad = run_command(kVlit + " render " + q(kDemo) + " -o " + q((dir / "x.png").string()) + " --specular shiny");
  CHECK(bad.exit_code == 2);  // a value the option does not allow: a usage error
  CHECK(bad.err.find("--specular: expected exact, exact-no-falloff, peak, neighborhood:K or none") != std::string::npos);
}

TEST_CASE("bake output is byte-identical with OMP_NUM_THREADS=1 and 2 (float batch kernels)") {
  const auto dir = vlit::test::temp_dir("cli-threads");
  const std::string one = (dir / "one.glb").string(), two = (dir / "two.glb").string();
  const auto a = run_command("OMP_NUM_THREADS=1 " + kVlit + " bake " + q(kDemo) + " --lights " + q(kDemoLights) +
                             " -o " + q(one) + " --explain -q");
  const auto b = run_command("OMP_NUM_THREADS=2 " + kVlit + " bake " + q(kDemo) + " --lights " + q(kDemoLights) +
                             " -o " + q(two) + " -q");
  REQUIRE_MESSAGE(a.exit_code == 0, a.err);
  REQUIRE_MESSAGE(b.exit_code == 0, b.err);
  CHECK(a.out.find("float SIMD batch") != std::string::npos);  // the demo's lights take the batch path
  const std::string bytes_one = vlit::test::read_all(one), bytes_two = vlit::test::read_all(two);
  CHECK(!bytes_one.empty());
  CHECK(bytes_one == bytes_two);
}

TEST_CASE("batch progress: a rate and ETA line on a terminal only, never with --quiet or into a file") {
  const auto dir = vlit::test::temp_dir("cli-progress");
  const std::string inputs = q(kDemo) + " " + q(kDemo);  // two arguments: a batch (of one file: named twice, baked once)
  // Not a terminal (run_command redirects stdout and stderr to files): no progress at all.
  const auto plain = run_command(kVlit + " bake " + inputs + " --lights " + q(kDemoLights) + " -o " + q((dir / "a").string()));
  CHECK_MESSAGE(plain.exit_code == 0, plain.err);
  for (const std::string* s : {&plain.out, &plain.err}) {
    CHECK(s->find('\r') == std::string::npos);
    CHECK(s->find("files/s") == std::string::npos);
  }
  // On a terminal (util-linux `script` gives the command a pseudo-terminal): the line appears,
  // and --quiet silences it.
  if (run_command("command -v script").exit_code != 0) {
    MESSAGE("skipped the terminal half: `script` (util-linux) is not installed");
    return;
  }
  auto in_terminal = [&](const std::string& args) {
    return run_command("script -qec " + q(kVlit + " bake " + inputs + " --lights " + kDemoLights + " " + args) + " /dev/null");
  };
  const auto tty = in_terminal("-o " + (dir / "b").string());
  CHECK_MESSAGE(tty.exit_code == 0, tty.out);
  CHECK(tty.out.find("baking 1/1 files") != std::string::npos);
  CHECK(tty.out.find("files/s  ETA") != std::string::npos);
  const auto quiet = in_terminal("-q -o " + (dir / "c").string());
  CHECK(quiet.exit_code == 0);
  CHECK(quiet.out.find("files/s") == std::string::npos);
  // The terminal ends lines (the demo's clipping warning) with \r\n; a progress line would
  // return the cursor with a \r of its own.
  std::string lines = quiet.out;
  for (std::size_t at = lines.find("\r\n"); at != std::string::npos; at = lines.find("\r\n", at)) lines.erase(at, 1);
  CHECK(lines.find('\r') == std::string::npos);
}

TEST_CASE("bake --specular-eye: a malformed eye is a one-line error") {
  const auto dir = vlit::test::temp_dir("cli-eye");
  const auto r = run_command(kVlit + " bake " + q(kDemo) + " --lights " + q(kDemoLights) + " --specular-eye 1,2 -o " +
                             q((dir / "out.glb").string()));
  CHECK(r.exit_code != 0);
  CHECK(count_lines(r.err) == 1);
  CHECK(r.err.find("--specular-eye") != std::string::npos);
  CHECK_FALSE(std::filesystem::exists(dir / "out.glb"));
  const auto ok = run_command(kVlit + " bake " + q(kDemo) + " --lights " + q(kDemoLights) + " --specular-eye 0,2,5 -o " +
                              q((dir / "eye.glb").string()));
  CHECK_MESSAGE(ok.exit_code == 0, ok.err);
}

TEST_CASE("--target accepts COLOR_n or an application-specific _NAME, anything else is a usage error (exit 2)") {
  const auto dir = vlit::test::temp_dir("cli-target");
  const std::string bake = kVlit + " bake " + q(kDemo) + " --lights " + q(kDemoLights) + " -q --target ";
  for (const std::string bad : {"NORMAL", "foo", "COLOR_", "COLOR_01", "COLOR_x", "_", "color_0", "TEXCOORD_0"}) {
    CAPTURE(bad);
    const auto r = run_command(bake + q(bad) + " -o " + q((dir / "bad.glb").string()));
    CHECK(r.exit_code == 2);
    CHECK(r.err.find("--target") != std::string::npos);
    CHECK(r.err.find("\"" + bad + "\"") != std::string::npos);                  // the value given
    CHECK(r.err.find("COLOR_n") != std::string::npos);                           // what is allowed
    CHECK(r.err.find("starting with an underscore") != std::string::npos);
    CHECK_FALSE(std::filesystem::exists(dir / "bad.glb"));
  }
  for (const std::string good : {"COLOR_0", "_LIGHT"}) {
    CAPTURE(good);
    const std::string out = (dir / (good + ".glb")).string();
    const auto r = run_command(bake + good + " -o " + q(out));
    REQUIRE_MESSAGE(r.exit_code == 0, r.err);
    const GltfFile baked = load_gltf_file(out);
    for (const auto& mesh : baked.model.meshes)
      for (const auto& prim : mesh.primitives) CHECK(prim.attributes.count(good) == 1);
  }
  // Other usage errors exit 2 as well (README "Exit status").
  CHECK(run_command(kVlit + " bake " + q(kDemo) + " -o " + q((dir / "x.glb").string()) + " --mode sideways").exit_code == 2);
  CHECK(run_command(kVlit + " bake").exit_code == 2);
}

TEST_CASE("--target COLOR_n on a primitive without the lower colour sets adds them in white (no gap, valid glTF)") {
  const auto dir = vlit::test::temp_dir("cli-target-gap");
  const std::string box = kSource + "/assets/samples/Box/Box.gltf";
  REQUIRE_MESSAGE(std::filesystem::exists(box), "missing test data: " << box);
  const std::string lights = (dir / "lights.json").string();
  std::ofstream(lights) << R"({"lights": [{"type": "point", "position": [1, 2, 3], "intensity": 8}]})";
  const GltfFile input = load_gltf_file(box);
  for (const auto& mesh : input.model.meshes)
    for (const auto& prim : mesh.primitives) REQUIRE(prim.attributes.count("COLOR_0") == 0);

  const std::string out = (dir / "box.glb").string();
  const auto r = run_command(kVlit + " bake " + q(box) + " --lights " + q(lights) + " --target COLOR_2 --color-format float -q -o " +
                             q(out));
  REQUIRE_MESSAGE(r.exit_code == 0, r.err);
  CHECK(r.err.find("added in white") != std::string::npos);
  const GltfFile baked = load_gltf_file(out);
  std::size_t primitives = 0;
  for (const auto& mesh : baked.model.meshes)
    for (const auto& prim : mesh.primitives) {
      ++primitives;
      const std::size_t vertices = baked.model.accessors[prim.attributes.at("POSITION")].count;
      for (const std::string set : {"COLOR_0", "COLOR_1"}) {
        CAPTURE(set);
        REQUIRE(prim.attributes.count(set) == 1);
        const std::vector<double> values = read_accessor_as_doubles(baked.model, prim.attributes.at(set), out);
        CHECK(values.size() >= 3 * vertices);
        CHECK(std::all_of(values.begin(), values.end(), [](double v) { return v == 1.0; }));
      }
      REQUIRE(prim.attributes.count("COLOR_2") == 1);
      const std::vector<double> light = read_accessor_as_doubles(baked.model, prim.attributes.at("COLOR_2"), out);
      CHECK(std::any_of(light.begin(), light.end(), [](double v) { return v != 1.0; }));  // the light, not white
    }
  CHECK(primitives > 0);
  // An application-specific attribute needs no colour set below it.
  const std::string custom = (dir / "custom.glb").string();
  REQUIRE(run_command(kVlit + " bake " + q(box) + " --lights " + q(lights) + " --target _LIGHT -q -o " + q(custom)).exit_code == 0);
  for (const auto& mesh : load_gltf_file(custom).model.meshes)
    for (const auto& prim : mesh.primitives) CHECK(prim.attributes.count("COLOR_0") == 0);
  std::filesystem::remove_all(dir);
}

TEST_CASE("render says once when the specular dominates, and not with the default exact specular") {
  // A rough metal floor (m = 1, kd = ks = 1) under a tube light 100 units up: its diffuse is
  // ~1e-4 per unit intensity. The paper's peak (the lobe's maximum, no falloff) is ~0.5: it
  // dominates everywhere; the default integral carries the same 1/|L|^2 and does not.
  const auto dir = vlit::test::temp_dir("cli-specular-dominates");
  vlit::test::GltfBuilder b;
  std::vector<float> positions, normals;
  std::vector<std::uint32_t> indices;
  constexpr int kCells = 8;
  for (int j = 0; j <= kCells; ++j)
    for (int i = 0; i <= kCells; ++i) {
      positions.insert(positions.end(), {float(i - kCells / 2), 0.0f, float(j - kCells / 2)});
      normals.insert(normals.end(), {0.0f, 1.0f, 0.0f});
    }
  for (std::uint32_t j = 0; j < kCells; ++j)
    for (std::uint32_t i = 0; i < kCells; ++i) {
      const std::uint32_t a = j * (kCells + 1) + i, c = a + kCells + 2;
      indices.insert(indices.end(), {a, c, a + 1, a, a + kCells + 1, c});
    }
  b.add_node(b.add_mesh(positions, normals, indices, TINYGLTF_MODE_TRIANGLES, b.add_material({1, 1, 1, 1}, 1.0, 1.0)));
  const std::string scene = b.write((dir / "floor.gltf").string());
  const auto lights = dir / "lights.json";
  std::ofstream(lights) << R"({"lights": [{"type": "linear", "from": [-5, 100, 0], "to": [5, 100, 0], "intensity": 1}]})";
  const std::string base = kVlit + " render " + q(scene) + " --lights " + q(lights.string()) + " -o " +
                           q((dir / "floor.png").string()) + " --width 32 --height 24 --samples 1 --quiet";
  const auto peak = run_command(base + " --specular peak");
  REQUIRE_MESSAGE(peak.exit_code == 0, peak.err);
  const std::string needle = "the specular is over 10x the diffuse or saturates at ";
  const auto first = peak.err.find(needle);
  CHECK_MESSAGE(first != std::string::npos, peak.err);
  CHECK(peak.err.find(needle, first + 1) == std::string::npos);  // once
  CHECK(peak.err.find("--specular exact integrates the lobe") != std::string::npos);
  const auto exact = run_command(base);
  REQUIRE_MESSAGE(exact.exit_code == 0, exact.err);
  CHECK_MESSAGE(exact.err.find(needle) == std::string::npos, exact.err);
}
