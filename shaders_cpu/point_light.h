// Point light: Lambert diffuse with distance falloff and Phong specular.
//
// Computes, for unit intensity (see conventions.h):
//   diffuse  = max(0, N.L̂) / |L|^n                     (Picott 1992, eq. 1 and 2)
//   specular = [N.L > 0] max(0, Rv.L̂)^m / |L|^n        (Picott 1992, eq. 6 with the diffuse's falloff)
// with L = Q - P. The paper's eq. 6 names the angle between the sight vector and the reflected
// light ray; Rv.L̂ is the same cosine (reflection about N preserves angles).
//
// Departures from the paper: horizon clipping (N.L <= 0 gives nothing, also to the specular); the
// specular carries the distance falloff of the diffuse (docs/conventions.md "Radiometric
// definitions"); eq. 6 as printed, without it, is SpecularFalloff::kNone.
// Tests: tests/unit/point_light_test.cpp ("point light specular carries the distance falloff").
// Stiff cases: P at Q (|L| = 0) gives zero rather than Inf (tests/unit/point_light_test.cpp,
// "point light at the surface point").
#pragma once

#include <cmath>

#include "conventions.h"
#include "core/robust_math.h"

namespace vlit {

template <class T>
struct PointLight {
  Vec3<T> position;
  T falloff{2};  // decay exponent n of eq. 1
};

template <class T>
Response<T> shade_point(const PointLight<T>& light, const ShadingPoint<T>& sp, bool with_specular,
                        SpecularFalloff specular_falloff = SpecularFalloff::kAsDiffuse) {
  const Vec3<T> l = light.position - sp.p;
  const T dist2 = length_squared(l);
  const T n_dot_l = dot(sp.n, l);
  if (!(dist2 > T(0)) || n_dot_l <= T(0)) return {};
  const T dist = std::sqrt(dist2);
  const T cos_theta = n_dot_l / dist;
  Response<T> r;
  // eq. 1: cos(theta) / |L|^n; integer exponents avoid pow for the common n = 2.
  const T falloff = light.falloff == T(2) ? dist2 : (light.falloff == T(0) ? T(1) : std::pow(dist, light.falloff));
  r.diffuse = cos_theta / falloff;
  if (with_specular) {
    r.specular = phong_power(dot(sp.rv, l) / dist, sp.shininess);  // eq. 6
    if (specular_falloff == SpecularFalloff::kAsDiffuse) r.specular /= falloff;
  }
  return r;
}

}  // namespace vlit
