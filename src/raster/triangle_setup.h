// Projection, snapping and per-triangle setup: from clipped vertices to the integer edges and
// attribute gradients that the scanline loop (rasterize_triangle.h) consumes. Everything the loop
// needs per pixel is computed here, once per triangle.
//
// Coordinates are those of the sample grid (the image scaled by the supersampling factor):
// x to the right, y down, pixel (i, j) covers [i, i+1) x [j, j+1) with its centre at +0.5.
//
// Depth: stored as reversed window depth d = (1 - z_ndc) / 2 = (w - z) / (2w): 1 at the near
// plane, 0 at the far plane (or at infinity for the infinite perspective), greater is nearer.
// It is affine in screen space, so it is interpolated without division; reversed, it keeps float
// precision for distant surfaces (d ~ znear / distance for the infinite projection).
//
// Perspective-correct colour: 1/w and colour/w are affine in screen space; the loop interpolates
// both and divides.
#pragma once

#include <array>
#include <cstdint>
#include <optional>

#include "core/vec3.h"
#include "raster/clip.h"

namespace vlit::raster {

// A clipped vertex after the perspective divide, snapped to fixed point.
struct ScreenVertex {
  int64_t x = 0, y = 0;  // fixed point, kSubpixelBits fractional bits, sample-grid pixels
  double depth = 0;      // reversed window depth, see above
  double inv_w = 0;      // 1 / w_clip
  Vec3d color_over_w;    // colour / w_clip
};

// nullopt when the projected vertex is not finite (w = 0 or NaN/Inf input).
std::optional<ScreenVertex> project_to_screen(const ClipVertex& v, int grid_width, int grid_height);

// An attribute as a plane over the sample grid: value(x, y) = at_ref + ddx (x - ref_x) + ddy (y - ref_y),
// x, y in sample-grid pixels, (ref_x, ref_y) = the top vertex (SetupTriangle::ref_x(), ref_y()).
struct Gradient {
  double at_ref = 0, ddx = 0, ddy = 0;
};

constexpr uint8_t kEdgeTopMid = 1, kEdgeMidBottom = 2, kEdgeTopBottom = 4;

struct SetupTriangle {
  std::array<int32_t, 3> x{}, y{};  // snapped vertices sorted by y (top first), fixed point
  bool long_edge_on_left = false;   // the edge top -> bottom is the left side of every row
  // Which edges belong to the source triangle (not to a clip plane or a fan diagonal of a clipped
  // polygon), for the wireframe view: kEdgeTopMid | kEdgeMidBottom | kEdgeTopBottom.
  uint8_t original_edges = 0;
  int row_begin = 0, row_end = 0;   // sample rows whose centres it may cover, clamped to the grid
  Gradient depth, inv_w;
  std::array<Gradient, 3> color_over_w;

  // The top vertex in pixels, origin of the gradients (exact: a division by a power of two).
  double ref_x() const { return double(x[0]) / double(int64_t{1} << 8); }
  double ref_y() const { return double(y[0]) / double(int64_t{1} << 8); }
};
// 160 bytes: the rasterizer keeps one per visible triangle until the frame is drawn.
static_assert(sizeof(SetupTriangle) == 160);

// Sets up the triangle a, b, c (in its original winding). Returns nullopt when it covers no
// sample centre of the grid (zero area after snapping, outside the rows or columns), or when
// cull_back_face is set and it is back-facing. Front-facing = counter-clockwise in NDC (glTF).
// original_edges: bit 0 = edge a->b, bit 1 = b->c, bit 2 = c->a is an edge of the source
// triangle (stored in SetupTriangle::original_edges in sorted-vertex terms).
std::optional<SetupTriangle> setup_triangle(const ScreenVertex& a, const ScreenVertex& b,
                                            const ScreenVertex& c, bool cull_back_face,
                                            int grid_width, int grid_height, uint8_t original_edges = 7);

}  // namespace vlit::raster
