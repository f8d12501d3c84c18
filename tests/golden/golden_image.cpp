// Golden-image comparison: PNG loading through stb_image, per-pixel and PSNR metrics, diff image.
#include "golden/golden_image.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>

#include <stb_image.h>

namespace vlit::test {

std::optional<Rgb8Image> load_png_rgb8(const std::string& path) {
  int w = 0, h = 0, channels = 0;
  unsigned char* data = stbi_load(path.c_str(), &w, &h, &channels, 3);
  if (!data) return std::nullopt;
  Rgb8Image image{w, h, std::vector<std::uint8_t>(data, data + std::size_t(w) * std::size_t(h) * 3)};
  stbi_image_free(data);
  return image;
}

std::string GoldenComparison::summary() const {
  if (!same_size) return "image sizes differ";
  char buf[256];
  std::snprintf(buf, sizeof buf, "%s: max |diff| %d/255, %zu pixels (%.4f%%) over threshold, PSNR %.2f dB",
                match ? "match" : "MISMATCH", max_abs_diff, pixels_differing, 100 * fraction_differing, psnr_db);
  return buf;
}

GoldenComparison compare_to_golden(const Rgb8Image& golden, const Rgb8Image& actual, const GoldenTolerance& tolerance) {
  GoldenComparison c;
  c.same_size = golden.width == actual.width && golden.height == actual.height && golden.rgb.size() == actual.rgb.size() &&
                !golden.rgb.empty();
  if (!c.same_size) return c;
  const std::size_t pixels = golden.rgb.size() / 3;
  double squared = 0;
  for (std::size_t p = 0; p < pixels; ++p) {
    int pixel_max = 0;
    for (int k = 0; k < 3; ++k) {
      const int d = std::abs(int(golden.rgb[3 * p + k]) - int(actual.rgb[3 * p + k]));
      pixel_max = std::max(pixel_max, d);
      squared += double(d) * d;
    }
    c.max_abs_diff = std::max(c.max_abs_diff, pixel_max);
    if (pixel_max > tolerance.pixel_threshold) ++c.pixels_differing;
  }
  c.fraction_differing = double(c.pixels_differing) / double(pixels);
  const double mse = squared / double(3 * pixels);
  c.psnr_db = mse == 0 ? std::numeric_limits<double>::infinity() : 10 * std::log10(255.0 * 255.0 / mse);
  c.match = c.fraction_differing <= tolerance.max_fraction_differing && c.psnr_db >= tolerance.min_psnr_db;
  return c;
}

Rgb8Image diff_image(const Rgb8Image& golden, const Rgb8Image& actual, const GoldenTolerance& tolerance) {
  Rgb8Image out{golden.width, golden.height, std::vector<std::uint8_t>(golden.rgb.size(), 0)};
  if (golden.rgb.size() != actual.rgb.size()) return out;
  for (std::size_t p = 0; p < golden.rgb.size() / 3; ++p) {
    int pixel_max = 0, luma = 0;
    for (int k = 0; k < 3; ++k) {
      pixel_max = std::max(pixel_max, std::abs(int(golden.rgb[3 * p + k]) - int(actual.rgb[3 * p + k])));
      luma += golden.rgb[3 * p + k];
    }
    const auto grey = static_cast<std::uint8_t>(luma / 12);
    std::uint8_t* o = &out.rgb[3 * p];
    o[0] = o[1] = o[2] = grey;
    if (pixel_max > tolerance.pixel_threshold) o[0] = static_cast<std::uint8_t>(std::min(255, 64 + 16 * pixel_max));
    else if (pixel_max > 0) o[2] = 160;
  }
  return out;
}

}  // namespace vlit::test
