// Disk light: a one-sided (or two-sided) Lambertian disk. Diffuse analytic, specular through a
// bracket of polygons prepared once per light.
//
// Computes the same quantities as area_light.h (diffuse; peak / neighbourhood / exact specular)
// for the disk {x : (x - center).normal = 0, |x - center| <= radius}, emitting toward `normal`.
//
// Method (docs/area-lights.md "Disk lights"):
// - diffuse: Lambert's contour integral (Picott 1992 eq. 9) in closed form over the circle, with
//   horizon clipping (arc + chord): disk_diffuse_contour.h. Rounding-level accurate; no polygon.
// - exact specular: the lobe's contour integral over the disk's own boundary (rim arcs and
//   chords), error-controlled: disk_specular_exact.h.
// - peak and neighbourhood specular: the inscribed regular 64-gon (vertex radius R) and the
//   circumscribed one (R / cos(pi/64)), prepared once per light by prepare_disk_light, shaded by
//   the area specular kernels. All integrands are >= 0 and the peak is monotone in the set, so
//     I_in <= I_disk <= I_out   (a rigorous bracket for the exact specular and the peak)
//   and we return (2 I_out + I_in) / 3, whose area is exact to O(n^-4)
//   (A_in/A = 1 - 2 pi^2/(3 n^2) + ..., A_out/A = 1 + pi^2/(3 n^2) + ...).
// Sources: Picott 1992 eq. 9-12; Archimedes' bracket for the specular.
// Conventions: conventions.h. Departures from the paper: the paper has no disk lights.
// Scalar type: computed in AreaReal<T> (double for T = float), rounded once.
// Stiff cases: tests/kernels/area/disk_test.cpp.
// Measured accuracy: docs/area-lights.md "Disk lights" (`./build/release/tests/area_light_tests -tc="disk*"`).
#pragma once

#include <cmath>
#include <stdexcept>

#include "area_light.h"
#include "disk_diffuse_contour.h"
#include "disk_specular_exact.h"

namespace vlit {

template <class T>
struct DiskLight {
  Vec3<T> center;
  Vec3<T> normal;  // emits toward normal (need not be unit)
  T radius{1};
  bool two_sided = false;
};

// Edge count of the specular bracket's polygons (the area kernels' vertex cap).
inline constexpr int kDiskSpecularEdges = kMaxAreaVertices;

// The regular n-gon of vertex radius `vertex_radius` in the disk's plane, CCW seen from normal.
// Throws std::invalid_argument for a disk without a finite center, a non-zero normal and radius > 0.
template <class T>
PreparedAreaLight<T> disk_polygon(const DiskLight<T>& light, int n, AreaReal<T> vertex_radius) {
  using R = AreaReal<T>;
  if (n < 3 || n > kMaxAreaVertices) throw std::invalid_argument("disk light: bad edge count");
  const Vec3<R> nl = normalize(static_cast<Vec3<R>>(light.normal));
  if (!is_finite(nl) || !(length_squared(nl) > R(0)) || !(light.radius > T(0)) || !std::isfinite(light.radius) ||
      !is_finite(light.center))
    throw std::invalid_argument("disk light: needs a finite center, a non-zero normal and radius > 0");
  const Vec3<R> helper = std::abs(nl.x) < R(0.6) ? Vec3<R>{1, 0, 0} : Vec3<R>{0, 1, 0};
  const Vec3<R> e1 = normalize(cross(helper, nl));
  const Vec3<R> e2 = cross(nl, e1);
  PreparedAreaLight<T> pl;
  pl.count = n;
  pl.two_sided = light.two_sided;
  pl.center = static_cast<Vec3<R>>(light.center);
  pl.normal = nl;
  pl.u = e1;
  pl.v = e2;
  pl.radius = vertex_radius;
  pl.area = R(n) / R(2) * vertex_radius * vertex_radius * std::sin(R(2 * M_PI) / R(n));
  for (int k = 0; k < n; ++k) {
    const R phi = R(2 * M_PI) * R(k) / R(n);
    pl.d[k] = (e1 * std::cos(phi) + e2 * std::sin(phi)) * vertex_radius;
  }
  return pl;
}

// Per-light constants, computed once: the frame (in the polygons) and the specular bracket.
template <class T>
struct PreparedDiskLight {
  AreaReal<T> radius{0};
  PreparedAreaLight<T> inscribed, circumscribed;  // same center, normal and frame (u, v)
  // The regular 64-gon of the disk's area (the inscribed one scaled by
  // sqrt(2 pi / (n sin(2 pi / n)))): the specular of a partly hidden disk (src/shadow/disk_pieces.h).
  PreparedAreaLight<T> equal_area;
};

template <class T>
PreparedDiskLight<T> prepare_disk_light(const DiskLight<T>& light) {
  using R = AreaReal<T>;
  PreparedDiskLight<T> pd;
  pd.radius = static_cast<R>(light.radius);
  pd.inscribed = disk_polygon(light, kDiskSpecularEdges, pd.radius);
  pd.circumscribed = disk_polygon(light, kDiskSpecularEdges, pd.radius / std::cos(R(M_PI) / R(kDiskSpecularEdges)));
  pd.equal_area = pd.inscribed;
  const int n = pd.equal_area.count;
  const R scale = std::sqrt(R(2 * M_PI) / (R(n) * std::sin(R(2 * M_PI) / R(n))));
  for (int i = 0; i < n; ++i) pd.equal_area.d[i] = pd.equal_area.d[i] * scale;
  pd.equal_area.radius *= scale;
  pd.equal_area.area = R(M_PI) * pd.radius * pd.radius;
  return pd;
}

// Specular of one prepared polygon (no diffuse): the area kernels' dispatch.
template <class T, class R = AreaReal<T>>
R polygon_specular(const PreparedAreaLight<T>& pl, const Vec3<R>& p, const Vec3<R>& n, const Vec3<R>& rv, R m,
                   const SpecularOptions& spec) {
  const AreaView<R> view = make_area_view(pl, p);
  if (!view.lit) return R(0);
  ClipPolygon<R> visible;
  clip_to_horizon(pl, view, n, visible);
  if (visible.count < 3) return R(0);
  switch (spec.method) {
    case SpecularMethod::kNone: return R(0);
    case SpecularMethod::kPeak: return area_specular_peak(visible, view, rv, m);
    case SpecularMethod::kNeighborhood:
      return area_specular_neighborhood(visible, view, rv, m, spec.neighborhood_samples);
    case SpecularMethod::kExact:
      return area_specular_exact(visible, view, rv, m, static_cast<R>(spec.exact_tolerance));
  }
  return R(0);
}

template <class T>
struct DiskSpecularBracket {
  AreaReal<T> inscribed{0}, circumscribed{0}, estimate{0};
};

template <class T>
DiskSpecularBracket<T> disk_specular_bracket(const PreparedDiskLight<T>& light, const ShadingPoint<T>& sp,
                                             const SpecularOptions& spec) {
  using R = AreaReal<T>;
  const Vec3<R> p = static_cast<Vec3<R>>(sp.p), n = static_cast<Vec3<R>>(sp.n), rv = static_cast<Vec3<R>>(sp.rv);
  const R m = static_cast<R>(sp.shininess);
  DiskSpecularBracket<T> b;
  b.inscribed = polygon_specular(light.inscribed, p, n, rv, m, spec);
  b.circumscribed = polygon_specular(light.circumscribed, p, n, rv, m, spec);
  b.estimate = (R(2) * b.circumscribed + b.inscribed) / R(3);
  return b;
}

// Shades with a prepared disk (the bake loop's form): no allocation, no polygon construction.
// with_diffuse = false leaves the diffuse 0 (a caller that has it from the batch kernel).
template <class T>
Response<T> shade_disk(const PreparedDiskLight<T>& light, const ShadingPoint<T>& sp, const SpecularOptions& spec,
                       bool with_diffuse = true) {
  using R = AreaReal<T>;
  const Vec3<R> p = static_cast<Vec3<R>>(sp.p);
  const AreaView<R> view = make_area_view(light.inscribed, p);
  if (!view.lit) return {};
  Response<T> r;
  if (with_diffuse) r.diffuse = static_cast<T>(disk_diffuse_contour(view, light.radius, static_cast<Vec3<R>>(sp.n)));
  if (spec.method == SpecularMethod::kExact) {
    r.specular = static_cast<T>(disk_specular_exact(view, light.radius, static_cast<Vec3<R>>(sp.n),
                                                    static_cast<Vec3<R>>(sp.rv), static_cast<R>(sp.shininess),
                                                    static_cast<R>(spec.exact_tolerance)));
  } else if (spec.method != SpecularMethod::kNone) {
    r.specular = static_cast<T>(disk_specular_bracket(light, sp, spec).estimate);
  }
  return r;
}

// Convenience form: validates and prepares on every call (throws std::invalid_argument).
template <class T>
Response<T> shade_disk(const DiskLight<T>& light, const ShadingPoint<T>& sp, const SpecularOptions& spec) {
  return shade_disk(prepare_disk_light(light), sp, spec);
}

}  // namespace vlit
