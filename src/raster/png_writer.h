// Atomic RGB8 PNG output through stb_image_write (libstb).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace vlit::raster {

// Writes width x height RGB8 pixels (rows top first, 3 bytes per pixel) as a PNG at `path`.
// Atomic: the image goes to a fresh temporary file in the same directory, flushed and synced,
// then renamed over `path`; readers never see a partial file. On failure no file is left
// behind (an existing `path` is untouched), false is returned and *error (if given) says why.
// The file gets mode 0644. Images over 2 GiB of raw pixels are refused (stb's int sizes).
bool write_png(const std::string& path, int width, int height, const std::vector<uint8_t>& rgb8,
               std::string* error);

}  // namespace vlit::raster
