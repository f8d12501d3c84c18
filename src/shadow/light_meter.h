// The light meter of `vlit probe` and of the library's probe: diffuse and specular at one point,
// kd = ks = 1, summed over the lights with their scalar intensities (colours ignored), each light
// hidden by the occluders when given and when it casts shadows (double only: the shadowed
// kernels are double). wedges: the crease wedges of the mesh vertex the point stands on
// (point_wedges.h), empty for other points.
#pragma once

#include <span>
#include <type_traits>
#include <vector>

#include "shading/prepared_light.h"
#include "shadow/shadowed_light.h"

namespace vlit {

struct MeterReading {
  double diffuse = 0, specular = 0;
};

template <class T>
MeterReading light_meter(const std::vector<PreparedLight<T>>& lights, const std::vector<LightSource>& sources,
                         const ShadingPoint<T>& sp, const ShadeOptions& options, const OccluderBvh* occluders,
                         std::span<const WedgeCone> wedges = {}) {
  MeterReading out;
  for (std::size_t l = 0; l < lights.size(); ++l) {
    Response<T> r;
    if constexpr (std::is_same_v<T, double>) {
      r = occluders && sources[l].casts_shadows ? shade_shadowed(lights[l], sp, options, *occluders, wedges)
                                                : shade(lights[l], sp, options);
    } else {
      r = shade(lights[l], sp, options);
    }
    out.diffuse += sources[l].intensity * static_cast<double>(r.diffuse);
    out.specular += sources[l].intensity * static_cast<double>(r.specular);
  }
  return out;
}

}  // namespace vlit
