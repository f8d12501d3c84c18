// libFuzzer target: bytes -> parse_lights_json (LIGHTS.json, docs/lights-json.md). Bad input must
// end in an InputError; a parsed light must be finite and valid (what the kernels assume).
#include <cmath>
#include <cstdint>
#include <cstdlib>

#include "core/input_error.h"
#include "io/lights_json.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  try {
    const auto lights = vlit::parse_lights_json(std::string(reinterpret_cast<const char*>(data), size), "fuzz.json");
    for (const auto& l : lights) {
      if (!std::isfinite(l.intensity) || l.intensity < 0 || !vlit::is_finite(l.color)) std::abort();
      if (!(l.falloff >= 0 && l.falloff <= 3)) std::abort();
      if (!vlit::is_finite(l.position) || !vlit::is_finite(l.direction)) std::abort();
    }
  } catch (const vlit::InputError&) {
  }
  return 0;
}
