// The --specular option shared by render and probe: peak | neighborhood:K | exact | none.
#pragma once

#include <string>

#include "conventions.h"

namespace vlit::cli {

// Throws InputError("--specular", ...) for anything else.
SpecularOptions parse_specular(const std::string& text);

}  // namespace vlit::cli
