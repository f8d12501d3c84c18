// Vertex transform and per-triangle clip / project / snap / setup; see geometry_stage.h.
#include "raster/geometry_stage.h"

#include <algorithm>
#include <array>

#include "raster/clip.h"
#include "raster/fixed_point.h"

namespace vlit::raster {

namespace {

constexpr size_t kTriangleChunk = 4096;
constexpr long long kMinParallelVertices = 1 << 15;

// Per-vertex flags next to the clip outcode bits (bits 0..5, one per plane of clip.h).
constexpr uint8_t kPlaneBits = 0x3f;
constexpr uint8_t kNotFinite = 0x80;     // the clip-space position has a NaN or an infinity
constexpr uint8_t kNoProjection = 0x40;  // inside every plane but its projection is not finite

Vec3d vertex_color(const DrawMesh& mesh, uint32_t i) {
  return i < mesh.colors.size() ? Vec3d(mesh.colors[i]) : Vec3d{1, 1, 1};
}

// Appends triangle (i0, i1, i2) of `mesh` (whose vertex i is at base + i in screen_vertices and
// flags) to the chunk. Vertices inside every plane were projected once; a triangle using only
// those is deferred (DrawEntry). A triangle that needs clipping recomputes its clip-space
// positions (the same arithmetic, so the same values) and goes through clip_triangle.
void setup_one(const DrawMesh& mesh, const Mat4d& clip_from_world, const std::vector<uint8_t>& flags, size_t base,
               uint32_t i0, uint32_t i1, uint32_t i2, const ClipPlanes& planes, const GeometryOptions& options, bool cull,
               uint32_t chunk_index, SetupChunk& chunk) {
  const size_t n = mesh.positions.size();
  if (i0 >= n || i1 >= n || i2 >= n) {
    ++chunk.bad_index_triangles;
    return;
  }
  if (base + n > size_t(UINT32_MAX)) return;  // beyond 2^32 vertices in one frame (docs/rasterizer.md, limits)
  const uint8_t f0 = flags[base + i0], f1 = flags[base + i1], f2 = flags[base + i2];
  const uint8_t any = f0 | f1 | f2;
  if (any & kNotFinite) return;
  if (f0 & f1 & f2 & kPlaneBits) return;  // entirely outside one plane
  if ((any & kPlaneBits) == 0) {          // entirely inside: no clipping, set up where drawn
    if (any & kNoProjection) return;
    chunk.entries.push_back({uint32_t(base + i0), uint32_t(base + i1), uint32_t(base + i2),
                             cull ? DrawEntry::kDeferredCulled : DrawEntry::kDeferred});
    return;
  }
  std::vector<SetupTriangle>& out = chunk.clipped;
  const auto vertex = [&](uint32_t i) {
    return ClipVertex{transform_point_h(clip_from_world, Vec3d(mesh.positions[i])), vertex_color(mesh, i)};
  };
  const ClipVertex a = vertex(i0), b = vertex(i1), c = vertex(i2);

  std::array<ClipVertex, kMaxClipVertices> polygon;
  const int count = clip_triangle(a, b, c, planes, polygon);
  std::array<ScreenVertex, kMaxClipVertices> screen;
  for (int k = 0; k < count; ++k) {
    const std::optional<ScreenVertex> s = project_to_screen(polygon[k], options.grid_width, options.grid_height);
    if (!s) return;
    screen[k] = *s;
  }
  for (int k = 1; k + 1 < count; ++k) {  // fan: keeps the winding, shares the inner edges exactly
    // Edges 0 -> k and k+1 -> 0 are fan diagonals except on the polygon's boundary.
    const uint8_t original = uint8_t((k == 1 && polygon[0].original_edge_to_next ? 1 : 0) |
                                     (polygon[k].original_edge_to_next ? 2 : 0) |
                                     (k + 2 == count && polygon[count - 1].original_edge_to_next ? 4 : 0));
    if (auto t = setup_triangle(screen[0], screen[k], screen[k + 1], cull, options.grid_width, options.grid_height,
                                original)) {
      chunk.entries.push_back({uint32_t(out.size()), chunk_index, 0, DrawEntry::kClipped});
      out.push_back(*t);
    }
  }
}

}  // namespace

const SetupTriangle* SetupBuffers::triangle(const DrawEntry& e, int grid_width, int grid_height,
                                            SetupTriangle* scratch) const {
  if (e.kind == DrawEntry::kClipped) return &chunks[e.b].clipped[e.a];
  const std::optional<SetupTriangle> t =
      setup_triangle(screen[e.a], screen[e.b], screen[e.c], e.kind == DrawEntry::kDeferredCulled, grid_width, grid_height);
  if (!t) return nullptr;
  *scratch = *t;
  return scratch;
}

size_t SetupBuffers::bad_index_triangles() const {
  size_t n = 0;
  for (size_t c = 0; c < chunk_count; ++c) n += chunks[c].bad_index_triangles;
  return n;
}

void SetupBuffers::rows(const DrawEntry& e, int grid_height, int* row_begin, int* row_end) const {
  if (e.kind == DrawEntry::kClipped) {
    const SetupTriangle& t = chunks[e.b].clipped[e.a];
    *row_begin = t.row_begin;
    *row_end = t.row_end;
    return;
  }
  const int64_t top = std::min({screen[e.a].y, screen[e.b].y, screen[e.c].y});
  const int64_t bottom = std::max({screen[e.a].y, screen[e.b].y, screen[e.c].y});
  *row_begin = int(std::clamp<int64_t>(first_center_at_or_after(top), 0, grid_height));
  *row_end = int(std::clamp<int64_t>(first_center_at_or_after(bottom), 0, grid_height));
}

void setup_meshes(const std::vector<DrawMesh>& meshes, const Mat4d& clip_from_world, const GeometryOptions& options,
                  SetupBuffers& buffers) {
  const ClipPlanes planes = make_clip_planes(options.grid_width, options.grid_height, options.has_far_plane);
  buffers.chunk_count = 0;
  std::vector<ScreenVertex>& screen = buffers.screen;
  std::vector<uint8_t>& flags = buffers.flags;
  size_t total_vertices = 0;
  for (const DrawMesh& mesh : meshes) total_vertices += mesh.positions.size();
  screen.resize(total_vertices);
  flags.resize(total_vertices);
  size_t base = 0;
  for (const DrawMesh& mesh : meshes) {
    const bool cull = mesh.always_cull_back_faces || (options.cull_back_faces && !mesh.double_sided);
    const long long vertex_count = (long long)mesh.positions.size();
    // Small loops stay on the calling thread: waking the team costs more than the work (and,
    // on a loaded machine, a scheduler latency).
#pragma omp parallel for schedule(static) if (vertex_count >= kMinParallelVertices)
    for (long long i = 0; i < vertex_count; ++i) {
      uint8_t& f = flags[base + size_t(i)];
      const Vec4d clip = transform_point_h(clip_from_world, Vec3d(mesh.positions[i]));
      if (!is_finite(clip)) {
        f = kNotFinite;
        continue;
      }
      f = outcode(planes, clip);
      if (f != 0) continue;
      const std::optional<ScreenVertex> s =
          project_to_screen(ClipVertex{clip, vertex_color(mesh, uint32_t(i))}, options.grid_width, options.grid_height);
      if (s) screen[base + size_t(i)] = *s;
      else f = kNoProjection;
    }

    const size_t triangle_count = mesh.indices.size() / 3;
    const size_t first_chunk = buffers.chunk_count;
    const long long chunk_count = (long long)((triangle_count + kTriangleChunk - 1) / kTriangleChunk);
    buffers.chunk_count += size_t(chunk_count);
    if (buffers.chunks.size() < buffers.chunk_count) buffers.chunks.resize(buffers.chunk_count);
#pragma omp parallel for schedule(dynamic, 1) if (chunk_count > 1)
    for (long long chunk = 0; chunk < chunk_count; ++chunk) {
      const uint32_t chunk_index = uint32_t(first_chunk + size_t(chunk));
      SetupChunk& out = buffers.chunks[chunk_index];
      out.entries.clear();
      out.clipped.clear();
      out.bad_index_triangles = 0;
      const size_t end = std::min(triangle_count, size_t(chunk + 1) * kTriangleChunk);
      out.entries.reserve(end - size_t(chunk) * kTriangleChunk);
      for (size_t t = size_t(chunk) * kTriangleChunk; t < end; ++t)
        setup_one(mesh, clip_from_world, flags, base, mesh.indices[3 * t], mesh.indices[3 * t + 1],
                  mesh.indices[3 * t + 2], planes, options, cull, chunk_index, out);
    }
    base += mesh.positions.size();
  }
}

std::vector<SetupTriangle> setup_meshes(const std::vector<DrawMesh>& meshes, const Mat4d& clip_from_world,
                                        const GeometryOptions& options) {
  SetupBuffers buffers;
  setup_meshes(meshes, clip_from_world, options, buffers);
  std::vector<SetupTriangle> result;
  SetupTriangle scratch;
  for (size_t c = 0; c < buffers.chunk_count; ++c)
    for (const DrawEntry& e : buffers.chunks[c].entries)
      if (const SetupTriangle* t = buffers.triangle(e, options.grid_width, options.grid_height, &scratch))
        result.push_back(*t);
  return result;
}

}  // namespace vlit::raster
