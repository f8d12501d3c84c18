#include <doctest/doctest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "core/input_error.h"
#include "io/atomic_write.h"
#include "support/gltf_builder.h"

using namespace vlit;

namespace {
std::string slurp(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}
std::size_t entries(const std::filesystem::path& dir) {
  return static_cast<std::size_t>(std::distance(std::filesystem::directory_iterator(dir), {}));
}
}  // namespace

TEST_CASE("atomic write creates, replaces, and leaves no temporary behind") {
  const auto dir = vlit::test::temp_dir("atomic");
  const auto path = (dir / "out.bin").string();
  write_file_atomically(path, "first");
  CHECK(slurp(path) == "first");
  write_file_atomically(path, std::string(1 << 20, 'x'));
  CHECK(slurp(path).size() == (1u << 20));
  CHECK(entries(dir) == 1);
}

TEST_CASE("atomic write into a missing directory fails with the path and leaves nothing") {
  const auto dir = vlit::test::temp_dir("atomic-missing");
  const auto path = (dir / "no" / "such" / "out.bin").string();
  CHECK_THROWS_WITH_AS(write_file_atomically(path, "x"), doctest::Contains(path.c_str()), InputError);
  CHECK(entries(dir) == 0);
}

TEST_CASE("output_of_temporary: the file a hidden temporary was for, nothing else") {
  CHECK(output_of_temporary("out/.Duck.glb.vlit-tmp-Ab12Cd") == "out/Duck.glb");
  CHECK(output_of_temporary(".a.gltf.vlit-tmp-XXXXXX") == "a.gltf");
  CHECK(output_of_temporary("out/Duck.glb").empty());
  CHECK(output_of_temporary("out/.Duck.glb.vlit-tmp-Ab12C").empty());    // 5 random characters
  CHECK(output_of_temporary("out/.Duck.glb.vlit-tmp-Ab12Cde").empty());  // 7
  CHECK(output_of_temporary("out/Duck.glb.vlit-tmp-Ab12Cd").empty());    // not hidden
  CHECK(output_of_temporary("out/..vlit-tmp-Ab12Cd").empty());           // no name
}
