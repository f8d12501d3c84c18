// The golden comparison is honest: an identical image and one with invisible noise pass, while a
// brightened region, one grossly wrong pixel, a shifted image or a size change fail, on a real
// golden (tests/golden/images/light-point.png).
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <string>

#include "golden/golden_image.h"

using namespace vlit::test;

namespace {

Rgb8Image reference_golden() {
  const auto g = load_png_rgb8(std::string(VLIT_SOURCE_DIR) + "/tests/golden/images/light-point.png");
  REQUIRE_MESSAGE(g.has_value(), "tests/golden/images/light-point.png is missing (scripts/update-goldens.sh)");
  return *g;
}

std::uint8_t add_clamped(std::uint8_t v, int d) { return static_cast<std::uint8_t>(std::clamp(int(v) + d, 0, 255)); }

}  // namespace

TEST_CASE("golden comparison: identical and near-identical images match") {
  const Rgb8Image golden = reference_golden();
  const GoldenTolerance tolerance;
  const auto same = compare_to_golden(golden, golden, tolerance);
  CHECK(same.match);
  CHECK(same.max_abs_diff == 0);
  CHECK(std::isinf(same.psnr_db));

  // +-1 on every channel of every pixel (what a different rounding of the lighting could do).
  Rgb8Image noisy = golden;
  std::mt19937 rng(12345);
  for (auto& v : noisy.rgb) v = add_clamped(v, int(rng() % 3) - 1);
  const auto n = compare_to_golden(golden, noisy, tolerance);
  MESSAGE(n.summary());
  CHECK(n.match);
}

TEST_CASE("golden comparison: a deliberately perturbed image fails") {
  const Rgb8Image golden = reference_golden();
  const GoldenTolerance tolerance;
  REQUIRE(golden.width >= 40);
  REQUIRE(golden.height >= 40);

  SUBCASE("a 10 x 10 region brightened by 8/255 (PSNR alone would pass it)") {
    Rgb8Image img = golden;
    for (int y = 20; y < 30; ++y)
      for (int x = 20; x < 30; ++x)
        for (int k = 0; k < 3; ++k) {
          auto& v = img.rgb[3 * (std::size_t(y) * golden.width + x) + k];
          v = add_clamped(v, 8);
        }
    const auto c = compare_to_golden(golden, img, tolerance);
    MESSAGE(c.summary());
    CHECK_FALSE(c.match);
    CHECK(c.psnr_db >= tolerance.min_psnr_db);  // the per-pixel criterion is what catches it
    CHECK(c.pixels_differing >= 90);
  }
  SUBCASE("one pixel inverted (the pixel count alone would pass it)") {
    Rgb8Image img = golden;
    const std::size_t p = 3 * (std::size_t(golden.height / 2) * golden.width + golden.width / 2);
    for (int k = 0; k < 3; ++k) img.rgb[p + k] = static_cast<std::uint8_t>(255 - img.rgb[p + k]);
    // Invert a second pixel too if the centre happened to be mid-grey.
    for (int k = 0; k < 3; ++k) img.rgb[k] = static_cast<std::uint8_t>(255 - img.rgb[k]);
    const auto c = compare_to_golden(golden, img, tolerance);
    MESSAGE(c.summary());
    CHECK_FALSE(c.match);
    CHECK(c.pixels_differing <= 2);
  }
  SUBCASE("the image shifted right by one pixel") {
    Rgb8Image img = golden;
    for (int y = 0; y < golden.height; ++y)
      for (int x = golden.width - 1; x > 0; --x)
        for (int k = 0; k < 3; ++k)
          img.rgb[3 * (std::size_t(y) * golden.width + x) + k] = golden.rgb[3 * (std::size_t(y) * golden.width + x - 1) + k];
    const auto c = compare_to_golden(golden, img, tolerance);
    MESSAGE(c.summary());
    CHECK_FALSE(c.match);
  }
  SUBCASE("a different size") {
    Rgb8Image img = golden;
    img.height -= 1;
    img.rgb.resize(std::size_t(img.width) * img.height * 3);
    CHECK_FALSE(compare_to_golden(golden, img, tolerance).match);
  }
}

TEST_CASE("golden comparison: the diff image marks exactly the differing pixels") {
  const Rgb8Image golden = reference_golden();
  const GoldenTolerance tolerance;
  Rgb8Image img = golden;
  img.rgb[0] = add_clamped(img.rgb[0], img.rgb[0] < 128 ? 50 : -50);
  const Rgb8Image diff = diff_image(golden, img, tolerance);
  REQUIRE(diff.rgb.size() == golden.rgb.size());
  CHECK(diff.rgb[0] >= 64 + 16 * 3);  // red, bright
  std::size_t red = 0;
  for (std::size_t p = 0; p < diff.rgb.size() / 3; ++p) red += diff.rgb[3 * p] > diff.rgb[3 * p + 1];
  CHECK(red == 1);
}
