// The text of a progress line: what is done, the rate and the estimated time left, e.g.
//   "lighting scene.glb  45%  1.20 M vertices/s  ETA 3 s"
//   "baking 3/10 files  Avocado.glb 40%  0.52 files/s  ETA 13 s"
// Pure formatting (the terminal drawing is src/cli/terminal.h), so it can be tested.
#pragma once

#include <cstddef>
#include <string>

namespace vlit {

// One item being worked on: `done` of `total` units after `seconds`. Rate = done / seconds; ETA =
// (total - done) / rate. No rate or ETA before any time has passed or anything is done.
std::string progress_line(const std::string& label, double done, double total, double seconds);

// A batch of files: `files_done` complete, the current file `current` at `fraction` in [0, 1].
// The rate counts the current file's fraction, so it moves during a long file.
std::string batch_progress_line(std::size_t files_done, std::size_t files_total, const std::string& current,
                                double fraction, double seconds);

// "ETA 3 s", "ETA 2 min 5 s", "ETA 1 h 4 min".
std::string format_duration(double seconds);

// `line` shortened to at most `width` characters (0: no limit) for a terminal of that many
// columns: `name`, a part of the line such as a file path, loses characters from its left and
// starts with "...", so the file's own name stays in view
// ("baking 3/10 files  ...glTF/Duck.gltf 40%  0.52 files/s  ETA 13 s"); when that is not enough,
// the line is cut at `width`.
std::string fit_width(const std::string& line, const std::string& name, std::size_t width);

// A bake whose estimated time left is long deserves a warning before the user waits for it.
// After at least kLongBakeMinSeconds of work on `name`, with `done` of `total` units, when the time
// left at the rate so far exceeds kLongBakeSeconds: the warning's text, e.g.
// "scene.glb: this bake will take about 11 h 59 min more (1% done after 7 s); Ctrl-C stops it
// without writing an output". Empty otherwise.
inline constexpr double kLongBakeSeconds = 600;
inline constexpr double kLongBakeMinSeconds = 5;
std::string long_bake_warning(const std::string& name, double done, double total, double seconds);

}  // namespace vlit
