// Baking: a model in memory (bake), a file to a file (bake_asset, the command line's own path,
// bake/bake_file.h), and meshes given as arrays (light_meshes).
#include "api/api_internal.h"
#include "bake/bake_file.h"
#include "bake/clipping_advice.h"
#include "bake/light_vertices.h"
#include "bake/target_attribute.h"
#include "bake/vertex_color_bake.h"
#include "gltf/gltf_file.h"

namespace vlit {
namespace {

BakeOptions encode_options(const BakeSettings& s, const std::string& name) {
  if (!(s.exposure > 0) || !std::isfinite(s.exposure)) throw Error(name, "exposure must be finite and > 0", "settings.exposure");
  if (s.specular_eye && !(std::isfinite((*s.specular_eye)[0]) && std::isfinite((*s.specular_eye)[1]) &&
                          std::isfinite((*s.specular_eye)[2])))
    throw Error(name, "specular_eye must be finite", "settings.specular_eye");
  if (const std::string problem = target_attribute_problem(s.target); !problem.empty())
    throw Error(name, problem, "settings.target");
  BakeOptions o;
  o.target = s.target;
  o.mode = s.existing == ExistingColors::kMultiply ? BakeMode::kMultiply : BakeMode::kReplace;
  o.format = s.encoding == ColorEncoding::kUnorm8 ? ColorFormat::kUnorm8
             : s.encoding == ColorEncoding::kFloat ? ColorFormat::kFloat : ColorFormat::kUnorm16;
  o.exposure = s.exposure;
  o.mark_unlit = s.mark_unlit;
  o.source = name;
  return o;
}

// What bake_file asks of the per-vertex loop for these settings.
LightingRequest bake_request(const BakeSettings& s) {
  LightingRequest request;
  request.shade.with_specular = s.specular_eye.has_value();
  request.shade.specular = api::shade_options(s).specular;
  if (s.specular_eye) request.eye = api::to_vec3d(*s.specular_eye);
  request.shadows = s.shadows;
  request.progress = s.progress;
  request.cancel = s.cancel;
  return request;
}

BakeSummary summary_of(const BakeReport& report, std::size_t lights, std::vector<std::string> warnings) {
  BakeSummary summary;
  summary.vertices = report.vertices;
  summary.lights = lights;
  summary.clipped_vertices = report.clipped_vertices;
  summary.max_quantization_error = report.max_quantization_error;
  summary.replaced_attributes = report.replaced_attributes;
  summary.duplicated_meshes = report.duplicated_meshes;
  summary.warnings = std::move(warnings);
  return summary;
}

}  // namespace

BakeSummary bake(tinygltf::Model& model, const Lights& lights, const BakeSettings& settings, const std::string& name) {
  return api::translate_errors(name, [&] {
    api::check_settings(settings, name);
    BakeOptions encode = encode_options(settings, name);
    check_decodable(model, name);
    api::ThreadCount threads(settings.threads);
    // The scene is read from the caller's model, moved in and back out (never copied); on an
    // exception it goes back unchanged, since only bake_vertex_colors (which does not throw on
    // a scene built from this model) writes to it.
    GltfFile file;
    file.path = name;
    file.model = std::move(model);
    struct GiveBack {
      tinygltf::Model& to;
      GltfFile& from;
      ~GiveBack() { to = std::move(from.model); }
    } give_back{model, file};
    std::vector<std::string> warnings;
    Scene scene = build_scene(file, warnings, {api::scene_limits(settings), settings.file_lights});
    scene.lights.insert(scene.lights.end(), lights.impl().sources.begin(), lights.impl().sources.end());
    if (scene.lights.empty()) warnings.push_back(name + ": no lights; the bake is black");
    const LightingRequest request = bake_request(settings);
    const ScenePlan plan = plan_lighting(scene, request);
    for (const std::string& line : unreached_light_warnings(plan, scene)) warnings.push_back(name + ": " + line);
    const std::vector<VertexLight> light = light_scene_vertices(scene, plan, request);
    if (api::cancelled(settings)) throw Cancelled(name);
    const BakeReport report = bake_vertex_colors(file.model, scene, light, encode);
    if (report.specular_unrepresentable > 0)
      warnings.push_back(name + ": " + std::to_string(report.specular_unrepresentable) +
                         " vertices have specular light in a channel whose base colour is 0; a multiplier of the "
                         "base colour cannot show it (left out)");
    if (const std::string advice = clipping_advice(report, encode.exposure); !advice.empty())
      warnings.push_back(name + ": " + advice);
    // Multiplying the existing colours is what multiply mode asks for: no warning. Replacing drops them.
    if (report.replaced_attributes > 0 && encode.mode == BakeMode::kReplace)
      warnings.push_back(name + ": replaced the existing " + encode.target + " of " +
                         std::to_string(report.replaced_attributes) + " primitive(s) (--mode multiply keeps them as a factor)");
    if (report.filled_color_sets > 0)
      warnings.push_back(name + ": " + std::to_string(report.filled_color_sets) + " lower colour set(s) missing below " +
                         encode.target + " added in white (glTF requires COLOR_0 .. COLOR_n without gaps)");
    return summary_of(report, scene.lights.size(), std::move(warnings));
  });
}

BakeSummary bake_asset(const std::string& input, const std::string& output, const Lights& lights,
                       const BakeSettings& settings) {
  return api::translate_errors(input, [&] {
    api::check_settings(settings, input);
    BakeFileOptions options;
    options.lights = lights.impl().sources;
    options.limits = api::scene_limits(settings);
    options.use_file_lights = settings.file_lights;
    options.shadows = settings.shadows;
    options.encode = encode_options(settings, input);
    if (settings.specular_eye) options.specular_eye = api::to_vec3d(*settings.specular_eye);
    options.specular = api::shade_options(settings).specular;
    options.cancel = settings.cancel;
    options.progress = settings.progress;
    api::ThreadCount threads(settings.threads);
    try {
      const BakeFileResult r = bake_file(input, output, options);
      return summary_of(r.report, r.lights, r.warnings);
    } catch (const InputError&) {
      if (api::cancelled(settings)) throw Cancelled(input);
      throw;
    }
  });
}

std::vector<VertexLighting> light_meshes(const std::vector<Mesh>& meshes, const Lights& lights, const Settings& settings,
                                         const std::optional<Vector3>& eye) {
  return api::translate_errors("meshes", [&] {
    api::check_settings(settings, "meshes");
    Scene scene = api::scene_of_meshes(meshes);
    scene.lights = lights.impl().sources;
    api::ThreadCount threads(settings.threads);
    LightingRequest request;
    request.shade = api::shade_options(settings);
    request.shade.with_specular = eye.has_value() && request.shade.with_specular;
    if (eye) request.eye = api::to_vec3d(*eye);
    request.shadows = settings.shadows;
    request.progress = settings.progress;
    request.cancel = settings.cancel;
    const std::vector<VertexLight> light = light_scene_vertices(scene, request);
    if (api::cancelled(settings)) throw Cancelled("meshes");
    std::vector<VertexLighting> out(light.size());
    for (std::size_t i = 0; i < light.size(); ++i) {
      out[i].diffuse.reserve(light[i].diffuse.size());
      for (const Vec3f& c : light[i].diffuse) out[i].diffuse.push_back({c.x, c.y, c.z});
      out[i].specular.reserve(light[i].specular.size());
      for (const Vec3f& c : light[i].specular) out[i].specular.push_back({c.x, c.y, c.z});
    }
    return out;
  });
}

}  // namespace vlit
