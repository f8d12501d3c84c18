// sRGB encoding; see srgb.h.
#include "raster/srgb.h"

#include <algorithm>
#include <cmath>

namespace vlit::raster {

double srgb_oetf(double linear) {
  if (!(linear > 0)) return 0;  // also NaN
  if (linear >= 1) return 1;
  return linear <= 0.0031308 ? 12.92 * linear : 1.055 * std::pow(linear, 1.0 / 2.4) - 0.055;
}

uint8_t encode_srgb8(float linear, float exposure) {
  const double v = srgb_oetf(double(linear) * double(exposure));
  return uint8_t(std::lround(v * 255.0));
}

std::vector<uint8_t> encode_srgb8(const Image& image, float exposure) {
  std::vector<uint8_t> out(image.rgb.size());
  const long long n = (long long)image.rgb.size();
#pragma omp parallel for schedule(static)
  for (long long i = 0; i < n; ++i) out[i] = encode_srgb8(image.rgb[i], exposure);
  return out;
}

std::vector<uint8_t> encode_unorm8(const Image& image) {
  std::vector<uint8_t> out(image.rgb.size());
  for (size_t i = 0; i < out.size(); ++i) {
    const float v = image.rgb[i];
    out[i] = v > 0 ? uint8_t(std::lround(double(std::min(v, 1.0f)) * 255.0)) : 0;
  }
  return out;
}

}  // namespace vlit::raster
