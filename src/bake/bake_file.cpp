#include "bake/bake_file.h"

#include <chrono>
#include <filesystem>

#include "bake/clipping_advice.h"
#include "bake/light_vertices.h"
#include "core/input_error.h"
#include "gltf/gltf_writer.h"
#include "gltf/mesh_to_gltf.h"
#include "load/load_scene.h"

namespace vlit {
namespace {

bool same_file(const std::string& a, const std::string& b) {
  std::error_code ec;
  if (std::filesystem::equivalent(a, b, ec)) return true;
  return std::filesystem::weakly_canonical(a, ec) == std::filesystem::weakly_canonical(b, ec);
}

}  // namespace

BakeFileResult bake_file(const std::string& input, const std::string& output, const BakeFileOptions& options) {
  if (same_file(input, output)) throw InputError(output, "refusing to overwrite the input; choose another output path");
  using Clock = std::chrono::steady_clock;
  auto since = [](Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); };
  auto t = Clock::now();
  LoadedScene loaded = load_scene(input, options.lights_path, {options.limits, options.use_file_lights});
  loaded.scene.lights.insert(loaded.scene.lights.end(), options.lights.begin(), options.lights.end());
  // A mesh file (OBJ, PLY, OFF, STL) becomes a new glTF document holding its meshes.
  tinygltf::Model model = loaded.gltf ? std::move(loaded.gltf->model) : gltf_from_mesh_scene(loaded.scene);
  BakeFileResult result;
  result.seconds.load = since(t);
  result.warnings = std::move(loaded.warnings);
  result.lights = loaded.scene.lights.size();
  if (loaded.scene.lights.empty())
    result.warnings.push_back(input + ": no lights (pass --lights LIGHTS.json); the bake is black");

  LightingRequest request;
  // Without an eye a bake stores the view-independent diffuse light only.
  request.shade.with_specular = options.specular_eye.has_value();
  request.shade.specular = options.specular;
  request.eye = options.specular_eye;
  request.float_batch = options.float_batch;
  request.shadows = options.shadows;
  request.progress = options.progress;
  request.cancel = options.cancel;
  t = Clock::now();
  const ScenePlan plan = plan_lighting(loaded.scene, request);
  result.plan = describe(plan, loaded.scene);
  for (const std::string& line : unreached_light_warnings(plan, loaded.scene)) result.warnings.push_back(input + ": " + line);
  result.seconds.plan = since(t);
  t = Clock::now();
  const auto light = light_scene_vertices(loaded.scene, plan, request);
  result.seconds.light = since(t);
  if (options.cancel && options.cancel->load()) throw InputError(input, "interrupted; no output written");

  t = Clock::now();
  BakeOptions encode = options.encode;
  encode.source = input;
  result.report = bake_vertex_colors(model, loaded.scene, light, encode);
  result.seconds.encode = since(t);
  if (result.report.specular_unrepresentable > 0)
    result.warnings.push_back(input + ": " + std::to_string(result.report.specular_unrepresentable) +
                              " vertices have specular light in a channel whose base colour is 0; a multiplier of the "
                              "base colour cannot show it (left out)");
  if (const std::string advice = clipping_advice(result.report, options.encode.exposure); !advice.empty())
    result.warnings.push_back(input + ": " + advice);
  // Multiplying the existing colours is what multiply mode asks for: no warning. Replacing drops them.
  if (result.report.replaced_attributes > 0 && options.encode.mode == BakeMode::kReplace)
    result.warnings.push_back(input + ": replaced the existing " + options.encode.target + " of " +
                              std::to_string(result.report.replaced_attributes) +
                              " primitive(s) (--mode multiply keeps them as a factor)");
  if (result.report.filled_color_sets > 0)
    result.warnings.push_back(input + ": " + std::to_string(result.report.filled_color_sets) +
                              " lower colour set(s) missing below " + options.encode.target +
                              " added in white (glTF requires COLOR_0 .. COLOR_n without gaps; a viewer's picture is "
                              "unchanged)");
  t = Clock::now();
  GltfWriteOptions write;
  write.embed_images = options.embed_images;
  write.meshopt = options.meshopt;
  write_gltf(std::move(model), input, output, write);
  result.seconds.write = since(t);
  return result;
}

}  // namespace vlit
