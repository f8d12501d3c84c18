// Disk light, exact specular: the Phong lobe integrated over the visible part of the disk, as a
// contour integral over its boundary (rim arcs and chords), error-controlled on the disk itself.
//
// Computes (unit intensity, ks = 1; conventions.h):
//   Is(exact) = ∫_Omega [N.w > 0] max(0, Rv.w)^m dw over the directions toward the disk.
// Method: as area_specular_exact.h (polar coordinates about Rv, radial integral closed):
//   Is = -1/(m + 1) ∮ (1 - c^{m+1}) dphi,  dphi = Rv.(x x dx) / |Rv x x|^2,  c = Rv.x / |x|,
// (or +1/(m + 1) ∮ c^{m+1} dphi when Rv misses the visible part: the winding number is 0),
// over the boundary of disk ∩ {N.(x - P) >= 0} ∩ {Rv.(x - P) >= 0} (also for m = 0: its limit m -> 0+),
// traversed counter-clockwise about the disk's normal n (toward P). In the disk's plane
// (coordinates p relative to the centre, axes u, v with u x v = n) each half-space is
// alpha.p + beta >= 0; the boundary is made of
//   - rim arcs x(theta) = D + R e(theta), dx = R e'(theta) dtheta (D = c - P), the sub-arcs between
//     the rim crossings of the two lines whose midpoint satisfies both constraints;
//   - chords of each line between its rim crossings, traversed with the region on the left and
//     clipped to the other half-space.
// Each piece is integrated by the same globally adaptive Gauss-Kronrod 7/15 as the polygon edges
// (adaptive_kronrod.h), with initial cuts graded around the rim point nearest P (width ~ its
// distance) and the rim point nearest the lobe's axis (width ~ lobe width), until
// Σ error <= tol |Σ value|.
// Sources: docs/conventions.md "Radiometric definitions" (the definition); Picott 1992 eq. 9's contour idea.
// Scalar type: R = AreaReal<T> (double for T = float).
// Stiff cases and measurements: tests/kernels/area/disk_test.cpp, docs/area-lights.md.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>

#include "adaptive_kronrod.h"
#include "area_specular_exact.h"

namespace vlit {

inline constexpr int kDiskExactMaxPieces = 1024;
inline constexpr int kDiskExactMaxCuts = 64;  // initial cut points per arc or chord, its ends included

namespace disk_exact_detail {

// The visible part of the disk in its plane: the half-spaces alpha.p + beta >= 0 (the horizon
// and the lobe, also for m = 0) and where their lines cross the rim.
template <class R>
struct DiskClip {
  struct Line { R ax, ay, beta; };
  std::array<Line, 2> lines{};
  int nl = 0;
  std::array<R, 4> breaks{};  // rim angles of the crossings, theta_k -+ omega_k
  int nb = 0;
  std::array<bool, 2> has_chord{};
  std::array<R, 2> chord_lo{}, chord_hi{};
  bool empty = false;  // the whole disk is outside one half-space

  bool inside(R px, R py) const {
    for (int k = 0; k < nl; ++k)
      if (lines[k].ax * px + lines[k].ay * py + lines[k].beta < R(0)) return false;
    return true;
  }
};

template <class R>
DiskClip<R> clip_disk(const AreaView<R>& view, R radius, const Vec3<R>& n, const Vec3<R>& rv, R m) {
  DiskClip<R> clip;
  auto add_line = [&](const Vec3<R>& k) { clip.lines[clip.nl++] = {dot(k, view.u), dot(k, view.v), dot(k, view.D)}; };
  add_line(n);
  add_line(rv);  // the lobe's half-space, also for m = 0 (its limit m -> 0+ is [Rv.w > 0])
  for (int k = 0; k < clip.nl; ++k) {
    const auto& line = clip.lines[k];
    const R mu = std::hypot(line.ax, line.ay);
    if (!(mu > R(0)) || std::abs(line.beta) >= radius * mu) {
      if (line.beta < R(0)) {  // the whole disk is outside this half-space
        clip.empty = true;
        return clip;
      }
      continue;
    }
    const R tau = -line.beta / (radius * mu);
    const R omega = std::atan2(std::sqrt((R(1) - tau) * (R(1) + tau)), tau);
    const R theta = std::atan2(line.ay, line.ax);
    clip.has_chord[k] = true;
    clip.chord_lo[k] = theta - omega;
    clip.chord_hi[k] = theta + omega;
    clip.breaks[clip.nb++] = theta - omega;
    clip.breaks[clip.nb++] = theta + omega;
  }
  return clip;
}

// Whether Rv meets the disk, or passes within a lobe width of its rim as seen from P: then the full
// form; otherwise the tail form (see area_specular_exact.h).
template <class R>
bool rv_near_disk(const AreaView<R>& view, R radius, const Vec3<R>& n, const Vec3<R>& rv, R lobe_width) {
  const R toward = -dot(view.normal, rv);
  if (!(toward > R(0))) return false;
  const Vec3<R> hit = rv * (view.height / toward) - view.D;  // relative to the centre
  if (length_squared(hit) <= radius * radius && dot(n, rv) >= R(0)) return true;
  const R lh = length(hit);
  if (!(lh > R(0))) return false;
  const Vec3<R> rim = view.D + hit * (radius / lh);  // rim point nearest the hit, from P
  return std::atan2(length(cross(rv, rim)), dot(rv, rim)) <= lobe_width;
}

// One curve of the boundary and the integrand Rv.(x x dx/dt) lobe_per_azimuth(x) along it:
// kind 0 = rim arc, t = theta; kind 1 = straight segment x = a + t e (a relative to P).
template <class R>
struct DiskCurve {
  int kind;
  Vec3<R> a, e;
};

template <class R>
R disk_curve_integrand(const AreaView<R>& view, R radius, const Vec3<R>& rv, R m, bool tail, const DiskCurve<R>& cv, R t) {
  if (cv.kind == 1) return dot(rv, cross(cv.a, cv.e)) * area_exact_detail::lobe_per_azimuth(cv.a + cv.e * t, rv, m, tail);
  const Vec3<R> e = view.u * std::cos(t) + view.v * std::sin(t), de = view.v * std::cos(t) - view.u * std::sin(t);
  const Vec3<R> x = view.D + e * radius;
  return dot(rv, cross(x, de * radius)) * area_exact_detail::lobe_per_azimuth(x, rv, m, tail);
}

// The open disk's boundary: at most 4 rim arcs and 2 chords.
template <class R>
struct DiskContour {
  const AreaView<R>& view;
  R radius;
  Vec3<R> rv;
  R m;
  bool tail;
  std::array<DiskCurve<R>, 8> curves{};
  int count = 0;

  R operator()(int c, R t) const { return disk_curve_integrand(view, radius, rv, m, tail, curves[c], t); }
};

// Where the integrand along the rim peaks: the rim angle nearest the foot of P (width ~ its
// distance, in radians of rim angle) and, for m > 0, the rim angle nearest the lobe's axis (its
// hit point on the plane; width ~ the lobe's).
template <class R>
struct RimCuts {
  R foot_theta{0}, foot_width{0}, lobe_theta{0}, lobe_width{0};
};

template <class R>
RimCuts<R> rim_cuts(const AreaView<R>& view, R radius, const Vec3<R>& rv, R m, R lobe_width) {
  RimCuts<R> cuts;
  const R du = dot(view.D, view.u), dv = dot(view.D, view.v);
  cuts.foot_theta = std::atan2(-dv, -du);
  cuts.foot_width = std::hypot(view.height, std::hypot(du, dv) - radius) / radius;
  cuts.lobe_theta = cuts.foot_theta;
  const R toward = -dot(view.normal, rv);
  if (m > R(0) && toward > R(0)) {
    const Vec3<R> hit = rv * (view.height / toward) - view.D;  // relative to the centre
    cuts.lobe_theta = std::atan2(dot(hit, view.v), dot(hit, view.u));
    cuts.lobe_width = lobe_width *
                      length(view.D + (view.u * std::cos(cuts.lobe_theta) + view.v * std::sin(cuts.lobe_theta)) * radius) /
                      radius;
  }
  return cuts;
}

// Adds the rim arc [t0, t1] (curve c of f) to the integrator, cut around the peaks of `cuts`.
template <class R, class F, class Quad>
void add_rim_arc(const F& f, int c, R t0, R t1, const RimCuts<R>& cuts, R m, Quad& quad) {
  const R pi = R(M_PI);
  // centres shifted by 2 pi into [t0, t1] where needed
  auto shift = [&](R t) { while (t < t0) t += R(2) * pi; while (t > t0 + R(2) * pi) t -= R(2) * pi; return t; };
  const R centers[4] = {shift(cuts.foot_theta), shift(cuts.foot_theta) - R(2) * pi, shift(cuts.lobe_theta),
                        shift(cuts.lobe_theta) - R(2) * pi};
  const R widths[4] = {cuts.foot_width, cuts.foot_width, cuts.lobe_width, cuts.lobe_width};
  quad.template add_graded<kDiskExactMaxCuts>(f, c, t0, t1, centers, widths, m > R(0) ? 4 : 2, R(1));
}

// Adds the straight segment x = a + t e, t in [s0, s1] (curve c of f; a relative to P), cut around
// the point nearest P and the point nearest in angle to Rv.
template <class R, class F, class Quad>
void add_straight(const F& f, int c, const Vec3<R>& a, const Vec3<R>& e, R s0, R s1, const Vec3<R>& rv, R m,
                  R lobe_width, Quad& quad) {
  const R e2 = length_squared(e), len = std::sqrt(e2);
  const R tp = std::clamp(-dot(a, e) / e2, s0, s1);
  R centers[2] = {tp, tp}, widths[2] = {length(a + e * tp) / len, R(0)};
  if (m > R(0)) {
    const Vec3<R> cr = cross(a, e);
    const R lc = length(cr);
    if (lc > R(0)) {
      const Vec3<R> pole = cr / lc;
      const Vec3<R> wdir = rv - pole * dot(rv, pole);
      const R den = dot(cross(e, wdir), pole);
      if (den != R(0)) {
        centers[1] = std::clamp(-dot(cross(a, wdir), pole) / den, s0, s1);
        const Vec3<R> xr = a + e * centers[1];
        const R angle = std::atan2(length(cross(rv, xr)), dot(rv, xr));
        widths[1] = std::max(std::min(lobe_width, angle), R(1e-300)) * length(xr) / len;
      }
    }
  }
  quad.template add_graded<kDiskExactMaxCuts>(f, c, s0, s1, centers, widths, 2, R(1));
}

// The rim arcs between consecutive crossings (cyclically; the whole rim if there are none) whose
// midpoint is visible.
template <class R, class Quad>
void add_rim_arcs(DiskContour<R>& contour, DiskClip<R>& clip, R lobe_width, Quad& quad) {
  const R radius = contour.radius, pi = R(M_PI);
  const RimCuts<R> cuts = rim_cuts(contour.view, radius, contour.rv, contour.m, lobe_width);
  // At most 4 crossings: insertion sort (std::sort's 16-element threshold made GCC 12 warn of
  // out-of-bounds access on this 4-element array, a false positive).
  auto& breaks = clip.breaks;
  const int nb = clip.nb;
  for (int i = 1; i < nb; ++i)
    for (int j = i; j > 0 && breaks[j] < breaks[j - 1]; --j) std::swap(breaks[j], breaks[j - 1]);
  for (int i = 0; i < std::max(nb, 1); ++i) {
    const R t0 = nb == 0 ? cuts.foot_theta - pi : breaks[i];
    const R t1 = nb == 0 ? cuts.foot_theta + pi : (i + 1 < nb ? breaks[i + 1] : breaks[0] + R(2) * pi);
    if (!(t1 > t0)) continue;
    const R mid = (t0 + t1) / 2;
    if (!clip.inside(radius * std::cos(mid), radius * std::sin(mid))) continue;
    const int c = contour.count++;
    contour.curves[c] = {0, {}, {}};
    add_rim_arc([&contour, c](R t) { return contour(c, t); }, c, t0, t1, cuts, contour.m, quad);
  }
}

// The chords: each line from its crossing at theta_k + omega_k back to theta_k - omega_k (region
// on the left), clipped to the other half-space.
template <class R, class Quad>
void add_chords(DiskContour<R>& contour, const DiskClip<R>& clip, R lobe_width, Quad& quad) {
  const AreaView<R>& view = contour.view;
  const R radius = contour.radius;
  for (int k = 0; k < clip.nl; ++k) {
    if (!clip.has_chord[k]) continue;
    const R ax = radius * std::cos(clip.chord_hi[k]), ay = radius * std::sin(clip.chord_hi[k]);
    const R bx = radius * std::cos(clip.chord_lo[k]), by = radius * std::sin(clip.chord_lo[k]);
    R s0 = 0, s1 = 1;
    for (int j = 0; j < clip.nl; ++j) {
      if (j == k) continue;
      const auto& line = clip.lines[j];
      const R fa = line.ax * ax + line.ay * ay + line.beta;
      const R fb = line.ax * bx + line.ay * by + line.beta;
      if (fa < R(0) && fb < R(0)) { s1 = s0; break; }
      if (fa < R(0)) s0 = std::max(s0, fa / (fa - fb));
      else if (fb < R(0)) s1 = std::min(s1, fa / (fa - fb));
    }
    if (!(s1 > s0)) continue;
    const Vec3<R> pa = view.u * ax + view.v * ay, pb = view.u * bx + view.v * by;
    const Vec3<R> a = view.D + pa, e = pb - pa;
    const int c = contour.count++;
    contour.curves[c] = {1, a, e};
    add_straight([&contour, c](R t) { return contour(c, t); }, c, a, e, s0, s1, contour.rv, contour.m, lobe_width, quad);
  }
}

}  // namespace disk_exact_detail

template <class R>
R disk_specular_exact(const AreaView<R>& view, R radius, const Vec3<R>& n, const Vec3<R>& rv_in, R m, R tolerance) {
  using namespace disk_exact_detail;
  if (!view.lit) return R(0);
  const Vec3<R> rv = normalize(rv_in);  // unit Rv, as in area_specular_exact.h
  DiskClip<R> clip = clip_disk(view, radius, n, rv, m);
  if (clip.empty) return R(0);
  const R lobe_width = R(1) / std::sqrt(m + R(1));
  // Rv outside the visible part: integrate only the tail c^{m+1} (area_specular_exact.h).
  DiskContour<R> contour{view, radius, rv, m, m > R(0) && !rv_near_disk(view, radius, n, rv, lobe_width)};
  AdaptiveKronrod<R, kDiskExactMaxPieces> quad;
  add_rim_arcs(contour, clip, lobe_width, quad);
  add_chords(contour, clip, lobe_width, quad);
  const R value = quad.refine(contour, [](int) { return R(1); }, tolerance);
  if (contour.tail) return std::max(value / (m + R(1)), R(0));
  return std::max(-value / (m + R(1)), R(0));
}

}  // namespace vlit
