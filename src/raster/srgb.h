// Linear RGB to 8-bit sRGB: exposure scale, the exact sRGB OETF (IEC 61966-2-1), clamping to
// [0, 1], and rounding to nearest.
#pragma once

#include <cstdint>
#include <vector>

#include "raster/image.h"

namespace vlit::raster {

// sRGB OETF of a linear value: 12.92 v below 0.0031308, else 1.055 v^(1/2.4) - 0.055.
// Input clamped to [0, 1] first; NaN maps to 0.
double srgb_oetf(double linear);

// One channel: round(255 * srgb_oetf(exposure * linear)).
uint8_t encode_srgb8(float linear, float exposure);

// The whole image, 3 bytes per pixel, same layout as Image::rgb. Exposure is a linear scale
// (1 = unchanged), applied here and only here.
std::vector<uint8_t> encode_srgb8(const Image& image, float exposure);

// For images whose values are already display values, not light (the normals debug view):
// round(255 * clamp(v, 0, 1)) per channel, no OETF, no exposure. NaN maps to 0.
std::vector<uint8_t> encode_unorm8(const Image& image);

}  // namespace vlit::raster
