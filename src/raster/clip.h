// Homogeneous clipping of triangles against the near plane, the far plane (when the projection
// has one) and a guard band around the image (Sutherland-Hodgman in clip space, before the
// perspective divide, so vertices behind the eye never wrap around).
//
// The guard band keeps projected vertices inside [-2^20, 2^20] pixels so the fixed-point bit
// budget of fixed_point.h holds whatever the input; triangles that merely cross the image border
// are not clipped (the scanline loop clamps spans to the image), only absurdly large ones are.
//
// Watertightness: an edge is always cut from its inside vertex towards its outside vertex, so two
// triangles sharing an edge compute bit-identical intersection points.
#pragma once

#include <array>
#include <cstdint>

#include "core/mat4.h"
#include "core/vec3.h"

namespace vlit::raster {

struct ClipVertex {
  Vec4d position;  // clip space (OpenGL convention, -w <= x, y, z <= w is the view volume)
  Vec3d color;     // linear RGB, interpolated linearly in clip space (= perspective-correct)
  // Whether the polygon edge from this vertex to the next one lies on an edge of the original
  // triangle (true) or on a clip plane (false). The wireframe view draws only original edges.
  bool original_edge_to_next = true;
};

// Planes as 4-vectors: a point p is inside when dot(plane, p) >= 0.
struct ClipPlanes {
  std::array<Vec4d, 6> planes{};
  int count = 0;
};

// Each plane adds at most one vertex to a convex polygon (3 + 6 = 9); the capacity leaves room
// for rounding making a clipped polygon very slightly non-convex. A polygon that would exceed it
// (never observed) is dropped rather than overflow.
constexpr int kMaxClipVertices = 16;

// Near plane (z >= -w), far plane (z <= w) if has_far, and the guard band for a sample grid of
// grid_width x grid_height pixels (x, y within [-kGuardBandPixels, kGuardBandPixels] pixels).
ClipPlanes make_clip_planes(int grid_width, int grid_height, bool has_far);

// Bit i is set when p is outside plane i (dot(plane, p) < 0). A triangle whose vertices' codes
// are all 0 needs no clipping; one whose codes share a bit is entirely outside (clip_triangle's
// own fast paths, computed once per vertex instead of once per triangle corner).
inline uint8_t outcode(const ClipPlanes& planes, const Vec4d& p) {
  uint8_t code = 0;
  for (int i = 0; i < planes.count; ++i) code |= uint8_t(dot(planes.planes[i], p) < 0 ? 1 << i : 0);
  return code;
}

// Clips the triangle a, b, c (order kept, so the winding is kept) and returns the number of
// vertices of the resulting convex polygon written to `out`: 0 if nothing is left, else 3..16.
// Each output vertex's original_edge_to_next tells whether the edge it starts lies on one of the
// triangle's edges (inputs: a->b, b->c, c->a as given by the inputs' own flags).
int clip_triangle(const ClipVertex& a, const ClipVertex& b, const ClipVertex& c,
                  const ClipPlanes& planes, std::array<ClipVertex, kMaxClipVertices>& out);

}  // namespace vlit::raster
