// The accuracy report's parts, one per light model (linear_report.cpp, area_report.cpp,
// disk_report.cpp) and one per end-to-end measurement (end_to_end_report.cpp,
// cycles_report.cpp). Each returns its sections and numbers; none writes prose: the document's
// text is docs/accuracy.md.in, filled by bench/accuracy_report.cpp.
#pragma once

#include <string>
#include <vector>

#include "report_core.h"

namespace vlit::bench::accuracy {

// Linear light: closed forms, adaptive and fixed Gauss-Legendre, Monte Carlo (diffuse); peak,
// neighbourhood, exact, fixed GL, Monte Carlo (specular); and the peak against the lobe's maximum.
struct LinearSections {
  Section diffuse, specular;
  Stats peak_vs_max, peak_vs_max_float;  // the peak method against the lobe's maximum (ordinary cases)
  // (lobe maximum) / (exact integral) over the lit ordinary cases: count, min, median, max.
  std::size_t ratio_count = 0;
  double ratio_min = NAN, ratio_med = NAN, ratio_max = NAN;
};
LinearSections linear_report(const Options& o);

// Area light: contour form and Monte Carlo (diffuse); peak, neighbourhood, exact, Monte Carlo (specular).
struct AreaSections {
  Section diffuse, specular;
};
AreaSections area_report(const Options& o);

// Disk light: the analytic contour and equal-area polygons (diffuse); exact specular by tolerance.
struct DiskSections {
  Section diffuse, specular;
};
DiskSections disk_report(const Options& o);

// Where the end-to-end figure draws an error of exactly 0 (log scale).
constexpr double kEndToEndZero = 1e-9;

// vlit against Blender Cycles on the asset (reference/accuracy_blender.h, bench/blender_bake.py).
struct CyclesComparison {
  bool available = false;
  std::string why_not;  // without Cycles data: why (a sentence)
  std::string table;    // markdown table: vlit settings and Cycles runs
  std::string plot;     // extra gnuplot clauses for the end-to-end figure (", 'file' using ...")
  std::string calibration, cli_bake;  // Cycles' calibration output and the CLI bake's times; may be empty
  std::string asset_name, lights_name, blender_version;
  std::size_t vertices = 0, triangles = 0, unmatched = 0, cycles_lights = 0;
  int runs_counted = 1, best_samples = 0, tube_points = 0;
  double import_seconds = 0, best_seconds = 0, best_error = 0, vlit_seconds = 0, vlit_error = 0;
  double ratio_at_best = NAN;  // Cycles time at its most accurate point / vlit default time
  double slope_med = NAN, slope_max = NAN, samples_needed = 0, seconds_needed = 0, chain_error = 0;
};
CyclesComparison cycles_comparison(const Options& o);

// A real asset lit by linear and area lights under several settings, against a reference setting.
struct EndToEnd {
  bool done = false;
  std::string asset_name;
  std::size_t vertices = 0, triangles = 0;
  std::string table;  // markdown: one row per setting
  // COLOR_0 encodings of the default bake: largest |stored - exact| over unclipped channels,
  // vertices with a channel clipped above 1, encode time, bytes per vertex of the attribute.
  struct Format { std::string name; double max_quantization = NAN; std::size_t clipped = 0; double seconds = 0; int bytes = 0; };
  std::vector<Format> formats;
  double light_top = 0;       // largest diffuse channel of the default bake
  double default_seconds = 0;  // lighting time of the default setting
  double diffuse_max_rel = NAN;  // default vs reference, diffuse max/top
  // Diffuse-only lighting at equal settings: float SIMD batch kernels vs scalar double kernels.
  struct Run { double max_rel = NAN; double seconds = NAN; };
  Run batch, scalar_double;
  int nonfinite = 0;
  CyclesComparison cycles;
};
EndToEnd end_to_end(const Options& o);

}  // namespace vlit::bench::accuracy
