// Disk light, diffuse: Lambert's contour integral (Picott 1992 eq. 9) evaluated in closed form
// over the circle, with horizon clipping.
//
// Computes (unit intensity, kd = 1; conventions.h):
//   Id = ∫_A max(0, cos theta) cos theta_l / r^2 dA = -1/2 N . ∮ (r x dr) / |r|^2
// over the part of the disk above the tangent plane of P, its boundary traversed
// counter-clockwise about the disk's normal n (toward P). For a polygon the contour is a sum of
// straight edges, each giving beta_i cos delta_i (eq. 9). For a disk the contour is the circle
// (or, when the tangent plane of P cuts the disk, an arc [theta1, theta2] of it plus a straight
// chord on the horizon line):
//   r(theta) = d + R e(theta),  d = c - P,  e = u cos theta + v sin theta,  u x v = n,
//   N . (r x r') = R (C + alpha cos psi + beta sin psi),   |r|^2 = a + rho cos psi,
// psi = theta - phi0 measured from the direction phi0 of d_par (the in-plane part of d), and,
// with h = n.(P - c) > 0, rho_par = |d_par|, dhat = d_par / rho_par:
//   a = h^2 + rho_par^2 + R^2,  rho = 2 R rho_par,  s = sqrt(a^2 - rho^2)
//     = sqrt((h^2 + (rho_par - R)^2)(h^2 + (rho_par + R)^2))   (a product: no cancellation),
//   C = R N.n,  alpha = rho_par N.n + h N.dhat,  beta = h N.(n x dhat).
// Full circle: Id = pi R^2 / (s (a + s)) [ -N.n (X + s) + 2 h rho_par N.dhat ], X = h^2 + R^2 - rho_par^2,
// with X + s = 4 rho_par^2 h^2 / (s - X) when X < 0 (P outside the rim near the plane).
// Arc: I = ∫ (C + alpha cos psi + beta sin psi) / (a + rho cos psi) dpsi from three integrals
//   J0 = ∫ dpsi / (a + rho cos psi) = (2/s) arg(w2 conj(w1)), w = cos(psi/2) + i k sin(psi/2),
//        k = sqrt((h^2 + (rho_par - R)^2) / (h^2 + (rho_par + R)^2))    (an atan2 in [0, pi]),
//   Js = ∫ sin psi / (...) = -ln(|r2|^2 / |r1|^2) / rho                (log1p form for small rho),
//   Jc = ∫ cos psi / (...) = (dpsi - a J0) / rho,
// assembled so that no term carries 1/rho or 1/s without its cancelling partner:
//   q = rho / (a + s) < 1/4 (P far from the rim, small or distant disk): Jc from the Fourier
//     series 1/(a + rho cos psi) = (1/s)(1 + 2 Σ (-q)^n cos n psi) and I = C J0 + alpha Jc + beta Js;
//   q >= 1/4 (near the rim): I = K J0 + alpha dpsi / rho + beta Js with
//     K = C - alpha a / rho = N.n (X - 2 h^2) / (2R) - a h N.dhat / (2 R rho_par), free of the
//     1/s-sized cancellation between C J0 and alpha Jc.
// The chord is a straight edge of eq. 9: beta_c (a x b).N / |a x b| (area_diffuse_contour.h).
// Derivation and measurements: docs/area-lights.md "Disk lights".
//
// Departures from the paper: the paper has no disk lights; horizon clipping as for polygons.
// Scalar type: R = AreaReal<T> (double for the float instantiation: computed in double, rounded
// once by the caller).
// Stiff cases: tests/kernels/area/disk_test.cpp (rim at height 1e-4, P in the plane, grazing,
// far 1e6, near 1e-6, radius 1e-6 and 1e6, crossing the horizon).
#pragma once

#include <algorithm>
#include <cmath>

#include "area_polygon.h"

namespace vlit {

// Below this q = rho / (a + s) the arc's cos-integral is summed as a Fourier series (q^28 < 1e-16).
inline constexpr double kDiskSeriesRatio = 0.25;

namespace disk_detail {

// ∫_{mid - w}^{mid + w} cos psi / (a + rho cos psi) dpsi = (1/s) [S_1 + Σ_{n>=1} (-q)^n (S_{n+1}/(n+1) + T_{n-1})],
// S_m = sin m psi2 - sin m psi1 = 2 cos(m mid) sin(m w), T_0 = 2w, T_m = S_m / m. For q < 1/4.
template <class R>
R cos_integral_series(R q, R s, R mid, R w) {
  // cos(m mid) and sin(m w) by the Chebyshev recurrence x_{m+1} = 2 cos(.) x_m - x_{m-1}.
  const R cm1 = std::cos(mid), sw1 = std::sin(w), cw1 = std::cos(w);
  R c_prev = R(1), c_cur = cm1;        // cos(0 mid), cos(1 mid)
  R s_prev = R(0), s_cur = sw1;        // sin(0 w), sin(1 w)
  auto advance = [&]() {
    const R c_next = R(2) * cm1 * c_cur - c_prev;
    const R s_next = R(2) * cw1 * s_cur - s_prev;
    c_prev = c_cur; c_cur = c_next;
    s_prev = s_cur; s_cur = s_next;
  };
  // S_m for m = 1, 2, ...: keep S_{n-1}/(n-1) (T_{n-1}) and S_{n+1}/(n+1).
  const R s1 = R(2) * c_cur * s_cur;  // S_1
  R sum = s1;
  R t_prev = R(2) * w;                // T_0
  R t_cur = s1;                       // T_1 = S_1 / 1
  R power = R(1);
  for (int n = 1; n < 64; ++n) {
    power *= -q;
    advance();                                      // now c_cur = cos((n+1) mid), s_cur = sin((n+1) w)
    const R t_next = R(2) * c_cur * s_cur / R(n + 1);  // T_{n+1}
    const R term = power * (t_next + t_prev);
    sum += term;
    t_prev = t_cur;
    t_cur = t_next;
    if (std::abs(power) < R(1e-17)) break;
  }
  return sum / s;
}

}  // namespace disk_detail

// The quantities of the header's formulas for one disk seen from P (with normal N).
template <class R>
struct DiskFrame {
  R h, h2, big_r, rho_par, cphi, sphi, nn, nu, nv, n_dhat, n_ndhat, inner, outer, s, a, x;
};

template <class R>
DiskFrame<R> disk_frame(const AreaView<R>& view, R radius, const Vec3<R>& N) {
  DiskFrame<R> f;
  f.h = view.height;
  f.h2 = f.h * f.h;
  f.big_r = radius;
  const R du = dot(view.D, view.u), dv = dot(view.D, view.v);
  f.rho_par = std::hypot(du, dv);
  f.cphi = f.rho_par > R(0) ? du / f.rho_par : R(1);
  f.sphi = f.rho_par > R(0) ? dv / f.rho_par : R(0);
  f.nn = dot(N, view.normal);
  f.nu = dot(N, view.u);
  f.nv = dot(N, view.v);
  f.n_dhat = f.nu * f.cphi + f.nv * f.sphi;   // N . dhat
  f.n_ndhat = f.nv * f.cphi - f.nu * f.sphi;  // N . (n x dhat)
  f.inner = f.h2 + (f.rho_par - f.big_r) * (f.rho_par - f.big_r);  // |P - nearest rim point|^2
  f.outer = f.h2 + (f.rho_par + f.big_r) * (f.rho_par + f.big_r);  // |P - farthest rim point|^2
  f.s = std::sqrt(f.inner) * std::sqrt(f.outer);
  f.a = f.h2 + f.rho_par * f.rho_par + f.big_r * f.big_r;
  f.x = f.h2 + (f.big_r - f.rho_par) * (f.big_r + f.rho_par);
  return f;
}

// The arc part of the contour integral, R ∫ N.(r x r') / |r|^2 dtheta, over the rim arc from
// theta1 counter-clockwise (about view.normal) to theta2 = theta1 + 2 omega, omega in (0, pi]
// (the arc's half-width, passed as well so that the caller's rounding of theta2 is not redone).
// The diffuse of a region bounded by rim arcs and straight edges a -> b is
// -1/2 (Σ arcs + Σ edges), each edge atan2(|a x b|, a.b) / |a x b| N.(a x b) (a, b from P).
template <class R>
R disk_arc_contour(const AreaView<R>& view, const DiskFrame<R>& f, R theta1, R theta2, R omega) {
  const R pi = R(M_PI);
  const R h = f.h, h2 = f.h2, big_r = f.big_r, rho_par = f.rho_par, cphi = f.cphi, sphi = f.sphi;
  const R nn = f.nn, n_dhat = f.n_dhat, n_ndhat = f.n_ndhat, inner = f.inner, outer = f.outer, s = f.s, a = f.a, x = f.x;
  R psi1 = std::remainder(theta1 - std::atan2(sphi, cphi), R(2) * pi);  // in [-pi, pi]
  const R psi2 = psi1 + R(2) * omega;
  const R mid = psi1 + omega;

  const Vec3<R> e1 = view.u * std::cos(theta1) + view.v * std::sin(theta1);
  const Vec3<R> e2 = view.u * std::cos(theta2) + view.v * std::sin(theta2);
  const R r1sq = length_squared(view.D + e1 * big_r), r2sq = length_squared(view.D + e2 * big_r);
  const R rho = R(2) * big_r * rho_par;
  const R q = rho / (a + s);

  // J0 = ∫ dpsi / (a + rho cos psi) over [psi1, psi2]
  const R k = std::sqrt(inner / outer);
  const R g = std::atan2(k * std::sin(omega), std::cos(psi2 / 2) * std::cos(psi1 / 2) +
                                                   k * k * std::sin(psi2 / 2) * std::sin(psi1 / 2));
  const R j0 = R(2) * g / s;
  // Js = ∫ sin psi / (a + rho cos psi) = -ln(r2sq / r1sq) / rho
  R js;
  const R dcos = R(-2) * std::sin(mid) * std::sin(omega);  // cos psi2 - cos psi1
  if (q < R(kDiskSeriesRatio)) {
    const R t = rho * dcos / r1sq;
    js = -(dcos / r1sq) * (t == R(0) ? R(1) : std::log1p(t) / t);
  } else {
    js = -std::log(r2sq / r1sq) / rho;
  }
  const R c_coef = big_r * nn;
  const R alpha = rho_par * nn + h * n_dhat;
  const R beta = h * n_ndhat;
  R arc;
  if (q < R(kDiskSeriesRatio)) {
    arc = c_coef * j0 + alpha * disk_detail::cos_integral_series(q, s, mid, omega) + beta * js;
  } else {
    const R kk = nn * (x - R(2) * h2) / (R(2) * big_r) - a * h * n_dhat / (R(2) * big_r * rho_par);
    arc = kk * j0 + alpha * (R(2) * omega) / rho + beta * js;
  }
  return big_r * arc;
}

// Diffuse response of a disk of radius `radius` seen through `view` (area_polygon.h: D = c - P,
// view.normal toward P, view.u x view.v = view.normal, height h > 0) at P with unit normal N.
template <class R>
R disk_diffuse_contour(const AreaView<R>& view, R radius, const Vec3<R>& N) {
  if (!view.lit) return R(0);
  const R pi = R(M_PI);
  const DiskFrame<R> f = disk_frame(view, radius, N);
  const R h = f.h, h2 = f.h2, big_r = f.big_r, rho_par = f.rho_par, nn = f.nn, nu = f.nu, nv = f.nv;
  const R n_dhat = f.n_dhat, s = f.s, a = f.a, x = f.x;
  const R x_plus_s = x >= R(0) ? x + s : R(4) * rho_par * rho_par * h2 / (s - x);

  // Horizon: N.(c + R e(theta) - P) = N.D + R mu cos(theta - thetaN) >= 0.
  const R nd = dot(N, view.D);
  const R mu = std::hypot(nu, nv);
  if (nd >= big_r * mu) {  // the whole disk is above the tangent plane: full circle
    const R id = pi * big_r * big_r / (s * (a + s)) * (R(2) * h * rho_par * n_dhat - nn * x_plus_s);
    return std::max(id, R(0));
  }
  if (nd <= -big_r * mu) return R(0);  // entirely below the horizon
  const R tau = -nd / (big_r * mu);    // in (-1, 1)
  const R omega = std::atan2(std::sqrt((R(1) - tau) * (R(1) + tau)), tau);  // half-width of the visible arc
  const R theta_n = std::atan2(nv, nu);
  const R theta1 = theta_n - omega, theta2 = theta_n + omega;
  const R arc = disk_arc_contour(view, f, theta1, theta2, omega);
  // Chord from r(theta2) back to r(theta1): a straight edge of eq. 9.
  const Vec3<R> e1 = view.u * std::cos(theta1) + view.v * std::sin(theta1);
  const Vec3<R> e2 = view.u * std::cos(theta2) + view.v * std::sin(theta2);
  const Vec3<R> ra = view.D + e2 * big_r, rb = view.D + e1 * big_r;
  const Vec3<R> cr = cross(view.D, (e1 - e2) * big_r) + cross(e2, e1) * (big_r * big_r);
  const R len = length(cr);
  R chord = R(0);
  if (len > R(0)) chord = std::atan2(len, dot(ra, rb)) / len * dot(N, cr);
  const R id = R(-0.5) * (arc + chord);
  return std::max(id, R(0));
}

}  // namespace vlit
