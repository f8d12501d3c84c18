// Disk light, diffuse, batch over structure-of-arrays points: disk_diffuse_contour.h's closed
// forms (full circle; arc + chord where P's horizon cuts the disk) in double lanes.
//
// What it computes (unit intensity, kd = 1; conventions.h): Id = ∫_A max(0, cos theta) cos theta_l
// / r^2 dA over the disk (Picott 1992 eq. 9 over the circle; docs/area-lights.md "Disk lights"),
// the same quantity as disk_diffuse_contour.h. When the whole disk is above P's tangent plane
// (N.D >= R mu, mu = |N projected on the disk's plane|) that is the full-circle closed form
//   Id = pi R^2 / (s (a + s)) [2 h rho_par N.dhat - N.n (X + s)],
//   a = h^2 + rho_par^2 + R^2,  s = sqrt(h^2 + (rho_par - R)^2) sqrt(h^2 + (rho_par + R)^2),
//   X = h^2 + (R - rho_par)(R + rho_par),  X + s = 4 rho_par^2 h^2 / (s - X) when X < 0,
// with h = |n.(P - c)|, D = c - P, rho_par = |D in the disk's plane|, dhat = that part / rho_par,
// n the emitting normal toward P (flipped for the back of a two-sided disk). A disk entirely
// below the tangent plane (N.D <= -R mu) gives 0, as does P behind a one-sided disk or in its
// plane.
//
// Lanes whose tangent plane cuts the disk get the arc + chord form of disk_diffuse_contour.h in a
// second pass over those lanes alone (gathered, kDiskArcBlock at a time), also in double lanes:
// the same integrals J0, Js, Jc and the same two assemblies (Fourier series for q < 1/4, the
// K-form near the rim), with every angle's cosine and sine formed algebraically instead of by
// trigonometric calls: theta_n from N's components (cos = N.u/mu), omega from tau (cos = tau,
// sin = sqrt((1 - tau)(1 + tau))), theta1,2 = theta_n -+ omega and psi = theta - phi0 by the
// angle-difference formulas, psi1/2 by the half-angle formulas in their cancellation-free forms;
// atan2 from atan2_upper.h, ln and ln(1 + x) from double_log.h, and the series summed to a fixed
// 40 terms (q < 1/4: the remainder is below 1e-24 of the sum). No lane is flagged.
// Precision: the lanes compute in double, with the scalar kernel's expressions and
// cancellation-free rearrangements, and round once to float: the result is the scalar double
// kernel's to the float rounding (tests/kernels/batch/batch_kernels_test.cpp "disk batch"; the
// first pass marks the cut lanes in BatchOutput::stiff, which the second pass clears). Per-light constants
// (batch_kernel_for): centre, unit normal and the in-plane frame u, v of the prepared disk.
#pragma once

#include <cmath>

#include "batch/atan2_upper.h"
#include "batch/batch_points.h"
#include "batch/double_log.h"

namespace vlit {

struct DiskBatchLight {
  double center[3];
  double normal[3];  // unit emitting normal
  double u[3], v[3];  // unit frame of the disk's plane, u x v = normal
  double radius;
  bool two_sided;
};

namespace batch_detail {

inline constexpr int kDiskArcBlock = 128;
inline constexpr int kDiskSeriesTerms = 40;

// ∫_{mid - w}^{mid + w} cos psi / (a + rho cos psi) dpsi times s, for q = rho / (a + s) < 1/4: the
// series of disk_detail::cos_integral_series (disk_diffuse_contour.h) to a fixed number of terms,
// from cos(mid), sin(w), cos(w) and w.
inline double disk_cos_series(double q, double cos_mid, double sin_w, double cos_w, double w) {
  double c_prev = 1., c_cur = cos_mid;  // cos(m mid) for m = 0, 1
  double s_prev = 0., s_cur = sin_w;    // sin(m w) for m = 0, 1
  const double s1 = 2. * c_cur * s_cur;
  double sum = s1, t_prev = 2. * w, t_cur = s1, power = 1.;
  for (int n = 1; n < kDiskSeriesTerms; ++n) {
    power *= -q;
    const double c_next = 2. * cos_mid * c_cur - c_prev;
    const double s_next = 2. * cos_w * s_cur - s_prev;
    c_prev = c_cur; c_cur = c_next;
    s_prev = s_cur; s_cur = s_next;
    const double t_next = 2. * c_cur * s_cur / double(n + 1);
    sum += power * (t_next + t_prev);
    t_prev = t_cur;
    t_cur = t_next;
  }
  return sum;
}

// One lane whose tangent plane cuts the disk: disk_diffuse_contour's arc + chord branch.
// D = c - P, N the unit normal, orient +1 (front) or -1 (back of a two-sided disk).
inline double disk_arc_lane(const DiskBatchLight& L, double Dx, double Dy, double Dz, double nx, double ny, double nz,
                            double orient) {
  const double big_r = L.radius;
  const double lnx = orient * L.normal[0], lny = orient * L.normal[1], lnz = orient * L.normal[2];  // toward P
  const double ux = L.u[0], uy = L.u[1], uz = L.u[2];
  const double vx = orient * L.v[0], vy = orient * L.v[1], vz = orient * L.v[2];  // view frame: u x v = normal
  const double h = -(lnx * Dx + lny * Dy + lnz * Dz), h2 = h * h;
  const double du = Dx * ux + Dy * uy + Dz * uz, dv = Dx * vx + Dy * vy + Dz * vz;
  const double rho_par = std::sqrt(du * du + dv * dv);
  const bool on_axis = !(rho_par > 0.);
  const double rho_safe = on_axis ? 1. : rho_par;
  const double cphi = on_axis ? 1. : du / rho_safe, sphi = on_axis ? 0. : dv / rho_safe;
  const double nn = nx * lnx + ny * lny + nz * lnz;
  const double nu = nx * ux + ny * uy + nz * uz, nv = nx * vx + ny * vy + nz * vz;
  const double n_dhat = nu * cphi + nv * sphi, n_ndhat = nv * cphi - nu * sphi;
  const double inner = h2 + (rho_par - big_r) * (rho_par - big_r);
  const double outer = h2 + (rho_par + big_r) * (rho_par + big_r);
  const double s = std::sqrt(inner) * std::sqrt(outer);
  const double a = h2 + rho_par * rho_par + big_r * big_r;
  const double x = h2 + (big_r - rho_par) * (big_r + rho_par);
  const double nd = nx * Dx + ny * Dy + nz * Dz;
  const double mu = std::sqrt(nu * nu + nv * nv);  // > 0: the horizon cuts the disk
  const double mu_safe = mu > 0. ? mu : 1.;
  // omega: half-width of the visible arc; theta_n: direction of N in the disk's plane.
  const double tau = -nd / (big_r * mu_safe);
  const double cos_w = tau, sin_w = std::sqrt((1. - tau) * (1. + tau));
  const double omega = atan2_upper(sin_w, tau);
  const double cos_n = nu / mu_safe, sin_n = nv / mu_safe;
  const double c1 = cos_n * cos_w + sin_n * sin_w, s1 = sin_n * cos_w - cos_n * sin_w;  // theta1 = theta_n - omega
  const double c2 = cos_n * cos_w - sin_n * sin_w, s2 = sin_n * cos_w + cos_n * sin_w;  // theta2 = theta_n + omega
  // psi1 = theta1 - phi0 in [-pi, pi]; its half angle in [-pi/2, pi/2] without cancellation.
  const double cp1 = c1 * cphi + s1 * sphi, sp1 = s1 * cphi - c1 * sphi;
  const double half_cos_a = std::sqrt((1. + cp1) * 0.5);  // used where cp1 >= 0
  const double half_sin_b = std::sqrt((1. - cp1) * 0.5);  // used where cp1 < 0
  const double ch1 = cp1 >= 0. ? half_cos_a : (sp1 < 0. ? -sp1 : sp1) / (2. * (half_sin_b > 0. ? half_sin_b : 1.));
  const double sh1 = cp1 >= 0. ? sp1 / (2. * (half_cos_a > 0. ? half_cos_a : 1.)) : (sp1 < 0. ? -half_sin_b : half_sin_b);
  const double ch2 = ch1 * cos_w - sh1 * sin_w, sh2 = sh1 * cos_w + ch1 * sin_w;  // psi2 / 2 = psi1 / 2 + omega
  const double cos_mid = cos_n * cphi + sin_n * sphi, sin_mid = sin_n * cphi - cos_n * sphi;  // mid = theta_n - phi0
  // Rim points r(theta1), r(theta2) relative to P.
  const double e1x = ux * c1 + vx * s1, e1y = uy * c1 + vy * s1, e1z = uz * c1 + vz * s1;
  const double e2x = ux * c2 + vx * s2, e2y = uy * c2 + vy * s2, e2z = uz * c2 + vz * s2;
  const double r1x = Dx + e1x * big_r, r1y = Dy + e1y * big_r, r1z = Dz + e1z * big_r;
  const double r2x = Dx + e2x * big_r, r2y = Dy + e2y * big_r, r2z = Dz + e2z * big_r;
  const double r1sq = r1x * r1x + r1y * r1y + r1z * r1z, r2sq = r2x * r2x + r2y * r2y + r2z * r2z;
  const double rho = 2. * big_r * rho_par;
  const double q = rho / (a + s);
  const bool series = q < 0.25;
  // J0 = ∫ dpsi / (a + rho cos psi) = (2/s) arg(w2 conj(w1)), w = cos(psi/2) + i k sin(psi/2).
  const double k = std::sqrt(inner / outer);
  const double g = atan2_upper(k * sin_w, ch2 * ch1 + k * k * sh2 * sh1);
  const double j0 = 2. * g / s;
  // Js = ∫ sin psi / (...) = -ln(|r2|^2 / |r1|^2) / rho.
  const double dcos = -2. * sin_mid * sin_w;  // cos psi2 - cos psi1
  const double r1sq_safe = r1sq > 0. ? r1sq : 1.;
  const double t = rho * dcos / r1sq_safe;
  const double log1p_over_t = t == 0. ? 1. : log1p_double(t > -1. ? t : 0.) / (t == 0. ? 1. : t);
  const double rho_div = rho > 0. ? rho : 1.;
  const double ratio = r2sq / r1sq_safe;
  const double js = series ? -(dcos / r1sq_safe) * log1p_over_t : -log_positive(ratio > 0. ? ratio : 1.) / rho_div;
  const double c_coef = big_r * nn;
  const double alpha = rho_par * nn + h * n_dhat;
  const double beta = h * n_ndhat;
  const double jc_series = disk_cos_series(series ? q : 0., cos_mid, sin_w, cos_w, omega) / s;
  const double kk = nn * (x - 2. * h2) / (2. * big_r) - a * h * n_dhat / (2. * big_r * rho_safe);
  const double arc = series ? c_coef * j0 + alpha * jc_series + beta * js : kk * j0 + alpha * (2. * omega) / rho_div + beta * js;
  // Chord from r(theta2) back to r(theta1): a straight edge of eq. 9.
  const double fx = (e1x - e2x) * big_r, fy = (e1y - e2y) * big_r, fz = (e1z - e2z) * big_r;
  const double r2 = big_r * big_r;
  const double crx = (Dy * fz - Dz * fy) + (e2y * e1z - e2z * e1y) * r2;
  const double cry = (Dz * fx - Dx * fz) + (e2z * e1x - e2x * e1z) * r2;
  const double crz = (Dx * fy - Dy * fx) + (e2x * e1y - e2y * e1x) * r2;
  const double len = std::sqrt(crx * crx + cry * cry + crz * crz);
  const double len_safe = len > 0. ? len : 1.;
  const double chord_dot = r2x * r1x + r2y * r1y + r2z * r1z;
  const double chord = len > 0. ? atan2_upper(len, chord_dot) / len_safe * (nx * crx + ny * cry + nz * crz) : 0.;
  const double id = -0.5 * (big_r * arc + chord);
  return id > 0. ? id : 0.;
}

inline void disk_diffuse_lanes(const DiskBatchLight& L, const BatchPoints& pts, long begin, long end, const BatchOutput& out) {
  const double cx = L.center[0], cy = L.center[1], cz = L.center[2];
  const double lnx = L.normal[0], lny = L.normal[1], lnz = L.normal[2];
  const double ux = L.u[0], uy = L.u[1], uz = L.u[2], vx = L.v[0], vy = L.v[1], vz = L.v[2];
  const double big_r = L.radius, r2 = big_r * big_r;
  const double back = L.two_sided ? -1. : 0.;
  constexpr double kPi = 3.14159265358979323846;
  for_each_lane(pts, begin, end, out, [=](double px, double py, double pz, float nxf, float nyf, float nzf, float& diffuse,
                                          std::uint8_t& stiff_out) {
    const double Dx = cx - px, Dy = cy - py, Dz = cz - pz;
    const double nx = nxf, ny = nyf, nz = nzf;
    const double side = -(lnx * Dx + lny * Dy + lnz * Dz);  // n_l.(P - c)
    const double orient = side > 0. ? 1. : (side < 0. ? back : 0.);
    const double h = side < 0. ? -side : side, h2 = h * h;
    const double du = Dx * ux + Dy * uy + Dz * uz, dv = Dx * vx + Dy * vy + Dz * vz;
    const double rho_par = std::sqrt(du * du + dv * dv);
    const double nn = orient * (nx * lnx + ny * lny + nz * lnz);  // N.n, n toward P
    const double nu = nx * ux + ny * uy + nz * uz, nv = nx * vx + ny * vy + nz * vz;
    const double n_dhat = rho_par > 0. ? (nu * du + nv * dv) / (rho_par > 0. ? rho_par : 1.) : 0.;
    const double inner = h2 + (rho_par - big_r) * (rho_par - big_r);  // |P - nearest rim point|^2
    const double outer = h2 + (rho_par + big_r) * (rho_par + big_r);  // |P - farthest rim point|^2
    const double s = std::sqrt(inner) * std::sqrt(outer);
    const double a = h2 + rho_par * rho_par + r2;
    const double x = h2 + (big_r - rho_par) * (big_r + rho_par);
    const double s_minus_x = s - x > 0. ? s - x : 1.;
    const double x_plus_s = x >= 0. ? x + s : 4. * rho_par * rho_par * h2 / s_minus_x;
    const double nd = nx * Dx + ny * Dy + nz * Dz;  // N.D
    const double mu = std::sqrt(nu * nu + nv * nv);
    const double full = kPi * r2 / (s * (a + s) > 0. ? s * (a + s) : 1.) * (2. * h * rho_par * n_dhat - nn * x_plus_s);
    // Conditions as 0/1 doubles and nested selects: GCC 12 does not vectorise & between these masks.
    const double above = nd >= big_r * mu ? 1. : 0., below = nd <= -big_r * mu ? 1. : 0.;
    double value = full > 0. ? full : 0.;
    value = above > 0. ? value : 0.;
    value = orient != 0. ? value : 0.;
    diffuse = float(value);
    const double cut = (orient != 0. ? 1. : 0.) * (1. - above) * (1. - below);
    stiff_out = cut > 0. ? 1 : 0;
  });
}

}  // namespace batch_detail

namespace batch_detail {

// The lanes v = lanes[0..m) (m <= kDiskArcBlock) whose horizon cuts the disk: arc + chord.
inline void disk_arc_lanes(const DiskBatchLight& L, const BatchPoints& pts, const long* lanes, int m, const BatchOutput& out) {
  double Dx[kDiskArcBlock], Dy[kDiskArcBlock], Dz[kDiskArcBlock], nx[kDiskArcBlock], ny[kDiskArcBlock], nz[kDiskArcBlock];
  double orient[kDiskArcBlock], result[kDiskArcBlock];
  for (int j = 0; j < m; ++j) {
    const long v = lanes[j];
    Dx[j] = L.center[0] - pts.px[v];
    Dy[j] = L.center[1] - pts.py[v];
    Dz[j] = L.center[2] - pts.pz[v];
    nx[j] = pts.nx[v]; ny[j] = pts.ny[v]; nz[j] = pts.nz[v];
    const double side = -(L.normal[0] * Dx[j] + L.normal[1] * Dy[j] + L.normal[2] * Dz[j]);
    orient[j] = side > 0. ? 1. : -1.;  // cut lanes are lit: in front, or behind a two-sided disk
  }
  const int padded = (m + 7) / 8 * 8;  // whole 8-lane vectors (copies of the last lane)
  for (int j = m; j < padded; ++j) {
    Dx[j] = Dx[m - 1]; Dy[j] = Dy[m - 1]; Dz[j] = Dz[m - 1];
    nx[j] = nx[m - 1]; ny[j] = ny[m - 1]; nz[j] = nz[m - 1];
    orient[j] = orient[m - 1];
  }
  const DiskBatchLight light = L;  // a local copy: provably not aliased by the arrays
#pragma omp simd
  for (int j = 0; j < padded; ++j) result[j] = disk_arc_lane(light, Dx[j], Dy[j], Dz[j], nx[j], ny[j], nz[j], orient[j]);
  for (int j = 0; j < m; ++j) {
    out.diffuse[lanes[j]] = float(result[j]);
    out.stiff[lanes[j]] = 0;
  }
}

}  // namespace batch_detail

// Diffuse of one disk light at lanes [begin, end), every lane in double.
inline void disk_diffuse_batch(const DiskBatchLight& light, const BatchPoints& pts, long begin, long end,
                               const BatchOutput& out) {
  batch_detail::disk_diffuse_lanes(light, pts, begin, end, out);  // full circle; cut lanes marked in out.stiff
  long lanes[batch_detail::kDiskArcBlock];
  int m = 0;
  for (long v = begin; v < end; ++v) {
    if (!out.stiff[v]) continue;
    lanes[m++] = v;
    if (m == batch_detail::kDiskArcBlock) {
      batch_detail::disk_arc_lanes(light, pts, lanes, m, out);
      m = 0;
    }
  }
  if (m > 0) batch_detail::disk_arc_lanes(light, pts, lanes, m, out);
  if (out.in_double)  // every lane is computed in double
    for (long v = begin; v < end; ++v) out.in_double[v] = 1;
}

}  // namespace vlit
