// Area light, specular, reference quality: the Phong lobe integrated over the visible light.
//
// Computes (unit intensity, ks = 1; conventions.h):
//   Is(exact) = ∫_A [cos theta > 0] max(0, Rv.w)^m cos theta_l / r^2 dA
//             = ∫_Omega [N.w > 0] max(0, Rv.w)^m dw        (cos theta_l dA / r^2 = dw)
// by error-controlled adaptive cubature over the polygon in the light's plane.
//
// Sources: MISSION.md "Area light" (the definition); Picott 1992 "Future work" (the paper has no
// exact area specular). Arvo 1995 gives a closed form for integer m (not used here, see
// docs/area-lights.md); its form needs exactly the clipping done below.
//
// Method:
//  1. clip the light to the horizon N.(x - P) >= 0 and, for m > 0, to the lobe's half-space
//     Rv.(x - P) >= 0 (after that the integrand is smooth: no kink of max(0, .));
//  2. fan-triangulate the clipped polygon (signed triangles, so non-convex polygons and
//     Sutherland-Hodgman bridge edges are exact as chains) from the point where the peak
//     direction (area_specular_peak.h) meets the plane, and split again at the foot of P: the
//     two places where the integrand can be sharply peaked (lobe width ~ 1/sqrt(m), and the
//     factor h / r^3 of width ~ h for a light close to P) are vertices of the initial mesh;
//  3. on each triangle, a Duffy-collapsed 5x5 Gauss-Legendre rule with a 4x4 one as error
//     estimate; globally adaptive: split the triangle with the largest error estimate into 4
//     until Σ error ≤ tol |Σ value| (tol = SpecularOptions::exact_tolerance) or the fixed
//     work list (kExactMaxTriangles) is full. The error estimate is that of the 4x4 rule; the 5x5
//     result that is returned is typically far more accurate.
//  The work list is a fixed array (kExactMaxTriangles * 64 bytes = 128 KiB of stack): no heap.
//
// Departures: none from the definition; the paper's Is is the peak (area_specular_peak.h).
// Stiff cases: tests/kernels/area/area_specular_test.cpp "stiff exact specular cases" (tiny,
// distant, thin, huge, grazing, horizon crossing, behind, shininess 1..1e4).
// Measured accuracy (docs/area-lights.md; `./build/area/tests/area_light_tests`): 6.2e-11 on 40
// random cases, ≤ 2.2e-9 on the stiff table, m up to 1e4 — but NOT met: a light 1e3 times larger
// than its distance (15% low: the fixed work list fills), m = 1e4 at the light's edge (3e-7).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "area_specular_peak.h"

namespace vlit {

inline constexpr int kExactMaxTriangles = 2048;

namespace area_exact_detail {

template <class R>
struct Tri {
  R x[3], y[3];
  R value, error;
};

template <class R>
struct Integrand {
  Vec3<R> D, u, v, rv;
  R height, m;
  R operator()(R x, R y) const {
    const Vec3<R> a = D + u * x + v * y;
    const R r2 = length_squared(a);
    const R r = std::sqrt(r2);
    R lobe = R(1);
    if (m != R(0)) {
      const R c = dot(rv, a) / r;
      // Odd extension sign(c)|c|^m: only reached by fan triangles of non-convex polygons that
      // leave the clipped region; their signed contributions cancel there.
      lobe = c == R(0) ? R(0) : std::copysign(std::exp(m * std::log(std::abs(c))), c);
    }
    return lobe * height / (r2 * r);
  }
};

// Gauss-Legendre nodes and weights on [0, 1].
template <class R>
struct GaussRule5 {
  static constexpr int n = 5;
  static constexpr R x[5] = {R(0.5) - R(0.4530899229693319963988134391496965),
                             R(0.5) - R(0.2692346550528415455863364804340580), R(0.5),
                             R(0.5) + R(0.2692346550528415455863364804340580),
                             R(0.5) + R(0.4530899229693319963988134391496965)};
  static constexpr R w[5] = {R(0.1184634425280945437571320203599587),
                             R(0.2393143352496832340206457574604735),
                             R(0.2844444444444444444444444444444444),
                             R(0.2393143352496832340206457574604735),
                             R(0.1184634425280945437571320203599587)};
};
template <class R>
struct GaussRule4 {
  static constexpr int n = 4;
  static constexpr R x[4] = {R(0.5) - R(0.4305681557970262876596226036441820),
                             R(0.5) - R(0.1699905217924281324880709381430226),
                             R(0.5) + R(0.1699905217924281324880709381430226),
                             R(0.5) + R(0.4305681557970262876596226036441820)};
  static constexpr R w[4] = {R(0.1739274225687269286865319746109997),
                             R(0.3260725774312730713134680253890003),
                             R(0.3260725774312730713134680253890003),
                             R(0.1739274225687269286865319746109997)};
};

// Duffy rule on the triangle (p0, p1, p2), collapsed at p0: p = p0 + s e1 + s t (e2 - e1),
// Jacobian s (e1 x e2) (signed: CCW triangles count positive).
template <class Rule, class R, class F>
R duffy(const F& f, const R* x, const R* y) {
  const R e1x = x[1] - x[0], e1y = y[1] - y[0];
  const R e2x = x[2] - x[0], e2y = y[2] - y[0];
  const R jac = e1x * e2y - e1y * e2x;
  if (jac == R(0)) return R(0);
  R sum = 0;
  for (int i = 0; i < Rule::n; ++i) {
    const R s = Rule::x[i];
    R inner = 0;
    for (int j = 0; j < Rule::n; ++j) {
      const R t = Rule::x[j];
      inner += Rule::w[j] * f(x[0] + s * (e1x + t * (e2x - e1x)), y[0] + s * (e1y + t * (e2y - e1y)));
    }
    sum += Rule::w[i] * s * inner;
  }
  return sum * jac;
}

template <class R, class F>
void evaluate(const F& f, Tri<R>& tri) {
  const R fine = duffy<GaussRule5<R>>(f, tri.x, tri.y);
  const R coarse = duffy<GaussRule4<R>>(f, tri.x, tri.y);
  tri.value = fine;
  tri.error = std::abs(fine - coarse);
}

template <class R>
bool less_error(const Tri<R>& a, const Tri<R>& b) { return a.error < b.error; }

// Barycentric inside test (closed) of point (px, py) in triangle.
template <class R>
bool triangle_contains(const R* x, const R* y, R px, R py) {
  const R d0 = (x[1] - x[0]) * (py - y[0]) - (y[1] - y[0]) * (px - x[0]);
  const R d1 = (x[2] - x[1]) * (py - y[1]) - (y[2] - y[1]) * (px - x[1]);
  const R d2 = (x[0] - x[2]) * (py - y[2]) - (y[0] - y[2]) * (px - x[2]);
  return (d0 >= 0 && d1 >= 0 && d2 >= 0) || (d0 <= 0 && d1 <= 0 && d2 <= 0);
}

}  // namespace area_exact_detail

// Is(exact) of the horizon-clipped polygon `horizon_clipped`.
template <class R>
R area_specular_exact(const ClipPolygon<R>& horizon_clipped, const AreaView<R>& view,
                      const Vec3<R>& rv, R shininess, R tolerance) {
  using namespace area_exact_detail;
  if (!view.lit || horizon_clipped.count < 3) return R(0);
  // 1. Lobe clip (not for m = 0, where max(0, c)^0 = 1 everywhere: the solid angle).
  ClipPolygon<R> lobe_clipped;
  const ClipPolygon<R>* poly = &horizon_clipped;
  if (shininess != R(0)) {
    clip_halfspace(horizon_clipped.d.data(), horizon_clipped.count, rv, dot(rv, view.D), lobe_clipped);
    poly = &lobe_clipped;
  }
  const int n = poly->count;
  if (n < 3) return R(0);
  const Integrand<R> f{view.D, view.u, view.v, rv, view.height, shininess};

  // 2. Apex: where the peak direction meets the plane; second split point: the foot of P.
  std::array<R, kMaxClipVertices> px{}, py{};
  for (int i = 0; i < n; ++i) { px[i] = dot(view.u, poly->d[i]); py[i] = dot(view.v, poly->d[i]); }
  R ax = px[0], ay = py[0];
  if (shininess != R(0)) {
    const AreaPeak<R> peak = area_specular_peak_direction(*poly, view, rv);
    const R toward = -dot(view.normal, peak.direction);
    if (peak.visible && toward > R(0)) {
      const Vec3<R> hit = peak.direction * (view.height / toward) - view.D;
      if (is_finite(hit)) { ax = dot(view.u, hit); ay = dot(view.v, hit); }
    }
  }
  const R fx = -dot(view.u, view.D), fy = -dot(view.v, view.D);  // foot of P

  const R lobe_width = R(1) / std::sqrt(shininess + R(1));  // ~ angular width of cos^m
  std::array<Tri<R>, kExactMaxTriangles> heap;
  int size = 0;
  R value = 0, error = 0;  // running sums over the work list
  auto push = [&](R x0, R y0, R x1, R y1, R x2, R y2) {
    Tri<R>& t = heap[size];
    t.x[0] = x0; t.x[1] = x1; t.x[2] = x2;
    t.y[0] = y0; t.y[1] = y1; t.y[2] = y2;
    evaluate(f, t);
    // Forced refinement at the lobe's peak: a triangle with the peak at a corner is split
    // until its angular size (as seen from P) is below 2 lobe widths, so a narrow lobe cannot
    // slip between the nodes of a large triangle (false convergence).
    const bool at_peak = (x0 == ax && y0 == ay) || (x1 == ax && y1 == ay) || (x2 == ax && y2 == ay);
    if (shininess > R(0) && at_peak) {
      const R size = std::max({std::hypot(x1 - x0, y1 - y0), std::hypot(x2 - x0, y2 - y0), std::hypot(x2 - x1, y2 - y1)});
      const R dist = length(view.D + view.u * ax + view.v * ay);
      if (size > R(2) * lobe_width * dist) t.error = std::numeric_limits<R>::infinity();
    }
    value += t.value; error += t.error;
    ++size;
    std::push_heap(heap.begin(), heap.begin() + size, less_error<R>);
  };
  for (int i = 0; i < n && size + 3 <= kExactMaxTriangles; ++i) {
    const int j = (i + 1) % n;
    const R tx[3] = {ax, px[i], px[j]}, ty[3] = {ay, py[i], py[j]};
    if (triangle_contains(tx, ty, fx, fy)) {
      push(fx, fy, tx[0], ty[0], tx[1], ty[1]);
      push(fx, fy, tx[1], ty[1], tx[2], ty[2]);
      push(fx, fy, tx[2], ty[2], tx[0], ty[0]);
    } else {
      push(ax, ay, px[i], py[i], px[j], py[j]);
    }
  }

  // 3. Global adaptivity: split the worst triangle into 4 (midpoint subdivision).
  int splits = 0;
  while (error > tolerance * std::abs(value) && size + 3 <= kExactMaxTriangles) {
    std::pop_heap(heap.begin(), heap.begin() + size, less_error<R>);
    const Tri<R> t = heap[--size];
    const R m01x = (t.x[0] + t.x[1]) / 2, m01y = (t.y[0] + t.y[1]) / 2;
    const R m12x = (t.x[1] + t.x[2]) / 2, m12y = (t.y[1] + t.y[2]) / 2;
    const R m20x = (t.x[2] + t.x[0]) / 2, m20y = (t.y[2] + t.y[0]) / 2;
    push(t.x[0], t.y[0], m01x, m01y, m20x, m20y);  // keeps the collapse point t[0]
    push(m01x, m01y, t.x[1], t.y[1], m12x, m12y);
    push(m20x, m20y, m12x, m12y, t.x[2], t.y[2]);
    push(m12x, m12y, m20x, m20y, m01x, m01y);
    // Running sums drift by rounding; recount them exactly now and then.
    value -= t.value; error -= t.error;
    if (++splits % 32 == 0 || !std::isfinite(error)) {
      value = 0; error = 0;
      for (int k = 0; k < size; ++k) { value += heap[k].value; error += heap[k].error; }
    }
  }
  value = 0;
  for (int k = 0; k < size; ++k) value += heap[k].value;
  return std::max(value, R(0));
}

}  // namespace vlit
