// Conventions shared by every per-vertex lighting kernel in shaders_cpu/.
//
// Frames and units
// - All positions and directions are in world space, in the asset's units (glTF: metres).
// - P is the shaded surface point, N its unit normal, E the eye. V = normalize(E - P) and the
//   reflected view direction Rv = 2 (N.V) N - V (the paper's S) is unit length.
// - Kernels compute the response to a light of unit intensity with kd = ks = 1 (white, scalar):
//   the caller multiplies by the light's intensity, colour and the material's kd / ks.
// - Horizon clipping: light arriving from below the tangent plane of P (L.N <= 0) contributes
//   nothing, to the diffuse and to the specular term. The paper ignores this; we do not.
// - Diffuse = Ip kd ∫ max(0, cos theta) (falloff) over the light, specular = Ip ks ∫ [L.N > 0]
//   max(0, Rv.L̂)^m (falloff) with the same distance falloff 1/|L|^n as the diffuse for point, spot
//   and linear lights (SpecularFalloff; the paper's eq. 6 has none), or the paper's
//   most-important-point approximation of it (the lobe's maximum); see docs/conventions.md
//   "Radiometric definitions".
// - Colours are linear RGB everywhere; encoding (sRGB PNG, unorm glTF) happens only at output.
//
// Scalar type: every kernel is a template on T = float or double. Kernels know nothing about
// glTF, JSON, threads or allocation policy: they read plain structs and return numbers.
#pragma once

#include "core/vec3.h"

namespace vlit {

// What a kernel needs to know about the surface point.
template <class T>
struct ShadingPoint {
  Vec3<T> p;        // position P
  Vec3<T> n;        // unit normal N
  Vec3<T> rv;       // unit reflected view direction Rv = 2(N.V)N - V
  T shininess{1};   // Phong exponent m >= 0
};

// Builds a ShadingPoint from P, a (not necessarily unit) normal and the eye position.
template <class T>
ShadingPoint<T> make_shading_point(const Vec3<T>& p, const Vec3<T>& normal, const Vec3<T>& eye,
                                   T shininess) {
  const Vec3<T> n = normalize(normal);
  const Vec3<T> v = normalize(eye - p);
  const Vec3<T> rv = normalize(n * (T(2) * dot(n, v)) - v);
  return {p, n, rv, shininess};
}

// Diffuse and specular response of one light at one point, for unit intensity and kd = ks = 1.
template <class T>
struct Response {
  T diffuse{0};
  T specular{0};
  constexpr Response& operator+=(const Response& o) { diffuse += o.diffuse; specular += o.specular; return *this; }
};

// How the specular of an extended (linear or area) light is evaluated.
enum class SpecularMethod {
  kNone,          // diffuse only
  kPeak,          // paper eq. 7-8 / 11-12: the lobe's maximum over the light (fast mode)
  kNeighborhood,  // the paper's refinement: K samples around the most important point
  kExact,         // the Phong lobe integrated over the light (the definition; the default)
};

// Whether the specular of point, spot and linear lights carries the light's distance falloff
// 1/|L|^n (the radiometric definition: the BRDF scales the light's irradiance, as in glTF) or not
// (Picott 1992 eq. 6 as printed, and its integral along the segment: reachable by name,
// `--specular exact-no-falloff`). Area, disk and directional lights have no 1/|L|^n to drop: their
// specular is the same under both. The peak and neighbourhood specular of a linear light is the
// lobe's maximum (no falloff) under both.
enum class SpecularFalloff {
  kAsDiffuse,  // 1/|L|^n on the specular, as on the diffuse (default)
  kNone,       // the paper's eq. 6: no distance falloff on the specular
};

struct SpecularOptions {
  SpecularMethod method = SpecularMethod::kExact;
  SpecularFalloff falloff = SpecularFalloff::kAsDiffuse;
  int neighborhood_samples = 4;        // K for kNeighborhood
  double exact_tolerance = 1e-9;       // relative tolerance of the exact (quadrature) specular
};

}  // namespace vlit
