// Mesa's software OpenGL (llvmpipe) as a baseline for the rasterizer benchmark: an EGL surfaceless
// context (no window, no GPU), an offscreen RGBA8 + 24-bit depth framebuffer, and one draw call of
// a vertex-coloured triangle list with Gouraud (smooth, perspective-correct) interpolation and a
// depth test, the same job as vlit::raster::render with one sample per pixel.
//
// Optional: built only when CMake finds OpenGL and EGL (Debian: libegl-dev libgl-dev, and
// libgl1-mesa-dri for the driver at run time). Which driver runs is printed (renderer()); the
// thread count of llvmpipe is LP_NUM_THREADS, which must be set before create().
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace vlit::bench {

class LlvmpipeRenderer {
 public:
  // Creates the context and a width x height framebuffer; nullptr and *error on failure.
  static std::unique_ptr<LlvmpipeRenderer> create(int width, int height, std::string* error);
  ~LlvmpipeRenderer();

  // GL_RENDERER, e.g. "llvmpipe (LLVM 15.0.6, 256 bits)".
  std::string renderer() const;

  // Uploads the mesh once (static buffers): positions and linear RGB colours, 3 floats per vertex.
  void upload(const std::vector<float>& positions, const std::vector<float>& colors, const std::vector<uint32_t>& indices);

  // One frame: clear colour and depth, draw with clip_from_world (column-major, as OpenGL wants
  // it), glFinish so the frame is complete when this returns.
  void draw(const std::array<float, 16>& clip_from_world_column_major, const std::array<float, 3>& background);

  // The framebuffer as RGB8, top row first (for a sanity comparison, not timed).
  std::vector<uint8_t> read_rgb8() const;

 private:
  LlvmpipeRenderer() = default;
  struct State;
  std::unique_ptr<State> state_;
};

}  // namespace vlit::bench
