// The progress line's text: percentages, rates and ETAs worked out by hand.
#include <doctest/doctest.h>

#include "bake/progress_line.h"

using namespace vlit;

TEST_CASE("progress line of one file: percent, vertices per second, time left") {
  // 3 M of 4 M vertices in 2 s: 1.5 M/s, 1 M left -> 0.67 s -> "1 s".
  CHECK(progress_line("lighting a.glb", 3e6, 4e6, 2.0) == "lighting a.glb   75%  1.50 M vertices/s  ETA 1 s");
  CHECK(progress_line("lighting a.glb", 0, 4e6, 0.0) == "lighting a.glb    0%");  // no rate yet
}

TEST_CASE("batch progress line: files done, the current file, files per second, time left") {
  // 3 files done and the 4th at 50 % after 7 s: 3.5 / 7 = 0.5 files/s; 6.5 left -> 13 s.
  CHECK(batch_progress_line(3, 10, "Avocado.glb", 0.5, 7.0) == "baking 3/10 files  Avocado.glb 50%  0.50 files/s  ETA 13 s");
  // Between files: 4 of 10 in 200 s -> 0.02 files/s, 6 left -> 300 s.
  CHECK(batch_progress_line(4, 10, "", 0, 200.0) == "baking 4/10 files  0.02 files/s  ETA 5 min 0 s");
  CHECK(batch_progress_line(0, 10, "a.glb", 0, 0.0) == "baking 0/10 files  a.glb 0%");
  CHECK(format_duration(3 * 3600 + 125) == "3 h 2 min");
}

TEST_CASE("fit_width: the path loses characters from its left, the line fits the terminal") {
  const std::string path = "library/vehicles/Duck/glTF-Quantized/Duck.gltf";
  const std::string line = batch_progress_line(3, 10, path, 0.4, 7.0);
  CHECK(fit_width(line, path, 0) == line);           // no limit
  CHECK(fit_width(line, path, line.size()) == line);  // fits
  const std::string fitted = fit_width(line, path, 60);
  CHECK(fitted.size() == 60);
  CHECK(fitted == "baking 3/10 files  .../Duck.gltf 40%  0.49 files/s  ETA 14 s");
  // Too narrow for even a shortened path: the line is cut.
  CHECK(fit_width(line, path, 20) == line.substr(0, 20));
  CHECK(fit_width(line, "", 30).size() == 30);
}

TEST_CASE("long_bake_warning: once the time left at the rate so far is over 10 minutes, after 5 s of work") {
  // 1 % in 7 s: 99 % left at 1/7 % per s -> 693 s = 11 min 33 s.
  CHECK(long_bake_warning("scene.glb", 1, 100, 7) ==
        "scene.glb: this bake will take about 11 min 33 s more (1% done after 7 s); Ctrl-C stops it without writing an output");
  CHECK(long_bake_warning("scene.glb", 1, 100, 4.9).empty());   // too early to tell
  CHECK(long_bake_warning("scene.glb", 2, 100, 7).empty());     // 343 s left: not long
  CHECK(long_bake_warning("scene.glb", 0, 100, 60).empty());    // no rate yet
  CHECK(long_bake_warning("scene.glb", 100, 100, 9000).empty());  // done
}
