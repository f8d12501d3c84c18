// The rasterizer's output: a linear-RGB float image.
#pragma once

#include <cstddef>
#include <vector>

namespace vlit::raster {

struct Image {
  int width = 0, height = 0;
  std::vector<float> rgb;  // linear RGB, 3 floats per pixel, row-major, top row first

  float* pixel(int x, int y) { return rgb.data() + 3 * (std::size_t(y) * std::size_t(width) + std::size_t(x)); }
  const float* pixel(int x, int y) const { return rgb.data() + 3 * (std::size_t(y) * std::size_t(width) + std::size_t(x)); }
};

}  // namespace vlit::raster
