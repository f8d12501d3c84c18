// Area (panel) light geometry shared by the area kernels: the light type, its validated
// per-light constants, and the per-point geometry (horizon clip, ray/polygon test).
//
// What it computes: nothing radiometric. It turns an AreaLight into a PreparedAreaLight
// (vertices relative to their mean c, unit emitting normal n_l, in-plane frame u, v with
// u x v = n_l) and clips the polygon, as seen from a shading point P, against half-spaces
// through P (the horizon N.(x - P) >= 0 and, for the exact specular, the lobe Rv.(x - P) >= 0).
//
// Sources: Sutherland-Hodgman re-entrant polygon clipping (CACM 1974); Newell's normal.
// Conventions: conventions.h. All geometry is carried relative to the light's vertex mean c:
// a_i = Q_i - P is formed as D + d_i with D = c - P and d_i = Q_i - c, so a tiny light far away
// keeps its shape to full relative precision (test "stiff: distant").
//
// Scalar type: the kernels compute in AreaReal<T>: double for T = float (the float instantiation
// computes internally in double and rounds once at the end; docs/area-lights.md), T otherwise.
//
// Limits: at most kMaxAreaVertices (64) vertices, enforced by prepare_area_light (throws
// std::invalid_argument). Clipping an n-gon (convex or not) against one plane gives at most
// 4n/3 vertices, against two at most 16n/9 < 2n, so every clip buffer is a fixed stack array of
// kMaxClipVertices = 2 * kMaxAreaVertices: no heap allocation per evaluation.
//
// Non-convex polygons: Sutherland-Hodgman joins the pieces of a non-convex polygon cut by a
// plane with "bridge" edges lying on the cut line, traversed in both directions. Every
// quantity computed from the clipped polygon here is a boundary integral (contour sums,
// winding numbers, contour integrals along the edges) for which the bridges cancel as chains; tests
// "non-convex L-shape crossing the horizon" and "U-shape clipped into two pieces" check it.
#pragma once

#include <array>
#include <cmath>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

#include "conventions.h"
#include "core/robust_math.h"

namespace vlit {

inline constexpr int kMaxAreaVertices = 64;
inline constexpr int kMaxClipVertices = 2 * kMaxAreaVertices;

// Computation type of the area kernels for scalar type T.
template <class T>
using AreaReal = std::conditional_t<std::is_same_v<T, float>, double, T>;

// Planar polygon, vertices counter-clockwise as seen from the side it emits to; one-sided unless
// two_sided. At most kMaxAreaVertices vertices.
template <class T>
struct AreaLight {
  std::vector<Vec3<T>> polygon;
  bool two_sided = false;
};

// Per-light constants, computed once (prepare_area_light). Trivially copyable, no heap.
template <class T>
struct PreparedAreaLight {
  using R = AreaReal<T>;
  int count = 0;
  std::array<Vec3<R>, kMaxAreaVertices> d{};  // Q_i - c
  Vec3<R> center{};                           // c = mean of the vertices
  Vec3<R> normal{};                           // unit n_l, toward the emitting side (Newell)
  Vec3<R> u{}, v{};                           // in-plane frame, u x v = normal
  R area{0};                                  // polygon area
  R radius{0};                                // max |d_i|
  bool two_sided = false;
};

// Validates and prepares a light: 3..kMaxAreaVertices finite vertices, non-zero area, planar
// within 1e-6 (double) / 1e-4 (float) of its radius. Throws std::invalid_argument otherwise.
template <class T>
PreparedAreaLight<T> prepare_area_light(const AreaLight<T>& light) {
  using R = AreaReal<T>;
  const int n = static_cast<int>(light.polygon.size());
  if (n < 3 || n > kMaxAreaVertices)
    throw std::invalid_argument("area light: needs 3.." + std::to_string(kMaxAreaVertices) +
                                " vertices, got " + std::to_string(n));
  PreparedAreaLight<T> pl;
  pl.count = n;
  pl.two_sided = light.two_sided;
  Vec3<R> c{};
  for (const auto& q : light.polygon) {
    if (!is_finite(q)) throw std::invalid_argument("area light: non-finite vertex");
    c += static_cast<Vec3<R>>(q);
  }
  c = c / R(n);
  pl.center = c;
  Vec3<R> newell{};
  R radius = 0;
  for (int i = 0; i < n; ++i) pl.d[i] = static_cast<Vec3<R>>(light.polygon[i]) - c;
  for (int i = 0; i < n; ++i) {
    newell += cross(pl.d[i], pl.d[(i + 1) % n]);
    radius = std::max(radius, length(pl.d[i]));
  }
  const R twice_area = length(newell);
  if (!(twice_area > R(0)) || !(twice_area > R(1e-300) * radius * radius) ||
      !std::isfinite(twice_area))
    throw std::invalid_argument("area light: zero area (degenerate or self-cancelling polygon)");
  pl.normal = newell / twice_area;
  pl.area = twice_area / R(2);
  pl.radius = radius;
  const R planarity_tol = std::is_same_v<T, float> ? R(1e-4) : R(1e-6);
  for (int i = 0; i < n; ++i)
    if (std::abs(dot(pl.d[i], pl.normal)) > planarity_tol * radius)
      throw std::invalid_argument("area light: polygon is not planar");
  // In-plane frame: u along the longest vertex offset (well conditioned for thin polygons).
  int far = 0;
  for (int i = 1; i < n; ++i)
    if (length_squared(pl.d[i]) > length_squared(pl.d[far])) far = i;
  pl.u = normalize(pl.d[far] - pl.normal * dot(pl.normal, pl.d[far]));
  pl.v = cross(pl.normal, pl.u);
  return pl;
}

// A polygon relative to the light's center c, in a fixed-capacity buffer.
template <class R>
struct ClipPolygon {
  int count = 0;
  std::array<Vec3<R>, kMaxClipVertices> d{};
};

// Sutherland-Hodgman: keeps the part of `in` where dot(k, x) + offset >= 0 (x relative to c).
// Vertices exactly on the plane are kept and create no new vertex.
template <class R>
void clip_halfspace(const Vec3<R>* in, int n, const Vec3<R>& k, R offset, ClipPolygon<R>& out) {
  out.count = 0;
  if (n == 0) return;
  R s_prev = dot(k, in[n - 1]) + offset;
  Vec3<R> prev = in[n - 1];
  for (int i = 0; i < n; ++i) {
    const Vec3<R>& cur = in[i];
    const R s_cur = dot(k, cur) + offset;
    const bool in_prev = s_prev >= R(0), in_cur = s_cur >= R(0);
    if (in_prev != in_cur) {
      // Strict sign change: t in (0, 1), denominator non-zero.
      const R t = s_prev / (s_prev - s_cur);
      if (out.count < kMaxClipVertices) out.d[out.count++] = prev + (cur - prev) * t;
    }
    if (in_cur && out.count < kMaxClipVertices) out.d[out.count++] = cur;
    prev = cur;
    s_prev = s_cur;
  }
  if (out.count < 3) out.count = 0;
}

// The shading point as seen by one light: D = c - P, the effective emitting normal (flipped for
// the back of a two-sided light) and its orientation sign, the height h = n_l.(P - c) > 0.
template <class R>
struct AreaView {
  Vec3<R> D{};
  Vec3<R> normal{};   // effective n_l (toward P)
  Vec3<R> u{}, v{};   // frame with u x v = normal
  R orient{1};        // +1: polygon CCW seen from P's side; -1: the back of a two-sided light
  R height{0};        // distance of P from the light's plane
  bool lit = false;   // false: P is behind a one-sided light or in its plane
};

template <class T, class R = AreaReal<T>>
AreaView<R> make_area_view(const PreparedAreaLight<T>& pl, const Vec3<R>& p) {
  AreaView<R> view;
  view.D = pl.center - p;
  const R side = -dot(pl.normal, view.D);  // n_l.(P - c)
  if (side > R(0)) {
    view.normal = pl.normal; view.u = pl.u; view.v = pl.v; view.orient = R(1);
  } else if (side < R(0) && pl.two_sided) {
    view.normal = -pl.normal; view.u = pl.u; view.v = -pl.v; view.orient = R(-1);
  } else {
    return view;  // behind a one-sided light, or in the light's plane: cos(theta_l) <= 0
  }
  view.height = std::abs(side);
  view.lit = true;
  return view;
}

// The light clipped to the upper hemisphere of P (horizon clipping, docs/conventions.md).
template <class T, class R = AreaReal<T>>
void clip_to_horizon(const PreparedAreaLight<T>& pl, const AreaView<R>& view, const Vec3<R>& n,
                     ClipPolygon<R>& out) {
  clip_halfspace(pl.d.data(), pl.count, n, dot(n, view.D), out);
}

// Winding number of the polygon around the point x (relative to c, in the light's plane).
template <class R>
int winding_number(const ClipPolygon<R>& poly, const AreaView<R>& view, const Vec3<R>& x) {
  const R px = dot(view.u, x), py = dot(view.v, x);
  int wn = 0;
  for (int i = 0; i < poly.count; ++i) {
    const Vec3<R>& a = poly.d[i];
    const Vec3<R>& b = poly.d[(i + 1) % poly.count];
    const R ax = dot(view.u, a) - px, ay = dot(view.v, a) - py;
    const R bx = dot(view.u, b) - px, by = dot(view.v, b) - py;
    const R side = difference_of_products(ax, by, bx, ay);
    if (ay <= R(0)) {
      if (by > R(0) && side > R(0)) ++wn;
    } else if (by <= R(0) && side < R(0)) {
      --wn;
    }
  }
  return wn;
}

// Winding number of the (clipped) polygon about the point where the ray P + t dir (t > 0) meets
// the light's plane; 0 where the ray does not go toward the plane (or meets it beyond what double
// holds).
template <class R>
int ray_winding_number(const ClipPolygon<R>& poly, const AreaView<R>& view, const Vec3<R>& dir) {
  const R toward = -dot(view.normal, dir);  // > 0: the ray goes toward the light's plane
  if (!(toward > R(0)) || poly.count < 3) return 0;
  const R t = view.height / toward;
  if (!std::isfinite(t)) return 0;
  return winding_number(poly, view, dir * t - view.D);  // the hit, relative to c
}

// True if the ray P + t dir (t > 0) hits the inside of the (clipped) polygon.
template <class R>
bool ray_hits_polygon(const ClipPolygon<R>& poly, const AreaView<R>& view, const Vec3<R>& dir) {
  return ray_winding_number(poly, view, dir) != 0;
}

// a x b for a = D + d_i, b = D + d_j (D = c - P, d relative to the light's centre c), by the
// form with the smaller rounding error: D x (d_j - d_i) + d_i x d_j keeps a small light far away
// exact (terms ~ |D| |d|), a x b keeps an edge close to P exact when P is far from c (terms
// ~ |a| |b|; the first form would cancel terms ~ |d|^2 down to ~ |a| |b|).
template <class R>
Vec3<R> edge_cross(const Vec3<R>& D, const Vec3<R>& di, const Vec3<R>& dj) {
  const Vec3<R> a = D + di, b = D + dj;
  const R direct = length_squared(a) * length_squared(b);
  const R split = std::max(length_squared(D) * length_squared(dj - di), length_squared(di) * length_squared(dj));
  if (direct < split) return cross(a, b);
  return cross(D, dj - di) + cross(di, dj);
}

// max(0, cos alpha)^m from the angle alpha in [0, pi], accurate for alpha -> 0 and large m:
// cos alpha = 1 - 2 sin^2(alpha/2), so log(cos alpha) = log1p(-2 sin^2(alpha/2)).
// m = 0 is the limit m -> 0+: 1 for alpha < pi/2, 0 beyond (phong_power in core/robust_math.h).
template <class R>
R phong_lobe_from_angle(R alpha, R m) {
  if (!(alpha < R(M_PI / 2))) return R(0);
  if (m == R(0)) return R(1);
  const R s = std::sin(alpha / R(2));
  return std::exp(m * std::log1p(R(-2) * s * s));
}

}  // namespace vlit
