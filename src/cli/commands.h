// The vlit subcommands. Each file in src/cli/ registers one command on the CLI11 app and runs it
// by calling the library; no lighting or file-format logic lives here.
#pragma once

#include <CLI/CLI.hpp>

namespace vlit::cli {

// Each returns a callback that runs the command once CLI11 has parsed its options, and
// returns the process exit code.
using Runner = std::function<int()>;

Runner add_bake_command(CLI::App& app);
Runner add_render_command(CLI::App& app);
Runner add_probe_command(CLI::App& app);
Runner add_manifest_summary_command(CLI::App& app);

}  // namespace vlit::cli
