// Spot light: a point light (point_light.h) times a smooth cone attenuation.
//
// Cone attenuation as in glTF KHR_lights_punctual: with c = cos of the angle between the spot axis
// and the ray from the light to P, s = clamp((c - cos_outer) / (cos_inner - cos_outer), 0, 1),
// attenuation = s^2. Inside the inner cone the light is a point light; outside the outer cone it
// is dark. The same factor scales diffuse and specular (the paper's figure 3 spotlights); the
// specular has the point light's distance falloff (point_light.h).
// Stiff cases: inner = outer (a hard cone edge) divides by max(cos_inner - cos_outer, 1e-6).
#pragma once

#include <algorithm>

#include "point_light.h"

namespace vlit {

template <class T>
struct SpotLight {
  Vec3<T> position;
  Vec3<T> direction{0, 0, -1};  // unit axis of the cone, pointing away from the light
  T cos_inner{1};               // cosine of the inner cone half-angle
  T cos_outer{T(0.70710678118654752)};  // cosine of the outer cone half-angle (<= cos_inner)
  T falloff{2};
};

template <class T>
T spot_attenuation(const SpotLight<T>& light, const Vec3<T>& p) {
  const Vec3<T> from_light = normalize(p - light.position);
  const T c = dot(from_light, light.direction);
  const T width = std::max(light.cos_inner - light.cos_outer, T(1e-6));
  const T s = std::clamp((c - light.cos_outer) / width, T(0), T(1));
  return s * s;
}

template <class T>
Response<T> shade_spot(const SpotLight<T>& light, const ShadingPoint<T>& sp, bool with_specular,
                       SpecularFalloff specular_falloff = SpecularFalloff::kAsDiffuse) {
  const T attenuation = spot_attenuation(light, sp.p);
  if (attenuation <= T(0)) return {};
  Response<T> r = shade_point(PointLight<T>{light.position, light.falloff}, sp, with_specular, specular_falloff);
  r.diffuse *= attenuation;
  r.specular *= attenuation;
  return r;
}

}  // namespace vlit
