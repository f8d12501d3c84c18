// Disk light: a one-sided (or two-sided) Lambertian disk, shaded as a bracket of polygons.
//
// Computes the same quantities as area_light.h (diffuse, peak / neighbourhood / exact specular)
// for the disk {x : (x - center).normal = 0, |x - center| <= radius}, emitting toward `normal`.
//
// Method (docs/area-lights.md "Disk lights"): not analytic. For n = 8, 16, 32, 64 edges we shade
// the inscribed regular n-gon (vertex radius R) and the circumscribed one (R / cos(pi/n)) with
// the area kernels. All integrands are >= 0 and the peak is monotone in the set, so
//   I_in(n) <= I_disk <= I_out(n)      (a rigorous bracket, diffuse and every specular method)
// and we return I(n) = (2 I_out + I_in) / 3, the combination whose area is exact to O(n^-4)
// (A_in/A = 1 - 2 pi^2/(3 n^2) + ..., A_out/A = 1 + pi^2/(3 n^2) + ...), which lies inside the
// bracket. n is the first that brings the bracket below the requested relative tolerance
// (|I_out - I_in| <= tol (I_out + I_in)) for the diffuse and the requested specular; n = 64 is
// the cap (kMaxAreaVertices), and the bracket width is then the error bound (shade_disk_bracket
// reports it). Sources: Picott 1992 eq. 9-12 via the area kernels; Archimedes' bracket.
// Conventions: conventions.h. Departures from the paper: the paper has no disk lights.
// Stiff cases: tests/kernels/area/disk_test.cpp (far disk = point light, P near the rim,
// horizon crossing, behind, degenerate radius rejected).
// Measured accuracy (docs/area-lights.md, `./build/area/tests/area_light_tests -tc="disk*"`):
// diffuse 5.5e-8 .. 7.7e-7 at n = 64 away from the rim, 9.1e-5 with P 0.1 radius from the rim.
#pragma once

#include <cmath>
#include <stdexcept>

#include "area_light.h"

namespace vlit {

template <class T>
struct DiskLight {
  Vec3<T> center;
  Vec3<T> normal;  // emits toward normal (need not be unit)
  T radius{1};
  bool two_sided = false;
};

inline constexpr double kDiskDefaultTolerance = 1e-6;

// The regular n-gon of vertex radius `vertex_radius` in the disk's plane, CCW seen from normal.
template <class T>
PreparedAreaLight<T> disk_polygon(const DiskLight<T>& light, int n, AreaReal<T> vertex_radius) {
  using R = AreaReal<T>;
  if (n < 3 || n > kMaxAreaVertices) throw std::invalid_argument("disk light: bad edge count");
  const Vec3<R> nl = normalize(static_cast<Vec3<R>>(light.normal));
  if (!(length_squared(nl) > R(0)) || !(light.radius > T(0)) || !std::isfinite(light.radius) ||
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

template <class T>
struct DiskBracket {
  Response<T> inscribed, circumscribed, estimate;
  int edges = 0;
};

template <class T>
DiskBracket<T> shade_disk_bracket(const DiskLight<T>& light, const ShadingPoint<T>& sp,
                                  const SpecularOptions& spec, double tolerance = kDiskDefaultTolerance,
                                  int min_edges = 8, int max_edges = kMaxAreaVertices) {
  using R = AreaReal<T>;
  DiskBracket<T> b;
  for (int n = min_edges; n <= max_edges; n *= 2) {
    const R r = static_cast<R>(light.radius);
    const Response<T> in = shade_area(disk_polygon(light, n, r), sp, spec);
    const Response<T> out = shade_area(disk_polygon(light, n, r / std::cos(R(M_PI) / R(n))), sp, spec);
    b.inscribed = in;
    b.circumscribed = out;
    b.edges = n;
    b.estimate.diffuse = static_cast<T>((R(2) * out.diffuse + in.diffuse) / R(3));
    b.estimate.specular = static_cast<T>((R(2) * out.specular + in.specular) / R(3));
    const bool diffuse_ok = std::abs(R(out.diffuse) - R(in.diffuse)) <= R(tolerance) * (R(out.diffuse) + R(in.diffuse));
    const bool specular_ok = std::abs(R(out.specular) - R(in.specular)) <= R(tolerance) * (R(out.specular) + R(in.specular));
    if (diffuse_ok && specular_ok) break;
    if (n * 2 > max_edges) break;
  }
  return b;
}

template <class T>
Response<T> shade_disk(const DiskLight<T>& light, const ShadingPoint<T>& sp, const SpecularOptions& spec) {
  return shade_disk_bracket(light, sp, spec).estimate;
}

}  // namespace vlit
