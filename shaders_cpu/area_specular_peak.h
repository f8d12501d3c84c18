// Area light, specular, paper method: the Phong lobe at the light's most important direction.
//
// Computes (unit intensity, ks = 1; conventions.h):
//   Is(peak) = max over directions w toward the visible (horizon-clipped) light of max(0, Rv.w)^m
// i.e. the lobe at the direction of the light closest in angle to Rv (Picott 1992 eq. 11-12 and
// the sidebar "Area-light specular mathematics").
//
// Method: (1) as in eq. 11-12, intersect the ray P + t Rv with the light's plane and test the
// hit against the clipped polygon (winding number, so N-gons and non-convex polygons work);
// inside: the angle is 0. (2) Otherwise the closest direction of a spherical polygon to an
// outside point lies on its boundary: for each edge Q_i Q_{i+1}, the directions to the edge
// sweep a great-circle arc with pole n_i = unit(a_i x a_{i+1}); the arc's closest direction to
// Rv is the projection w = Rv - (Rv.n_i) n_i if it lies between a_i and a_{i+1}, at angle
// atan2(|Rv.n_i|, |w|), else the nearer endpoint (angle_between). This is the same 1D problem as
// the linear light's peak (Picott eq. 7-8), solved in angle form (no 0/0, no second root).
//
// Departures from the paper (docs/area-lights.md "The sidebar's rule"): the sidebar's "one
// parameter out of range -> the closest point lies on that axis, found by intersecting the
// projection of Rv with the edge's line" is not the closest direction in general (projection
// onto the plane does not preserve angles as seen from P; with both parameters out of range the
// closest point can also lie on an edge neither parameter names). We use the exact boundary
// search above, for N-gons, and for the horizon-clipped polygon (the paper does not clip).
//
// Stiff cases (tests/kernels/area/area_specular_test.cpp "stiff peak cases"): Rv inside, Rv
// grazing the plane, Rv parallel to the light, Rv exactly toward a vertex, light crossing the
// horizon, shininess 1..1e4 (lobe from the angle via log1p, accurate for alpha -> 0).
//
// Measured accuracy: peak angle vs a dense search + sidebar-formula refinement in long double:
// 3.9e-15 rad, direction 1.9e-14 rad on 294 random cases (docs/area-lights.md;
// `./build/area/tests/area_light_tests -tc="*peak*"`).
#pragma once

#include <cmath>

#include "area_polygon.h"

namespace vlit {

template <class R>
struct AreaPeak {
  bool visible = false;  // the clipped light is non-empty
  R angle{0};            // angle between Rv and the closest direction toward the light
  Vec3<R> direction{};   // that direction (unit)
};

// Edge d_i -> d_j seen from P (a = D + d_i, b = D + d_j): the projection w = Rv - (Rv.n) n of Rv
// onto the plane of its great circle (unit pole n), and whether w lies on the arc between a and b,
// where it is the arc's closest direction to Rv, at sin(angle) = |Rv.n| (the arc is shorter than
// pi: a, b are not antiparallel here). between = false also where the edge has no plane (a x b = 0)
// or Rv is its pole (w = 0).
template <class R>
struct ArcFoot {
  Vec3<R> w;
  R rv_n{0};
  bool between = false;
};

template <class R>
ArcFoot<R> arc_foot(const AreaView<R>& view, const Vec3<R>& di, const Vec3<R>& dj, const Vec3<R>& rv) {
  ArcFoot<R> f;
  const Vec3<R> cr = cross(view.D, dj - di) + cross(di, dj);  // a x b
  const R s = length(cr);
  if (!(s > R(0))) return f;
  const Vec3<R> pole = cr / s;
  f.rv_n = dot(rv, pole);
  f.w = rv - pole * f.rv_n;
  if (!(length_squared(f.w) > R(0))) return f;
  const Vec3<R> a = view.D + di, b = view.D + dj;
  f.between = dot(cross(a, f.w), pole) >= R(0) && dot(cross(f.w, b), pole) >= R(0);
  return f;
}

template <class R>
AreaPeak<R> area_specular_peak_direction(const ClipPolygon<R>& poly, const AreaView<R>& view,
                                         const Vec3<R>& rv) {
  AreaPeak<R> peak;
  if (!view.lit || poly.count < 3) return peak;
  peak.visible = true;
  if (ray_hits_polygon(poly, view, rv)) {
    peak.angle = R(0);
    peak.direction = rv;
    return peak;
  }
  R best = R(4);  // > pi
  for (int i = 0; i < poly.count; ++i) {
    const Vec3<R> a = view.D + poly.d[i];
    const R angle_a = angle_between(rv, a);
    if (angle_a < best) { best = angle_a; peak.direction = normalize(a); }
    const ArcFoot<R> f = arc_foot(view, poly.d[i], poly.d[(i + 1) % poly.count], rv);
    if (!f.between) continue;
    const R angle_w = std::atan2(std::abs(f.rv_n), length(f.w));
    if (angle_w < best) { best = angle_w; peak.direction = normalize(f.w); }
  }
  // Endpoints b are the next edge's a: covered by the loop.
  peak.angle = best;
  return peak;
}

// Whether some direction toward the (clipped) light lies within the angle acos(cos_min) of the
// unit rv, 0 < cos_min < 1: whether the peak's angle above is at most that, by the same boundary
// search with cosines and sines instead of angles (no atan2): a vertex direction a with
// Rv.a >= cos_min |a|, or an arc whose closest direction to Rv has |Rv.n| <= sin. The exact
// specular's dispatch (area_light.h) asks it.
template <class R>
bool area_lobe_reaches(const ClipPolygon<R>& poly, const AreaView<R>& view, const Vec3<R>& rv, R cos_min) {
  if (!view.lit || poly.count < 3) return false;
  if (ray_hits_polygon(poly, view, rv)) return true;
  const R sin_max = std::sqrt((R(1) - cos_min) * (R(1) + cos_min));
  for (int i = 0; i < poly.count; ++i) {
    const Vec3<R> a = view.D + poly.d[i];
    if (dot(rv, a) >= cos_min * length(a)) return true;
    const ArcFoot<R> f = arc_foot(view, poly.d[i], poly.d[(i + 1) % poly.count], rv);
    if (f.between && std::abs(f.rv_n) <= sin_max) return true;
  }
  return false;
}

// Is(peak) for a prepared light (see file comment).
template <class R>
R area_specular_peak(const ClipPolygon<R>& poly, const AreaView<R>& view, const Vec3<R>& rv,
                     R shininess) {
  const AreaPeak<R> peak = area_specular_peak_direction(poly, view, rv);
  if (!peak.visible) return R(0);
  return phong_lobe_from_angle(peak.angle, shininess);
}

}  // namespace vlit
