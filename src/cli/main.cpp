// vlit: per-vertex lighting of triangle meshes with point, linear and area lights, baked into glTF
// vertex colours or rasterized to PNG. This file only wires the subcommands together.
#include <iostream>

#include "cli/commands.h"
#include "cli/openmp_wait_policy.h"
#include "cli/option_suggestion.h"
#include "cli/terminal.h"
#include "cli/usage_error.h"
#include "core/input_error.h"
#include "core/version.h"

int main(int argc, char** argv) {
  vlit::cli::prefer_passive_openmp_wait(argv);
  CLI::App app{"vlit: light triangle meshes per vertex with point, spot, directional, linear (tube) and area\n"
               "(panel) lights, then bake the light into glTF vertex colors or render it to PNG."};
  app.set_version_flag("--version", std::string("vlit ") + vlit::kVersion);
  app.require_subcommand(1);
  app.footer("Run 'vlit COMMAND --help' for the options of a command. Formats: docs/lights-json.md.\n"
             "Threads: OMP_NUM_THREADS (default: all cores). vlit sets OMP_WAIT_POLICY=passive unless it is\n"
             "set, so that several bakes at once do not slow each other down (docs/performance.md).");

  const vlit::cli::Runner bake = vlit::cli::add_bake_command(app);
  const vlit::cli::Runner render = vlit::cli::add_render_command(app);
  const vlit::cli::Runner probe = vlit::cli::add_probe_command(app);
  const vlit::cli::Runner manifest_summary = vlit::cli::add_manifest_summary_command(app);

  try {
    app.parse(argc, argv);
  } catch (const CLI::ExtrasError& e) {
    // An unknown option or command: name the closest known one.
    std::cerr << e.what() << vlit::cli::did_you_mean(app) << "\nRun with --help for more information.\n";
    return 2;
  } catch (const CLI::RequiredError& e) {
    // "vlit bkae ...": CLI11 reports the missing command; name the one that was mistyped.
    if (app.get_subcommands().empty() && argc > 1 && argv[1][0] != '-') {
      std::cerr << "Unknown command \"" << argv[1] << "\"" << vlit::cli::did_you_mean_command(app, argv[1])
                << "\nRun with --help for more information.\n";
      return 2;
    }
    return app.exit(e) == 0 ? 0 : 2;
  } catch (const CLI::ParseError& e) {
    // --help and --version exit 0; every usage error exits 2 (README "Exit status").
    return app.exit(e) == 0 ? 0 : 2;
  }
  try {
    if (app.got_subcommand("bake")) return bake();
    if (app.got_subcommand("render")) return render();
    if (app.got_subcommand("probe")) return probe();
    if (app.got_subcommand("manifest-summary")) return manifest_summary();
  } catch (const vlit::cli::UsageError& e) {
    vlit::cli::print_error(e.what());
    return 2;
  } catch (const vlit::InputError& e) {
    vlit::cli::print_error(e.what());
    return 1;
  } catch (const std::bad_alloc&) {
    vlit::cli::print_error("out of memory");
    return 1;
  } catch (const std::exception& e) {
    vlit::cli::print_error(e.what());
    return 1;
  }
  return 0;
}
