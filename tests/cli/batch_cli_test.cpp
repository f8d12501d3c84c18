// Batches with `vlit bake`: outputs keep the inputs' folders, collisions fail before anything is
// written, --shard splits a batch so that every input is baked exactly once, --skip-existing
// resumes, --manifest records every input and `vlit manifest-summary` merges the manifests.
#include <doctest/doctest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>

#include "batch/manifest.h"
#include "gltf/gltf_file.h"
#include "support/gltf_builder.h"
#include "support/run_command.h"

using namespace vlit;
using vlit::test::run_command;
namespace fs = std::filesystem;

namespace {

const std::string kVlit = VLIT_BINARY;

std::string q(const std::string& s) { return "'" + s + "'"; }
std::string q(const fs::path& p) { return q(p.string()); }

// A batch of small assets in nested folders (a triangle each), with a point light, under dir/in.
struct SmallBatch {
  fs::path dir, in, lights;
  std::vector<std::string> keys;  // relative to in, '/'-separated
};

SmallBatch make_batch(const std::string& name, int count) {
  SmallBatch b;
  b.dir = vlit::test::temp_dir(name);
  b.in = b.dir / "in";
  b.lights = b.dir / "lights.json";
  std::ofstream(b.lights) << R"({"lights": [{"type": "point", "position": [0.3, 0.3, 1], "intensity": 1}]})";
  vlit::test::GltfBuilder g;
  g.add_node(g.add_mesh({0, 0, 0, 1, 0, 0, 0, 1, 0}, {}, {0, 1, 2}));
  for (int i = 0; i < count; ++i) {
    // Duck/glTF/asset.glb next to Duck/glTF-Quantized/asset.glb: the same name in two folders.
    const std::string key = "set" + std::to_string(i / 4) + (i % 2 ? "/glTF-Quantized/" : "/glTF/") + "asset" +
                            std::to_string(i % 4 / 2) + ".glb";
    fs::create_directories((b.in / key).parent_path());
    g.write((b.in / key).string());
    b.keys.push_back(key);
  }
  std::sort(b.keys.begin(), b.keys.end());
  return b;
}

std::set<std::string> files_under(const fs::path& root) {
  std::set<std::string> files;
  std::error_code ec;
  for (auto it = fs::recursive_directory_iterator(root, ec); !ec && it != fs::recursive_directory_iterator(); ++it)
    if (it->is_regular_file()) files.insert(fs::relative(it->path(), root).generic_string());
  return files;
}

std::map<std::string, int> baked_per_key(const std::vector<std::string>& manifests) {
  std::map<std::string, int> n;
  for (const auto& m : manifests)
    for (const auto& r : read_manifest(m))
      if (r.status == "baked") ++n[r.key];
  return n;
}

}  // namespace

TEST_CASE("batch: outputs keep the inputs' folders, same names in two folders do not collide") {
  const SmallBatch b = make_batch("cli-layout", 8);
  const auto out = b.dir / "out";
  const auto r = run_command(kVlit + " bake " + q(b.in) + " --lights " + q(b.lights) + " -o " + q(out));
  REQUIRE_MESSAGE(r.exit_code == 0, r.err);
  CHECK(files_under(out) == std::set<std::string>(b.keys.begin(), b.keys.end()));
  CHECK(r.err.find("8 of 8 files baked") != std::string::npos);
  // A quoted glob keeps the folders below its first wildcard.
  const auto globbed = b.dir / "globbed";
  const auto g = run_command(kVlit + " bake " + q((b.in / "set0/*/asset0.glb").string()) + " --lights " + q(b.lights) +
                             " -o " + q(globbed));
  REQUIRE_MESSAGE(g.exit_code == 0, g.err);
  CHECK(files_under(globbed) == std::set<std::string>{"glTF-Quantized/asset0.glb", "glTF/asset0.glb"});
}

TEST_CASE("batch: two inputs for one output fail before anything is written") {
  const SmallBatch b = make_batch("cli-collide", 4);
  const auto out = b.dir / "out";
  const std::string one = (b.in / "set0/glTF/asset0.glb").string(), two = (b.in / "set0/glTF-Quantized/asset0.glb").string();
  const auto r = run_command(kVlit + " bake " + q(one) + " " + q(two) + " --lights " + q(b.lights) + " -o " + q(out));
  CHECK(r.exit_code == 1);
  CAPTURE(r.err);
  CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 1);  // one error line
  CHECK(r.err.find((out / "asset0.glb").string() + " <- " + one + ", " + two) != std::string::npos);
  CHECK_FALSE(fs::exists(out));  // not even the directory
}

TEST_CASE("--shard I/N: N shards bake every input exactly once, whatever the order of the arguments") {
  const SmallBatch b = make_batch("cli-shards", 24);
  // Flat copies with unique names, passed as file arguments in a different order to each shard.
  std::vector<std::string> files;
  for (std::size_t i = 0; i < b.keys.size(); ++i) {
    const fs::path flat = b.dir / "flat" / ("tile" + std::to_string(i) + ".glb");
    fs::create_directories(flat.parent_path());
    fs::copy_file(b.in / b.keys[i], flat);
    files.push_back(flat.string());
  }
  const int kShards = 3;
  std::map<std::string, int> times;
  std::vector<std::string> manifests;
  std::vector<std::set<std::string>> by_shard;
  for (int s = 0; s < kShards; ++s) {
    const auto out = b.dir / ("out" + std::to_string(s));
    const std::string manifest = (b.dir / ("m" + std::to_string(s) + ".jsonl")).string();
    manifests.push_back(manifest);
    std::vector<std::string> args = files;
    std::rotate(args.begin(), args.begin() + 7 * s, args.end());
    if (s == 1) std::reverse(args.begin(), args.end());
    std::string inputs;
    for (const auto& a : args) {
      inputs += " ";
      inputs += q(a);
    }
    const auto r = run_command(kVlit + " bake" + inputs + " --lights " + q(b.lights) + " -o " + q(out) + " --shard " +
                               std::to_string(s) + "/" + std::to_string(kShards) + " --manifest " + q(manifest));
    REQUIRE_MESSAGE(r.exit_code == 0, r.err);
    CHECK(r.err.find("shard " + std::to_string(s) + "/3: ") != std::string::npos);
    by_shard.push_back(files_under(out));
    for (const auto& f : by_shard.back()) ++times[f];
  }
  CHECK(times.size() == files.size());
  for (const auto& item : times) {
    // Named, not bound: CAPTURE's lambda captures it (clang 14 does not capture structured bindings).
    const auto& file = item.first;
    const auto& n = item.second;
    CAPTURE(file);
    CHECK(n == 1);
  }
  for (const auto& shard : by_shard) CHECK(!shard.empty());  // 24 inputs: no shard is empty
  // The manifests say the same, and their summary finds nothing missing or doubled.
  const auto baked = baked_per_key(manifests);
  CHECK(baked.size() == files.size());
  CHECK(std::all_of(baked.begin(), baked.end(), [](const auto& k) { return k.second == 1; }));
  std::string all_manifests;
  for (const auto& m : manifests) {
    all_manifests += " ";
    all_manifests += q(m);
  }
  const auto summary = run_command(kVlit + " manifest-summary" + all_manifests);
  CAPTURE(summary.out);
  CHECK(summary.exit_code == 0);
  CHECK(summary.out.find("24 inputs in 24 records; shards 0/3 1/3 2/3\n") != std::string::npos);
  CHECK(summary.out.find("baked 24, skipped 0, failed 0, interrupted 0") != std::string::npos);

  // --shard auto in a Slurm job array task 2 of --array=1-3 is shard 1/3.
  const auto slurm = b.dir / "slurm";
  const auto r = run_command("env SLURM_ARRAY_TASK_ID=2 SLURM_ARRAY_TASK_MIN=1 SLURM_ARRAY_TASK_MAX=3 "
                             "SLURM_ARRAY_TASK_COUNT=3 " + kVlit + " bake " + q(b.dir / "flat") + " --lights " +
                             q(b.lights) + " -o " + q(slurm) + " --shard auto");
  REQUIRE_MESSAGE(r.exit_code == 0, r.err);
  CHECK(r.err.find("shard 1/3 from SLURM_ARRAY_TASK_ID=2") != std::string::npos);
  CHECK(files_under(slurm) == by_shard[1]);
  // A Kubernetes Indexed Job without the count is a readable error.
  const auto k8s = run_command("env JOB_COMPLETION_INDEX=0 " + kVlit + " bake " + q(b.dir / "flat") + " --lights " +
                               q(b.lights) + " -o " + q(b.dir / "k8s") + " --shard auto");
  CHECK(k8s.exit_code == 1);
  CHECK(k8s.err.find("set VLIT_SHARD_COUNT") != std::string::npos);
  const auto file_out = run_command(kVlit + " bake " + q(b.dir / "flat") + " -o " + q(b.dir / "one.glb") + " --shard 0/3");
  CHECK(file_out.exit_code == 2);  // usage errors (README "Exit status")
  CHECK(file_out.err.find("needs -o to be a directory, not a .glb or .gltf file name") != std::string::npos);
  CHECK_FALSE(fs::exists(b.dir / "one.glb"));
  const auto bad = run_command(kVlit + " bake " + q(b.dir / "flat") + " -o " + q(b.dir / "bad") + " --shard 3/3");
  CHECK(bad.exit_code == 2);
  CHECK(bad.err.find("--shard: shard index 3 is not below the count 3") != std::string::npos);
}

TEST_CASE("--skip-existing bakes only what is missing or older than its input, the manifest says which") {
  const SmallBatch b = make_batch("cli-resume", 8);
  const auto out = b.dir / "out";
  const std::string bake = kVlit + " bake " + q(b.in) + " --lights " + q(b.lights) + " -o " + q(out);
  const auto first = run_command(bake + " -q");
  REQUIRE_MESSAGE(first.exit_code == 0, first.err);
  // As if a shard had been killed: two outputs missing; one input changed after its bake.
  fs::remove(out / b.keys[1]);
  fs::remove(out / b.keys[6]);
  const auto kept = fs::last_write_time(out / b.keys[0]);
  fs::last_write_time(b.in / b.keys[3], fs::last_write_time(out / b.keys[3]) + std::chrono::seconds(2));
  const std::string manifest = (b.dir / "resume.jsonl").string();
  const auto again = run_command(bake + " --skip-existing --manifest " + q(manifest));
  REQUIRE_MESSAGE(again.exit_code == 0, again.err);
  CHECK(again.err.find("3 of 8 files baked into " + out.string() + "; 5 up to date (skipped); 0 failed") != std::string::npos);
  std::map<std::string, std::string> status;
  for (const auto& r : read_manifest(manifest)) status[r.key] = r.status;
  CHECK(status.size() == 8);
  for (std::size_t i = 0; i < b.keys.size(); ++i) {
    CAPTURE(b.keys[i]);
    CHECK(status[b.keys[i]] == (i == 1 || i == 3 || i == 6 ? "baked" : "skipped"));
  }
  CHECK(fs::last_write_time(out / b.keys[0]) == kept);  // not rewritten
  CHECK(files_under(out).size() == 8);
  // A newer LIGHTS.json makes every output stale.
  fs::last_write_time(b.lights, fs::file_time_type::clock::now() + std::chrono::seconds(5));
  const auto relit = run_command(bake + " --skip-existing");
  CHECK(relit.err.find("8 of 8 files baked") != std::string::npos);
}

TEST_CASE("--manifest records failures with their error, manifest-summary exits 1 and lists them") {
  const SmallBatch b = make_batch("cli-manifest", 4);
  std::ofstream(b.in / "broken.gltf") << "{ not json";
  const std::string manifest = (b.dir / "m.jsonl").string();
  const auto r = run_command(kVlit + " bake " + q(b.in) + " --lights " + q(b.lights) + " -o " + q(b.dir / "out") +
                             " --manifest " + q(manifest) + " -q");
  CHECK(r.exit_code == 1);
  const auto records = read_manifest(manifest);
  REQUIRE(records.size() == 5);
  std::size_t failed = 0;
  for (const auto& rec : records) {
    CAPTURE(rec.input);
    CHECK(rec.input == (b.in / rec.key).string());
    if (rec.status == "failed") {
      ++failed;
      CHECK(rec.key == "broken.gltf");
      CHECK(rec.error.find("broken.gltf: not a valid glTF 2.0 file") != std::string::npos);
      CHECK(rec.vertices == 0);
    } else {
      CHECK(rec.status == "baked");
      CHECK(rec.vertices == 3);
      CHECK(rec.seconds > 0);
      CHECK(rec.output == (b.dir / "out" / rec.key).string());
    }
    CHECK(rec.time.size() == 24);
  }
  CHECK(failed == 1);
  const auto s = run_command(kVlit + " manifest-summary " + q(manifest));
  CHECK(s.exit_code == 1);
  CHECK(s.out.find("baked 4, skipped 0, failed 1") != std::string::npos);
  CHECK(s.out.find("failed: " + (b.in / "broken.gltf").string()) != std::string::npos);
  const auto missing = run_command(kVlit + " manifest-summary " + q(b.dir / "none.jsonl"));
  CHECK(missing.exit_code != 0);
}

TEST_CASE("the batch progress line fits a narrow terminal: the path is shortened, not wrapped") {
  if (run_command("command -v script").exit_code != 0) {
    MESSAGE("skipped: `script` (util-linux) is not installed");
    return;
  }
  const SmallBatch b = make_batch("cli-narrow", 2);
  const fs::path deep = b.in / "a-rather-long-folder-name/and-another-long-one/model-with-a-long-name.glb";
  fs::create_directories(deep.parent_path());
  fs::copy_file(b.in / b.keys[0], deep);
  // `script` gives vlit a pseudo-terminal of no size; vlit then reads COLUMNS.
  std::string command = "COLUMNS=50 script -qec ";  // appended: GCC 12 warns falsely (-Wrestrict) on "..." + std::string&&
  command += q(kVlit + " bake " + q(b.in) + " --lights " + q(b.lights) + " -o " + q(b.dir / "out"));
  command += " /dev/null";
  const auto r = run_command(command);
  REQUIRE_MESSAGE(r.exit_code == 0, r.out);
  std::size_t lines = 0;
  std::string segment;
  for (const char c : r.out + "\n") {
    if (c != '\r' && c != '\n') {
      segment += c;
      continue;
    }
    if (segment.find("baking ") == 0) {
      ++lines;
      CAPTURE(segment);
      CHECK(segment.size() <= 49);
    }
    segment.clear();
  }
  CHECK(lines >= 3);  // one line per file at least
  CHECK(r.out.find("...") != std::string::npos);  // the long path was shortened
}

TEST_CASE("a folder of mesh files is a batch, x.obj next to x.glb is a collision") {
  const SmallBatch b = make_batch("cli-mesh-folder", 1);
  const fs::path meshes = b.dir / "meshes";
  fs::create_directories(meshes / "sub");
  std::ofstream(meshes / "tri.obj") << "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
  std::ofstream(meshes / "sub" / "quad.off") << "OFF\n4 1 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n4 0 1 2 3\n";
  const auto out = b.dir / "out";
  const auto r = run_command(kVlit + " bake " + q(meshes) + " --lights " + q(b.lights) + " -o " + q(out));
  REQUIRE_MESSAGE(r.exit_code == 0, r.err);
  CHECK(files_under(out) == std::set<std::string>{"sub/quad.glb", "tri.glb"});
  CHECK(load_gltf_file((out / "sub/quad.glb").string()).model.meshes.size() == 1);
  fs::copy_file(b.in / b.keys[0], meshes / "tri.glb");
  const auto clash = run_command(kVlit + " bake " + q(meshes) + " --lights " + q(b.lights) + " -o " + q(b.dir / "out2"));
  CHECK(clash.exit_code == 1);
  CHECK(clash.err.find((b.dir / "out2/tri.glb").string() + " <- " + (meshes / "tri.glb").string() + ", " +
                       (meshes / "tri.obj").string()) != std::string::npos);
  CHECK_FALSE(fs::exists(b.dir / "out2"));
}

TEST_CASE("batch: a ** glob matches at any depth (zero or more folders), * stays within one folder") {
  const SmallBatch b = make_batch("cli-globstar", 8);  // in/setS/glTF[-Quantized]/assetK.glb
  // One more at the root of the pattern (** matches zero folders) and one in a hidden folder.
  fs::copy_file(b.in / b.keys[0], b.in / "top.glb");
  fs::create_directories(b.in / ".cache");
  fs::copy_file(b.in / b.keys[0], b.in / ".cache" / "hidden.glb");
  const auto out = b.dir / "out";
  const auto r = run_command(kVlit + " bake " + q((b.in / "**/*.glb").string()) + " --lights " + q(b.lights) + " -q -o " + q(out));
  REQUIRE_MESSAGE(r.exit_code == 0, r.err);
  std::set<std::string> expected(b.keys.begin(), b.keys.end());
  expected.insert("top.glb");
  CHECK(files_under(out) == expected);
  // ** in the middle: every asset0 below set1, whatever the folders between.
  const auto middle = b.dir / "middle";
  const auto m = run_command(kVlit + " bake " + q((b.in / "set1/**/asset0.glb").string()) + " --lights " + q(b.lights) +
                             " -q -o " + q(middle));
  REQUIRE_MESSAGE(m.exit_code == 0, m.err);
  CHECK(files_under(middle) == std::set<std::string>{"glTF-Quantized/asset0.glb", "glTF/asset0.glb"});
  // Without **, * does not cross a folder: nothing matches at the top level but top.glb.
  const auto flat = b.dir / "flat";
  const auto f = run_command(kVlit + " bake " + q((b.in / "*.glb").string()) + " --lights " + q(b.lights) + " -q -o " + q(flat));
  REQUIRE_MESSAGE(f.exit_code == 0, f.err);
  CHECK(files_under(flat) == std::set<std::string>{"top.glb"});
  const auto none = run_command(kVlit + " bake " + q((b.in / "**/*.obj").string()) + " --lights " + q(b.lights) + " -o " +
                                q(b.dir / "none"));
  CHECK(none.exit_code == 1);
  CHECK(none.err.find("pattern matches no file") != std::string::npos);
  fs::remove_all(b.dir);
}
