#include "scene/light_source.h"

namespace vlit {

const char* light_type_name(LightType type) {
  switch (type) {
    case LightType::kPoint: return "point";
    case LightType::kDirectional: return "directional";
    case LightType::kSpot: return "spot";
    case LightType::kLinear: return "linear";
    case LightType::kArea: return "area";
    case LightType::kDisk: return "disk";
  }
  return "unknown";
}

}  // namespace vlit
