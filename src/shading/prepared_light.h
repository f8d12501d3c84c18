// A light ready for the per-vertex loop: the user's LightSource turned into the kernel of its
// model (shaders_cpu/), with every per-light constant computed once, in the scalar type T the
// loop runs in. shade() is the one place that dispatches on the light model.
#pragma once

#include <algorithm>
#include <optional>
#include <stdexcept>
#include <string>
#include <variant>

#include "conventions.h"
#include "area_light.h"
#include "directional_light.h"
#include "disk_light.h"
#include "linear_light.h"
#include "point_light.h"
#include "scene/light_source.h"
#include "spot_light.h"

namespace vlit {

// How the visible part of a shadowed area light is found (src/shadow/): from the silhouette
// edges of the occluders (area_silhouette.h; falls back to the cuts where its checks fail), or by
// cutting the light with every occluder triangle (area_visibility.h; the tests' reference).
enum class AreaShadowMethod { kSilhouette, kTriangleCuts };
// The same for a linear light: from the silhouette edges crossing the plane of P and the segment
// (linear_silhouette.h; falls back to the intervals where its checks fail), or from every
// occluder triangle's hidden interval (linear_visibility.h; the tests' reference).
enum class LinearShadowMethod { kSilhouette, kTriangleIntervals };

struct ShadeOptions {
  bool with_specular = true;
  // false: the caller has the diffuse already (a batch kernel's) and reads only the specular;
  // linear, area and disk lights then skip their diffuse (Response::diffuse is 0); point, spot and
  // directional lights compute it (a few operations, shared with their specular).
  bool with_diffuse = true;
  SpecularOptions specular;
  LinearDiffuseOptions linear;
  AreaShadowMethod area_shadows = AreaShadowMethod::kSilhouette;
  LinearShadowMethod linear_shadows = LinearShadowMethod::kSilhouette;
  // The vertex loop searches the occluders once per cluster of neighbouring vertices
  // (src/shadow/silhouette_cluster.h) instead of once per vertex; same results. Off: the
  // benchmarks' baseline.
  bool shadow_clusters = true;
  // Most vertices per cluster (neighbours in Morton order; a cluster also ends where its box
  // would grow wider than a fifth of the light's diameter, src/shadow/shadowed_vertices.cpp).
  // Any size gives the same results; 64 was faster than 32 on the bowling lane, DamagedHelmet
  // and MetalRoughSpheres, and than 128 and 256 on the lane (docs/shadows.md, "Stop 45";
  // `shadow_bench --cluster-sizes`).
  int shadow_cluster_size = 64;
  // A mesh vertex is also hidden by the wedges of triangles that touch it across a crease or a
  // seam (src/shadow/crease_wedges.h). Off: every triangle touching the vertex's position hides
  // nothing (the behaviour before; for comparisons).
  bool crease_wedges = true;
};

template <class T>
struct PreparedLight {
  using Kernel = std::variant<PointLight<T>, DirectionalLight<T>, SpotLight<T>, LinearLight<T>, PreparedAreaLight<T>,
                              PreparedDiskLight<T>>;
  LightType type = LightType::kPoint;
  Vec3<T> radiance{1, 1, 1};  // colour x intensity
  Kernel kernel;
  // glTF KHR_lights_punctual range (point and spot): 0 = unlimited.
  T range{0};
  Vec3<T> position;  // where the range is measured from
};

// The range window recommended by KHR_lights_punctual: clamp(1 - (d / range)^4, 0, 1), so the
// light fades smoothly to zero at `range` instead of being cut off.
template <class T>
T range_window(const PreparedLight<T>& light, const Vec3<T>& p) {
  if (!(light.range > T(0))) return T(1);
  const T ratio2 = length_squared(p - light.position) / (light.range * light.range);
  return std::clamp(T(1) - ratio2 * ratio2, T(0), T(1));
}

template <class T>
PreparedLight<T> prepare_light(const LightSource& light) {
  auto v = [](const Vec3d& d) { return static_cast<Vec3<T>>(d); };
  PreparedLight<T> out;
  out.type = light.type;
  out.radiance = v(light.color * light.intensity);
  if (light.range && (light.type == LightType::kPoint || light.type == LightType::kSpot)) {
    out.range = T(*light.range);
    out.position = v(light.position);
  }
  switch (light.type) {
    case LightType::kPoint:
      out.kernel = PointLight<T>{v(light.position), T(light.falloff)};
      break;
    case LightType::kDirectional:
      out.kernel = DirectionalLight<T>{v(light.direction)};
      break;
    case LightType::kSpot:
      out.kernel = SpotLight<T>{v(light.position), v(light.direction), T(light.cos_inner), T(light.cos_outer),
                                T(light.falloff)};
      break;
    case LightType::kLinear:
      out.kernel = LinearLight<T>{v(light.from), v(light.to), T(light.falloff)};
      break;
    case LightType::kArea: {
      AreaLight<T> area;
      for (const Vec3d& q : light.polygon) area.polygon.push_back(v(q));
      area.two_sided = light.two_sided;
      out.kernel = prepare_area_light(area);  // per-light constants, once (throws if invalid)
      break;
    }
    case LightType::kDisk:
      // per-light constants (frame, specular polygons), once (throws if invalid)
      out.kernel = prepare_disk_light(DiskLight<T>{v(light.center), v(light.normal), T(light.radius), light.two_sided});
      break;
  }
  return out;
}

// One light model at one point, for unit intensity and kd = ks = 1 (conventions.h), without the
// range window. Called with a concrete kernel type, it has no dispatch: the per-vertex loop
// resolves the model once per batch of vertices and calls this in its inner loop.
template <class T, class K>
Response<T> shade_kernel(const K& k, const ShadingPoint<T>& sp, const ShadeOptions& options) {
  const bool spec = options.with_specular && options.specular.method != SpecularMethod::kNone;
  if constexpr (std::is_same_v<K, PointLight<T>>) return shade_point(k, sp, spec, options.specular.falloff);
  else if constexpr (std::is_same_v<K, DirectionalLight<T>>) return shade_directional(k, sp, spec);
  else if constexpr (std::is_same_v<K, SpotLight<T>>) return shade_spot(k, sp, spec, options.specular.falloff);
  else {
    SpecularOptions s = options.specular;
    if (!spec) s.method = SpecularMethod::kNone;
    if constexpr (std::is_same_v<K, LinearLight<T>>) return shade_linear(k, sp, s, options.linear, options.with_diffuse);
    else if constexpr (std::is_same_v<K, PreparedAreaLight<T>>) return shade_area(k, sp, s, options.with_diffuse);
    else return shade_disk(k, sp, s, options.with_diffuse);
  }
}

// Response of one light at one point for unit intensity and kd = ks = 1, range window included.
template <class T>
Response<T> shade(const PreparedLight<T>& light, const ShadingPoint<T>& sp, const ShadeOptions& options) {
  const T window = range_window(light, sp.p);
  if (window <= T(0)) return {};
  Response<T> r = std::visit([&](const auto& k) { return shade_kernel<T>(k, sp, options); }, light.kernel);
  r.diffuse *= window;
  r.specular *= window;
  return r;
}

}  // namespace vlit
