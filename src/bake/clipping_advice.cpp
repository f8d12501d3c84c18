#include "bake/clipping_advice.h"

#include <cmath>
#include <cstdio>

namespace vlit {

double round_down_significant(double value, int digits) {
  const double scale = std::pow(10.0, digits - 1 - static_cast<int>(std::floor(std::log10(value))));
  double rounded = std::floor(value * scale) / scale;
  // value * scale may round up to the next integer in floating point: step down once more.
  if (rounded > value) rounded = (std::floor(value * scale) - 1) / scale;
  return rounded;
}

std::string clipping_advice(const BakeReport& report, double exposure) {
  if (report.vertices == 0 || !(report.clipped_vertices > kClippedWarningFraction * static_cast<double>(report.vertices)))
    return {};
  char line[320];
  int at = std::snprintf(line, sizeof line, "%zu of %zu vertices (%.1f %%) clipped above 1 at exposure %g",
                         report.clipped_vertices, report.vertices,
                         100.0 * static_cast<double>(report.clipped_vertices) / static_cast<double>(report.vertices), exposure);
  if (report.brightest_channel > 1 && std::isfinite(report.brightest_channel))
    at += std::snprintf(line + at, sizeof line - at, "; --exposure %.3g fits them all",
                        round_down_significant(exposure / report.brightest_channel, 3));
  if (report.brightest_channel_p99 > 1 && std::isfinite(report.brightest_channel_p99))
    std::snprintf(line + at, sizeof line - at, ", %.3g fits 99 %%", round_down_significant(exposure / report.brightest_channel_p99, 3));
  return line;
}

}  // namespace vlit
