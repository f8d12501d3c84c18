// Where a batch's outputs go (batch/batch_inputs.h): inputs keep their folders under -o, two
// inputs for one output are an error naming both, the same file twice is baked once; and when an
// output is current for --skip-existing (batch/output_freshness.h).
#include <doctest/doctest.h>

#include <filesystem>
#include <fstream>
#include <set>
#include <thread>

#include "batch/batch_inputs.h"
#include "batch/output_freshness.h"
#include "core/input_error.h"
#include "support/gltf_builder.h"

using namespace vlit;
namespace fs = std::filesystem;

namespace {

void touch(const fs::path& p) {
  fs::create_directories(p.parent_path());
  std::ofstream(p) << "x";
}

std::vector<BatchInput> expand_all(const std::vector<std::string>& args) {
  std::vector<BatchInput> all;
  for (const auto& a : args) {
    const auto e = expand_batch_argument(a);
    all.insert(all.end(), e.begin(), e.end());
  }
  return all;
}

}  // namespace

TEST_CASE("glob_root: the folders before the first wildcard") {
  CHECK(glob_root("assets/*/glTF/*.gltf") == fs::path("assets"));
  CHECK(glob_root("a/b/Duck*.glb") == fs::path("a/b"));
  CHECK(glob_root("*.glb") == fs::path("."));
  CHECK(glob_root("/data/lib/[ab]/x.glb") == fs::path("/data/lib"));
}

TEST_CASE("a directory and a glob keep the inputs' folders: Duck/glTF and Duck/glTF-Quantized do not collide") {
  const fs::path dir = vlit::test::temp_dir("batch-layout");
  touch(dir / "in/Duck/glTF/Duck.gltf");
  touch(dir / "in/Duck/glTF-Quantized/Duck.gltf");
  touch(dir / "in/Box.glb");
  const auto items = lay_out_batch(expand_all({(dir / "in").string()}), dir / "out");
  REQUIRE(items.size() == 3);
  std::set<std::string> keys, outputs;
  for (const auto& i : items) {
    keys.insert(i.key);
    outputs.insert(i.output.string());
  }
  CHECK(keys == std::set<std::string>{"Box.glb", "Duck/glTF-Quantized/Duck.gltf", "Duck/glTF/Duck.gltf"});
  CHECK(outputs.count((dir / "out/Duck/glTF-Quantized/Duck.gltf").string()) == 1);
  CHECK(outputs.count((dir / "out/Duck/glTF/Duck.gltf").string()) == 1);

  const auto globbed = lay_out_batch(expand_all({(dir / "in/Duck/*/Duck.gltf").string()}), dir / "out");
  REQUIRE(globbed.size() == 2);
  CHECK(globbed[0].key == "glTF-Quantized/Duck.gltf");
  CHECK(globbed[1].key == "glTF/Duck.gltf");
  CHECK_FALSE(fs::exists(dir / "out"));  // laying out writes nothing
}

TEST_CASE("two inputs for one output: an error naming the output and both inputs") {
  const fs::path dir = vlit::test::temp_dir("batch-collide");
  touch(dir / "a/Duck.gltf");
  touch(dir / "b/Duck.gltf");
  touch(dir / "m/x.obj");
  touch(dir / "m/x.glb");
  try {
    lay_out_batch(expand_all({(dir / "a/Duck.gltf").string(), (dir / "b/Duck.gltf").string()}), dir / "out");
    FAIL("expected a collision");
  } catch (const InputError& e) {
    const std::string what = e.what();
    CAPTURE(what);
    CHECK(what.find((dir / "out/Duck.gltf").string()) != std::string::npos);
    CHECK(what.find((dir / "a/Duck.gltf").string()) != std::string::npos);
    CHECK(what.find((dir / "b/Duck.gltf").string()) != std::string::npos);
  }
  // A mesh file's output is .glb: x.obj and x.glb collide too.
  CHECK_THROWS_AS(lay_out_batch(expand_all({(dir / "m/x.obj").string(), (dir / "m/x.glb").string()}), dir / "out"),
                  InputError);
  // The same file named twice (directory and file) is baked once.
  const auto twice = lay_out_batch(expand_all({(dir / "a").string(), (dir / "a/./Duck.gltf").string()}), dir / "out");
  CHECK(twice.size() == 1);
}

TEST_CASE("an output is current when written after its input and its lights") {
  const fs::path dir = vlit::test::temp_dir("batch-fresh");
  const fs::path in = dir / "in.glb", lights = dir / "lights.json", out = dir / "out.glb";
  touch(in);
  touch(lights);
  CHECK_FALSE(output_is_current(out.string(), in.string(), lights.string()));  // no output
  touch(out);
  const auto now = fs::last_write_time(out);
  fs::last_write_time(in, now - std::chrono::seconds(10));
  fs::last_write_time(lights, now - std::chrono::seconds(10));
  CHECK(output_is_current(out.string(), in.string(), lights.string()));
  CHECK(output_is_current(out.string(), in.string(), ""));
  fs::last_write_time(lights, now + std::chrono::seconds(1));  // lights edited after the bake
  CHECK_FALSE(output_is_current(out.string(), in.string(), lights.string()));
  CHECK(output_is_current(out.string(), in.string(), ""));
  fs::last_write_time(in, now);  // same time: not strictly newer
  CHECK_FALSE(output_is_current(out.string(), in.string(), ""));
}
