// Tests of sRGB encoding and the atomic PNG writer (read back with stb_image).
#include <doctest/doctest.h>

#include <stb_image.h>  // implementation lives in libstb.so

#include <cmath>
#include <filesystem>
#include <fstream>

#include "raster/png_writer.h"
#include "raster/srgb.h"

using namespace vlit::raster;
namespace fs = std::filesystem;

TEST_CASE("srgb: known values") {
  CHECK(encode_srgb8(0.0f, 1.0f) == 0);
  CHECK(encode_srgb8(1.0f, 1.0f) == 255);
  CHECK(encode_srgb8(0.5f, 1.0f) == 188);    // 1.055 * 0.5^(1/2.4) - 0.055 = 0.7354 -> 187.5 -> 188
  CHECK(encode_srgb8(0.25f, 2.0f) == 188);   // exposure is a linear scale
  CHECK(encode_srgb8(0.18f, 1.0f) == 118);   // middle grey: 0.4614 * 255 = 117.66
  CHECK(encode_srgb8(-1.0f, 1.0f) == 0);
  CHECK(encode_srgb8(7.0f, 1.0f) == 255);
  CHECK(encode_srgb8(NAN, 1.0f) == 0);
  CHECK(encode_srgb8(INFINITY, 1.0f) == 255);
  // The linear segment and the threshold 0.0031308, where both branches meet (continuity).
  CHECK(srgb_oetf(0.001) == doctest::Approx(0.01292));
  const double t = 0.0031308;
  CHECK(srgb_oetf(t) == doctest::Approx(12.92 * t));
  CHECK(srgb_oetf(std::nextafter(t, 1.0)) == doctest::Approx(1.055 * std::pow(t, 1 / 2.4) - 0.055).epsilon(1e-9));
  CHECK(std::abs(12.92 * t - (1.055 * std::pow(t, 1 / 2.4) - 0.055)) < 1e-7);
  CHECK(encode_srgb8(float(t), 1.0f) == 10);  // 0.040450 * 255 = 10.31
  // Monotone over all 8-bit codes.
  int previous = 0;
  for (int i = 0; i <= 4096; ++i) {
    const int code = encode_srgb8(float(i) / 4096.0f, 1.0f);
    CHECK(code >= previous);
    previous = code;
  }
}

TEST_CASE("srgb: image encoding keeps the layout") {
  Image image{2, 1, {0.0f, 0.5f, 1.0f, 0.25f, 2.0f, -1.0f}};
  const auto bytes = encode_srgb8(image, 1.0f);
  REQUIRE(bytes.size() == 6);
  CHECK(bytes == std::vector<uint8_t>{0, 188, 255, encode_srgb8(0.25f, 1.0f), 255, 0});
}

namespace {

fs::path scratch_dir(const char* name) {
  const fs::path dir = fs::temp_directory_path() / (std::string("vlit_raster_test_") + name);
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

}  // namespace

TEST_CASE("png: write then read back gives the same bytes, no temporary file left") {
  const fs::path dir = scratch_dir("png");
  const int w = 37, h = 23;  // odd sizes: no row padding assumptions
  std::vector<uint8_t> rgb(size_t(w) * h * 3);
  for (size_t i = 0; i < rgb.size(); ++i) rgb[i] = uint8_t((i * 7919u) >> 3);
  const std::string path = (dir / "out.png").string();
  std::string error;
  REQUIRE(write_png(path, w, h, rgb, &error));
  CHECK(error.empty());
  int rw = 0, rh = 0, channels = 0;
  unsigned char* data = stbi_load(path.c_str(), &rw, &rh, &channels, 3);
  REQUIRE(data != nullptr);
  CHECK(rw == w);
  CHECK(rh == h);
  CHECK(channels == 3);
  CHECK(std::equal(rgb.begin(), rgb.end(), data));
  stbi_image_free(data);
  int files = 0;
  for ([[maybe_unused]] const auto& entry : fs::directory_iterator(dir)) ++files;
  CHECK(files == 1);
  // Overwriting an existing file works (rename over it).
  rgb[0] ^= 0xff;
  REQUIRE(write_png(path, w, h, rgb, &error));
  data = stbi_load(path.c_str(), &rw, &rh, &channels, 3);
  REQUIRE(data != nullptr);
  CHECK(data[0] == rgb[0]);
  stbi_image_free(data);
  fs::remove_all(dir);
}

TEST_CASE("png: failures report an error and leave no file") {
  const fs::path dir = scratch_dir("png_fail");
  std::string error;
  const std::vector<uint8_t> rgb(12, 0);
  CHECK_FALSE(write_png((dir / "missing_dir" / "x.png").string(), 2, 2, rgb, &error));
  CHECK_FALSE(error.empty());
  error.clear();
  CHECK_FALSE(write_png((dir / "wrong_size.png").string(), 3, 2, rgb, &error));
  CHECK_FALSE(error.empty());
  CHECK_FALSE(write_png((dir / "zero.png").string(), 0, 2, rgb, nullptr));
  // Target is a directory: rename fails after writing, the temporary file must be cleaned up.
  fs::create_directories(dir / "is_a_dir");
  fs::create_directories(dir / "is_a_dir" / "child");  // non-empty, so rename cannot replace it
  CHECK_FALSE(write_png((dir / "is_a_dir").string(), 2, 2, rgb, &error));
  int files = 0;
  for ([[maybe_unused]] const auto& entry : fs::directory_iterator(dir)) ++files;
  CHECK(files == 1);  // only is_a_dir
  fs::remove_all(dir);
}
