// Orchestration of the pipeline: geometry stage, then bands of rows in parallel; see render.h.
#include "raster/render.h"

#include <algorithm>
#include <cmath>

#include <omp.h>

#include "raster/fixed_point.h"
#include "raster/framebuffer.h"
#include "raster/geometry_stage.h"
#include "raster/rasterize_triangle.h"

namespace vlit::raster {

namespace {

constexpr int kMaxSamplesPerSide = 8;
constexpr int kMaxBandRows = 16;                      // image rows per band: many bands balance threads
constexpr size_t kBandSampleBudget = size_t{1} << 20;  // samples per band buffer (16 MiB)

}  // namespace

int samples_per_side(int samples) {
  for (int side = 1; side <= kMaxSamplesPerSide; ++side)
    if (side * side == samples) return side;
  return 1;
}

std::string validate_render_options(const RenderOptions& options) {
  if (options.width <= 0 || options.height <= 0) return "image width and height must be positive";
  if (samples_per_side(options.samples) * samples_per_side(options.samples) != options.samples)
    return "samples must be a perfect square from 1 to 64 (1, 4, 16, ...)";
  const long long side = samples_per_side(options.samples);
  if (options.width * side > kMaxGridSize || options.height * side > kMaxGridSize)
    return "image too large: width and height times sqrt(samples) must not exceed " +
           std::to_string(kMaxGridSize);
  if (!is_finite(options.background)) return "background colour must be finite";
  if (options.wireframe.enabled &&
      !(std::isfinite(options.wireframe.width) && options.wireframe.width > 0 && is_finite(options.wireframe.color)))
    return "wireframe line width must be positive and its colour finite";
  return {};
}

struct RenderWorkspace::Buffers {
  SetupBuffers setup;
  std::vector<std::vector<const DrawEntry*>> bins;  // per band, in draw order
  std::vector<SampleBand> bands;                        // per thread
};

RenderWorkspace::RenderWorkspace() : buffers(std::make_unique<Buffers>()) {}
RenderWorkspace::~RenderWorkspace() = default;
RenderWorkspace::RenderWorkspace(RenderWorkspace&&) noexcept = default;
RenderWorkspace& RenderWorkspace::operator=(RenderWorkspace&&) noexcept = default;
size_t RenderWorkspace::bad_index_triangles() const { return buffers ? buffers->setup.bad_index_triangles() : 0; }

Image render(const std::vector<DrawMesh>& meshes, const Camera& camera, const RenderOptions& options) {
  RenderWorkspace workspace;
  Image image;
  render(meshes, camera, options, workspace, image);
  return image;
}

void render(const std::vector<DrawMesh>& meshes, const Camera& camera, const RenderOptions& options,
            RenderWorkspace& workspace, Image& image) {
  if (!validate_render_options(options).empty()) {
    image = Image{};
    if (workspace.buffers) workspace.buffers->setup.chunk_count = 0;  // no triangle of this frame
    return;
  }
  if (!workspace.buffers) workspace.buffers = std::make_unique<RenderWorkspace::Buffers>();
  RenderWorkspace::Buffers& buffers = *workspace.buffers;
  const int side = samples_per_side(options.samples);
  image.width = options.width;
  image.height = options.height;
  image.rgb.resize(size_t(options.width) * options.height * 3);  // every pixel is written below
  const std::optional<Mat4d> clip_from_world_m = clip_from_world(camera, double(options.width) / options.height);
  if (!clip_from_world_m) {
    for (size_t i = 0; i < image.rgb.size(); i += 3) {
      image.rgb[i] = options.background.x;
      image.rgb[i + 1] = options.background.y;
      image.rgb[i + 2] = options.background.z;
    }
    buffers.setup.chunk_count = 0;  // no triangle of this frame
    return;
  }

  GeometryOptions geometry;
  geometry.grid_width = options.width * side;
  geometry.grid_height = options.height * side;
  geometry.has_far_plane = camera.orthographic || camera.zfar.has_value();
  geometry.cull_back_faces = options.cull_back_faces;
  setup_meshes(meshes, *clip_from_world_m, geometry, buffers.setup);

  const size_t samples_per_row = size_t(geometry.grid_width) * side;
  const int band_rows = int(std::clamp<size_t>(kBandSampleBudget / samples_per_row, 1, kMaxBandRows));
  const int band_count = (options.height + band_rows - 1) / band_rows;
  const int band_sample_rows = band_rows * side;
  const double wire_width_samples = options.wireframe.enabled ? options.wireframe.width * side : 0.0;

  // Bin the triangles by band, keeping draw order, so a band never looks at the others.
  std::vector<std::vector<const DrawEntry*>>& bins = buffers.bins;
  if (bins.size() < size_t(band_count)) bins.resize(band_count);
  for (int b = 0; b < band_count; ++b) bins[b].clear();
  const SetupBuffers& setup = buffers.setup;
  for (size_t c = 0; c < setup.chunk_count; ++c)
    for (const DrawEntry& e : setup.chunks[c].entries) {
      int row_begin = 0, row_end = 0;
      setup.rows(e, geometry.grid_height, &row_begin, &row_end);
      if (row_begin >= row_end) continue;
      for (int b = row_begin / band_sample_rows; b <= (row_end - 1) / band_sample_rows; ++b) bins[b].push_back(&e);
    }

  if (buffers.bands.size() < size_t(omp_get_max_threads())) buffers.bands.resize(omp_get_max_threads());
#pragma omp parallel
  {
    SampleBand& band = buffers.bands[omp_get_thread_num()];  // one buffer per thread, reused across bands and frames
#pragma omp for schedule(dynamic, 1)
    for (int b = 0; b < band_count; ++b) {
      const int y_end = std::min(options.height, (b + 1) * band_rows);
      // One sample per pixel: the band's colours are the image rows themselves (no copy).
      float* image_rows = side == 1 ? image.pixel(0, b * band_rows) : nullptr;
      band.reset(geometry.grid_width, b * band_rows * side, y_end * side, options.background, image_rows);
      SetupTriangle scratch;
      for (const DrawEntry* entry : bins[b]) {
        // Deferred triangles are set up here, by every band they overlap (same bits each time).
        const SetupTriangle* triangle = setup.triangle(*entry, geometry.grid_width, geometry.grid_height, &scratch);
        if (!triangle) continue;
        const SetupTriangle& t = *triangle;
        if (wire_width_samples > 0)
          scan_triangle(t, band.row_begin(), band.row_end(), geometry.grid_width, [&](int row, int col_begin, int col_end) {
            band.shade_span_wireframe(t, row, col_begin, col_end, wire_width_samples, options.wireframe.color);
          });
        else
          scan_triangle(t, band.row_begin(), band.row_end(), geometry.grid_width,
                        [&](int row, int col_begin, int col_end) { band.shade_span(t, row, col_begin, col_end); });
      }
      band.resolve(side, image);
    }
  }
}

}  // namespace vlit::raster
