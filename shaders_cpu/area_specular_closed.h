// Area light, specular, closed form for integer m: the Phong lobe integrated over the visible
// polygon as a sum of per-edge recurrences in m.
//
// What it computes: Is(exact) = ∫_Omega [N.w > 0] max(0, Rv.w)^m dw over the directions toward the
// light (unit intensity, ks = 1), integer m >= 0: the quantity area_specular_exact.h integrates
// adaptively (docs/conventions.md "Radiometric definitions"; m = 0 is the limit m -> 0+).
//
// Sources: Arvo 1995, "Applications of irradiance tensors to the simulation of non-Lambertian
// phenomena" (the axial moment of a polygon: a boundary sum with a recurrence in the exponent per
// edge, and the solid angle for even exponents); derived here again from the contour form of
// area_specular_exact.h. Conventions: conventions.h, geometry of area_polygon.h.
//
// Derivation. After clipping to the horizon and to the lobe's half-space Rv.(x - P) >= 0,
// area_specular_exact.h has Is = -orient / (m + 1) Σ_i Rv.(a_i x b_i) ∫_0^1 (1 - c^{m+1}) /
// |Rv x x|^2 dt. Along edge i, x̂ runs on the great circle of unit normal n_i = a x b / |a x b|
// with angle ψ from â (dψ = |a x b| dt / |x|^2, x̂(ψ) = cos ψ â + sin ψ (n_i x â)), and
// |Rv x x|^2 = |x|^2 (1 - c^2), so each edge term is (Rv.n_i) ∫_0^Θi (1 - c^{m+1}) / (1 - c^2) dψ,
// Θi = angle(a, b), c(ψ) = A cos ψ + B sin ψ (A = Rv.â, B = Rv.(n_i x â)). For integer m,
//   (1 - c^{m+1}) / (1 - c^2) = Σ_{j < (m+1)/2} c^{2j}                   (m odd)
//                             = 1 / (1 + c) + Σ_{j < m/2} c^{2j+1}        (m even),
// and the 1 / (1 + c) part is the m = 0 case, whose edge sum is the solid angle σ of the clipped
// polygon. So
//   Is = [m even] σ / (m + 1) - orient / (m + 1) Σ_i (Rv.n_i) Σ_{k in K} F_i(k),
//   F_i(k) = ∫_0^Θi c^k dψ,  K = {0, 2, .., m - 1} (m odd), {1, 3, .., m - 1} (m even),
// with k F(k) = (k - 1) C^2 F(k - 2) - [c^{k-1} c'] (c' = dc/dψ, C^2 = A^2 + B^2 = c^2 + c'^2),
// F(0) = Θ, F(1) = c'(0) - c'(Θ): O(m) per edge. σ by the fan of signed Van Oosterom-Strackee
// triangle solid angles.
//
// Where it loses digits: as for the segment (linear_specular_closed.h), the edge sums cancel when
// Rv lies outside the light (their "1" parts wind to 0 and the result is a tail), and the
// brackets cancel on short edges. The sum of the absolute values M of all terms is carried along;
// the result is accepted only when (m + 8) eps M / |Σ| <= kAreaClosedBound and M / |Σ| <= 64,
// otherwise area_specular_exact.h is used (area_specular_exact_dispatch in area_light.h).
// Measured (double; `./build/release/tests/area_light_tests -tc="closed-form*" -s`):
//   random convex 3..6-gons (size 1e-2..1e2, distance 0.3..30 sizes), integer m log-uniform in
//   [1, 1e3], 3000 seeds: 74 % within the bound; max rel. error 1.8e-13 against the Boost.Math
//   area quadrature (first 200 seeds, tol 1e-15), 4.5e-13 against the adaptive form (tol 1e-13);
//   error / estimate <= 1.4;
//   m in [1e3, 1e4], 400 seeds: 27 % within the bound, 4.6e-13 against the adaptive form (the
//   area quadrature is 4e-8 off there: it does not resolve lobes that narrow);
//   refused where needed: Rv 0.3 rad outside a unit square at distance 1, forced closed form
//   7e-9 off at m = 300 and 100 % at m = 1000, both refused;
//   named stiff cases (Rv inside, tiny 1e-6, thin 1e-6, huge 1e3, crossing the horizon, grazing
//   (m <= 40), behind the lobe) at m = 0, 1, 40, 1e4 through `--specular exact`: max 2.9e-12,
//   all finite.
// Float: the float instantiation computes in double (AreaReal) and rounds once.
// Cost: O(m) per edge, the edges' chains in step (docs/area-lights.md "Speed");
// bench/area_light_bench.cpp rows "closed form alone" and "adaptive form alone", and its
// --closed-by-m table (ns per evaluation at fixed m).
#pragma once

#include <array>
#include <cmath>
#include <limits>

#include "area_polygon.h"

namespace vlit {

inline constexpr double kAreaClosedBound = 5e-12;
inline constexpr double kAreaClosedMaxCancellation = 64;
inline constexpr int kAreaClosedMaxShininess = 100000;
// The dispatch (area_light.h) uses this form up to here only: its O(m) recurrence costs more than the
// adaptive form above (bench/area_light_bench.cpp; at m = 1e4 ~10x more).
inline constexpr int kAreaClosedDispatchMaxShininess = 1000;
// Above kAreaTailDispatchMaxShininess the dispatch tries this form only where max(0, Rv.w)^m
// reaches at least this on the light (1 / kAreaClosedMaxCancellation): where the lobe's peak on
// the light is lower, the result is a tail well below the edge terms, and the form refuses most
// such cases (tests/kernels/area/area_specular_closed_test.cpp counts them) after its O(m)
// recurrence. `./build/release/bench/area_light_bench --closed-by-m [--tails]`, docs/area-lights.md.
inline constexpr double kAreaClosedDispatchMinPeakLobe = 1.0 / kAreaClosedMaxCancellation;

// One edge d_i -> d_j of the clipped polygon as the per-edge recurrences see it (this file and
// area_specular_closed_real.h): with a = D + d_i, b = D + d_j and the edge's pole
// nh = a x b / |a x b|, the weight wn = Rv.nh, the arc theta from a to b, and at both ends
// c = Rv.x̂ and c' = Rv.(nh x x̂) (x̂ = â, b̂).
template <class R>
struct ArvoEdge {
  R wn, theta, c0, c0p, c1, c1p;
};

// False for an edge that adds nothing: a x b = 0 (zero-length, or P on its line), or Rv in the
// edge's plane (wn = 0). ah, bh: the unit vectors of a and b (a vertex's is shared by its two
// edges); with_theta = false leaves theta unset (even m does not need the arc).
template <class R>
bool arvo_edge(const AreaView<R>& view, const Vec3<R>& rv, const Vec3<R>& di, const Vec3<R>& dj, const Vec3<R>& ah,
               const Vec3<R>& bh, bool with_theta, ArvoEdge<R>& e) {
  const Vec3<R> cr = edge_cross(view.D, di, dj);  // a x b
  const R len_cr = length(cr);
  if (!(len_cr > R(0))) return false;
  const Vec3<R> nh = cr / len_cr;
  e.wn = dot(rv, nh);
  if (e.wn == R(0)) return false;
  e.theta = with_theta ? std::atan2(len_cr, dot(view.D + di, view.D + dj)) : R(0);
  e.c0 = dot(rv, ah);
  e.c0p = dot(rv, cross(nh, ah));
  e.c1 = dot(rv, bh);
  e.c1p = dot(rv, cross(nh, bh));
  return true;
}

template <class R>
bool arvo_edge(const AreaView<R>& view, const Vec3<R>& rv, const Vec3<R>& di, const Vec3<R>& dj, ArvoEdge<R>& e) {
  return arvo_edge(view, rv, di, dj, normalize(view.D + di), normalize(view.D + dj), true, e);
}

// The signed solid angle of a polygon seen from P: the fan from its first vertex of Van
// Oosterom-Strackee triangle solid angles; magnitude receives the sum of their absolute values.
template <class R>
R fan_solid_angle(const ClipPolygon<R>& poly, const AreaView<R>& view, R& magnitude) {
  const Vec3<R> a = view.D + poly.d[0];
  const R la = length(a);
  R omega = 0;
  magnitude = 0;
  for (int i = 1; i + 1 < poly.count; ++i) {
    const Vec3<R> b = view.D + poly.d[i], c = view.D + poly.d[i + 1];
    const R lb = length(b), lc = length(c);
    const R num = dot(a, cross(b, c));
    const R den = la * lb * lc + dot(a, b) * lc + dot(a, c) * lb + dot(b, c) * la;
    const R t = R(2) * std::atan2(num, den);
    omega += t;
    magnitude += std::fabs(t);
  }
  return omega;
}

template <class R>
struct AreaSpecularClosed {
  R value{0};
  R condition{0};
  bool accepted = true;
};

template <class R>
AreaSpecularClosed<R> area_specular_closed(const ClipPolygon<R>& horizon_clipped, const AreaView<R>& view,
                                           const Vec3<R>& rv_in, int m) {
  AreaSpecularClosed<R> r;
  if (!view.lit || horizon_clipped.count < 3) return r;
  const Vec3<R> rv = normalize(rv_in);
  ClipPolygon<R> poly;
  clip_halfspace(horizon_clipped.d.data(), horizon_clipped.count, rv, dot(rv, view.D), poly);
  const int n = poly.count;
  if (n < 3) return r;
  // The edges' chains run in step: the inner loops over edges are independent and vectorise (one
  // edge's chain alone waits on its previous step's result at every step). m = 0 has no chains.
  std::array<R, kMaxClipVertices> wn, f, f_mag, p0, p1, q0, q1, c2, c0p, c1p, s, s_mag;  // [0, edges) written
  int edges = 0;
  const Vec3<R> first = m > 0 ? normalize(view.D + poly.d[0]) : Vec3<R>{};
  Vec3<R> ah = first;  // the direction of edge i's first vertex from P (shared with edge i - 1)
  for (int i = 0; i < n && m > 0; ++i) {
    ArvoEdge<R> edge;
    const int j = i + 1 < n ? i + 1 : 0;
    const Vec3<R> bh = j == 0 ? first : normalize(view.D + poly.d[j]);
    const bool used = arvo_edge(view, rv, poly.d[i], poly.d[j], ah, bh, m % 2 == 1, edge);
    ah = bh;
    if (!used) continue;
    const int e = edges++;
    wn[e] = edge.wn;
    c2[e] = edge.c0 * edge.c0 + edge.c0p * edge.c0p;
    c0p[e] = edge.c0p;
    c1p[e] = edge.c1p;
    q0[e] = edge.c0 * edge.c0;
    q1[e] = edge.c1 * edge.c1;
    s[e] = 0;
    s_mag[e] = 0;
    // F(k0) and c^{k0+1} at both ends, k0 = 0 (m odd) or 1 (m even)
    if (m % 2 == 1) {
      f[e] = edge.theta;
      f_mag[e] = edge.theta;
      p0[e] = edge.c0;
      p1[e] = edge.c1;
    } else {
      f[e] = edge.c0p - edge.c1p;
      f_mag[e] = std::fabs(edge.c0p) + std::fabs(edge.c1p);
      p0[e] = q0[e];
      p1[e] = q1[e];
    }
  }
  // The chain k0, k0 + 2, .., m - 1: each step adds F(k) to the sums and moves to F(k + 2).
  const int k0 = (m % 2 == 1) ? 0 : 1;
  for (int k = k0; k + 2 <= m - 1; k += 2) {
    // F(k + 2) = ((k + 1) C^2 F(k) - [c^{k+1} c']) / (k + 2), the division as a product with
    // 1 / (k + 2) (one division per step for all edges, off the chains; the batch kernel
    // area_specular_batch.h does the same: `batch_kernel_tests -tc='area specular batch*' -s`
    // measures 0 between the two on every lane)
    const R k1 = R(k + 1), inv = R(1) / R(k + 2);
    for (int e = 0; e < edges; ++e) {
      s[e] += f[e];
      s_mag[e] += f_mag[e];
      const R e1 = p1[e] * c1p[e], e0 = p0[e] * c0p[e];
      f[e] = (k1 * c2[e] * f[e] - (e1 - e0)) * inv;
      f_mag[e] = (k1 * c2[e] * f_mag[e] + std::fabs(e1) + std::fabs(e0)) * inv;
      p0[e] *= q0[e];
      p1[e] *= q1[e];
    }
  }
  R sum = 0, mag = 0;
  for (int e = 0; e < edges; ++e) {  // the last F(m - 1) added here
    sum += wn[e] * (s[e] + f[e]);
    mag += std::fabs(wn[e]) * (s_mag[e] + f_mag[e]);
  }
  R total = -view.orient * sum;
  if (m % 2 == 0) {
    R omega_mag = 0;
    total += std::fabs(fan_solid_angle(poly, view, omega_mag));
    mag += omega_mag;
  }
  constexpr R eps = std::numeric_limits<R>::epsilon();
  const R abs_total = std::fabs(total);
  r.condition = abs_total > R(0) ? R(m + 8) * eps * mag / abs_total : (mag > R(0) ? std::numeric_limits<R>::infinity() : R(0));
  r.accepted = r.condition <= R(kAreaClosedBound) && mag <= R(kAreaClosedMaxCancellation) * abs_total;
  r.value = std::fmax(total / R(m + 1), R(0));
  return r;
}

}  // namespace vlit
