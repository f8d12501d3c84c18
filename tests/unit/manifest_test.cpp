// The manifest of a batch (batch/manifest.h): lines round-trip, bad lines name the file and line,
// and the summary counts each input once with its latest record.
#include <doctest/doctest.h>

#include <filesystem>
#include <fstream>

#include "batch/manifest.h"
#include "core/input_error.h"
#include "support/gltf_builder.h"

using namespace vlit;

namespace {

ManifestRecord record(std::string key, std::string status, std::string time, std::string shard = "0/2") {
  ManifestRecord r;
  r.input = "in/" + key;
  r.key = key;
  r.output = "out/" + key;
  r.shard = std::move(shard);
  r.status = std::move(status);
  r.vertices = r.status == "baked" ? 100 : 0;
  r.seconds = 0.5;
  r.error = r.status == "failed" ? "in/" + r.key + ": not a valid glTF 2.0 file" : "";
  r.time = std::move(time);
  return r;
}

}  // namespace

TEST_CASE("a manifest line has the documented fields and reads back") {
  ManifestRecord r = record("Duck/glTF/Duck.gltf", "failed", "2026-11-23T22:31:05.120Z");
  r.error = "quote \" and\nnewline";
  const std::string line = manifest_line(r);
  CHECK(line.find('\n') == std::string::npos);  // one line whatever the error text
  CHECK(line.rfind(R"({"input":"in/Duck/glTF/Duck.gltf","key":"Duck/glTF/Duck.gltf",)", 0) == 0);
  for (const char* field : {"\"output\":", "\"shard\":\"0/2\"", "\"status\":\"failed\"", "\"vertices\":0", "\"seconds\":0.5", "\"error\":", "\"time\":"})
    CHECK(line.find(field) != std::string::npos);
  const ManifestRecord back = parse_manifest_line(line, "m.jsonl", 1);
  CHECK(back.input == r.input);
  CHECK(back.error == r.error);
  CHECK(back.status == "failed");
  CHECK(back.time == r.time);
  CHECK(manifest_line(record("a", "baked", "t")).find("\"error\":null") != std::string::npos);
}

TEST_CASE("a bad manifest line is an error naming the file and line") {
  const auto dir = vlit::test::temp_dir("manifest-bad");
  const auto path = (dir / "m.jsonl").string();
  std::ofstream(path) << manifest_line(record("a", "baked", "t")) << "\n\n{\"input\": \"x\"}\n";
  try {
    read_manifest(path);
    FAIL("expected an error");
  } catch (const InputError& e) {
    CHECK(std::string(e.what()) == path + ": line 3: missing \"status\"");
  }
  CHECK_THROWS_AS(parse_manifest_line("not json", "m", 1), InputError);
  CHECK_THROWS_AS(parse_manifest_line(R"({"input":"a","status":"baked","vertices":-3})", "m", 1), InputError);
}

TEST_CASE("the writer appends whole lines, a re-run adds to the same file") {
  const auto dir = vlit::test::temp_dir("manifest-append");
  const auto path = (dir / "m.jsonl").string();
  {
    ManifestWriter w(path);
    w.append(record("a", "baked", "1"));
  }
  {
    ManifestWriter w(path);
    w.append(record("b", "failed", "2"));
  }
  const auto records = read_manifest(path);
  REQUIRE(records.size() == 2);
  CHECK(records[0].key == "a");
  CHECK(records[1].status == "failed");
  CHECK_THROWS_AS(ManifestWriter((dir / "no/such/dir/m.jsonl").string()), InputError);
}

TEST_CASE("summary: the latest record of each input counts, double bakes and silent shards are reported") {
  const std::vector<ManifestRecord> records = {
      record("a", "baked", "2026-01-01T00:00:01.000Z", "0/3"),
      record("b", "failed", "2026-01-01T00:00:02.000Z", "1/3"),
      record("c", "interrupted", "2026-01-01T00:00:03.000Z", "1/3"),
      record("b", "baked", "2026-01-01T00:01:00.000Z", "1/3"),    // the re-run fixed b
      record("a", "skipped", "2026-01-01T00:01:01.000Z", "0/3"),  // and kept a
      record("d", "baked", "2026-01-01T00:00:04.000Z", "0/3"),
      record("d", "baked", "2026-01-01T00:00:05.000Z", "1/3"),    // two shards baked d
  };
  const ManifestSummary s = summarize_manifests(records);
  CHECK(s.records == 7);
  CHECK(s.inputs == 4);
  CHECK(s.final_status.at("baked") == 2);   // b, d
  CHECK(s.final_status.at("skipped") == 1);  // a
  CHECK(s.final_status.at("interrupted") == 1);  // c
  CHECK(s.final_status.count("failed") == 0);
  REQUIRE(s.not_done.size() == 1);
  CHECK(s.not_done[0].key == "c");
  CHECK_FALSE(s.complete());
  REQUIRE(s.baked_more_than_once.size() == 1);
  CHECK(s.baked_more_than_once[0] == std::pair<std::string, std::size_t>("d", 2));
  CHECK(s.vertices == 200);
  CHECK(s.seconds == doctest::Approx(3.5));
  const std::string text = describe(s);
  CAPTURE(text);
  CHECK(text.find("4 inputs in 7 records") != std::string::npos);
  CHECK(text.find("no line from 2/3") != std::string::npos);
  CHECK(text.find("baked 2, skipped 1, failed 0, interrupted 1") != std::string::npos);
  CHECK(text.find("baked more than once: 1 input(s): d (2 times)") != std::string::npos);
  CHECK(text.find("interrupted: in/c") != std::string::npos);
}
