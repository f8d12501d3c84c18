// `vlit bake` of an OBJ with its .mtl: the output glTF keeps one primitive per material with its
// base colour and emission, and the emitter lights the floor.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "gltf/accessor_reader.h"
#include "gltf/gltf_file.h"
#include "support/cornell_obj.h"
#include "support/gltf_builder.h"
#include "support/run_command.h"

using namespace vlit;
using vlit::test::run_command;

namespace {

const std::string kVlit = VLIT_BINARY;

std::string q(const std::string& s) { return "'" + s + "'"; }

const tinygltf::Material* material_named(const tinygltf::Model& model, const std::string& name) {
  for (const auto& m : model.materials)
    if (m.name == name) return &m;
  return nullptr;
}

}  // namespace

TEST_CASE("vlit bake of a Cornell-like OBJ + MTL: materials kept, the emitter lights the floor") {
  const auto dir = vlit::test::temp_dir("cli-obj-mtl");
  const auto obj = vlit::test::write_cornell_obj(dir);
  const auto out = dir / "cornell.glb";
  const auto r = run_command(kVlit + " bake " + q(obj.string()) + " -o " + q(out.string()) + " --color-format float -q");
  REQUIRE_MESSAGE(r.exit_code == 0, r.err);
  CHECK(r.err.empty());  // lights found in the file: no "no lights" warning
  const tinygltf::Model model = load_gltf_file(out.string()).model;
  REQUIRE(model.meshes.size() == 4);
  REQUIRE(model.materials.size() == 4);
  const auto* red = material_named(model, "red");
  const auto* light = material_named(model, "light");
  REQUIRE(red);
  REQUIRE(light);
  CHECK(red->pbrMetallicRoughness.baseColorFactor[0] == doctest::Approx(0.65));
  CHECK(red->pbrMetallicRoughness.baseColorFactor[1] == doctest::Approx(0.05));
  // Ke (5, 4, 3): factor (1, 0.8, 0.6) x KHR_materials_emissive_strength 5.
  REQUIRE(light->emissiveFactor.size() == 3);
  CHECK(light->emissiveFactor[1] == doctest::Approx(0.8));
  REQUIRE(light->extensions.count("KHR_materials_emissive_strength"));
  CHECK(light->extensions.at("KHR_materials_emissive_strength").Get("emissiveStrength").GetNumberAsDouble() ==
        doctest::Approx(5));
  CHECK(std::count(model.extensionsUsed.begin(), model.extensionsUsed.end(), "KHR_materials_emissive_strength") == 1);

  // The floor's centre vertex (1, 0, 1) in the white mesh (mesh 0): lit by the panel above it.
  const auto& prim = model.meshes[0].primitives[0];
  const auto pos = read_accessor_as_doubles(model, prim.attributes.at("POSITION"), out.string());
  const auto colour = read_accessor_as_doubles(model, prim.attributes.at("COLOR_0"), out.string());
  const std::size_t n = pos.size() / 3, comps = colour.size() / n;
  std::size_t centre = n;
  for (std::size_t v = 0; v < n; ++v)
    if (pos[3 * v] == 1 && pos[3 * v + 1] == 0 && pos[3 * v + 2] == 1) centre = v;
  REQUIRE(centre < n);
  // Parallel-square form factor under its centre (Howell's C-11, four corner rectangles), times pi.
  const double X = vlit::test::kLightSide / 2 / vlit::test::kLightHeight, s = std::sqrt(1 + X * X);
  const double e = M_PI * 4 * (2 * X / s * std::atan(X / s)) / (2 * M_PI);
  CHECK(colour[comps * centre] == doctest::Approx(5 * e).epsilon(1e-5));
  CHECK(colour[comps * centre + 2] == doctest::Approx(3 * e).epsilon(1e-5));

  // --no-file-lights: the emitter is not a light (and the bake says there is none).
  const auto dark = run_command(kVlit + " bake " + q(obj.string()) + " -o " + q((dir / "dark.glb").string()) +
                                " --no-file-lights -q");
  CHECK(dark.exit_code == 0);
  CHECK(dark.err.find("no lights") != std::string::npos);

  // A missing .mtl: a warning naming both files, the bake still succeeds (grey, unlit).
  std::filesystem::remove(dir / "cornell.mtl");
  const auto grey = run_command(kVlit + " bake " + q(obj.string()) + " -o " + q((dir / "grey.glb").string()));
  CHECK_MESSAGE(grey.exit_code == 0, grey.err);
  CHECK(grey.err.find(obj.string() + ": mtllib cornell.mtl: cannot open " + (dir / "cornell.mtl").string()) !=
        std::string::npos);

  // A malformed .mtl: exit 1, the error names the .mtl and its line, no output written.
  std::ofstream(dir / "cornell.mtl") << "newmtl white\nKd 0.7 0.7\n";
  const auto bad_out = dir / "bad.glb";
  const auto bad = run_command(kVlit + " bake " + q(obj.string()) + " -o " + q(bad_out.string()));
  CHECK(bad.exit_code != 0);
  CHECK(bad.err.find((dir / "cornell.mtl").string() + ": line 2: Kd needs 1 or 3 numbers") != std::string::npos);
  CHECK_FALSE(std::filesystem::exists(bad_out));
}
