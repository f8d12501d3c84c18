// The per-triangle front half of the pipeline: transform every vertex once, then clip, project,
// snap every triangle, in draw order (setup itself is deferred to the bands for triangles that
// need no clipping). Multi-threaded and deterministic: vertices and fixed-size chunks of
// triangles are processed independently and kept in order.
#pragma once

#include <cstdint>
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

// One triangle of the frame, in draw order. Triangles inside every clip plane (nearly all) are
// kept as three indices into SetupBuffers::screen and set up where they are drawn, by each band
// they overlap (setup_triangle is deterministic, so every band gets the same bits); that costs 16
// bytes per triangle instead of a 160-byte SetupTriangle. Triangles that needed clipping are set
// up here, once per piece, and stored in their chunk's `clipped` list.
struct DrawEntry {
  enum Kind : uint32_t { kDeferred = 0, kDeferredCulled = 1, kClipped = 2 };
  uint32_t a = 0, b = 0, c = 0;  // kDeferred*: indices into SetupBuffers::screen;
                                 // kClipped: a = index into chunks[b].clipped
  Kind kind = kDeferred;         // kDeferredCulled: back faces are culled
};

struct SetupChunk {
  std::vector<DrawEntry> entries;         // draw order
  std::vector<SetupTriangle> clipped;     // set-up pieces of clipped triangles
  size_t bad_index_triangles = 0;         // skipped: an index beyond the mesh's vertices
};

// The triangles of a frame, in draw order: chunks[0], chunks[1], ... up to chunk_count, each the
// visible triangles of a fixed-size run of source triangles. A renderer keeps this between frames
// so the storage is reused (clear() keeps capacity) instead of allocated and page-faulted anew.
struct SetupBuffers {
  // Every mesh's vertices, transformed once: their clip outcodes (clip.h) and flags, and for those
  // inside every plane their projected, snapped screen vertex (shared by the mesh's triangles).
  // Meshes follow each other (a mesh's vertex i is at its base offset + i).
  std::vector<ScreenVertex> screen;
  std::vector<uint8_t> flags;
  std::vector<SetupChunk> chunks;  // capacity kept across frames
  size_t chunk_count = 0;          // chunks in use this frame

  // The set-up triangle of an entry: the stored one (kClipped), or setup_triangle of its three
  // screen vertices into *scratch (nullptr when it covers no sample or is culled).
  const SetupTriangle* triangle(const DrawEntry& e, int grid_width, int grid_height, SetupTriangle* scratch) const;
  // Sample rows [*row_begin, *row_end) the entry may cover (exactly setup_triangle's, so empty
  // when setup would drop it for its rows).
  void rows(const DrawEntry& e, int grid_height, int* row_begin, int* row_end) const;
  // Triangles of this frame skipped because an index is beyond their mesh's vertices.
  size_t bad_index_triangles() const;
};

// Triangles with a non-finite vertex (NaN/Inf position or colour, or a projection that overflows)
// or an out-of-range index are skipped, as are zero-area ones (triangle_setup.h); the ones with an
// out-of-range index are counted (SetupBuffers::bad_index_triangles) so that the caller can say so.
void setup_meshes(const std::vector<DrawMesh>& meshes, const Mat4d& clip_from_world, const GeometryOptions& options,
                  SetupBuffers& buffers);

// The same, set up and concatenated into one list (for tests and small scenes).
std::vector<SetupTriangle> setup_meshes(const std::vector<DrawMesh>& meshes, const Mat4d& clip_from_world,
                                        const GeometryOptions& options);

}  // namespace vlit::raster
