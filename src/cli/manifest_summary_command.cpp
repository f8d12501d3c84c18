// vlit manifest-summary MANIFEST...: merges the manifests of a batch's shards (bake --manifest)
// into one summary on stdout. Exit 0 when every input was baked or is up to date, 1 otherwise.
#include <cstdio>

#include "batch/manifest.h"
#include "cli/commands.h"

namespace vlit::cli {

Runner add_manifest_summary_command(CLI::App& app) {
  auto files = std::make_shared<std::vector<std::string>>();
  CLI::App* cmd = app.add_subcommand(
      "manifest-summary", "Merge the manifests of a batch's shards (bake --manifest) into one summary.");
  cmd->add_option("manifests", *files, "Manifest files (JSON lines), e.g. one per shard")->required()->check(CLI::ExistingFile);
  cmd->footer("An input counts with its latest record, so a re-run that baked what an earlier one missed counts as\n"
              "baked. Exit status 0 when every input was baked or skipped as up to date, 1 when some failed or\n"
              "were interrupted. A shard with no input writes no line: compare the count with the batch.");
  return [files] {
    std::vector<ManifestRecord> records;
    for (const std::string& file : *files) {
      std::vector<ManifestRecord> more = read_manifest(file);
      records.insert(records.end(), std::make_move_iterator(more.begin()), std::make_move_iterator(more.end()));
    }
    const ManifestSummary summary = summarize_manifests(records);
    std::fputs(describe(summary).c_str(), stdout);
    return summary.complete() ? 0 : 1;
  };
}

}  // namespace vlit::cli
