// SIGINT during a batch bake (`vlit bake DIR -o OUTDIR`): the file being lit is abandoned, every
// finished file is complete, no partial or temporary file is left, and the exit status is 130.
#include <doctest/doctest.h>

#include <chrono>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <map>
#include <random>
#include <set>
#include <thread>

#include <fcntl.h>
#include <sys/wait.h>
#include <unistd.h>

#include "batch/manifest.h"
#include "batch/shard.h"
#include "gltf/gltf_file.h"
#include "support/gltf_builder.h"

namespace fs = std::filesystem;

namespace {

// A grid of (n+1)^2 vertices, 2 n^2 triangles, in the z = 0 plane.
void add_grid(vlit::test::GltfBuilder& b, int n) {
  std::vector<float> positions;
  std::vector<std::uint32_t> indices;
  for (int y = 0; y <= n; ++y)
    for (int x = 0; x <= n; ++x) positions.insert(positions.end(), {float(x) / n, float(y) / n, 0});
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x) {
      const std::uint32_t i = y * (n + 1) + x;
      indices.insert(indices.end(), {i, i + 1, i + n + 2, i, i + n + 2, i + n + 1});
    }
  b.add_node(b.add_mesh(positions, {}, indices));
}

}  // namespace

TEST_CASE("SIGINT during a batch bake: finished files complete, no partial file, exit 130") {
  const fs::path dir = vlit::test::temp_dir("robust-sigint");
  const fs::path in = dir / "in", out = dir / "out";
  fs::create_directories(in);
  vlit::test::GltfBuilder b;
  add_grid(b, 400);  // 160 801 vertices per file
  const int kFiles = 24;
  for (int i = 0; i < kFiles; ++i) b.write((in / ("grid" + std::to_string(100 + i) + ".glb")).string());
  {
    // Many linear lights make each file take a noticeable time.
    std::ofstream lights(dir / "lights.json");
    lights << R"({"lights": [)";
    for (int i = 0; i < 24; ++i)
      lights << (i ? "," : "") << R"({"type": "linear", "from": [)" << i * 0.05 << R"(, 0, 1], "to": [)" << i * 0.05
             << R"(, 1, 1.5], "intensity": 1})";
    lights << "]}";
  }

  const std::string vlit = VLIT_BINARY;
  const std::string lights = (dir / "lights.json").string(), err_path = (dir / "stderr.txt").string();
  const pid_t pid = ::fork();
  REQUIRE(pid >= 0);
  if (pid == 0) {
    const int fd = ::open(err_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    ::dup2(fd, 2);
    ::execl(vlit.c_str(), vlit.c_str(), "bake", in.c_str(), "-o", out.c_str(), "--lights", lights.c_str(), "--quiet",
            static_cast<char*>(nullptr));
    ::_exit(127);
  }
  // Interrupt as soon as the first output exists.
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(300);
  auto count_outputs = [&] {
    std::size_t n = 0;
    std::error_code ec;
    for (const auto& e : fs::directory_iterator(out, ec))
      if (e.path().extension() == ".glb") ++n;
    return n;
  };
  while (count_outputs() == 0 && std::chrono::steady_clock::now() < deadline)
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  REQUIRE_MESSAGE(count_outputs() > 0, "no output appeared within the deadline");
  ::kill(pid, SIGINT);
  int status = 0;
  REQUIRE(::waitpid(pid, &status, 0) == pid);
  std::ifstream err_file(err_path);
  const std::string err((std::istreambuf_iterator<char>(err_file)), std::istreambuf_iterator<char>());
  CAPTURE(err);
  REQUIRE(WIFEXITED(status));
  CHECK(WEXITSTATUS(status) == 130);
  CHECK(err.find("interrupted") != std::string::npos);

  std::size_t complete = 0;
  for (const auto& e : fs::directory_iterator(out)) {
    const std::string name = e.path().filename().string();
    CAPTURE(name);
    CHECK_MESSAGE(name.find(".vlit-tmp") == std::string::npos, "temporary file left behind");
    if (e.path().extension() != ".glb") continue;
    const vlit::GltfFile baked = vlit::load_gltf_file(e.path().string());  // throws if truncated
    for (const auto& mesh : baked.model.meshes)
      for (const auto& prim : mesh.primitives) {
        REQUIRE(prim.attributes.count("COLOR_0"));
        CHECK(baked.model.accessors[prim.attributes.at("COLOR_0")].count ==
              baked.model.accessors[prim.attributes.at("POSITION")].count);
      }
    ++complete;
  }
  CHECK(complete >= 1);
  CHECK_MESSAGE(complete < kFiles, "every file finished before SIGINT arrived: the test proved nothing");
  MESSAGE(complete << " of " << kFiles << " files complete when SIGINT arrived");
  fs::remove_all(dir);
}

namespace {

// Starts `vlit ARGS...` with stderr into err_path; returns its pid.
pid_t spawn_vlit(const std::vector<std::string>& args, const std::string& err_path) {
  const pid_t pid = ::fork();
  if (pid == 0) {
    const int fd = ::open(err_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    ::dup2(fd, 2);
    std::vector<char*> argv;
    const std::string vlit = VLIT_BINARY;
    argv.push_back(const_cast<char*>(vlit.c_str()));
    for (const auto& a : args) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    ::execv(vlit.c_str(), argv.data());
    ::_exit(127);
  }
  return pid;
}

// Waits for `pid` at most `seconds`; kills it (SIGKILL) if it is still running then. Returns
// whether it ended by itself, with its wait status in `status`.
bool wait_at_most(pid_t pid, double seconds, int& status) {
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
  while (std::chrono::steady_clock::now() < deadline) {
    if (::waitpid(pid, &status, WNOHANG) == pid) return true;
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
  ::kill(pid, SIGKILL);
  ::waitpid(pid, &status, 0);
  return false;
}

std::string read_text(const fs::path& p) {
  std::ifstream in(p);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// A bake with shadows on that takes tens of seconds even with the fastest visibility we have had
// (silhouettes: > 20 s): a 200 x 200 grid under a soup of 4000 small random triangles, lit by
// 8 area lights. Returns the arguments of `vlit bake` writing `out`.
std::vector<std::string> slow_shadowed_bake(const fs::path& dir, const fs::path& out) {
  vlit::test::GltfBuilder b;
  add_grid(b, 200);
  std::vector<float> soup;
  std::vector<std::uint32_t> indices;
  std::mt19937 rng(5);
  std::uniform_real_distribution<float> unit(0, 1);
  for (std::uint32_t t = 0; t < 4000; ++t) {
    const float cx = unit(rng), cy = unit(rng), cz = 0.3f + 0.4f * unit(rng);
    for (int v = 0; v < 3; ++v)
      soup.insert(soup.end(), {cx + 0.03f * (unit(rng) - 0.5f), cy + 0.03f * (unit(rng) - 0.5f), cz + 0.01f * (unit(rng) - 0.5f)});
    indices.insert(indices.end(), {3 * t, 3 * t + 1, 3 * t + 2});
  }
  b.add_node(b.add_mesh(soup, {}, indices));
  const fs::path scene = dir / "soup.glb", lights = dir / "panels.json";
  b.write(scene.string());
  std::ofstream json(lights);
  json << R"({"lights": [)";
  for (int j = 0; j < 8; ++j) {
    const double x = (j % 4) / 4.0, y = (j / 4) / 4.0;
    json << (j ? "," : "") << R"({"type": "area", "intensity": 1, "polygon": [)" << "[" << x << "," << y + 0.2 << ",1],["
         << x + 0.2 << "," << y + 0.2 << ",1],[" << x + 0.2 << "," << y << ",1],[" << x << "," << y << ",1]]}";
  }
  json << "]}";
  return {"bake", scene.string(), "--lights", lights.string(), "--shadows", "on", "-o", out.string(), "-q"};
}

}  // namespace

TEST_CASE("Ctrl-C during a bake with shadows on: stopped within 2 s, exit 130, no output") {
  const fs::path dir = vlit::test::temp_dir("robust-sigint-shadows");
  const fs::path out = dir / "out.glb", err = dir / "stderr.txt";
  const pid_t pid = spawn_vlit(slow_shadowed_bake(dir, out), err.string());
  REQUIRE(pid > 0);
  std::this_thread::sleep_for(std::chrono::milliseconds(1500));  // well into the shadowed lighting
  int status = 0;
  REQUIRE_MESSAGE(::waitpid(pid, &status, WNOHANG) == 0, "the bake ended before the signal: the test proved nothing");
  const auto sent = std::chrono::steady_clock::now();
  ::kill(pid, SIGINT);
  REQUIRE_MESSAGE(wait_at_most(pid, 10, status), "still running 10 s after SIGINT (killed)");
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - sent).count();
  const std::string text = read_text(err);
  CAPTURE(text);
  MESSAGE("stopped " << seconds << " s after SIGINT");
  CHECK(seconds < 2.0);
  REQUIRE(WIFEXITED(status));
  CHECK(WEXITSTATUS(status) == 130);
  CHECK(text.find("interrupted; no output written") != std::string::npos);
  CHECK_FALSE(fs::exists(out));
  for (const auto& e : fs::directory_iterator(dir)) CHECK(e.path().filename().string().find(".vlit-tmp") == std::string::npos);
  CHECK(std::distance(fs::directory_iterator(dir), {}) == 3);  // the scene, its lights, stderr
  fs::remove_all(dir);
}

TEST_CASE("a second signal ends a bake at once, with a message, exit 130, no output") {
  const fs::path dir = vlit::test::temp_dir("robust-sigint-twice");
  const fs::path out = dir / "out.glb", err = dir / "stderr.txt";
  const pid_t pid = spawn_vlit(slow_shadowed_bake(dir, out), err.string());
  REQUIRE(pid > 0);
  std::this_thread::sleep_for(std::chrono::milliseconds(700));
  int status = 0;
  REQUIRE(::waitpid(pid, &status, WNOHANG) == 0);
  // Two different signals, so that the kernel cannot merge them into one.
  ::kill(pid, SIGINT);
  ::kill(pid, SIGTERM);
  REQUIRE_MESSAGE(wait_at_most(pid, 10, status), "still running 10 s after two signals (killed)");
  const std::string text = read_text(err);
  CAPTURE(text);
  REQUIRE(WIFEXITED(status));
  CHECK(WEXITSTATUS(status) == 130);
  CHECK(text.find("interrupted again; stopped at once") != std::string::npos);
  CHECK_FALSE(fs::exists(out));
  fs::remove_all(dir);
}

TEST_CASE("a shard killed with SIGKILL resumes with --skip-existing: only what is missing is baked") {
  const fs::path dir = vlit::test::temp_dir("robust-resume");
  const fs::path in = dir / "in", out = dir / "out";
  fs::create_directories(in);
  vlit::test::GltfBuilder b;
  add_grid(b, 300);  // 90 601 vertices per file
  const vlit::Shard shard{1, 2};
  std::set<std::string> mine, others;  // keys of shard 1/2 and of shard 0/2
  for (int i = 0; i < 12; ++i) {
    const std::string key = "grid" + std::to_string(100 + i) + ".glb";
    b.write((in / key).string());
    (vlit::shard_of_key(key, shard.count) == shard.index ? mine : others).insert(key);
  }
  REQUIRE(mine.size() >= 3);
  REQUIRE(!others.empty());
  {
    std::ofstream lights(dir / "lights.json");
    lights << R"({"lights": [)";
    for (int i = 0; i < 24; ++i)
      lights << (i ? "," : "") << R"({"type": "linear", "from": [)" << i * 0.05 << R"(, 0, 1], "to": [)" << i * 0.05
             << R"(, 1, 1.5], "intensity": 1})";
    lights << "]}";
  }
  const std::string first_manifest = (dir / "run1.jsonl").string(), second_manifest = (dir / "run2.jsonl").string();
  auto args = [&](const std::string& manifest) {
    return std::vector<std::string>{"bake", in.string(), "-o", out.string(), "--lights", (dir / "lights.json").string(),
                                    "--shard", shard.text(), "--skip-existing", "--manifest", manifest};
  };
  const pid_t pid = spawn_vlit(args(first_manifest), (dir / "run1.txt").string());
  REQUIRE(pid > 0);
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(300);
  auto outputs = [&] {
    std::set<std::string> names;
    std::error_code ec;
    for (const auto& e : fs::directory_iterator(out, ec))
      if (e.path().extension() == ".glb") names.insert(e.path().filename().string());
    return names;
  };
  while (outputs().empty() && std::chrono::steady_clock::now() < deadline)
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  ::kill(pid, SIGKILL);  // no handler runs: as a preemption without grace
  int status = 0;
  REQUIRE(::waitpid(pid, &status, 0) == pid);
  const std::set<std::string> before = outputs();
  REQUIRE_MESSAGE(!before.empty(), "no output appeared within the deadline");
  REQUIRE_MESSAGE(before.size() < mine.size(), "the shard finished before SIGKILL: the test proved nothing");
  // A temporary abandoned by the kill, for an output of this shard, and one of the other shard's.
  const std::string missing = *std::find_if(mine.begin(), mine.end(), [&](const auto& k) { return !before.count(k); });
  std::ofstream(out / ("." + missing + ".vlit-tmp-Ab12Cd")) << "half a file";
  std::ofstream(out / ("." + *others.begin() + ".vlit-tmp-Ef34Gh")) << "another shard's";

  const pid_t again = spawn_vlit(args(second_manifest), (dir / "run2.txt").string());
  REQUIRE(::waitpid(again, &status, 0) == again);
  const std::string text = read_text(dir / "run2.txt");
  CAPTURE(text);
  REQUIRE(WIFEXITED(status));
  CHECK(WEXITSTATUS(status) == 0);
  // At least the planted one (the kill may have left a real one too).
  CHECK(text.find(" temporary file(s) left by a killed run") != std::string::npos);
  CHECK(outputs() == mine);  // the whole shard, nothing of the other
  CHECK_FALSE(fs::exists(out / ("." + missing + ".vlit-tmp-Ab12Cd")));
  CHECK(fs::exists(out / ("." + *others.begin() + ".vlit-tmp-Ef34Gh")));  // not this shard's to remove
  // The resumed run kept what the killed one finished and baked only the rest.
  std::map<std::string, std::string> status_of;
  for (const auto& r : vlit::read_manifest(second_manifest)) status_of[r.key] = r.status;
  CHECK(status_of.size() == mine.size());
  for (const auto& key : mine) {
    CAPTURE(key);
    CHECK(status_of[key] == (before.count(key) ? "skipped" : "baked"));
  }
  // No input baked twice over the two runs (the killed run may have renamed its last output
  // into place without living to write its manifest line: that one is "skipped" only).
  std::map<std::string, int> baked;
  for (const auto& m : {first_manifest, second_manifest})
    for (const auto& r : vlit::read_manifest(m))
      if (r.status == "baked") ++baked[r.key];
  CHECK(baked.size() >= mine.size() - 1);
  for (const auto& item : baked) {
    // Named, not bound: CAPTURE's lambda captures it (clang 14 does not capture structured bindings).
    const auto& key = item.first;
    const auto& n = item.second;
    CAPTURE(key);
    CHECK(n == 1);
  }
  for (const auto& key : mine) vlit::load_gltf_file((out / key).string());  // complete files
  fs::remove_all(dir);
}
