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
