// The advice a bake gives when an unorm encoding clips many vertices: how many, and the exposure
// that would fit them (all of them, and 99 %), from the brightest channels BakeReport measured.
#pragma once

#include <string>

#include "bake/vertex_color_bake.h"

namespace vlit {

// More than this fraction of the vertices clipped above 1 earns a warning.
constexpr double kClippedWarningFraction = 0.02;

// Empty when at most kClippedWarningFraction of the vertices clipped; otherwise one line,
// "4319 of 4555 vertices (94.8 %) clipped above 1 at exposure 1; --exposure 0.0123 fits them all,
// 0.0456 fits 99 %". The exposures are rounded down to 3 significant digits, so that they fit.
std::string clipping_advice(const BakeReport& report, double exposure);

// `value` rounded toward zero to `digits` significant digits (value > 0 and finite).
double round_down_significant(double value, int digits);

}  // namespace vlit
