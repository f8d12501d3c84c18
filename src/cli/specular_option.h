// The --specular option shared by render, bake and probe:
//   exact (default)    the lobe integrated over the light, with the diffuse's distance falloff
//                      (docs/conventions.md "Radiometric definitions")
//   exact-no-falloff   the same integral without 1/|L|^n on point, spot and linear lights (the
//                      paper's eq. 6 and its integral along the segment)
//   peak               the lobe's maximum over a linear or area light (paper eq. 7-8, 11-12; fast)
//   neighborhood:K     the lobe's maximum refined by K samples around it (the paper's refinement)
//   none               no specular
#pragma once

#include <string>

#include "conventions.h"

namespace vlit::cli {

// Throws InputError("--specular", ...) for anything else.
SpecularOptions parse_specular(const std::string& text);

}  // namespace vlit::cli
