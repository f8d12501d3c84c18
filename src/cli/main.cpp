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
             "set, so that several bakes at once do not slow each other down (docs/performance.md).\n"
             "Exit status: 0 everything done; 1 an input could not be read, lit or written (in a batch: any file\n"
             "failed, the others are still baked); 2 usage error (unknown option, bad value), nothing read or\n"
             "written; 130 interrupted (Ctrl-C).");

  const vlit::cli::Runner bake = vlit::cli::add_bake_command(app);
  const vlit::cli::Runner render = vlit::cli::add_render_command(app);
  const vlit::cli::Runner probe = vlit::cli::add_probe_command(app);
  const vlit::cli::Runner manifest_summary = vlit::cli::add_manifest_summary_command(app);

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == 0) return app.exit(e);  // --help, --version: printed on stdout, exit 0
    // Every usage error: one line in the style of every other error, exit 2 (README "Exit status").
    std::string message = e.what();
    if (dynamic_cast<const CLI::ExtrasError*>(&e)) {
      message += vlit::cli::did_you_mean(app);  // an unknown option or command: the closest known one
    } else if (dynamic_cast<const CLI::RequiredError*>(&e) && app.get_subcommands().empty() && argc > 1 &&
               argv[1][0] != '-') {
      // "vlit bkae ...": CLI11 reports the missing command; name the one that was mistyped.
      message = "unknown command \"" + std::string(argv[1]) + "\"" + vlit::cli::did_you_mean_command(app, argv[1]);
    }
    vlit::cli::print_error(message + "; run with --help for the options");
    return 2;
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
