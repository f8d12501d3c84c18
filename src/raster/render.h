// The rasterizer's entry point: draws world-space meshes with per-vertex colours from a camera
// into a linear-RGB image. Pipeline (docs/rasterizer.md): transform -> clip (homogeneous) ->
// project -> snap (fixed point) -> setup (once per triangle) -> scanline per horizontal band
// (depth test, perspective-correct Gouraud) -> resolve (box filter over the supersamples).
//
// Threads: OpenMP over vertices, triangle chunks, and image bands. Every band rasterizes every
// triangle clipped to its rows, so the image is bit-identical whatever the thread count.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "core/vec3.h"
#include "raster/camera.h"
#include "raster/draw_mesh.h"
#include "raster/image.h"

namespace vlit::raster {

// The wireframe debug view: the edges of every source triangle drawn over the shading.
// Line rule: a covered sample belongs to the wire when its centre is closer than `width` image
// pixels to the line through one of its triangle's own edges (the snapped screen-space edge;
// edges created by clipping or by fanning a clipped polygon do not count). The wire is thus
// drawn on the inner side of each edge: a shared edge gets a line 2 x width wide, half from each
// triangle, a silhouette edge width wide; wire samples keep their triangle's depth, so hidden
// edges stay hidden, and the supersamples antialias the lines like everything else.
struct WireframeOptions {
  bool enabled = false;
  double width = 0.5;            // image pixels, > 0, on each side of a shared edge
  Vec3f color{1.0f, 0.35f, 0.0f};  // linear RGB, scaled by exposure like every other colour
};

struct RenderOptions {
  int width = 800, height = 600;  // pixels, >= 1; width * side and height * side <= kMaxGridSize
  // Samples per pixel on an ordered side x side grid at ((i + 0.5)/side, (j + 0.5)/side):
  // a perfect square, 1 to 64 (1, 4, 16 are the documented choices).
  int samples = 1;
  Vec3f background{0, 0, 0};  // linear RGB
  bool cull_back_faces = false;  // cull back faces of meshes that are not double-sided
  WireframeOptions wireframe;
  // There is deliberately no exposure here: render() returns scene-linear values and exposure is
  // applied exactly once, by encode_srgb8(image, exposure).
};

// Empty string if the options can be rendered, else what is wrong. The caller refuses zero or
// negative sizes and bad sample counts with this message; render() itself never crashes on
// them (it returns an empty image).
std::string validate_render_options(const RenderOptions& options);

// Side of the supersampling grid for options.samples (1 when invalid).
int samples_per_side(int samples);

// Memory that render() keeps between frames: the set-up triangles, the band bins, one band buffer
// per thread. Rendering many frames with one workspace (and one Image) reuses their storage
// instead of allocating and page-faulting it every frame; the image is bit-identical either way.
// One workspace per concurrent render() call.
class RenderWorkspace {
 public:
  RenderWorkspace();
  ~RenderWorkspace();
  RenderWorkspace(RenderWorkspace&&) noexcept;
  RenderWorkspace& operator=(RenderWorkspace&&) noexcept;
  struct Buffers;  // render.cpp
  std::unique_ptr<Buffers> buffers;
  // Triangles that the last render() with this workspace skipped because an index was beyond
  // their mesh's vertices (0 before the first frame, and for a frame refused or not projected).
  size_t bad_index_triangles() const;
};

// Renders into `image` (resized as needed, storage reused), with the workspace's buffers.
void render(const std::vector<DrawMesh>& meshes, const Camera& camera, const RenderOptions& options,
            RenderWorkspace& workspace, Image& image);

// Renders the meshes. Preconditions: validate_render_options(options) and validate_camera(camera)
// are empty; otherwise returns an empty Image (0 x 0) for bad options, and a background-filled
// image for a singular camera. Degenerate triangles (zero area, NaN/Inf vertices, bad indices)
// are skipped.
Image render(const std::vector<DrawMesh>& meshes, const Camera& camera, const RenderOptions& options);

}  // namespace vlit::raster
