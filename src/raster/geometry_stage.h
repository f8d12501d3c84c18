// The per-triangle front half of the pipeline: transform every vertex once, then clip, project,
// snap and set up every triangle, in draw order. Multi-threaded and deterministic: vertices and
// fixed-size chunks of triangles are processed independently and concatenated in order.
#pragma once

#include <vector>

#include "core/mat4.h"
#include "raster/draw_mesh.h"
#include "raster/triangle_setup.h"

namespace vlit::raster {

struct GeometryOptions {
  int grid_width = 0, grid_height = 0;  // sample grid size, in [1, kMaxGridSize]
  bool has_far_plane = false;           // clip against z <= w too
  bool cull_back_faces = false;         // applies to meshes that are not double-sided
};

// Triangles with a non-finite vertex (NaN/Inf position or colour, or a projection that overflows)
// or an out-of-range index are skipped, as are zero-area ones (triangle_setup.h).
std::vector<SetupTriangle> setup_meshes(const std::vector<DrawMesh>& meshes, const Mat4d& clip_from_world,
                                        const GeometryOptions& options);

}  // namespace vlit::raster
