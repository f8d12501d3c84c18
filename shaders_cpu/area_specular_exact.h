// Area light, specular, reference quality: the Phong lobe integrated over the visible light,
// reduced to a contour integral and integrated along the edges with error control.
//
// Computes (unit intensity, ks = 1; conventions.h):
//   Is(exact) = ∫_A [cos theta > 0] max(0, Rv.w)^m cos theta_l / r^2 dA
//             = ∫_Omega [N.w > 0] max(0, Rv.w)^m dw        (cos theta_l dA / r^2 = dw)
//
// Sources: docs/conventions.md "Radiometric definitions" (the definition); Picott 1992 "Future work" (the paper has no
// exact area specular). The reduction to the boundary is the same idea as eq. 9 (Lambert's
// contour integral) with polar coordinates about Rv instead of Stokes' theorem.
//
// Method (docs/area-lights.md "Exact specular"):
//  1. clip the light to the horizon N.(x - P) >= 0 and to the lobe's half-space Rv.(x - P) >= 0,
//     so that c = Rv.w >= 0 on the visible set (also for m = 0, whose lobe is the limit m -> 0+,
//     [Rv.w > 0]: continuous in m; "m -> 0 continuity" in tests/kernels/area/area_specular_test.cpp);
//  2. polar coordinates (Theta, phi) about the axis Rv: dw = sin Theta dTheta dphi and the radial
//     integral is closed: ∫_0^Theta cos^m t sin t dt = (1 - cos^{m+1} Theta) / (m + 1). Fanning the
//     spherical polygon from Rv (signed: valid whether Rv is inside or not),
//       Is = -orient / (m + 1) Σ_edges ∫ (1 - c^{m+1}) dphi.
//     Along an edge x(t) = a + t e (a = Q_i - P, e = Q_{i+1} - Q_i, t in [0, 1]),
//     dphi = Rv.(x x dx) / |Rv x x|^2 = Rv.(a x b) dt / |Rv x x|^2 (the numerator is constant), so
//       Is = -orient / (m + 1) Σ_i Rv.(a_i x b_i) ∫_0^1 (1 - c(t)^{m+1}) / |Rv x x(t)|^2 dt,
//     a smooth 1D integrand: where the edge passes through Rv, (1 - c^{m+1}) / |Rv x x|^2 ->
//     (m + 1) / (2 |x|^2); 1 - c^{m+1} = -expm1((m + 1) log1p(-(1 - c))) with
//     1 - c = |Rv x x|^2 / (|x| (|x| + Rv.x)), no cancellation near the peak.
//     When Rv is outside the visible light the "1" part sums to 0 exactly (winding number 0) and
//     only the tail is integrated: Is = orient Σ_i Rv.(a_i x b_i) / (m + 1) ∫ c^{m+1} / |Rv x x|^2 dt
//     (no cancellation of terms ~ 1 / (m + 1) down to a tiny value). Rv inside the light, more
//     than a lobe width from every edge's great circle: the "1" part sums to 2 pi k (k turns
//     about Rv) and Is = -orient 2 pi k / (m + 1) + orient Σ_i Rv.(a_i x b_i) / (m + 1) ∫ c^{m+1} /
//     |Rv x x|^2 dt, the lobe outside the light integrated as a tail to the absolute accuracy
//     tol 2 pi k / (m + 1) (docs/area-lights.md "Rv inside the light").
//  3. globally adaptive Gauss-Kronrod (7/15 points, adaptive_kronrod.h) over all edges: each edge starts split at the
//     point closest to P (the 1/|x|^2 peak, width ~ its distance d_P: graded cuts at d_P 4^k) and at
//     the point closest in angle to Rv (the lobe, width ~ |x| / sqrt(m + 1): graded likewise);
//     the piece with the largest |K15 - G7| is bisected until Σ error <= max(tol |Σ value|,
//     tol eps 2 pi / (m + 1)) (tol = SpecularOptions::exact_tolerance; the second term is tol
//     times the rounding of the largest value Is can take at this m) or the fixed work list is
//     full. In the tail form each initial piece enters unevaluated with a bound of its integral as
//     its error, and is evaluated only if that bound becomes the largest error: pieces the lobe
//     does not reach are never evaluated, and where the lobe's peak on the light bounds Is below
//     that absolute target the result is 0 at once.
//  The work list is a fixed array (kExactMaxPieces * 40 bytes = 80 KiB of stack): no heap.
//  Initial cuts: at most 48 per edge (kExactMaxCuts).
//
// Departures: none from the definition; the paper's Is is the peak (area_specular_peak.h).
// Stiff cases: tests/kernels/area/area_specular_test.cpp "stiff exact specular cases" (tiny,
// thin, huge, P 1e-6 above the light, grazing, horizon crossing, behind, shininess 1..1e4).
// Measured accuracy: docs/area-lights.md; `./build/release/tests/area_light_tests -tc="*exact*"`.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "adaptive_kronrod.h"
#include "area_polygon.h"
#include "area_specular_peak.h"
#include "core/robust_math.h"

namespace vlit {

inline constexpr int kExactMaxPieces = 2048;
inline constexpr int kExactMaxCuts = 48;  // initial cut points per edge, its ends included
// A deferred tail piece counts as an error of 1000 times its bound, so the pieces left out add at
// most tol / 1000 of the value: the evaluated pieces' |K15 - G7| overstates their error by about
// that much (the accuracy report's area rows: 7.9e-13 at tol 1e-9 with every piece evaluated, and
// 3.1e-10 with the bound counted once). The factor also covers the rounding of c^{m+1}
// ((m + 1) eps relative) and of 1 - c^2 in the bound.
inline constexpr double kDeferredCharge = 1e3;

namespace area_exact_detail {

// (1 - c^{m+1}) / |Rv x x|^2 at the point x (relative to P), c = Rv.x / |x|: the radial integral
// of the lobe per unit azimuth about Rv, divided by |Rv x x|^2 (dphi = Rv.(x x dx) / |Rv x x|^2).
// tail: c^{m+1} / |Rv x x|^2 instead (the "1" part integrates to the winding number exactly).
template <class R>
R lobe_per_azimuth(const Vec3<R>& x, const Vec3<R>& rv, R m, bool tail = false) {
  const R r = length(x);
  const R rx = dot(rv, x);
  const R perp2 = length_squared(cross(rv, x));
  if (!(r > R(0))) return R(0);
  if (tail) {
    if (!(perp2 > R(0))) return R(0);
    if (!(rx > R(0))) return R(0);  // the tail form runs for m > 0 only: max(0, c)^{m+1} = 0
    return std::exp((m + R(1)) * std::log(rx / r)) / perp2;
  }
  if (!(rx > R(0))) {  // c <= 0 (on the lobe clip's boundary, or past it by rounding): lobe 0
    return perp2 > R(0) ? R(1) / perp2 : R(0);
  }
  const R base = r * (r + rx);  // perp2 = (1 - c) * base
  const R one_minus_c = std::min(perp2 / base, R(1));
  if (one_minus_c == R(0)) return (m + R(1)) / base;
  // (1 - c^{m+1}) / (1 - c), c^{m+1} = exp((m + 1) log1p(-(1 - c)))
  const R ratio = -std::expm1((m + R(1)) * std::log1p(-one_minus_c)) / one_minus_c;
  return ratio / base;
}

// One edge x(t) = a + t e as seen from P, and the radial-integrated lobe along it.
template <class R>
struct EdgeIntegrand {
  Vec3<R> a, e, rv;
  R m;
  bool tail = false;
  R operator()(R t) const { return lobe_per_azimuth(a + e * t, rv, m, tail); }
};

}  // namespace area_exact_detail

// Is(exact) of the horizon-clipped polygon `horizon_clipped`.
// rv is normalised here: the identities below (|Rv x x|^2 = |x|^2 - (Rv.x)^2) need a unit Rv, and
// the definition's lobe is max(0, Rv.w)^m with unit Rv (a float-rounded Rv is off by ~1e-7, which
// m = 1e3 would turn into 1e-4).
// bounded_tails = false evaluates every initial piece of the tail form and has no absolute target
// (relative tolerance only; tests compare the two).
template <class R>
R area_specular_exact(const ClipPolygon<R>& horizon_clipped, const AreaView<R>& view,
                      const Vec3<R>& rv_in, R shininess, R tolerance, bool bounded_tails = true) {
  using namespace area_exact_detail;
  if (!view.lit || horizon_clipped.count < 3) return R(0);
  const Vec3<R> rv = normalize(rv_in);
  // 1. Lobe clip, also for m = 0: the lobe there is the limit m -> 0+, [Rv.w > 0] (the solid
  // angle of the part of the light in front of the lobe's half-space; core/robust_math.h).
  ClipPolygon<R> lobe_clipped;
  clip_halfspace(horizon_clipped.d.data(), horizon_clipped.count, rv, dot(rv, view.D), lobe_clipped);
  const ClipPolygon<R>* poly = &lobe_clipped;
  const int n = poly->count;
  if (n < 3) return R(0);
  const R lobe_width = R(1) / std::sqrt(shininess + R(1));  // ~ angular width of cos^m
  // Rv outside the visible light: Σ ∫ dphi = 0 exactly, so integrate only the tail c^{m+1}
  // (form B); otherwise the edge terms, each ~ 1 / (m + 1), would cancel down to a value that
  // can be 1e-12 of them (a lobe that barely reaches the light).
  // Only when Rv is at least a lobe width away from the light: closer, the tail's integrand
  // c^{m+1} / |Rv x x|^2 has a peak of height 1 / angle^2 and the full form is the better one.
  const R peak_angle = shininess > R(0) ? area_specular_peak_direction(*poly, view, rv).angle : R(0);
  // Rv inside the light, at least a lobe width from every edge's great circle: the "1" parts sum
  // to 2 pi k / (m + 1) (k the number of turns the boundary makes about Rv, counted from the
  // edges' azimuths), and Is = -orient 2 pi k / (m + 1) + orient Σ w_i ∫ c^{m+1} / |Rv x x|^2 dt:
  // the integrated part is the lobe outside the light, a correction that needs only the
  // absolute accuracy tol Is, so the tail form's deferred pieces apply (those the lobe does not
  // reach are never evaluated).
  int turns = 0;
  if (shininess > R(0) && bounded_tails && !(peak_angle > R(0))) {
    R azimuth = 0, nearest = R(1);  // Σ of the edges' azimuths about Rv; least sin of the angle to a great circle
    for (int i = 0; i < n; ++i) {
      const Vec3<R> a = view.D + poly->d[i], b = view.D + poly->d[(i + 1) % n];
      const Vec3<R> cr = edge_cross(view.D, poly->d[i], poly->d[(i + 1) % n]);
      const R len = length(cr);
      if (!(len > R(0))) continue;
      nearest = std::min(nearest, std::abs(dot(rv, cr)) / len);
      azimuth += std::atan2(dot(rv, cr), dot(a, b) - dot(rv, a) * dot(rv, b));
    }
    // k from the edges' own azimuths, so that its sign is that of the full form's "1" parts
    // (ray_winding_number counts in the light's plane, with the polygon's orientation there)
    const R k = std::round(azimuth / R(2 * M_PI));
    // sin(lobe width) < nearest: every great circle farther than a lobe width
    if (k != R(0) && nearest > std::sin(std::min(lobe_width, R(1.5))) && std::abs(azimuth - k * R(2 * M_PI)) < R(1e-3))
      turns = int(k);
  }
  const bool inside_tail = turns != 0;
  const bool tail = peak_angle > lobe_width || inside_tail;
  // Absolute error target: tol eps 2 pi / (m + 1), tol times the rounding of the largest value Is
  // takes at this m (2 pi / (m + 1), a light covering the half-space around Rv). Values below it
  // are astronomically small tails whose edge terms can cancel: relative accuracy there cost many
  // pieces and bought nothing an output can hold.
  const R floor = tolerance * std::numeric_limits<R>::epsilon() * R(2 * M_PI) / (shininess + R(1));
  // Is <= c_max^m Omega <= c_max^m 2 pi (c <= c_max = cos(peak angle) on the light, whose solid
  // angle is at most 2 pi): below the floor, 0 is within it.
  if (tail && !inside_tail && bounded_tails && phong_lobe_from_angle(peak_angle, shininess) * R(2 * M_PI) <= floor)
    return R(0);
  // The "1" parts' sum, -orient 2 pi k / (m + 1), with the sign of the full form below,
  // Is = -orient Σ w_i ∫ (1 - c^{m+1}) / |Rv x x|^2 dt.
  const R whole = inside_tail ? -view.orient * R(2 * M_PI) * R(turns) / (shininess + R(1)) : R(0);

  // Per-edge constants: weight Rv.(a x b) / (m + 1) and the integrand.
  std::array<EdgeIntegrand<R>, kMaxClipVertices> edge{};
  std::array<R, kMaxClipVertices> weight{};
  AdaptiveKronrod<R, kExactMaxPieces> quad;
  for (int i = 0; i < n; ++i) {
    const Vec3<R>& di = poly->d[i];
    const Vec3<R>& dj = poly->d[(i + 1) % n];
    const Vec3<R> e = dj - di;
    const R e2 = length_squared(e);
    if (!(e2 > R(0))) continue;
    const Vec3<R> cr = edge_cross(view.D, di, dj);  // a x b
    const R w = dot(rv, cr) / (shininess + R(1));
    if (w == R(0)) continue;  // the edge's plane contains Rv: dphi = 0 along it
    edge[i] = {view.D + di, e, rv, shininess, tail};
    weight[i] = w;
    // Initial cuts: graded around the point closest to P and the point closest in angle to Rv.
    const Vec3<R>& a = edge[i].a;
    const R len = std::sqrt(e2);
    const R tp = std::clamp(-dot(a, e) / e2, R(0), R(1));
    R centers[2] = {tp, tp}, widths[2] = {length(a + e * tp) / len, R(0)};
    // tr: x parallel to Rv's projection on the edge's plane, clamped to the edge; c's largest value
    // on the edge is there or at an end.
    R tr = R(0);
    if (shininess > R(0)) {
      // x(t) parallel to the projection of Rv on the edge's plane: a x w + t (e x w) = 0.
      const Vec3<R> pole = cr / length(cr);
      const Vec3<R> wdir = rv - pole * dot(rv, pole);
      const R den = dot(cross(e, wdir), pole);
      if (den != R(0)) {
        tr = std::clamp(-dot(cross(a, wdir), pole) / den, R(0), R(1));
        // the integrand's peak width there: the lobe's, or (tail form) the angle to Rv if smaller
        const Vec3<R> xr = a + e * tr;
        const R angle = std::atan2(length(cross(rv, xr)), dot(rv, xr));
        centers[1] = tr;
        widths[1] = std::max(std::min(lobe_width, angle), R(1e-300)) * length(xr) / len;
      }
    }
    if (!tail || !bounded_tails) {
      quad.template add_graded<kExactMaxCuts>(edge[i], i, R(0), R(1), centers, widths, 2, w);
      continue;
    }
    // Tail pieces are added deferred (evaluated only where they matter), bounded as follows. c is
    // unimodal along the edge (x / |x| runs along a great circle, on which c = C cos(psi - psi0),
    // and the lobe clip keeps |psi - psi0| <= pi/2), so on [t0, t1] its largest value is at t0, t1
    // or tr; |x|^2 is convex in t with its minimum at tp. With c^{m+1} / |Rv x x|^2 =
    // c^{m+1} / (|x|^2 (1 - c^2)) the integrand is below c_max^{m+1} / (|x|_min^2 (1 - c_max^2)).
    const auto cos_at = [&](R t) {
      const Vec3<R> x = a + e * t;
      return std::max(dot(rv, x) / length(x), R(0));
    };
    const auto bound = [&](R t0, R t1) {
      const R c = std::max({cos_at(t0), cos_at(t1), cos_at(std::clamp(tr, t0, t1))});
      const R sin2 = (R(1) - c) * (R(1) + c);
      if (!(sin2 > R(0))) return R(-1);  // no bound: evaluate the piece
      const R r2 = length_squared(a + e * std::clamp(tp, t0, t1));
      return R(kDeferredCharge) * (t1 - t0) * phong_power(c, shininess + R(1)) / (r2 * sin2);
    };
    quad.template add_graded<kExactMaxCuts>(edge[i], i, R(0), R(1), centers, widths, 2, w, bound);
  }

  // 3. Global adaptivity: bisect the piece with the largest error estimate. Inside, the target is
  // absolute: tol times the whole lobe's part, of which the integrated correction is a fraction.
  const R target = inside_tail ? tolerance * std::abs(whole) : (bounded_tails ? floor : R(0));
  const R value = quad.refine([&](int i, R t) { return edge[i](t); }, [&](int i) { return weight[i]; }, tolerance, target);
  if (inside_tail) return std::max(whole + view.orient * value, R(0));
  if (tail) return std::max(view.orient * value, R(0));  // Is = orient Σ w_i ∫ c^{m+1} / |Rv x x|^2
  return std::max(-view.orient * value, R(0));
}

}  // namespace vlit
