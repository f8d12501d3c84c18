// Golden-image comparison for the golden suite: 8-bit sRGB PNGs compared per pixel and in
// aggregate, with a diff image written next to a failure. docs/golden-images.md explains the
// thresholds and how to regenerate the goldens.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace vlit::test {

struct Rgb8Image {
  int width = 0, height = 0;
  std::vector<std::uint8_t> rgb;  // 3 bytes per pixel, top row first
};

// Reads a PNG as 8-bit RGB (alpha dropped); nothing if the file is missing or unreadable.
std::optional<Rgb8Image> load_png_rgb8(const std::string& path);

// The tolerance of a golden comparison. A pixel "differs" when any channel is off by more than
// pixel_threshold (in 1/255 units). The images match when at most max_fraction_differing of the
// pixels differ AND the PSNR over all channels is at least min_psnr_db. The first catches a
// local change (a region, an edge moved by a pixel), the second a few grossly wrong pixels or a
// small change everywhere.
struct GoldenTolerance {
  int pixel_threshold = 2;
  double max_fraction_differing = 0.001;
  double min_psnr_db = 45;
};

struct GoldenComparison {
  bool same_size = false;
  int max_abs_diff = 0;             // largest channel difference, 0..255
  std::size_t pixels_differing = 0; // pixels with a channel off by more than the threshold
  double fraction_differing = 0;
  double psnr_db = 0;               // infinity for identical images
  bool match = false;
  std::string summary() const;      // one line: all of the above
};

GoldenComparison compare_to_golden(const Rgb8Image& golden, const Rgb8Image& actual, const GoldenTolerance& tolerance);

// A picture of where the images differ: the golden dimmed to a quarter in grey, pixels over the
// threshold in red (brighter = larger difference, x16), pixels off by 1..threshold in blue.
Rgb8Image diff_image(const Rgb8Image& golden, const Rgb8Image& actual, const GoldenTolerance& tolerance);

}  // namespace vlit::test
