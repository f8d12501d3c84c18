// vlit bake IN.gltf|IN.glb --lights LIGHTS.json -o OUT.glb|OUT.gltf
#include <cstdio>
#include <filesystem>
#include <iostream>

#include "bake/light_vertices.h"
#include "bake/vertex_color_bake.h"
#include "cli/commands.h"
#include "cli/terminal.h"
#include "core/input_error.h"
#include "gltf/gltf_writer.h"
#include "scene/load_scene.h"

namespace vlit::cli {
namespace {

struct BakeArgs {
  std::string input, output, lights;
  std::string color_format = "unorm16";
  double exposure = 1;
  bool no_unlit = false;
  bool quiet = false;
  bool no_file_lights = false;
};

bool same_file(const std::string& a, const std::string& b) {
  std::error_code ec;
  if (std::filesystem::equivalent(a, b, ec)) return true;
  return std::filesystem::weakly_canonical(a, ec) == std::filesystem::weakly_canonical(b, ec);
}

int run_bake(const BakeArgs& args) {
  if (same_file(args.input, args.output))
    throw InputError(args.output, "refusing to overwrite the input; choose another output path");
  LoadedScene loaded = load_scene(args.input, args.lights, !args.no_file_lights);
  if (!loaded.gltf) throw InputError(args.input, "bake writes vertex colors into glTF and needs a .gltf or .glb input");
  for (const auto& w : loaded.warnings) print_warning(w);
  if (loaded.scene.lights.empty()) print_warning(args.input + ": no lights (pass --lights LIGHTS.json); the bake will be black");

  Progress progress("lighting " + args.input, !args.quiet);
  LightingRequest request;
  request.shade.with_specular = false;  // a bake stores the view-independent diffuse light
  request.progress = [&](std::size_t done, std::size_t total) { progress.update(done, total); };
  const auto light = light_scene_vertices(loaded.scene, request);
  progress.finish();

  BakeOptions options;
  options.exposure = args.exposure;
  options.mark_unlit = !args.no_unlit;
  options.format = args.color_format == "unorm8" ? ColorFormat::kUnorm8
                   : args.color_format == "float" ? ColorFormat::kFloat : ColorFormat::kUnorm16;
  tinygltf::Model model = loaded.gltf->model;
  const BakeReport report = bake_vertex_colors(model, loaded.scene, light, options);
  if (report.replaced_attributes > 0)
    print_warning(args.input + ": replaced the existing " + options.target + " of " +
                  std::to_string(report.replaced_attributes) + " primitive(s)");
  write_gltf(std::move(model), args.input, args.output);
  if (!args.quiet) {
    std::fprintf(stderr, "baked %zu vertices into %s (%s", report.vertices, args.output.c_str(), args.color_format.c_str());
    if (options.format != ColorFormat::kFloat)
      std::fprintf(stderr, ", max quantization error %.3g, %zu vertices clipped above 1", report.max_quantization_error,
                   report.clipped_vertices);
    std::fprintf(stderr, ")\n");
  }
  return 0;
}

}  // namespace

Runner add_bake_command(CLI::App& app) {
  auto args = std::make_shared<BakeArgs>();
  CLI::App* cmd = app.add_subcommand("bake", "Light every vertex and store the light as glTF vertex colors (COLOR_0).");
  cmd->add_option("input", args->input, "Input asset (.gltf or .glb); it is never modified")->required()->check(CLI::ExistingFile);
  cmd->add_option("-o,--output", args->output, "Output file (.glb or .gltf); written atomically")->required();
  cmd->add_option("--lights", args->lights, "LIGHTS.json with lights to add to the asset's own (docs/lights-json.md)")->check(CLI::ExistingFile);
  cmd->add_option("--color-format", args->color_format,
                  "Encoding of the baked colors: unorm16 (default), unorm8 or float")
      ->check(CLI::IsMember({"unorm16", "unorm8", "float"}));
  cmd->add_option("--exposure", args->exposure, "Multiplier applied to the light before encoding (default 1)")
      ->check(CLI::PositiveNumber);
  cmd->add_flag("--no-unlit", args->no_unlit, "Do not mark materials KHR_materials_unlit (viewers will light the asset again)");
  cmd->add_flag("--no-file-lights", args->no_file_lights, "Ignore the lights stored in the asset (KHR_lights_punctual)");
  cmd->add_flag("-q,--quiet", args->quiet, "No progress or summary on stderr");
  cmd->footer("The baked color is the multiplier glTF viewers apply to the base color: viewer = light x albedo.");
  return [args] { return run_bake(*args); };
}

}  // namespace vlit::cli
