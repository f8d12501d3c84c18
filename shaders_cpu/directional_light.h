// Directional light: Lambert diffuse and Phong specular for parallel rays (no falloff).
//
// Computes, for unit intensity (see conventions.h), with L̂ = -direction (towards the light):
//   diffuse  = max(0, N.L̂)                        (Picott 1992, eq. 1 with |L|^n = 1)
//   specular = [N.L̂ > 0] max(0, Rv.L̂)^m          (eq. 6)
// Departures from the paper: horizon clipping of the specular, as for every light.
#pragma once

#include "conventions.h"
#include "core/robust_math.h"

namespace vlit {

template <class T>
struct DirectionalLight {
  Vec3<T> direction{0, 0, -1};  // unit direction in which the light travels
};

template <class T>
Response<T> shade_directional(const DirectionalLight<T>& light, const ShadingPoint<T>& sp, bool with_specular) {
  const Vec3<T> to_light = -light.direction;
  const T cos_theta = dot(sp.n, to_light);
  if (cos_theta <= T(0)) return {};
  Response<T> r;
  r.diffuse = cos_theta;
  if (with_specular) r.specular = phong_power(dot(sp.rv, to_light), sp.shininess);
  return r;
}

}  // namespace vlit
