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

// The set-up triangles of a frame, in draw order: chunks[0], chunks[1], ... up to chunk_count,
// each the visible pieces of a fixed-size run of source triangles. They are not concatenated (a
// copy of ~160 bytes per triangle); a renderer keeps this between frames so that the storage is
// reused (clear() keeps capacity) instead of freshly allocated and page-faulted every frame.
struct SetupBuffers {
  // One mesh's vertices, transformed once: their clip outcodes (clip.h) and flags, and for those
  // inside every plane their projected, snapped screen vertex (shared by the mesh's triangles).
  std::vector<ScreenVertex> screen;
  std::vector<uint8_t> flags;
  std::vector<std::vector<SetupTriangle>> chunks;    // capacity kept across frames
  size_t chunk_count = 0;                            // chunks in use this frame
};

// Triangles with a non-finite vertex (NaN/Inf position or colour, or a projection that overflows)
// or an out-of-range index are skipped, as are zero-area ones (triangle_setup.h).
void setup_meshes(const std::vector<DrawMesh>& meshes, const Mat4d& clip_from_world, const GeometryOptions& options,
                  SetupBuffers& buffers);

// The same, concatenated into one list (for tests and small scenes).
std::vector<SetupTriangle> setup_meshes(const std::vector<DrawMesh>& meshes, const Mat4d& clip_from_world,
                                        const GeometryOptions& options);

}  // namespace vlit::raster
