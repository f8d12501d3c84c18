#include "cli/scene_args.h"

namespace vlit::cli {

void add_scene_options(CLI::App& cmd, SceneArgs& args) {
  cmd.add_option("--lights", args.lights, "LIGHTS.json with lights to add to the asset's own (docs/lights-json.md)")
      ->check(CLI::ExistingFile);
  cmd.add_flag("--no-file-lights", args.no_file_lights,
               "Ignore the lights stored in the asset (KHR_lights_punctual, EXT_lights_area, VLIT_lights_linear, "
               "emissive geometry)");
  cmd.add_option("--shadows", args.shadows,
                 "on: lights are hidden by the scene's triangles (soft shadows, docs/shadows.md); off (default)")
      ->check(CLI::IsMember({"on", "off"}));
  cmd.add_flag("--explain", args.explain,
               "Print the scene plan (kernels per light, skipped work and why) and per-stage times on stdout");
  cmd.add_option("--max-vertices", args.max_vertices,
                 "Refuse an asset with more vertices than this, counting every instance (default 50000000)")
      ->check(CLI::PositiveNumber);
  cmd.add_option("--max-emissive-lights", args.max_emissive_lights,
                 "Keep at most this many lights made from emissive geometry, the brightest (default 64)")
      ->check(CLI::NonNegativeNumber);
}

}  // namespace vlit::cli
