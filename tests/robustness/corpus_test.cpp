// The malformed-glTF corpus (assets/bad-gltf, vendored: 283 inputs from the Khronos
// glTF-Validator, tinygltf and assimp test suites) through the real executable:
//   vlit bake FILE -o OUT    (bounded by timeout 60)
// Contract (docs/robustness.md): exit 0 and a complete output that loads back, or exit 1 with
// exactly one stderr line naming the input; never a signal, a crash or a timeout; no output and
// no temporary file left behind on failure. Validator inputs with no errors (controls) must bake,
// except the few listed in kControlExceptions with the reason they cannot.
#include <doctest/doctest.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>

#include "gltf/gltf_file.h"
#include "gltf/gltf_scene.h"
#include "support/gltf_builder.h"
#include "support/run_command.h"

namespace fs = std::filesystem;
using vlit::test::run_command;

namespace {

const std::string kVlit = VLIT_BINARY;
const fs::path kCorpus = fs::path(VLIT_ASSETS_DIR) / "bad-gltf";

// Controls (validator: errors=0) that vlit refuses, and why. Each is a limit of tinygltf 2.7
// (Debian's libtinygltf-dev, which refuses them before vlit sees the model) or a deliberate
// vlit policy. Keep in step with docs/robustness.md.
const std::map<std::string, std::string> kControlExceptions = {
    {"glTF-Validator/base/data/accessor/unknown_type.gltf",
     "tinygltf 2.7 refuses an accessor type outside the spec's list (\"NotaVEC3\")"},
    {"glTF-Validator/base/data/buffer/custom_property.gltf",
     "tinygltf 2.7 refuses a .gltf buffer without a uri"},
    {"glTF-Validator/base/data/root/named_objects.gltf", "tinygltf 2.7 refuses a .gltf buffer without a uri"},
    {"glTF-Validator/base/data/root/unused_objects.gltf", "tinygltf 2.7 refuses a .gltf buffer without a uri"},
    {"glTF-Validator/base/data/buffer/data_uri.glb",
     "tinygltf 2.7 decodes only base64 data: URIs (this one is data:application/gltf-buffer,0)"},
    {"glTF-Validator/base/data/buffer/valid_placeholder.glb",
     "tinygltf 2.7 requires the GLB BIN chunk to hold the whole first buffer (placeholder buffer of 1024 bytes, chunk of 4)"},
    {"glTF-Validator/base/data/buffer/non_relative_uri.gltf",
     "vlit never fetches over the network (buffer uri http://example.com/buffer.bin)"},
    {"glTF-Validator/base/data/mesh/valid.gltf",
     "tinygltf 2.7 refuses primitive accessors without a bufferView (\"accessor[0] invalid bufferView\")"},
};

// MANIFEST.tsv: file -> expected outcome.
std::map<std::string, std::string> read_manifest() {
  std::map<std::string, std::string> expected;
  std::ifstream in(kCorpus / "MANIFEST.tsv");
  std::string line;
  std::getline(in, line);  // header
  while (std::getline(in, line)) {
    std::istringstream fields(line);
    std::string file, source, path, outcome;
    std::getline(fields, file, '\t');
    std::getline(fields, source, '\t');
    std::getline(fields, path, '\t');
    std::getline(fields, outcome, '\t');
    if (!file.empty()) expected[file] = outcome;
  }
  return expected;
}

bool is_control(const std::string& outcome) { return outcome.rfind("validator: errors=0 ", 0) == 0; }

std::string q(const std::string& s) { return "'" + s + "'"; }

std::vector<std::string> lines_of(const std::string& s) {
  std::vector<std::string> lines;
  std::istringstream in(s);
  std::string line;
  while (std::getline(in, line)) lines.push_back(line);
  return lines;
}

// A short name for the refusal reason, for the tally printed at the end (docs/robustness.md).
std::string reason_of(const std::string& error) {
  if (error.find("not a valid glTF 2.0 file") != std::string::npos) return "tinygltf refuses the file";
  if (error.find("reached twice") != std::string::npos) return "node cycle or node with two parents";
  if (error.find("does not exist") != std::string::npos) return "reference to a missing node or mesh";
  if (error.find("not below the vertex count") != std::string::npos) return "index out of range";
  if (error.find("requires ") != std::string::npos) return "required extension vlit cannot decode";
  if (error.find("extensions.") != std::string::npos) return "malformed light or emission extension";
  if (error.find("accessor") != std::string::npos || error.find("bufferView") != std::string::npos)
    return "accessor or bufferView out of bounds / malformed";
  return "other: " + error;
}

std::vector<std::string> corpus_inputs() {
  std::vector<std::string> inputs;
  for (const auto& entry : fs::recursive_directory_iterator(kCorpus)) {
    if (!entry.is_regular_file()) continue;
    const std::string ext = entry.path().extension().string();
    if (ext == ".gltf" || ext == ".glb") inputs.push_back(fs::relative(entry.path(), kCorpus).string());
  }
  std::sort(inputs.begin(), inputs.end());
  return inputs;
}

}  // namespace

TEST_CASE("malformed glTF corpus: every input bakes or is refused in one line, never a crash") {
  REQUIRE_MESSAGE(fs::is_regular_file(kCorpus / "MANIFEST.tsv"), "missing test data: the corpus " << kCorpus.string());
  const auto manifest = read_manifest();
  const auto inputs = corpus_inputs();
  CHECK(inputs.size() == 283);
  CHECK(manifest.size() == 283);

  const fs::path work = vlit::test::temp_dir("robust-corpus");
  std::size_t baked = 0, refused = 0, controls = 0, controls_refused = 0;
  std::map<std::string, std::size_t> reasons;
  const auto start = std::chrono::steady_clock::now();
  std::size_t n = 0;
  for (const std::string& relative : inputs) {
    CAPTURE(relative);
    const std::string input = (kCorpus / relative).string();
    const fs::path out_dir = work / std::to_string(n++);
    fs::create_directories(out_dir);
    const fs::path out = out_dir / "out.glb";
    const auto r = run_command("timeout 60 " + q(kVlit) + " bake " + q(input) + " -o " + q(out.string()));
    const auto err_lines = lines_of(r.err);

    // Never a signal (128+N), a timeout (124) or a sanitizer abort: only 0 or 1.
    REQUIRE_MESSAGE((r.exit_code == 0 || r.exit_code == 1), "exit " << r.exit_code << "\n" << r.err);

    std::vector<std::string> left;
    for (const auto& e : fs::directory_iterator(out_dir)) left.push_back(e.path().filename().string());
    if (r.exit_code == 0) {
      ++baked;
      CHECK_MESSAGE(left == std::vector<std::string>{"out.glb"}, "files left: " << left.size());
      try {
        const vlit::GltfFile back = vlit::load_gltf_file(out.string());
        std::vector<std::string> warnings;
        vlit::build_scene(back, warnings);
      } catch (const std::exception& e) {
        FAIL_CHECK("the baked output does not load back: " << std::string(e.what()));
      }
    } else {
      ++refused;
      CHECK_MESSAGE(left.empty(), "a failed bake left " << left.size() << " file(s) in the output directory");
      REQUIRE_MESSAGE(err_lines.size() == 1, "stderr:\n" << r.err);
      CHECK_MESSAGE(err_lines[0].find(input) != std::string::npos, "error does not name the input: " << err_lines[0]);
      ++reasons[reason_of(err_lines[0])];
    }

    const auto it = manifest.find(relative);
    CHECK_MESSAGE(it != manifest.end(), "not listed in MANIFEST.tsv");
    if (it != manifest.end() && is_control(it->second)) {
      ++controls;
      const auto exception = kControlExceptions.find(relative);
      if (r.exit_code != 0) ++controls_refused;
      if (exception == kControlExceptions.end())
        CHECK_MESSAGE(r.exit_code == 0, "a control (validator: no errors) was refused: " << r.err);
      else
        CHECK_MESSAGE(r.exit_code == 1, "listed as an exception (" << exception->second << ") but baked; update the list");
    }
  }
  fs::remove_all(work);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  CHECK(baked + refused == 283);  // every input of MANIFEST.tsv was run through the executable
  CHECK(controls == 99);
  CHECK(controls_refused == kControlExceptions.size());
  std::ostringstream tally;
  tally << inputs.size() << " inputs in " << seconds << " s: " << baked << " baked, " << refused << " refused ("
        << controls << " controls, " << controls_refused << " of them refused as listed)";
  for (const auto& [reason, count] : reasons) tally << "\n  " << count << "  " << reason;
  MESSAGE(tally.str());
}

TEST_CASE("malformed light extensions: refused in one line naming the file, no output") {
  // Hand-written .gltf texts (no buffers needed): each has one bad value in a light extension.
  // (An extension value that is not a JSON object never reaches vlit: tinygltf drops it.)
  const std::string head = R"({"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}], )";
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"area-lights-not-array", R"("extensions": {"EXT_lights_area": {"lights": {"type": "rect"}}}, "nodes": [{}]})"},
      {"area-size-string", R"("extensions": {"EXT_lights_area": {"lights": [{"type": "rect", "size": "big"}]}}, "nodes": [{}]})"},
      {"area-color-short", R"("extensions": {"EXT_lights_area": {"lights": [{"type": "disk", "color": [1, 1]}]}}, "nodes": [{}]})"},
      {"area-huge-index", R"("extensions": {"EXT_lights_area": {"lights": []}}, "nodes": [{"extensions": {"EXT_lights_area": {"light": 1e300}}}]})"},
      {"area-negative-index", R"("extensions": {"EXT_lights_area": {"lights": [{"type": "rect"}]}}, "nodes": [{"extensions": {"EXT_lights_area": {"light": -1}}}]})"},
      {"area-ref-no-root", R"("nodes": [{"extensions": {"EXT_lights_area": {"light": 0}}}]})"},
      {"linear-from-nan-like", R"("extensions": {"VLIT_lights_linear": {"lights": [{"from": [0, 0, 1e999], "to": [1, 0, 0]}]}}, "nodes": [{}]})"},
      {"linear-intensity-negative", R"("extensions": {"VLIT_lights_linear": {"lights": [{"from": [0, 0, 0], "to": [1, 0, 0], "intensity": -1}]}}, "nodes": [{}]})"},
      {"linear-ref-fraction", R"("extensions": {"VLIT_lights_linear": {"lights": [{"from": [0, 0, 0], "to": [1, 0, 0]}]}}, "nodes": [{"extensions": {"VLIT_lights_linear": {"light": 0.5}}}]})"},
      {"emissive-strength-negative", R"("materials": [{"extensions": {"KHR_materials_emissive_strength": {"emissiveStrength": -2}}}], "nodes": [{}]})"},
  };
  const fs::path work = vlit::test::temp_dir("robust-light-ext");
  for (const auto& item : cases) {
    // Named, not bound: CAPTURE's lambda captures it (clang 14 does not capture structured bindings).
    const auto& name = item.first;
    const auto& body = item.second;
    CAPTURE(name);
    const fs::path input = work / (name + ".gltf");
    std::ofstream(input) << head << body;
    const fs::path out = work / (name + "-out.glb");
    const auto r = run_command(q(kVlit) + " bake " + q(input.string()) + " -o " + q(out.string()));
    CHECK_MESSAGE(r.exit_code == 1, r.err);
    const auto err_lines = lines_of(r.err);
    CHECK_MESSAGE(err_lines.size() == 1, "stderr:\n" << r.err);
    if (!err_lines.empty()) CHECK_MESSAGE(err_lines[0].find(input.string()) != std::string::npos, err_lines[0]);
    CHECK_FALSE(fs::exists(out));
  }
  fs::remove_all(work);
}
