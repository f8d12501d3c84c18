// The committed paper scenes (assets/paper/) are exactly what their generator writes: it is run
// into a temporary directory and every file is compared byte for byte.
#include <doctest/doctest.h>

#include <filesystem>
#include <string>

#include "support/gltf_builder.h"
#include "support/run_command.h"

namespace fs = std::filesystem;

TEST_CASE("assets/paper/ is reproduced byte for byte by vlit_make_paper_scenes") {
  const std::string generator = VLIT_PAPER_GENERATOR;
  REQUIRE_MESSAGE(!generator.empty(), "the build has no vlit_make_paper_scenes target (add_subdirectory(assets))");
  const fs::path committed = fs::path(VLIT_SOURCE_DIR) / "assets" / "paper";
  const fs::path out = vlit::test::temp_dir("paper-scenes");
  const auto r = vlit::test::run_command("'" + generator + "' '" + out.string() + "'");
  REQUIRE_MESSAGE(r.exit_code == 0, r.err);
  int files = 0;
  for (const char* name : {"bowling.glb", "bowling-spot.json", "bowling-linear.json", "bowling-area.json", "studio.glb",
                           "studio-spot.json", "studio-linear.json", "studio-area.json"}) {
    CAPTURE(name);
    const std::string fresh = vlit::test::read_all(out / name), stored = vlit::test::read_all(committed / name);
    CHECK(!fresh.empty());
    CHECK_MESSAGE(fresh == stored, "regenerate with: vlit_make_paper_scenes assets/paper");
    CHECK(fresh.size() < 2'000'000u);
    ++files;
  }
  // Nothing else is written.
  CHECK(std::distance(fs::directory_iterator(out), fs::directory_iterator{}) == files);
  fs::remove_all(out);
}
