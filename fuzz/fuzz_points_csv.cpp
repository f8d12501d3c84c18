// libFuzzer target: bytes -> parse_points_csv (the probe's POINTS.csv). Bad input must end in an
// InputError; every accepted point is finite with a non-zero normal and m >= 0.
#include <cmath>
#include <cstdint>
#include <cstdlib>

#include "core/input_error.h"
#include "io/points_csv.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  try {
    const auto points = vlit::parse_points_csv(std::string(reinterpret_cast<const char*>(data), size), "fuzz.csv");
    for (const auto& p : points) {
      if (!vlit::is_finite(p.position) || !vlit::is_finite(p.normal) || !vlit::is_finite(p.eye)) std::abort();
      if (!(vlit::length_squared(p.normal) > 0) || !(p.shininess >= 0)) std::abort();
    }
  } catch (const vlit::InputError&) {
  }
  return 0;
}
