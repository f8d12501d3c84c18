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
// Each piece is integrated by the same globally adaptive Gauss-Kronrod 7/15 as the polygon edges,
// with initial cuts graded around the rim point nearest P (width ~ its distance) and the rim
// point nearest the lobe's axis (width ~ lobe width), until Σ error <= tol |Σ value|.
// Sources: docs/conventions.md "Radiometric definitions" (the definition); Picott 1992 eq. 9's contour idea.
// Scalar type: R = AreaReal<T> (double for T = float).
// Stiff cases and measurements: tests/kernels/area/disk_test.cpp, docs/area-lights.md.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>

#include "area_specular_exact.h"

namespace vlit {

inline constexpr int kDiskExactMaxPieces = 1024;

template <class R>
R disk_specular_exact(const AreaView<R>& view, R radius, const Vec3<R>& n, const Vec3<R>& rv_in, R m, R tolerance) {
  using namespace area_exact_detail;
  if (!view.lit) return R(0);
  const Vec3<R> rv = normalize(rv_in);  // unit Rv, as in area_specular_exact.h
  const R pi = R(M_PI);
  // Constraints alpha.p + beta >= 0 in the disk's plane.
  struct Line { R ax, ay, beta; };
  std::array<Line, 2> lines{};
  int nl = 0;
  auto add_line = [&](const Vec3<R>& k) { lines[nl++] = {dot(k, view.u), dot(k, view.v), dot(k, view.D)}; };
  add_line(n);
  add_line(rv);  // the lobe's half-space, also for m = 0 (its limit m -> 0+ is [Rv.w > 0])
  auto inside = [&](R px, R py, int skip) {
    for (int k = 0; k < nl; ++k)
      if (k != skip && lines[k].ax * px + lines[k].ay * py + lines[k].beta < R(0)) return false;
    return true;
  };
  // Rim crossings of each line: theta_k -+ omega_k (none if the line misses the disk).
  std::array<R, 4> breaks{};
  int nb = 0;
  std::array<bool, 2> has_chord{};
  std::array<R, 2> chord_lo{}, chord_hi{};
  for (int k = 0; k < nl; ++k) {
    const R mu = std::hypot(lines[k].ax, lines[k].ay);
    if (!(mu > R(0)) || std::abs(lines[k].beta) >= radius * mu) {
      if (lines[k].beta < R(0)) return R(0);  // the whole disk is outside this half-space
      continue;
    }
    const R tau = -lines[k].beta / (radius * mu);
    const R omega = std::atan2(std::sqrt((R(1) - tau) * (R(1) + tau)), tau);
    const R theta = std::atan2(lines[k].ay, lines[k].ax);
    has_chord[k] = true;
    chord_lo[k] = theta - omega;
    chord_hi[k] = theta + omega;
    breaks[nb++] = theta - omega;
    breaks[nb++] = theta + omega;
  }
  // Pieces: kind 0 = arc [t0, t1] in theta, kind 1 = chord of line k, x = a + t e, t in [t0, t1].
  struct Curve { int kind; Vec3<R> a, e; };
  std::array<Curve, 8> curves{};
  int nc = 0;
  std::array<Piece<R>, kDiskExactMaxPieces> heap;
  int size = 0;
  R value = 0, error = 0;
  const R lobe_width = R(1) / std::sqrt(m + R(1));
  // Rv outside the visible part: integrate only the tail c^{m+1} (area_specular_exact.h).
  bool rv_inside = false;
  {
    const R toward = -dot(view.normal, rv);
    if (toward > R(0)) {
      const Vec3<R> hit = rv * (view.height / toward) - view.D;  // relative to the centre
      rv_inside = length_squared(hit) <= radius * radius && dot(n, rv) >= R(0);
      // near the rim (within a lobe width as seen from P): keep the full form (see area_specular_exact.h)
      const R lh = length(hit);
      if (!rv_inside && lh > R(0)) {
        const Vec3<R> rim = view.D + hit * (radius / lh);  // rim point nearest the hit, from P
        if (std::atan2(length(cross(rv, rim)), dot(rv, rim)) <= lobe_width) rv_inside = true;
      }
    }
  }
  const bool tail = m > R(0) && !rv_inside;
  auto integrand = [&](int c, R t) {
    const Curve& cv = curves[c];
    if (cv.kind == 1) return dot(rv, cross(cv.a, cv.e)) * lobe_per_azimuth(cv.a + cv.e * t, rv, m, tail);
    const Vec3<R> e = view.u * std::cos(t) + view.v * std::sin(t), de = view.v * std::cos(t) - view.u * std::sin(t);
    const Vec3<R> x = view.D + e * radius;
    return dot(rv, cross(x, de * radius)) * lobe_per_azimuth(x, rv, m, tail);
  };
  auto push = [&](int c, R t0, R t1) {
    if (size >= kDiskExactMaxPieces) return;
    Piece<R>& p = heap[size];
    p.t0 = t0; p.t1 = t1; p.edge = c;
    evaluate([&](R t) { return integrand(c, t); }, p);
    value += p.value; error += p.error;
    ++size;
    std::push_heap(heap.begin(), heap.begin() + size, less_error<R>);
  };
  // Graded initial cuts of [t0, t1] around t (width w), then the pieces.
  auto push_graded = [&](int c, R t0, R t1, const R* centers, const R* widths, int count) {
    std::array<R, 64> cuts{};
    int k = 0;
    cuts[k++] = t0;
    cuts[k++] = t1;
    for (int i = 0; i < count; ++i) {
      if (!(widths[i] > R(0)) || !std::isfinite(centers[i])) continue;
      auto add = [&](R t) { if (t > t0 && t < t1 && k < int(cuts.size())) cuts[k++] = t; };
      add(centers[i]);
      for (R s = widths[i]; s < t1 - t0 && k + 2 <= int(cuts.size()); s *= R(4)) { add(centers[i] - s); add(centers[i] + s); }
    }
    std::sort(cuts.begin(), cuts.begin() + k);
    for (int i = 0; i + 1 < k; ++i)
      if (cuts[i + 1] > cuts[i]) push(c, cuts[i], cuts[i + 1]);
  };

  // Arcs: the rim angle nearest the foot of P, and nearest the lobe's axis (its hit point).
  const R du = dot(view.D, view.u), dv = dot(view.D, view.v);
  const R foot_theta = std::atan2(-dv, -du);
  const R rim_dist = std::hypot(view.height, std::hypot(du, dv) - radius);
  R lobe_theta = foot_theta, lobe_w = R(0);
  {
    const R toward = -dot(view.normal, rv);
    if (m > R(0) && toward > R(0)) {
      const Vec3<R> hit = rv * (view.height / toward) - view.D;  // relative to the centre
      lobe_theta = std::atan2(dot(hit, view.v), dot(hit, view.u));
      lobe_w = lobe_width * length(view.D + (view.u * std::cos(lobe_theta) + view.v * std::sin(lobe_theta)) * radius) / radius;
    }
  }
  {
    // At most 4 crossings: insertion sort (std::sort's 16-element threshold made GCC 12 warn of
    // out-of-bounds access on this 4-element array, a false positive).
    for (int i = 1; i < nb; ++i)
      for (int j = i; j > 0 && breaks[j] < breaks[j - 1]; --j) std::swap(breaks[j], breaks[j - 1]);
    // Sub-arcs between consecutive crossings (cyclically); the whole rim if there are none.
    const int count = std::max(nb, 1);
    for (int i = 0; i < count; ++i) {
      const R t0 = nb == 0 ? foot_theta - pi : breaks[i];
      const R t1 = nb == 0 ? foot_theta + pi : (i + 1 < nb ? breaks[i + 1] : breaks[0] + R(2) * pi);
      if (!(t1 > t0)) continue;
      const R mid = (t0 + t1) / 2;
      if (!inside(radius * std::cos(mid), radius * std::sin(mid), -1)) continue;
      curves[nc] = {0, {}, {}};
      // centres shifted by 2 pi into [t0, t1] where needed
      auto shift = [&](R t) { while (t < t0) t += R(2) * pi; while (t > t0 + R(2) * pi) t -= R(2) * pi; return t; };
      const R centers[4] = {shift(foot_theta), shift(foot_theta) - R(2) * pi, shift(lobe_theta), shift(lobe_theta) - R(2) * pi};
      const R widths[4] = {rim_dist / radius, rim_dist / radius, lobe_w, lobe_w};
      push_graded(nc, t0, t1, centers, widths, m > R(0) ? 4 : 2);
      ++nc;
    }
  }
  // Chords: from the crossing at theta_k + omega_k back to theta_k - omega_k (region on the left),
  // clipped to the other half-space.
  for (int k = 0; k < nl; ++k) {
    if (!has_chord[k]) continue;
    const R ax = radius * std::cos(chord_hi[k]), ay = radius * std::sin(chord_hi[k]);
    const R bx = radius * std::cos(chord_lo[k]), by = radius * std::sin(chord_lo[k]);
    R s0 = 0, s1 = 1;
    for (int j = 0; j < nl; ++j) {
      if (j == k) continue;
      const R fa = lines[j].ax * ax + lines[j].ay * ay + lines[j].beta;
      const R fb = lines[j].ax * bx + lines[j].ay * by + lines[j].beta;
      if (fa < R(0) && fb < R(0)) { s1 = s0; break; }
      if (fa < R(0)) s0 = std::max(s0, fa / (fa - fb));
      else if (fb < R(0)) s1 = std::min(s1, fa / (fa - fb));
    }
    if (!(s1 > s0)) continue;
    const Vec3<R> pa = view.u * ax + view.v * ay, pb = view.u * bx + view.v * by;
    const Vec3<R> a = view.D + pa, e = pb - pa;
    curves[nc] = {1, a, e};
    const R e2 = length_squared(e), len = std::sqrt(e2);
    R centers[2], widths[2];
    const R tp = std::clamp(-dot(a, e) / e2, s0, s1);
    centers[0] = tp;
    widths[0] = length(a + e * tp) / len;
    centers[1] = tp;
    widths[1] = R(0);
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
    push_graded(nc, s0, s1, centers, widths, 2);
    ++nc;
  }

  // Global adaptivity, as for polygons.
  int splits = 0;
  while (error > tolerance * std::abs(value) && size + 2 <= kDiskExactMaxPieces) {
    std::pop_heap(heap.begin(), heap.begin() + size, less_error<R>);
    const Piece<R> p = heap[--size];
    value -= p.value; error -= p.error;
    const R mid = (p.t0 + p.t1) / 2;
    if (!(mid > p.t0 && mid < p.t1)) {
      heap[size++] = p;
      std::push_heap(heap.begin(), heap.begin() + size, less_error<R>);
      break;
    }
    push(p.edge, p.t0, mid);
    push(p.edge, mid, p.t1);
    if (++splits % 64 == 0 || !std::isfinite(error)) {
      value = 0; error = 0;
      for (int k = 0; k < size; ++k) { value += heap[k].value; error += heap[k].error; }
    }
  }
  value = 0;
  for (int k = 0; k < size; ++k) value += heap[k].value;
  if (tail) return std::max(value / (m + R(1)), R(0));
  return std::max(-value / (m + R(1)), R(0));
}

}  // namespace vlit
