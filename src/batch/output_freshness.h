// --skip-existing: whether a batch can keep an output from an earlier run. Outputs are written
// atomically (io/atomic_write.h), so an output that exists is complete; it is current when it
// was written after its input and its LIGHTS.json were last changed.
#pragma once

#include <string>

namespace vlit {

// True when `output` exists and its modification time is strictly later than that of `input` and,
// if `lights` is not empty, of `lights`. Other files the input refers to (a .gltf's .bin and
// images, an .obj's .mtl) and the bake options are not compared (docs/batch-sharding.md).
bool output_is_current(const std::string& output, const std::string& input, const std::string& lights);

}  // namespace vlit
