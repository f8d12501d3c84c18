// Area light, specular, real (non-integer) m: the Phong lobe integrated over the visible polygon
// as per-edge recurrences in the exponent started from two small-exponent integrals, each
// integrated in the edge's angle by a fixed Gauss-Kronrod rule.
//
// What it computes: Is(exact) = ∫_Omega [N.w > 0] max(0, Rv.w)^m dw (unit intensity, ks = 1), real
// m >= 0: the quantity of area_specular_closed.h (integer m) and area_specular_exact.h (adaptive).
// glTF roughness gives non-integer m (src/scene/material.cpp).
//
// Sources: the edge form and the recurrence of area_specular_closed.h (Arvo 1995); the Kronrod
// 7/15 rule of adaptive_kronrod.h (Kronrod 1965, QUADPACK's tables and error heuristic,
// Piessens et al. 1983). Conventions: conventions.h, geometry of area_polygon.h.
//
// Derivation. As in area_specular_closed.h, Is = -orient / (m + 1) Σ_i (Rv.n_i) E_i with
// E_i = ∫_0^Θi (1 - c^{m+1}) / (1 - c^2) dψ, c(ψ) = A cos ψ + B sin ψ = C cos(ψ - ψ0) >= 0 after the
// lobe clip. For real μ = m + 1 write μ = s + 2J with s in [kRealBase, kRealBase + 2) (s = μ, J = 0
// when μ < kRealBase + 2); since (1 - c^μ) = (1 - c^s) + c^s (1 - c^{2J}),
//   E_i = H(s) + Σ_{j < J} F(s + 2j),  H(s) = ∫ (1 - c^s) / (1 - c^2) dψ,  F(k) = ∫ c^k dψ,
// and k F(k) = (k - 1) C^2 F(k - 2) - [c^{k-1} c'] holds for real k > 1 (c'' = -c and c^2 + c'^2 = C^2
// give (c^{k-1} c')' = (k - 1) C^2 c^{k-2} - k c^k), so F(s + 2), F(s + 4), .. follow from F(s) in O(m).
// H(s) and F(s) are integrals of bounded smooth functions of ψ whose only scale is the width of
// c^s (~ 1 / sqrt(s) rad, s < kRealBase + 2) and, at an end where the lobe clip made c = 0, the
// branch point of c^s (c^s ~ v^s, v the distance to that end; s >= kRealBase makes it harmless to
// a 15-point rule). Both are integrated on the same nodes: [0, Θ] in panels of width <=
// kRealPanel, Kronrod 15 points each, and 1 - c^2 = (Rv.n)^2 + C^2 sin^2(ψ - ψ0),
// 1 - c^s = -expm1(s log1p(-(1 - c))) so that nothing cancels near c = 1.
//
// Error: the quadrature error of each panel is estimated by QUADPACK's heuristic from |K15 - G7|
// (|K15 - G7| min(1, (200 |K15 - G7| / I_abs)^1.5), I_abs = K15 of |f - mean|); the recurrence's
// and the edge sum's rounding as in area_specular_closed.h (Σ of absolute values M). The result is
// accepted when (m + 8) eps M / |Σ| + Q / |Σ| <= kAreaClosedBound (Q: Σ of |Rv.n_i| times the
// quadrature estimates, F's counted J + 1 times: the recurrence carries an error of F(s) forward
// with factors (k - 1) C^2 / k <= 1) and M / |Σ| <= 64; otherwise a caller takes the adaptive form.
// Not dispatched by `--specular exact` (area_light.h): ~3 us per quad (about 120 nodes, each a
// sincos, a log1p and an exp) is 2-3x faster than the adaptive form on the bench's cases but was
// slower on the MetalRoughSpheres bake (docs/area-lights.md "Real m").
// Measured: docs/area-lights.md "Real m"; tests/kernels/area/area_specular_closed_test.cpp
// "real-m closed form*" (`./build/release/tests/area_light_tests -tc="real-m*" -s`).
// Float: computes in double (AreaReal) like the other area kernels.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>

#include "adaptive_kronrod.h"
#include "area_polygon.h"
#include "area_specular_closed.h"

namespace vlit {

inline constexpr double kRealBase = 6;      // base exponent s in [kRealBase, kRealBase + 2)
inline constexpr double kRealPanel = 1.2;   // rad: widest Kronrod panel along an edge
inline constexpr int kRealGradedPanels = 3;  // panels in w toward an end where c = 0 (2: estimates 1e-9)

namespace area_real_detail {

// The two base integrals of one edge on [psi_a, psi_b]: H(s) and F(s), with their error estimates.
template <class R>
struct BaseIntegrals {
  R h = 0, f = 0, h_err = 0, f_err = 0;
};

// e^x - 1 to ~1 ulp: exp(x) - 1 where |x| > 1/2 (the difference is >= 0.39 |e^x|, no cancellation),
// the Taylor series to x^15 / 15! below (remainder < 0.5^16 / 16! < 1e-18 relative). glibc's expm1
// took 40 % of this kernel's time (perf), its exp a fraction of that.
template <class R>
R expm1_small(R x) {
  if (std::fabs(x) > R(0.5)) return std::exp(x) - R(1);
  // x (1 + x/2 (1 + x/3 (1 + ... (1 + x/15))))
  constexpr R inv[16] = {R(0), R(1), R(1) / 2, R(1) / 3, R(1) / 4, R(1) / 5, R(1) / 6, R(1) / 7, R(1) / 8,
                         R(1) / 9, R(1) / 10, R(1) / 11, R(1) / 12, R(1) / 13, R(1) / 14, R(1) / 15};
  R p = R(1);
  for (int k = 15; k >= 2; --k) p = R(1) + x * p * inv[k];
  return x * p;
}

// QUADPACK's error heuristic for one panel (Piessens et al. 1983, qk15): the raw |K15 - G7| scaled
// by how well the panel resolves the integrand's variation.
template <class R>
R kronrod_error(R diff, R resasc) {
  diff = std::fabs(diff);
  if (!(resasc > R(0)) || diff == R(0)) return diff;
  return resasc * std::min(R(1), std::pow(R(200) * diff / resasc, R(1.5)));
}

// K15 and G7 of H's and F's integrands on the panel w in [w0, w1] of the map u = u_end - sign L w^q
// (q = 1, sign = -1: u = u_end + L w, a plain panel; q > 1: graded toward u_end, where c = 0),
// u = psi - psi0; wn2 = (Rv.n)^2, big_c = C (c = C cos u).
template <class R>
void kronrod_panel(R u_end, R sign, R len, R q, R w0, R w1, R big_c, R wn2, R s, BaseIntegrals<R>& out) {
  using K = kronrod_detail::Kronrod15<R>;
  const R c2 = big_c * big_c;
  const R mid = (w0 + w1) / 2, half = (w1 - w0) / 2;
  R fh[15], ff[15];
  for (int i = 0; i < 15; ++i) {
    const R x = i < 7 ? -K::x[i] : (i == 7 ? R(0) : K::x[14 - i]);
    const R w = mid + half * x;
    const R wq = q == R(1) ? w : (w * w) * (w * w);  // q is 1 or 4
    const R jac = q == R(1) ? len : len * q * wq / w;  // du/dw in absolute value
    const R u = u_end - sign * len * wq;
    const R su = std::sin(u), cu = std::cos(u);
    const R c = std::max(big_c * cu, R(0));
    const R one_minus_c2 = wn2 + c2 * su * su;
    const R one_minus_c = std::min(one_minus_c2 / (R(1) + c), R(1));
    // c^s - 1 = expm1(s log c); at c = 1 exactly (Rv on the edge) the ratio's limit is s / 2.
    const R em1 = c > R(0) ? expm1_small(s * std::log1p(-one_minus_c)) : R(-1);
    const R j = w > R(0) ? jac : R(0);
    fh[i] = j * (one_minus_c2 > R(0) ? -em1 / one_minus_c2 : s / R(2));
    ff[i] = j * (R(1) + em1);
  }
  // Kronrod 15 and its Gauss 7 (the odd-indexed nodes of each half), and the absolute variation.
  R kh = K::wk[7] * fh[7], kf = K::wk[7] * ff[7], gh = K::wg[3] * fh[7], gf = K::wg[3] * ff[7];
  for (int i = 0; i < 7; ++i) {
    kh += K::wk[i] * (fh[i] + fh[14 - i]);
    kf += K::wk[i] * (ff[i] + ff[14 - i]);
    if (i % 2 == 1) {
      gh += K::wg[i / 2] * (fh[i] + fh[14 - i]);
      gf += K::wg[i / 2] * (ff[i] + ff[14 - i]);
    }
  }
  const R mean_h = kh / 2, mean_f = kf / 2;
  R ah = K::wk[7] * std::fabs(fh[7] - mean_h), af = K::wk[7] * std::fabs(ff[7] - mean_f);
  for (int i = 0; i < 7; ++i) {
    ah += K::wk[i] * (std::fabs(fh[i] - mean_h) + std::fabs(fh[14 - i] - mean_h));
    af += K::wk[i] * (std::fabs(ff[i] - mean_f) + std::fabs(ff[14 - i] - mean_f));
  }
  out.h += kh * half;
  out.f += kf * half;
  out.h_err += kronrod_error((kh - gh) * half, ah * half);
  out.f_err += kronrod_error((kf - gf) * half, af * half);
}

// H(s) and F(s) on u in [u_a, u_b] (subset of [-pi/2, pi/2]): panels of width <= kRealPanel; an end
// where c = 0 (a vertex of the lobe clip, |u| = pi/2) is a branch point of c^s ~ v^s (v its
// distance), and the piece toward it is mapped v = L w^4 (for s < 7): v^s dv becomes w^{4s + 3} dw
// (exponent >= 7, since s >= 1) times a smooth function, and the smooth parts stay polynomials in w.
template <class R>
void base_integrals(R u_a, R u_b, R big_c, R wn2, R s, BaseIntegrals<R>& out) {
  if (!(u_b > u_a)) return;
  if (!(big_c > R(0))) {  // c = 0 along the edge (the lobe clip's own edge): H = length, F = 0
    out.h += u_b - u_a;
    return;
  }
  constexpr R kBranch = R(1e-9);  // |cos u| below this at an end: c = 0 there up to rounding
  const bool sing_a = std::cos(u_a) <= kBranch, sing_b = std::cos(u_b) <= kBranch;
  const R q = (sing_a || sing_b) && s < R(7) ? R(4) : R(1);
  auto piece = [&](R u0, R u1, bool graded_at_u1) {
    // graded toward u1 (sign = +1: u = u1 - L w^q) or plain from u0 (u = u0 + L w)
    const R len = u1 - u0;
    if (!(len > R(0))) return;
    const int panels = std::max(graded_at_u1 && q != R(1) ? kRealGradedPanels : 1, int(std::ceil(len / R(kRealPanel))));
    for (int p = 0; p < panels; ++p) {
      const R w0 = R(p) / R(panels), w1 = R(p + 1) / R(panels);
      if (graded_at_u1) kronrod_panel(u1, R(1), len, q, w0, w1, big_c, wn2, s, out);
      else kronrod_panel(u0, R(-1), len, R(1), w0, w1, big_c, wn2, s, out);
    }
  };
  auto piece_at_u0 = [&](R u0, R u1) {  // graded toward u0: u = u0 + L w^q
    const R len = u1 - u0;
    if (!(len > R(0))) return;
    const int panels = std::max(kRealGradedPanels, int(std::ceil(len / R(kRealPanel))));
    for (int p = 0; p < panels; ++p)
      kronrod_panel(u0, R(-1), len, q, R(p) / R(panels), R(p + 1) / R(panels), big_c, wn2, s, out);
  };
  if (q == R(1) || (!sing_a && !sing_b)) {
    piece(u_a, u_b, false);
  } else if (sing_a && sing_b) {
    const R mid = (u_a + u_b) / 2;
    piece_at_u0(u_a, mid);
    piece(mid, u_b, true);
  } else if (sing_b) {
    piece(u_a, u_b, true);
  } else {
    piece_at_u0(u_a, u_b);
  }
}

}  // namespace area_real_detail

// The closed form with a real exponent m >= 0 (also correct for integer m, where
// area_specular_closed.h is cheaper). Same contract as area_specular_closed().
template <class R>
AreaSpecularClosed<R> area_specular_closed_real(const ClipPolygon<R>& horizon_clipped, const AreaView<R>& view,
                                                const Vec3<R>& rv_in, R m) {
  using namespace area_real_detail;
  AreaSpecularClosed<R> r;
  if (!view.lit || horizon_clipped.count < 3) return r;
  const Vec3<R> rv = normalize(rv_in);
  ClipPolygon<R> poly;
  clip_halfspace(horizon_clipped.d.data(), horizon_clipped.count, rv, dot(rv, view.D), poly);
  const int n = poly.count;
  if (n < 3) return r;
  const R mu = m + R(1);
  const int J = mu < R(kRealBase + 2) ? 0 : int(std::floor((mu - R(kRealBase)) / R(2)));
  const R s = mu - R(2 * J);
  R sum = 0, mag = 0, quad_err = 0;
  for (int i = 0; i < n; ++i) {
    ArvoEdge<R> edge;
    if (!arvo_edge(view, rv, poly.d[i], poly.d[(i + 1) % n], edge)) continue;
    const auto [wn, theta, c0, c0p, c1, c1p] = edge;
    const R cc2 = c0 * c0 + c0p * c0p;  // C^2
    const R big_c = std::sqrt(cc2);
    const R psi0 = std::atan2(c0p, c0);  // c = C cos(psi - psi0)
    BaseIntegrals<R> base;
    base_integrals(-psi0, theta - psi0, big_c, wn * wn, s, base);
    // F(s + 2j), j < J, upward from F(s): F(k + 2) = ((k + 1) C^2 F(k) - [c^{k+1} c']) / (k + 2).
    const R e0c = std::max(c0, R(0)), e1c = std::max(c1, R(0));
    R f = base.f, f_mag = std::fabs(base.f);
    R p0 = std::pow(e0c, s + R(1)), p1 = std::pow(e1c, s + R(1));  // c^{k+1} at both ends
    const R q0 = c0 * c0, q1 = c1 * c1;
    R chain = 0, chain_mag = 0;
    R k = s;
    for (int j = 0; j < J; ++j) {
      chain += f;
      chain_mag += f_mag;
      if (j + 1 == J) break;
      const R e1 = p1 * c1p, e0 = p0 * c0p;
      f = ((k + R(1)) * cc2 * f - (e1 - e0)) / (k + R(2));
      f_mag = ((k + R(1)) * cc2 * f_mag + std::fabs(e1) + std::fabs(e0)) / (k + R(2));
      p0 *= q0;
      p1 *= q1;
      k += R(2);
    }
    sum += wn * (base.h + chain);
    mag += std::fabs(wn) * (std::fabs(base.h) + chain_mag);
    quad_err += std::fabs(wn) * (base.h_err + R(J) * base.f_err);
  }
  const R total = -view.orient * sum;
  constexpr R eps = std::numeric_limits<R>::epsilon();
  const R abs_total = std::fabs(total);
  r.condition = abs_total > R(0) ? ((m + R(8)) * eps * mag + quad_err) / abs_total
                                 : (mag > R(0) ? std::numeric_limits<R>::infinity() : R(0));
  r.accepted = r.condition <= R(kAreaClosedBound) && mag <= R(kAreaClosedMaxCancellation) * abs_total;
  r.value = std::fmax(total / mu, R(0));
  return r;
}

}  // namespace vlit
