// Disk light, diffuse, batch over structure-of-arrays points: the full-circle closed form of
// disk_diffuse_contour.h, in double lanes.
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
// Flagged for the scalar double kernel (BatchOutput::stiff): lanes whose tangent plane cuts the
// disk (the arc + chord form, with logarithms and a series, stays scalar).
// Precision: the closed form is a handful of operations with one square root and one division,
// so the lanes compute in double, with the scalar kernel's expressions and cancellation-free
// rearrangements, and round once to float: the result is the scalar double kernel's to the float
// rounding (tests/kernels/batch/batch_kernels_test.cpp "disk batch"). Per-light constants
// (batch_kernel_for): centre, unit normal and the in-plane frame u, v of the prepared disk.
#pragma once

#include <cmath>

#include "batch/batch_points.h"

namespace vlit {

struct DiskBatchLight {
  double center[3];
  double normal[3];  // unit emitting normal
  double u[3], v[3];  // unit frame of the disk's plane, u x v = normal
  double radius;
  bool two_sided;
};

namespace batch_detail {

inline void disk_diffuse_lanes(const DiskBatchLight& L, const BatchPoints& pts, long begin, long end, const BatchOutput& out) {
  const double* __restrict pxs = pts.px;
  const double* __restrict pys = pts.py;
  const double* __restrict pzs = pts.pz;
  const float* __restrict nxs = pts.nx;
  const float* __restrict nys = pts.ny;
  const float* __restrict nzs = pts.nz;
  float* __restrict diffuse = out.diffuse;
  std::uint8_t* __restrict stiff_out = out.stiff;
  const double cx = L.center[0], cy = L.center[1], cz = L.center[2];
  const double lnx = L.normal[0], lny = L.normal[1], lnz = L.normal[2];
  const double ux = L.u[0], uy = L.u[1], uz = L.u[2], vx = L.v[0], vy = L.v[1], vz = L.v[2];
  const double big_r = L.radius, r2 = big_r * big_r;
  const double back = L.two_sided ? -1. : 0.;
  constexpr double kPi = 3.14159265358979323846;
#pragma omp simd
  for (long k = begin; k < end; ++k) {
    const double Dx = cx - pxs[k], Dy = cy - pys[k], Dz = cz - pzs[k];
    const double nx = nxs[k], ny = nys[k], nz = nzs[k];
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
    diffuse[k] = float(value);
    const double cut = (orient != 0. ? 1. : 0.) * (1. - above) * (1. - below);
    stiff_out[k] = cut > 0. ? 1 : 0;
  }
}

}  // namespace batch_detail

// Diffuse of one disk light at lanes [begin, end); lanes whose horizon cuts the disk are flagged.
inline void disk_diffuse_batch(const DiskBatchLight& light, const BatchPoints& pts, long begin, long end,
                               const BatchOutput& out) {
  batch_detail::disk_diffuse_lanes(light, pts, begin, end, out);
  if (out.in_double)  // every lane not flagged was computed in double
    for (long v = begin; v < end; ++v) out.in_double[v] = out.stiff[v] ? 0 : 1;
}

}  // namespace vlit
