#include "cli/specular_option.h"

#include <stdexcept>

#include "cli/usage_error.h"

namespace vlit::cli {

SpecularOptions parse_specular(const std::string& text) {
  SpecularOptions s;
  if (text == "peak") s.method = SpecularMethod::kPeak;
  else if (text == "exact") s.method = SpecularMethod::kExact;
  else if (text == "exact-no-falloff") {
    s.method = SpecularMethod::kExact;
    s.falloff = SpecularFalloff::kNone;
  }
  else if (text == "none") s.method = SpecularMethod::kNone;
  else if (text.rfind("neighborhood:", 0) == 0) {
    s.method = SpecularMethod::kNeighborhood;
    const std::string k = text.substr(13);
    try {
      std::size_t used = 0;
      s.neighborhood_samples = std::stoi(k, &used);
      if (used != k.size() || s.neighborhood_samples < 1 || s.neighborhood_samples > 1024) throw std::invalid_argument(k);
    } catch (const std::exception&) {
      throw UsageError("--specular: neighborhood:K needs an integer K in [1, 1024], got \"" + k + "\"");
    }
  } else {
    throw UsageError("--specular: expected exact, exact-no-falloff, peak, neighborhood:K or none, got \"" + text + "\"");
  }
  return s;
}

}  // namespace vlit::cli
