// A horizontal band of the sample grid (colour + depth per sample), the per-span shading that
// writes into it (depth test, perspective-correct Gouraud colour), and the box-filter resolve of
// its samples into image pixels.
#pragma once

#include <vector>

#include "core/vec3.h"
#include "raster/image.h"
#include "raster/triangle_setup.h"

namespace vlit::raster {

class SampleBand {
 public:
  // Holds sample rows [row_begin, row_end) of a sample grid `width` samples wide, cleared to the
  // background colour and the far depth. Reuses its storage across calls. With one sample per
  // pixel the colours can live in the image itself: pass image_rows = the image's pixel at
  // (0, row_begin) (the image must be `width` wide); resolve() then only fills in the background.
  void reset(int width, int row_begin, int row_end, const Vec3f& background, float* image_rows = nullptr);

  // Depth-tests and writes the samples [col_begin, col_end) of sample row `row` covered by t.
  // A sample is written when its depth is strictly greater (nearer) than the stored one: on an
  // exact tie the triangle drawn first wins.
  void shade_span(const SetupTriangle& t, int row, int col_begin, int col_end);

  // shade_span, then samples closer than wire_width (sample-grid pixels) to one of t's original
  // edges (the line through it) get wire_color instead of the Gouraud colour (render.h's
  // WireframeOptions states the rule).
  void shade_span_wireframe(const SetupTriangle& t, int row, int col_begin, int col_end, double wire_width,
                            const Vec3f& wire_color);

  // Averages each samples_per_side x samples_per_side block (box filter, linear RGB) into the
  // image pixels of this band. The band must start and end on pixel boundaries.
  // With image_rows (see reset), writes the background into the samples no triangle covered.
  void resolve(int samples_per_side, Image& image);

  int row_begin() const { return row_begin_; }
  int row_end() const { return row_end_; }

 private:
  template <class ColorOf>
  void step_span(const SetupTriangle& t, int row, int col_begin, int col_end, const ColorOf& color_of);

  int width_ = 0, row_begin_ = 0, row_end_ = 0;
  std::vector<float> depth_;  // reversed depth (greater is nearer), cleared to -1 (below any surface)
  void store_color(size_t sample, const Vec3f& c) {
    float* p = color_ + 3 * sample;
    p[0] = c.x;
    p[1] = c.y;
    p[2] = c.z;
  }

  std::vector<float> own_color_;  // 3 floats per sample, the layout of Image::rgb
  float* color_ = nullptr;        // own_color_ or rows of the image
  Vec3f background_;
};

}  // namespace vlit::raster
