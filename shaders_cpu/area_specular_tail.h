// Area light, specular, closed form for lobe tails: the Phong lobe integrated over the visible
// polygon when Rv misses it, as per-edge recurrences whose terms do not cancel.
//
// What it computes: Is(exact) = ∫_Omega [N.w > 0] max(0, Rv.w)^m dw (unit intensity, ks = 1), m > 0,
// the quantity of area_specular_closed.h and area_specular_exact.h, when the ray along Rv misses
// the visible polygon (there the forward closed form's edge terms, each ~ 1 / (m + 1), cancel down
// to the tail and area_specular_closed.h refuses most such cases).
//
// Sources: the edge form of area_specular_closed.h (Arvo 1995, "Applications of irradiance
// tensors to the simulation of non-Lambertian phenomena"), derived here for the tail; backward
// recurrence for the decaying solution of a three-term recurrence (Gautschi 1967, "Computational
// aspects of three-term recurrence relations", SIAM Review 9). Conventions: conventions.h,
// geometry of area_polygon.h.
//
// Derivation. After the horizon and lobe clips, area_specular_closed.h has
// Is = -orient / (m + 1) Σ_i wn_i ∫_0^Θi (1 - c^{m+1}) / (1 - c^2) dψ (wn_i = Rv.n_i, c(ψ) =
// C cos(ψ - ψ0) >= 0 along edge i, C^2 = 1 - wn_i^2). When Rv misses the polygon, the "1" parts sum
// to 0 (the winding number of the polygon about Rv; area_specular_exact.h uses the same fact), so
//   Is = orient / (m + 1) Σ_i wn_i G_i(m + 1),   G(k) = ∫_0^Θ c^k / (1 - c^2) dψ > 0,
// with G(k) = G(k + 2) + F(k), F(k) = ∫_0^Θ c^k dψ, and (k + 1) C^2 F(k) = (k + 2) F(k + 2) +
// [c^{k+1} c']_0^Θ (area_specular_closed.h), for real k. Per edge:
//  - c has no maximum inside the arc (c'(0) <= 0 or c'(Θ) >= 0): F decays like s^k (s the larger
//    end value of c) while the other solution of the recurrence decays like C^k, so the recurrence
//    run downward damps every error by rho = s^2 / C^2 per step. Started from 0 at k = m + 1 + 2J,
//    with J so that rho^J is below 1e-17 (1 - s^2), it gives G(m + 1) to rounding. Scaled by
//    s^k, and split into the parts driven by each end, every quantity stays O(1) and no power of c
//    is formed inside the loop: f(k) = F_s(k) / s^k, g(k) = G_s(k) / s^k for the end where c = s,
//    h and q the same for the other end divided by r^{k+1} (r = c / s there):
//      f(k) = ((k + 2) s^2 f(k + 2) + s phi_s) / ((k + 1) C^2),   g(k) = s^2 g(k + 2) + f(k),
//      h(k) = ((k + 2) s^2 r^2 h(k + 2) + s phi_r) / ((k + 1) C^2), q(k) = s^2 r^2 q(k + 2) + h(k),
//      G(m + 1) = s^{m+1} (g + r^{m+2} q)   (phi: +-c' at that end, the sign of the bracket).
//    J grows as rho -> 1 (the maximum of c just past an end: ~39 / d^2 steps for an edge pointing
//    toward Rv from an angular distance d). For integer m the upward recurrence (below) runs
//    instead where J > m / 2 + 16 and rho^{(m+1)/2} >= 1e-3 (it then loses at most a factor 1e3),
//    and the downward one again where the upward one's estimate fails.
//  - c has its maximum inside the arc: both solutions decay like C^k; the upward recurrence
//    (area_specular_closed.h, from F(0) = Θ or F(1) = c'(0) - c'(Θ); integer m only) is stable.
//    Then G(m + 1) = G(k0) - Σ_{k < m+1} F(k) (k of m + 1's parity), with
//    G(0) = [atan2(-c', |wn| c)] / |wn| and G(1) = [atan2(-c', |wn|)] / |wn| (their derivatives are
//    |wn| / (1 - c^2) and |wn| c / (1 - c^2)), or, where that difference cancels,
//    G(m + 1) = Σ_{j >= 0} F(m + 1 + 2j) continued upward until the terms are below 1e-17 of the sum.
// Error: each edge's estimate is (its steps + 8) eps times the sum of the absolute values its terms
// reach (as area_specular_closed.h), plus the truncation, plus 4 eps / (1 - top^2) relative for the
// inputs' rounding (top: the largest c on the edge, near 1 where Rv is near the light); an edge
// whose bound top^{m+1} pi / (1 - top^2) lies below kAreaTailNegligibleEdge of another edge's
// counts as 0 with that bound as its error. The result is accepted when
// Σ_i |wn_i| err_i <= kAreaClosedBound |Σ_i wn_i G_i|. Refused (a caller takes another form):
// Rv inside the polygon or so near its boundary that the inputs' rounding alone fails the bound
// (1 - top^2 < 4 eps / kAreaClosedBound: ~0.013 rad), an edge needing the upward recurrence at real m or at
// m > kAreaClosedDispatchMaxShininess, more than kAreaTailMaxSteps steps in all, and every case
// whose estimate fails.
// Cost: per edge min(J, m / 2) steps, J independent of m: a tail far from the lobe's axis costs a
// few dozen steps whatever m; docs/area-lights.md "Lobe tails" has the figures, and why the
// dispatch stops at kAreaTailDispatchMaxShininess.
// Measured: tests/kernels/area/area_specular_tail_test.cpp (`./build/release/tests/area_light_tests
// -tc="tail*" -s`); docs/area-lights.md "Lobe tails".
// Float: computes in double (AreaReal) like the other area kernels.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "area_polygon.h"
#include "area_specular_closed.h"

namespace vlit {

// The exact specular's dispatch (area_light.h) tries this form up to here: above it the adaptive
// form is as fast on lobe tails (bench/area_light_bench.cpp --closed-by-m --tails).
inline constexpr double kAreaTailDispatchMaxShininess = 200;
// An edge with C = |Rv x n_i| below this has c = 0 along it but for rounding (the lobe clip's edge).
inline constexpr double kAreaTailLobeEdge = 1e-12;
// An edge whose G is bounded below this is taken as 0 (its recurrences would underflow), and one
// whose |wn| G is bounded below kAreaTailNegligibleEdge of another edge's bound (a far edge at
// large m); both are counted in the error estimate with their bound.
inline constexpr double kAreaTailNegligible = 1e-290;
inline constexpr double kAreaTailNegligibleEdge = 1e-20;
// The recurrences' steps over all edges at most (the downward one needs more as rho -> 1, the upward
// one m / 2): beyond this the adaptive form costs less.
inline constexpr int kAreaTailMaxSteps = 512;

namespace area_tail_detail {

// G(m + 1) of one edge, and an estimate of its absolute error; ok = false: refused.
template <class R>
struct EdgeTail {
  R g = 0, error = 0;
  bool ok = false;
};

// The downward recurrence (no maximum of c inside the arc): steps J, mu = m + 1.
template <class R>
EdgeTail<R> tail_downward(R c0, R c0p, R c1, R c1p, R c2, R mu, int steps) {
  constexpr R eps = std::numeric_limits<R>::epsilon();
  const bool high_at_end = c1 >= c0;
  const R s = high_at_end ? c1 : c0;
  const R r = std::max(high_at_end ? c0 : c1, R(0)) / s;
  const R phi_s = high_at_end ? c1p : -c0p, phi_r = high_at_end ? -c0p : c1p;
  const R s2 = s * s, s2r2 = s2 * r * r;
  R f = 0, g = 0, h = 0, q = 0, f_mag = 0, g_mag = 0, h_mag = 0, q_mag = 0;
  for (int j = steps - 1; j >= 0; --j) {
    const R k = mu + R(2 * j);
    const R inv = R(1) / ((k + R(1)) * c2);
    const R up = (k + R(2)) * s2;
    f = (up * f + s * phi_s) * inv;
    h = (up * r * r * h + s * phi_r) * inv;
    f_mag = (up * f_mag + s * std::fabs(phi_s)) * inv;
    h_mag = (up * r * r * h_mag + s * std::fabs(phi_r)) * inv;
    g = s2 * g + f;
    q = s2r2 * q + h;
    g_mag = s2 * g_mag + f_mag;
    q_mag = s2r2 * q_mag + h_mag;
  }
  const R scale = std::pow(s, mu), tail_r = std::pow(r, mu + R(1));
  EdgeTail<R> e;
  e.g = scale * (g + tail_r * q);
  const R rho = s2 / c2;
  e.error = scale * (g_mag + tail_r * q_mag) * (R(steps + 8) * eps) +
            std::fabs(e.g) * std::pow(rho, R(steps)) * (R(1) + R(1) / (R(1) - s2));
  e.ok = std::isfinite(e.g) && std::isfinite(e.error);
  return e;
}

// The upward recurrence (integer mu = m + 1 <= kAreaClosedDispatchMaxShininess + 1), for G(mu) as
// G(k0) - Σ_{k < mu} F(k) (k0 = 0 or 1, of mu's parity) where its estimate is within `bound`, else
// as Σ_{j >= 0} F(mu + 2j) if that one's estimate is the smaller. s_wn = |wn|.
template <class R>
EdgeTail<R> tail_upward(R c0, R c0p, R c1, R c1p, R c2, R theta, R s_wn, int mu, R bound) {
  constexpr R eps = std::numeric_limits<R>::epsilon();
  const int k0 = mu % 2;
  R f = k0 == 0 ? theta : c0p - c1p;
  R f_mag = k0 == 0 ? theta : std::fabs(c0p) + std::fabs(c1p);
  R p0 = k0 == 0 ? c0 : c0 * c0, p1 = k0 == 0 ? c1 : c1 * c1;
  const R q0 = c0 * c0, q1 = c1 * c1;
  R below = 0, below_mag = 0;  // Σ_{k < mu} F(k) and its terms' magnitudes
  int k = k0;
  auto step = [&] {
    const R k1 = R(k + 1), inv = R(1) / R(k + 2);
    const R e1 = p1 * c1p, e0 = p0 * c0p;
    f = (k1 * c2 * f - (e1 - e0)) * inv;
    f_mag = (k1 * c2 * f_mag + std::fabs(e1) + std::fabs(e0)) * inv;
    p0 *= q0;
    p1 *= q1;
    k += 2;
  };
  while (k < mu) {
    below += f;
    below_mag += f_mag;
    step();
  }
  EdgeTail<R> e;
  // G(k0) - Σ_{k < mu} F(k): G(0) = [atan2(-c', |wn| c)] / |wn|, G(1) = [atan2(-c', |wn|)] / |wn|
  // (d/dψ atan2(-c', |wn| c) = |wn| / (1 - c^2) and d/dψ atan2(-c', |wn|) = |wn| c / (1 - c^2), from
  // c = C cos(ψ - ψ0), c' = -C sin(ψ - ψ0), C^2 + wn^2 = 1).
  const R a1 = k0 == 0 ? std::atan2(-c1p, s_wn * c1) : std::atan2(-c1p, s_wn);
  const R a0 = k0 == 0 ? std::atan2(-c0p, s_wn * c0) : std::atan2(-c0p, s_wn);
  const R y = (a1 - a0) / s_wn;
  e.g = y - below;
  // The two angles carry eps of their size each (not of their difference).
  e.error = (R(mu + 8) * eps) * below_mag + R(4) * eps * (std::fabs(a1) + std::fabs(a0)) / s_wn;
  e.ok = std::isfinite(e.g) && e.g > R(0);
  if (e.ok && e.error <= bound * e.g) return e;
  // Σ_{j >= 0} F(mu + 2j), upward until a term is below 1e-17 (1 - C^2) of the sum.
  R sum = 0, sum_mag = 0;
  const int limit = kAreaTailMaxSteps;
  int taken = 0;
  const R stop = R(1e-17) * (R(1) - c2);
  for (; taken < limit; ++taken) {
    sum += f;
    sum_mag += f_mag;
    if (std::fabs(f) <= stop * sum) break;
    step();
  }
  EdgeTail<R> t;
  t.g = sum;
  t.error = (R(mu + taken + 8) * eps) * sum_mag;
  t.ok = taken < limit && std::isfinite(sum) && sum > R(0);
  if (t.ok && (!e.ok || t.error / t.g < e.error / e.g)) return t;
  return e;
}

}  // namespace area_tail_detail

// Is(exact) of the horizon-clipped polygon when Rv misses it (see above); accepted = false where
// it does not apply or its estimate fails. absolute_floor: where a bound of Is lies below it, 0 is
// returned at once (the adaptive form's absolute target, area_specular_exact.h).
template <class R>
AreaSpecularClosed<R> area_specular_tail(const ClipPolygon<R>& horizon_clipped, const AreaView<R>& view,
                                         const Vec3<R>& rv_in, R m, R absolute_floor = R(0)) {
  using namespace area_tail_detail;
  AreaSpecularClosed<R> r;  // the closed forms' result (area_specular_closed.h)
  r.accepted = false;       // every early return below refuses
  if (!view.lit || horizon_clipped.count < 3 || !(m > R(0))) return r;
  const Vec3<R> rv = normalize(rv_in);
  ClipPolygon<R> poly;
  clip_halfspace(horizon_clipped.d.data(), horizon_clipped.count, rv, dot(rv, view.D), poly);
  const int n = poly.count;
  if (n < 3) {  // nothing of the light in front of the lobe's half-space
    r.accepted = true;
    return r;
  }
  if (ray_hits_polygon(poly, view, rv)) return r;
  const R mu = m + R(1);
  const bool integer = m == std::floor(m) && m <= R(kAreaClosedDispatchMaxShininess);
  const R bound = R(kAreaClosedBound);
  constexpr R eps = std::numeric_limits<R>::epsilon();
  // First the edges and the plan for each (which recurrence, how many steps), so that a case whose
  // recurrences would run longer than kAreaTailMaxSteps in all, or whose inputs' rounding alone
  // fails the bound, is refused before any of them runs.
  enum class Kind : unsigned char { kZero, kDown, kUp };
  struct Plan {
    ArvoEdge<R> edge;
    Vec3<R> a_hat, b_hat;     // the edge's ends' directions from P
    R c2, s, top, log_most;   // log_most: log of top^{m+1} pi / (1 - top^2) >= G
    R zero_error;
    int steps, down_steps;    // down_steps: the downward recurrence's, 0 where it cannot run
    bool peak_inside;
    Kind kind;
  };
  std::array<Plan, kMaxClipVertices> plans;
  int planned = 0;
  R most_weighted = 0, log_most_weighted = -std::numeric_limits<R>::infinity();
  const Vec3<R> first = normalize(view.D + poly.d[0]);
  Vec3<R> ah = first;
  for (int i = 0; i < n; ++i) {
    const int j = i + 1 < n ? i + 1 : 0;
    const Vec3<R> bh = j == 0 ? first : normalize(view.D + poly.d[j]);
    Plan& plan = plans[planned];
    const bool used = arvo_edge(view, rv, poly.d[i], poly.d[j], ah, bh, false, plan.edge);
    plan.a_hat = ah;
    plan.b_hat = bh;
    ah = bh;
    if (!used) continue;
    const ArvoEdge<R>& edge = plan.edge;
    plan.c2 = std::min(edge.c0 * edge.c0 + edge.c0p * edge.c0p, R(1));
    plan.peak_inside = edge.c0p > R(0) && edge.c1p < R(0);
    plan.s = std::max(edge.c0, edge.c1);
    // The largest c on the edge (C where c peaks inside the arc): G <= top^{m+1} Θ / (1 - top^2).
    plan.top = plan.peak_inside ? std::sqrt(plan.c2) : plan.s;
    plan.log_most = plan.top > R(0) ? mu * std::log(plan.top) + std::log(R(M_PI) / std::max(R(1) - plan.top * plan.top, std::numeric_limits<R>::min()))
                                    : -std::numeric_limits<R>::infinity();
    const R log_weighted = std::log(std::fabs(edge.wn)) + plan.log_most;
    most_weighted += std::exp(log_weighted);
    log_most_weighted = std::max(log_most_weighted, log_weighted);
    ++planned;
  }
  // Is = orient / (m + 1) Σ wn_i G_i is below the caller's absolute target: 0, as the adaptive form.
  if (most_weighted / mu <= absolute_floor) {
    r.accepted = true;
    return r;
  }
  int total_steps = 0;
  for (int i = 0; i < planned; ++i) {
    Plan& plan = plans[i];
    const ArvoEdge<R>& edge = plan.edge;
    plan.steps = plan.down_steps = 0;
    const bool lobe_edge = plan.c2 <= R(kAreaTailLobeEdge * kAreaTailLobeEdge);
    if ((!plan.peak_inside && !(plan.s > R(0))) || lobe_edge || plan.log_most < std::log(R(kAreaTailNegligible)) ||
        std::log(std::fabs(edge.wn)) + plan.log_most < log_most_weighted + std::log(R(kAreaTailNegligibleEdge))) {
      // c <= 0 along the edge; or c = 0 but for rounding (an edge the lobe clip made: C = 0, where
      // the angles below would be those of rounding errors); or G below what double holds, or
      // below 1e-20 of another edge's bound: G = 0, off by at most its bound (counted below).
      plan.kind = Kind::kZero;
      plan.zero_error = lobe_edge ? std::pow(std::sqrt(plan.c2), mu) * R(M_PI) : std::exp(plan.log_most);
      continue;
    }
    // The inputs' rounding (below) would fail the bound on its own: this edge's G dominates. This
    // also refuses Rv within ~0.013 rad of the polygon's boundary, where the winding that makes the
    // "1" parts vanish would be decided by rounding.
    if (R(4) * eps / std::max(R(1) - plan.top * plan.top, std::numeric_limits<R>::min()) > bound) return r;
    const R s = plan.s;
    const R rho = plan.peak_inside ? R(1) : std::min(s * s / plan.c2, R(1));
    // Steps for rho^J <= 1e-17 (1 - s^2); the downward recurrence where it is about as short as
    // the upward one, where the upward one would lose more than 1e3, or where that cannot run
    // (real m, or m above the closed form's range).
    const R wanted = rho < R(1) ? std::log(R(1e-17) * (R(1) - s * s)) / std::log(rho) : std::numeric_limits<R>::infinity();
    const bool can_go_down = !plan.peak_inside && wanted <= R(kAreaTailMaxSteps);
    if (can_go_down) plan.down_steps = std::max(1, int(std::ceil(wanted)));
    if (can_go_down && (!integer || wanted <= R(0.5) * mu + R(16) || std::pow(rho, R(0.5) * mu) < R(1e-3))) {
      plan.kind = Kind::kDown;
      plan.steps = plan.down_steps;
    } else if (integer) {
      plan.kind = Kind::kUp;
      plan.steps = int(mu) / 2 + 1;
      // The arc, for F(0) (m + 1 even)
      if (int(mu) % 2 == 0) plan.edge.theta = std::atan2(length(cross(plan.a_hat, plan.b_hat)), dot(plan.a_hat, plan.b_hat));
    } else {
      return r;
    }
    total_steps += plan.steps;
    if (total_steps > kAreaTailMaxSteps) return r;
  }
  R sum = 0, error = 0;
  for (int i = 0; i < planned; ++i) {
    const Plan& plan = plans[i];
    const ArvoEdge<R>& edge = plan.edge;
    EdgeTail<R> e;
    switch (plan.kind) {
      case Kind::kZero:
        e.ok = true;
        e.error = plan.zero_error;
        break;
      case Kind::kDown:
        e = tail_downward(edge.c0, edge.c0p, edge.c1, edge.c1p, plan.c2, mu, plan.steps);
        break;
      case Kind::kUp:
        e = tail_upward(edge.c0, edge.c0p, edge.c1, edge.c1p, plan.c2, edge.theta, std::fabs(edge.wn), int(mu), bound);
        // Where its estimate fails on an edge without an inner maximum, the longer downward run.
        if (plan.down_steps > 0 && !(e.ok && e.error <= bound * e.g))
          e = tail_downward(edge.c0, edge.c0p, edge.c1, edge.c1p, plan.c2, mu, plan.down_steps);
        break;
    }
    if (!e.ok) return r;
    // The inputs' rounding: c, c' carry eps each, and 1 - c^2 near the largest c on the edge is
    // where G is most sensitive to it.
    if (plan.kind != Kind::kZero)
      e.error += std::fabs(e.g) * R(4) * eps / std::max(R(1) - plan.top * plan.top, std::numeric_limits<R>::min());
    sum += edge.wn * e.g;
    error += std::fabs(edge.wn) * e.error;
  }
  const R total = view.orient * sum;
  const R abs_total = std::fabs(total);
  r.condition = abs_total > R(0) ? error / abs_total : (error > R(0) ? std::numeric_limits<R>::infinity() : R(0));
  r.accepted = r.condition <= bound;
  r.value = std::fmax(total / mu, R(0));
  return r;
}

}  // namespace vlit
