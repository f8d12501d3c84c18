// vlit bake IN... --lights LIGHTS.json -o OUT
// One input and a file name: bake one file. Several inputs, a directory or a glob pattern, an
// existing directory as OUT, or --shard: a batch into the directory OUT, keeping going when a file
// fails. The batch's layout, sharding, resume and manifest are in src/batch/.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>
#include <set>

#include "bake/bake_file.h"
#include "bake/target_attribute.h"
#include "batch/abandoned_temporaries.h"
#include "batch/batch_inputs.h"
#include "batch/manifest.h"
#include "batch/output_freshness.h"
#include "batch/shard.h"
#include "cli/commands.h"
#include "cli/interrupt.h"
#include "cli/openmp_wait_policy.h"
#include "cli/scene_args.h"
#include "cli/specular_option.h"
#include "cli/terminal.h"
#include "cli/usage_error.h"
#include "cli/vector_option.h"
#include "core/input_error.h"
#include "gltf/gltf_file.h"
#include "gltf/gltf_scene.h"
#include "mesh/mesh_file.h"

namespace vlit::cli {
namespace {

namespace fs = std::filesystem;

struct BakeArgs {
  std::vector<std::string> inputs;
  std::string output;
  SceneArgs scene;                 // --lights, --no-file-lights, --shadows, --explain, limits
  std::string color_format = "unorm16";
  std::string mode = "replace";
  std::string target = "COLOR_0";
  std::vector<double> specular_eye;  // three numbers, or empty
  std::string specular = "exact";
  double exposure = 1;
  bool no_unlit = false;
  bool quiet = false;
  std::string shard;               // "I/N", "auto" or empty
  bool skip_existing = false;
  bool keep_image_links = false;
  bool meshopt = false;
  std::string manifest;            // JSON lines, appended; empty: none
};

BakeFileOptions file_options(const BakeArgs& args) {
  BakeFileOptions o;
  if (!args.specular_eye.empty()) o.specular_eye = Vec3d{args.specular_eye[0], args.specular_eye[1], args.specular_eye[2]};
  o.specular = parse_specular(args.specular);
  o.lights_path = args.scene.lights;
  o.use_file_lights = !args.scene.no_file_lights;
  o.limits = args.scene.scene_options().limits;
  o.shadows = args.scene.shadows_on();
  o.embed_images = !args.keep_image_links;
  o.meshopt = args.meshopt;
  o.encode.exposure = args.exposure;
  o.encode.mark_unlit = !args.no_unlit;
  o.encode.target = args.target;
  o.encode.mode = args.mode == "multiply" ? BakeMode::kMultiply : BakeMode::kReplace;
  o.encode.format = args.color_format == "unorm8" ? ColorFormat::kUnorm8
                    : args.color_format == "float" ? ColorFormat::kFloat : ColorFormat::kUnorm16;
  o.cancel = &interrupt_requested();
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

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// The shard this process bakes: --shard I/N, or --shard auto from the environment (batch/shard.h).
Shard chosen_shard(const BakeArgs& args) {
  if (args.shard != "auto") return parse_shard(args.shard);
  const ShardSource source = shard_from_environment([](const char* name) { return std::getenv(name); });
  if (!args.quiet) std::fprintf(stderr, "shard %s from %s\n", source.shard.text().c_str(), source.from.c_str());
  return source.shard;
}

int run_single(const BakeArgs& args, const BatchInput& input, BakeFileOptions options) {
  const std::string& in = input.path;
  std::unique_ptr<ManifestWriter> manifest;
  if (!args.manifest.empty()) manifest = std::make_unique<ManifestWriter>(args.manifest);
  ManifestRecord record{in, input.key, args.output, "", "", 0, 0, "", ""};
  auto log = [&](const std::string& status, const std::string& error) {
    if (!manifest) return;
    record.status = status;
    record.error = error;
    record.time = utc_timestamp();
    manifest->append(record);
  };
  if (args.skip_existing && output_is_current(args.output, in, args.scene.lights)) {
    if (!args.quiet) std::fprintf(stderr, "%s is newer than %s: skipped (--skip-existing)\n", args.output.c_str(), in.c_str());
    log("skipped", "");
    return 0;
  }
  Progress progress("lighting", in, !args.quiet);
  options.progress = [&](std::size_t done, std::size_t total) { progress.update(done, total); };
  const auto start = std::chrono::steady_clock::now();
  try {
    const BakeFileResult r = bake_file(in, args.output, options);
    progress.finish();
    record.vertices = r.report.vertices;
    record.seconds = seconds_since(start);
    log("baked", "");
    for (const auto& w : r.warnings) print_warning(w);
    if (args.scene.explain) print_explain(in, r);
    if (!args.quiet) print_summary(args.output, r, args.color_format);
  } catch (const std::exception& e) {
    progress.finish();
    record.seconds = seconds_since(start);
    if (interrupt_requested().load()) {
      log("interrupted", "interrupted; no output written");
      print_error(in + ": interrupted; no output written");
      return 130;
    }
    log("failed", e.what());
    throw;
  }
  return 0;
}

// The batch: every input keeps its path relative to its argument under OUT (batch/batch_inputs.h);
// with --shard only this shard's inputs are baked.
int run_batch(const BakeArgs& args, const std::vector<BatchInput>& inputs, BakeFileOptions options) {
  namespace fs = std::filesystem;
  std::vector<BatchItem> items = lay_out_batch(inputs, args.output);  // throws on a collision: nothing written yet
  const std::size_t batch_size = items.size();
  std::optional<Shard> shard;
  if (!args.shard.empty()) {
    shard = chosen_shard(args);
    std::erase_if(items, [&](const BatchItem& item) { return shard_of_key(item.key, shard->count) != shard->index; });
  }
  std::error_code ec;
  // `-o baked.glb` with several inputs or --shard is a mistake, not a folder to create.
  if (!fs::exists(args.output, ec) && is_gltf_path(args.output))
    throw UsageError(args.output + ": a batch (several inputs, a directory, a pattern or --shard) needs -o to be a "
                                   "directory, not a .glb or .gltf file name");
  std::unique_ptr<ManifestWriter> manifest;
  if (!args.manifest.empty()) manifest = std::make_unique<ManifestWriter>(args.manifest);
  if (!fs::exists(args.output, ec)) fs::create_directories(args.output, ec);
  if (!fs::is_directory(args.output, ec)) throw InputError(args.output, "a batch needs -o to be a directory");
  if (shard && !args.quiet)
    std::fprintf(stderr, "shard %s: %zu of %zu inputs\n", shard->text().c_str(), items.size(), batch_size);
  if (args.skip_existing) {
    std::set<std::string> outputs;
    for (const BatchItem& item : items) outputs.insert(item.output.lexically_normal().string());
    const std::size_t removed = remove_abandoned_temporaries(args.output, outputs);
    if (removed > 0 && !args.quiet)
      std::fprintf(stderr, "removed %zu temporary file(s) left by a killed run\n", removed);
  }

  std::size_t baked = 0, skipped = 0, failed = 0, done = 0;
  BatchProgress progress(items.size(), !args.quiet);
  options.progress = [&](std::size_t done_vertices, std::size_t total) { progress.update_file(done_vertices, total); };
  for (const BatchItem& item : items) {
    if (interrupt_requested().load()) break;
    const std::string output = item.output.string();
    ManifestRecord record{item.input, item.key, output, shard ? shard->text() : "", "", 0, 0, "", ""};
    const auto start = std::chrono::steady_clock::now();
    if (args.skip_existing && output_is_current(output, item.input, args.scene.lights)) {
      record.status = "skipped";
      ++skipped;
    } else {
      progress.start_file(item.key);
      try {
        fs::create_directories(item.output.parent_path(), ec);
        const BakeFileResult r = bake_file(item.input, output, options);
        if (!r.warnings.empty() || args.scene.explain) progress.clear();
        for (const auto& w : r.warnings) print_warning(w);
        if (args.scene.explain) print_explain(item.input, r);
        record.status = "baked";
        record.vertices = r.report.vertices;
        ++baked;
      } catch (const std::exception& e) {
        progress.clear();
        const bool interrupted = interrupt_requested().load();
        record.status = interrupted ? "interrupted" : "failed";
        record.error = dynamic_cast<const InputError*>(&e) ? e.what() : item.input + ": " + e.what();
        print_error(record.error);
        if (!interrupted) ++failed;
      }
    }
    record.seconds = seconds_since(start);
    record.time = utc_timestamp();
    if (manifest) manifest->append(record);
    ++done;
    progress.finish_file();
  }
  progress.clear();
  const std::size_t not_started = items.size() - done;
  if (!args.quiet || failed > 0 || not_started > 0) {
    std::string line = std::to_string(baked) + " of " + std::to_string(items.size()) + " files baked into " + args.output;
    if (skipped > 0) line += "; " + std::to_string(skipped) + " up to date (skipped)";
    line += "; " + std::to_string(failed) + " failed";
    if (interrupt_requested().load()) line += "; interrupted, " + std::to_string(items.size() - baked - skipped - failed) + " not baked";
    std::fprintf(stderr, "%s\n", line.c_str());
  }
  if (interrupt_requested().load()) return 130;
  return failed == 0 ? 0 : 1;
}

int run_bake(const BakeArgs& args) {
  install_interrupt_handlers();
  std::vector<BatchInput> inputs;
  bool batch = args.inputs.size() > 1 || !args.shard.empty();
  for (const auto& arg : args.inputs) {
    if (is_batch_argument(arg)) batch = true;
    const auto expanded = expand_batch_argument(arg);
    inputs.insert(inputs.end(), expanded.begin(), expanded.end());
  }
  std::error_code ec;
  if (std::filesystem::is_directory(args.output, ec)) batch = true;
  const BakeFileOptions options = file_options(args);
  return batch ? run_batch(args, inputs, options) : run_single(args, inputs.front(), options);
}

}  // namespace

Runner add_bake_command(CLI::App& app) {
  auto args = std::make_shared<BakeArgs>();
  CLI::App* cmd = app.add_subcommand("bake", "Light every vertex and store the light as glTF vertex colors (COLOR_0).");
  cmd->add_option("inputs", args->inputs,
                  "Input assets (.gltf or .glb; OBJ, PLY, OFF or STL meshes become a new glTF), directories "
                  "(searched recursively for all of these) or quoted glob patterns; inputs are never modified")
      ->required();
  cmd->add_option("-o,--output", args->output,
                  "Output file (.glb or .gltf) for one input; for several inputs, a directory")
      ->required();
  add_scene_options(*cmd, args->scene);
  cmd->add_option("--target", args->target,
                  "Attribute that receives the light: COLOR_n or an application-specific _NAME (default COLOR_0)")
      ->check(CLI::Validator([](const std::string& value) { return target_attribute_problem(value); }, "COLOR_n|_NAME"));
  cmd->add_option("--mode", args->mode, "When the attribute exists: replace (default, with a warning) or multiply")
      ->check(CLI::IsMember({"replace", "multiply"}));
  cmd->add_option("--color-format", args->color_format, "Encoding of the baked colors: unorm16 (default), unorm8 or float")
      ->check(CLI::IsMember({"unorm16", "unorm8", "float"}));
  cmd->add_option("--exposure", args->exposure, "Multiplier applied to the light before encoding (default 1)")
      ->check(CLI::PositiveNumber);
  add_vector3_option(*cmd, "--specular-eye", args->specular_eye,
                     "Also bake specular light seen from this world-space eye, x,y,z or x y z (off by default); it is "
                     "folded into the multiplier of the base color (docs/gltf-output.md)");
  cmd->add_option("--specular", args->specular,
                  "Specular with --specular-eye: exact (default, the lobe integrated with the light's falloff), "
                  "exact-no-falloff (the paper's eq. 6), peak or neighborhood:K (the lobe's maximum; fast)");
  cmd->add_flag("--no-unlit", args->no_unlit, "Do not mark materials KHR_materials_unlit (viewers will light the asset again)");
  cmd->add_flag("--keep-image-links", args->keep_image_links,
                "In a .glb output, keep the input's image files as links (rewritten relative to the output) "
                "instead of embedding them; a .gltf output always keeps links");
  cmd->add_flag("--meshopt", args->meshopt,
                "Write the output's vertex and index data compressed with EXT_meshopt_compression (lossless; the "
                "output then requires the extension, as gltfpack -c writes; docs/gltf-output.md)");
  cmd->add_flag("-q,--quiet", args->quiet, "No progress or summary on stderr (warnings and errors are still printed)");
  cmd->add_option("--shard", args->shard,
                  "I/N: bake only shard I (0 .. N-1) of the batch; the N shards together bake every input once, "
                  "each input's shard set by its path under its argument (docs/batch-sharding.md). auto: from a "
                  "Slurm job array, a Kubernetes Indexed Job (with VLIT_SHARD_COUNT), GNU parallel (PARALLEL_SEQ, "
                  "with VLIT_SHARD_COUNT) or VLIT_SHARD_INDEX/VLIT_SHARD_COUNT")
      ->check(CLI::Validator(
          [](const std::string& value) {  // I/N checked while parsing: a malformed shard is a usage error
            if (value == "auto") return std::string();
            try {
              parse_shard(value);
              return std::string();
            } catch (const InputError& e) {
              return e.problem();
            }
          },
          "I/N|auto"));
  cmd->add_flag("--skip-existing", args->skip_existing,
                "Keep an output that is newer than its input and --lights file (to resume a batch); the bake "
                "options are not compared");
  cmd->add_option("--manifest", args->manifest,
                  "Append one JSON line per input to this file: input, output, status, vertices, seconds, error "
                  "(merge with 'vlit manifest-summary')");
  cmd->footer("The baked color is the multiplier glTF viewers apply to the base color: viewer = light x albedo.\n"
              "Outputs are written atomically; a failed or interrupted file leaves no output. A batch keeps going\n"
              "when a file fails and exits 1 with a summary; its outputs keep the inputs' folders under -o (two\n"
              "inputs for one output are an error before anything is written). Ctrl-C stops within about a\n"
              "second (exit 130); a second Ctrl-C stops at once.");
  return [args] { return run_bake(*args); };
}

}  // namespace vlit::cli
