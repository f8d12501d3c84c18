// vlit bake IN... --lights LIGHTS.json -o OUT
// One input and a file name: bake one file. Several inputs, a directory or a glob pattern, or an
// existing directory as OUT: a batch into the directory OUT, keeping going when a file fails.
#include <algorithm>
#include <cmath>
#include <atomic>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <glob.h>
#include <iostream>

#include "bake/bake_file.h"
#include "cli/commands.h"
#include "cli/openmp_wait_policy.h"
#include "cli/specular_option.h"
#include "cli/terminal.h"
#include "core/input_error.h"
#include "gltf/gltf_file.h"
#include "gltf/gltf_scene.h"
#include "mesh/mesh_file.h"

namespace vlit::cli {
namespace {

namespace fs = std::filesystem;

std::atomic<bool> g_interrupted{false};
extern "C" void on_interrupt(int) { g_interrupted.store(true); }

struct BakeArgs {
  std::vector<std::string> inputs;
  std::string output, lights;
  std::string color_format = "unorm16";
  std::string mode = "replace";
  std::string target = "COLOR_0";
  std::string specular_eye;        // "x,y,z" or empty
  std::string specular = "peak";
  double exposure = 1;
  bool no_unlit = false;
  bool no_file_lights = false;
  bool quiet = false;
  bool explain = false;
  std::string shadows = "off";
  std::size_t max_vertices = SceneLimits{}.max_vertices;
  std::size_t max_emissive_lights = SceneLimits{}.max_emissive_lights;
};

// An input argument as a list of input files: a file as is, a directory searched recursively for
// glTF and mesh files (OBJ, PLY, OFF, STL), a pattern with * ? [ expanded (for shells that pass it through quoted). Each file is paired with
// its path relative to the argument's root, which names its output in a batch.
std::vector<std::pair<std::string, fs::path>> expand_input(const std::string& arg) {
  std::vector<std::pair<std::string, fs::path>> files;
  std::error_code ec;
  if (fs::is_directory(arg, ec)) {
    for (auto it = fs::recursive_directory_iterator(arg, ec); !ec && it != fs::recursive_directory_iterator(); it.increment(ec))
      if (it->is_regular_file(ec) && (is_gltf_path(it->path().string()) || is_mesh_path(it->path().string())))
        files.emplace_back(it->path().string(), fs::relative(it->path(), arg, ec));
    std::sort(files.begin(), files.end());
    if (files.empty()) throw InputError(arg, "directory holds no .gltf, .glb, .obj, .ply, .off or .stl file");
  } else if (!fs::exists(arg, ec) && arg.find_first_of("*?[") != std::string::npos) {
    glob_t g{};
    if (::glob(arg.c_str(), 0, nullptr, &g) == 0)
      for (std::size_t i = 0; i < g.gl_pathc; ++i) files.emplace_back(g.gl_pathv[i], fs::path(g.gl_pathv[i]).filename());
    ::globfree(&g);
    if (files.empty()) throw InputError(arg, "pattern matches no file");
  } else {
    if (!fs::is_regular_file(arg, ec)) throw InputError(arg, "no such file");
    files.emplace_back(arg, fs::path(arg).filename());
  }
  return files;
}

// "x,y,z": three finite numbers separated by commas.
Vec3d parse_eye(const std::string& text) {
  double c[3];
  std::size_t at = 0;
  for (int i = 0; i < 3; ++i) {
    const std::size_t end = i < 2 ? text.find(',', at) : text.size();
    if (end == std::string::npos) throw InputError("--specular-eye", "expected x,y,z, got \"" + text + "\"");
    const std::string part = text.substr(at, end - at);
    try {
      std::size_t used = 0;
      c[i] = std::stod(part, &used);
      if (used != part.size() || !std::isfinite(c[i])) throw std::invalid_argument(part);
    } catch (const std::exception&) {
      throw InputError("--specular-eye", "expected x,y,z with three finite numbers, got \"" + text + "\"");
    }
    at = end + 1;
  }
  return {c[0], c[1], c[2]};
}

BakeFileOptions file_options(const BakeArgs& args) {
  BakeFileOptions o;
  if (!args.specular_eye.empty()) o.specular_eye = parse_eye(args.specular_eye);
  o.specular = parse_specular(args.specular);
  o.lights_path = args.lights;
  o.use_file_lights = !args.no_file_lights;
  o.shadows = args.shadows == "on";
  o.encode.exposure = args.exposure;
  o.encode.mark_unlit = !args.no_unlit;
  o.encode.target = args.target;
  o.encode.mode = args.mode == "multiply" ? BakeMode::kMultiply : BakeMode::kReplace;
  o.encode.format = args.color_format == "unorm8" ? ColorFormat::kUnorm8
                    : args.color_format == "float" ? ColorFormat::kFloat : ColorFormat::kUnorm16;
  o.cancel = &g_interrupted;
  return o;
}

// --explain: the scene plan and where the time went, on stdout.
void print_explain(const std::string& input, const BakeFileResult& r) {
  std::printf("%s\n%s%s\n", input.c_str(), r.plan.c_str(), openmp_threads_line().c_str());
  std::printf("time: load %.3f s, plan %.3f s, light %.3f s, encode %.3f s, write %.3f s\n", r.seconds.load,
              r.seconds.plan, r.seconds.light, r.seconds.encode, r.seconds.write);
}

void print_summary(const std::string& output, const BakeFileResult& r, const std::string& format) {
  std::fprintf(stderr, "baked %zu vertices, %zu lights, into %s (%s", r.report.vertices, r.lights, output.c_str(), format.c_str());
  if (format != "float")
    std::fprintf(stderr, "; max quantization error %.3g; %zu vertices clipped above 1", r.report.max_quantization_error,
                 r.report.clipped_vertices);
  std::fprintf(stderr, ")\n");
}

int run_bake(const BakeArgs& args) {
  set_default_scene_limits({args.max_vertices, args.max_emissive_lights});
  std::signal(SIGINT, on_interrupt);
  std::signal(SIGTERM, on_interrupt);
  std::vector<std::pair<std::string, fs::path>> files;
  bool batch = args.inputs.size() > 1;
  for (const auto& arg : args.inputs) {
    std::error_code ec;
    if (fs::is_directory(arg, ec) || (!fs::exists(arg, ec) && arg.find_first_of("*?[") != std::string::npos)) batch = true;
    const auto expanded = expand_input(arg);
    files.insert(files.end(), expanded.begin(), expanded.end());
  }
  std::error_code ec;
  if (fs::is_directory(args.output, ec)) batch = true;

  BakeFileOptions options = file_options(args);
  if (!batch) {
    Progress progress("lighting " + files[0].first, !args.quiet);
    options.progress = [&](std::size_t done, std::size_t total) { progress.update(done, total); };
    try {
      const BakeFileResult r = bake_file(files[0].first, args.output, options);
      progress.finish();
      for (const auto& w : r.warnings) print_warning(w);
      if (args.explain) print_explain(files[0].first, r);
      if (!args.quiet) print_summary(args.output, r, args.color_format);
    } catch (const InputError&) {
      progress.finish();
      if (g_interrupted.load()) {
        print_error(files[0].first + ": interrupted; no output written");
        return 130;
      }
      throw;
    }
    return 0;
  }

  // Batch: OUT is a directory; each input keeps its relative path and its extension (.glb for a
  // mesh file).
  if (!fs::exists(args.output, ec)) fs::create_directories(args.output, ec);
  if (!fs::is_directory(args.output, ec)) throw InputError(args.output, "a batch needs -o to be a directory");
  std::vector<std::string> failures;
  BatchProgress progress(files.size(), !args.quiet);
  options.progress = [&](std::size_t done_vertices, std::size_t total) { progress.update_file(done_vertices, total); };
  std::size_t done = 0;
  for (const auto& [input, relative] : files) {
    if (g_interrupted.load()) break;
    fs::path output = fs::path(args.output) / relative;
    if (!is_gltf_path(input)) output.replace_extension(".glb");  // a mesh file's bake is a new glTF
    progress.start_file(relative.string());
    try {
      fs::create_directories(output.parent_path(), ec);
      const BakeFileResult r = bake_file(input, output.string(), options);
      if (!r.warnings.empty() || args.explain) progress.clear();
      for (const auto& w : r.warnings) print_warning(w);
      if (args.explain) print_explain(input, r);
    } catch (const InputError& e) {
      progress.clear();
      print_error(e.what());
      failures.push_back(input);
    } catch (const std::exception& e) {
      progress.clear();
      print_error(input + ": " + e.what());
      failures.push_back(input);
    }
    ++done;
    progress.finish_file();
  }
  progress.clear();
  const std::size_t skipped = files.size() - done;
  if (!args.quiet || !failures.empty() || skipped > 0)
    std::fprintf(stderr, "%zu of %zu files baked into %s; %zu failed%s\n", done - failures.size(), files.size(),
                 args.output.c_str(), failures.size(),
                 skipped > 0 ? (", " + std::to_string(skipped) + " not started (interrupted)").c_str() : "");
  if (g_interrupted.load()) return 130;
  return failures.empty() ? 0 : 1;
}

}  // namespace

Runner add_bake_command(CLI::App& app) {
  auto args = std::make_shared<BakeArgs>();
  CLI::App* cmd = app.add_subcommand("bake", "Light every vertex and store the light as glTF vertex colors (COLOR_0).");
  cmd->add_option("inputs", args->inputs,
                  "Input assets (.gltf or .glb; OBJ, PLY, OFF or STL meshes become a new glTF), directories "
                  "(searched recursively for glTF) or quoted glob patterns; inputs are never modified")
      ->required();
  cmd->add_option("-o,--output", args->output,
                  "Output file (.glb or .gltf) for one input; for several inputs, a directory")
      ->required();
  cmd->add_option("--lights", args->lights, "LIGHTS.json with lights to add to the asset's own (docs/lights-json.md)")
      ->check(CLI::ExistingFile);
  cmd->add_option("--target", args->target, "Attribute that receives the light (default COLOR_0)");
  cmd->add_option("--mode", args->mode, "When the attribute exists: replace (default, with a warning) or multiply")
      ->check(CLI::IsMember({"replace", "multiply"}));
  cmd->add_option("--color-format", args->color_format, "Encoding of the baked colors: unorm16 (default), unorm8 or float")
      ->check(CLI::IsMember({"unorm16", "unorm8", "float"}));
  cmd->add_option("--exposure", args->exposure, "Multiplier applied to the light before encoding (default 1)")
      ->check(CLI::PositiveNumber);
  cmd->add_option("--specular-eye", args->specular_eye,
                  "Also bake specular light seen from this world-space eye, x,y,z (off by default); it is folded into "
                  "the multiplier of the base color (docs/gltf-output.md)");
  cmd->add_option("--specular", args->specular,
                  "Specular method of linear and area lights with --specular-eye: peak (default), neighborhood:K, exact");
  cmd->add_flag("--no-unlit", args->no_unlit, "Do not mark materials KHR_materials_unlit (viewers will light the asset again)");
  cmd->add_flag("--no-file-lights", args->no_file_lights, "Ignore the lights stored in the asset (KHR_lights_punctual, EXT_lights_area, VLIT_lights_linear, emissive geometry)");
  cmd->add_option("--shadows", args->shadows,
                  "on: lights are hidden by the scene's triangles (soft shadows, docs/shadows.md); off (default)")
      ->check(CLI::IsMember({"on", "off"}));
  cmd->add_flag("--explain", args->explain,
                "Print the scene plan (kernels per light, skipped work and why) and per-stage times on stdout");
  cmd->add_flag("-q,--quiet", args->quiet, "No progress or summary on stderr (warnings and errors are still printed)");
  cmd->add_option("--max-vertices", args->max_vertices,
                  "Refuse an asset with more vertices than this, counting every instance (default 50000000)")
      ->check(CLI::PositiveNumber);
  cmd->add_option("--max-emissive-lights", args->max_emissive_lights,
                  "Keep at most this many lights made from emissive geometry, the brightest (default 64)")
      ->check(CLI::NonNegativeNumber);
  cmd->footer("The baked color is the multiplier glTF viewers apply to the base color: viewer = light x albedo.\n"
              "Outputs are written atomically; a failed or interrupted file leaves no output. A batch keeps going\n"
              "when a file fails and exits 1 with a summary.");
  return [args] { return run_bake(*args); };
}

}  // namespace vlit::cli
