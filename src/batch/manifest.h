// The manifest of a batch bake (--manifest FILE): one JSON object per line and per input, appended
// as soon as that input is done, so a shard that is killed keeps the lines of what it finished and
// a re-run appends to the same file. `vlit manifest-summary` merges the manifests of all shards.
//
//   {"input":"in/Duck/glTF/Duck.gltf","key":"Duck/glTF/Duck.gltf","output":"out/Duck/glTF/Duck.gltf",
//    "shard":"2/4","status":"baked","vertices":2399,"seconds":0.031,"error":null,
//    "time":"2026-11-23T22:31:05.120Z"}
//
// status: "baked"; "skipped" (--skip-existing found a current output); "failed" (error says why);
// "interrupted" (Ctrl-C or SIGTERM stopped it; no output was written). time: UTC, when the line
// was written. vertices: lit vertices of a baked input, else 0. seconds: wall time for this input.
#pragma once

#include <cstddef>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace vlit {

struct ManifestRecord {
  std::string input, key, output, shard, status;
  std::size_t vertices = 0;
  double seconds = 0;
  std::string error;  // empty: null
  std::string time;   // ISO 8601 UTC with milliseconds; sorts as text
};

// One line of JSON, without the newline.
std::string manifest_line(const ManifestRecord& record);
// Parses one line; throws InputError(file, problem, "line N") when it is not a manifest record.
ManifestRecord parse_manifest_line(const std::string& line, const std::string& file, std::size_t line_number);
// Every record of a manifest file, in order; blank lines are ignored.
std::vector<ManifestRecord> read_manifest(const std::string& path);

// The current UTC time as "2026-11-23T22:31:05.120Z".
std::string utc_timestamp();

// Appends records to a manifest file, one write per line (O_APPEND), so lines never interleave
// and a killed process leaves whole lines.
class ManifestWriter {
 public:
  // Throws InputError(path, ...) when the file cannot be opened for appending.
  explicit ManifestWriter(const std::string& path);
  ~ManifestWriter();
  ManifestWriter(const ManifestWriter&) = delete;
  ManifestWriter& operator=(const ManifestWriter&) = delete;
  void append(const ManifestRecord& record);  // throws InputError on a failed write

 private:
  std::string path_;
  int fd_ = -1;
};

// The merged view of one or more manifests. An input (by key, or by input path if it has no key)
// takes the status of its latest record (by time; a tie goes to the record read last), so a re-run
// that baked what an earlier run missed counts as baked.
struct ManifestSummary {
  std::size_t records = 0;
  std::size_t inputs = 0;
  std::map<std::string, std::size_t> final_status;     // status -> inputs
  std::vector<ManifestRecord> not_done;                // latest record of inputs neither baked nor skipped
  std::vector<std::pair<std::string, std::size_t>> baked_more_than_once;  // key, times baked
  std::size_t vertices = 0;    // of the latest record of each baked input
  double seconds = 0;          // sum over all records
  std::optional<ManifestRecord> slowest;  // the record with the most seconds
  std::map<std::string, std::size_t> shards;  // "I/N" -> records
  bool complete() const { return not_done.empty(); }
};

ManifestSummary summarize_manifests(const std::vector<ManifestRecord>& records);
// Human-readable, several lines, each ending in a newline.
std::string describe(const ManifestSummary& summary);

}  // namespace vlit
