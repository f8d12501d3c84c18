// LIGHTS.json: the lights side-file (format in docs/lights-json.md).
// Parsing and validation live here so that the kernels never see JSON: every problem is an
// InputError naming the file and the JSON pointer of the offending value.
#pragma once

#include <string>
#include <vector>

#include "scene/light_source.h"

namespace vlit {

// Reads and validates a LIGHTS.json file. Throws InputError on any problem.
std::vector<LightSource> read_lights_json(const std::string& path);

// Same, from text already in memory; `name` is used in messages in place of a path.
std::vector<LightSource> parse_lights_json(const std::string& text, const std::string& name);

}  // namespace vlit
