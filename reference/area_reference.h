// Independent references for the area-light kernels: nested adaptive Gauss-Kronrod (Boost.Math)
// over the polygon's area in the light's plane, in long double.
//
// Independent of the kernels by construction: the integrand is the area form
// (cos theta cos theta_l / r^2, lobe cos theta_l / r^2), not a contour; the polygon is given as
// a list of CONVEX pieces (non-convex lights are decomposed by hand in the tests); each piece is
// clipped in 2D, in the light's own plane coordinates, by the half-planes where the horizon
// (N.(x - P) >= 0) and the lobe (Rv.(x - P) >= 0) cut the plane; the pieces are fanned from the
// foot of P and split at the hit point of the ray P + t Rv, so that peaked integrands sit on
// vertices of the quadrature mesh.
#pragma once

#include <boost/math/quadrature/gauss.hpp>
#include <boost/math/quadrature/gauss_kronrod.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "core/vec3.h"

namespace vlit::test {

using LD = long double;
using V3 = Vec3<LD>;

struct RefPoint2 { LD x, y; };

struct RefQuery {
  std::vector<std::vector<Vec3d>> pieces;  // convex pieces, each CCW seen from the emitting side
  bool two_sided = false;
  Vec3d p, n, rv;
  double m = 1;
  bool specular = false;  // false: diffuse integrand; true: exact specular integrand
  LD tolerance = 1e-12L;
};

inline std::vector<RefPoint2> clip_convex_2d(const std::vector<RefPoint2>& poly, LD a, LD b, LD c) {
  // keep a x + b y + c >= 0
  std::vector<RefPoint2> out;
  const size_t n = poly.size();
  for (size_t i = 0; i < n; ++i) {
    const RefPoint2& p = poly[i];
    const RefPoint2& q = poly[(i + 1) % n];
    const LD sp = a * p.x + b * p.y + c, sq = a * q.x + b * q.y + c;
    if (sp >= 0) out.push_back(p);
    if ((sp >= 0) != (sq >= 0)) {
      const LD t = sp / (sp - sq);
      out.push_back({p.x + t * (q.x - p.x), p.y + t * (q.y - p.y)});
    }
  }
  return out;
}

inline bool inside_triangle_2d(const RefPoint2& a, const RefPoint2& b, const RefPoint2& c, const RefPoint2& p) {
  auto side = [](const RefPoint2& u, const RefPoint2& v, const RefPoint2& w) {
    return (v.x - u.x) * (w.y - u.y) - (v.y - u.y) * (w.x - u.x);
  };
  const LD d0 = side(a, b, p), d1 = side(b, c, p), d2 = side(c, a, p);
  return (d0 > 0 && d1 > 0 && d2 > 0) || (d0 < 0 && d1 < 0 && d2 < 0);
}

inline LD reference_integral(const RefQuery& q) {
  using boost::math::quadrature::gauss_kronrod;
  const V3 P = static_cast<V3>(q.p), N = static_cast<V3>(q.n);
  const V3 Rv = normalize(static_cast<V3>(q.rv));  // the lobe's Rv is a unit vector by definition
  const LD m = q.m;
  LD total = 0;
  for (const auto& piece_d : q.pieces) {
    std::vector<V3> piece;
    for (const auto& v : piece_d) piece.push_back(static_cast<V3>(v));
    const V3 o = piece[0];
    V3 newell{};
    for (size_t i = 0; i < piece.size(); ++i) newell += cross(piece[i] - o, piece[(i + 1) % piece.size()] - o);
    V3 nl = newell / length(newell);
    const LD hp = dot(nl, P - o);
    if (hp == 0) continue;
    if (hp < 0 && !q.two_sided) continue;
    const LD height = std::abs(hp);
    // The integrand at a = X - P: cos θ (diffuse) or the lobe max(0, Rv.â)^m, times cos θ_l / r².
    auto integrand_at = [&](const V3& a) -> LD {
      const LD r2 = length_squared(a);
      const LD r = std::sqrt(r2);
      const LD cos_l = height / r;
      if (!q.specular) return (dot(N, a) / r) * cos_l / r2;
      const LD c = dot(Rv, a) / r;
      const LD lobe = c > 0 ? std::pow(c, m) : 0;
      return lobe * cos_l / r2;
    };
    V3 e1 = piece[1] - o;
    e1 = e1 / length(e1);
    const V3 e2 = cross(nl, e1);  // (e1, e2) keeps the piece CCW
    std::vector<RefPoint2> poly;
    for (const auto& v : piece) poly.push_back({dot(e1, v - o), dot(e2, v - o)});
    // Horizon and lobe half-planes in plane coordinates: K.(o + x e1 + y e2 - P) >= 0.
    poly = clip_convex_2d(poly, dot(N, e1), dot(N, e2), dot(N, o - P));
    // The lobe's half-space, also for m = 0, whose lobe is the limit m -> 0+, [Rv.w > 0].
    if (q.specular && poly.size() >= 3) poly = clip_convex_2d(poly, dot(Rv, e1), dot(Rv, e2), dot(Rv, o - P));
    if (poly.size() < 3) continue;
    // Foot of P and the hit point of the ray P + t Rv.
    const RefPoint2 foot{dot(e1, P - o), dot(e2, P - o)};
    std::vector<RefPoint2> splits;
    const LD toward = -dot(nl, Rv) * (hp > 0 ? 1 : -1);
    if (q.specular && toward > 0) {
      const V3 hit = P + Rv * (height / toward);
      splits.push_back({dot(e1, hit - o), dot(e2, hit - o)});
    }
    // Polar coordinates (rho, phi) about a center C: the triangles (C, v_i, v_i+1) sum to the
    // piece. The area factor's peak (width ~ |P - C|) is at rho = 0: radial breakpoints at
    // |P - C| 2^k; the lobe's peak at the hit point H: breakpoints at its angle and radius.
    // Center: the foot if inside the (convex) piece, else the boundary point closest to it, so
    // the signed triangles never overlap (no cancellation between them).
    RefPoint2 center = foot;
    {
      bool inside = true;
      LD best = -1;
      for (size_t i = 0; i < poly.size(); ++i) {
        const RefPoint2& a = poly[i];
        const RefPoint2& b = poly[(i + 1) % poly.size()];
        const LD ex = b.x - a.x, ey = b.y - a.y;
        if (ex * (foot.y - a.y) - ey * (foot.x - a.x) < 0) inside = false;
        const LD len2 = ex * ex + ey * ey;
        const LD t = std::clamp(len2 > 0 ? ((foot.x - a.x) * ex + (foot.y - a.y) * ey) / len2 : LD(0), LD(0), LD(1));
        const RefPoint2 c{a.x + t * ex, a.y + t * ey};
        const LD d2 = (c.x - foot.x) * (c.x - foot.x) + (c.y - foot.y) * (c.y - foot.y);
        if (best < 0 || d2 < best) { best = d2; center = c; }
      }
      if (inside) {
        center = foot;
      } else {
        // A broad peak (P far from the closest point compared with the nearest vertex): fan
        // from that vertex instead, so thin polygons are not seen edge-on from their own edge.
        const V3 closest3 = o + e1 * center.x + e2 * center.y;
        LD vbest = -1;
        RefPoint2 vnear = poly[0];
        for (const auto& v : poly) {
          const LD d2 = (v.x - center.x) * (v.x - center.x) + (v.y - center.y) * (v.y - center.y);
          if (vbest < 0 || d2 < vbest) { vbest = d2; vnear = v; }
        }
        if (length(closest3 - P) > LD(0.5) * std::sqrt(vbest)) center = vnear;
      }
    }
    // Thin pieces (area < 1e-3 diameter^2) seen from afar: polar coordinates about a point of
    // the piece see the long edges nearly edge-on; use a Duffy fan from vertex 0 with nested
    // Gauss-Kronrod instead (the integrand is smooth across the thin direction).
    {
      LD area2 = 0, diam2 = 0;
      for (size_t i = 0; i < poly.size(); ++i) {
        const RefPoint2& a = poly[i];
        const RefPoint2& b = poly[(i + 1) % poly.size()];
        area2 += a.x * b.y - a.y * b.x;
        for (const auto& v : poly) diam2 = std::max(diam2, (v.x - a.x) * (v.x - a.x) + (v.y - a.y) * (v.y - a.y));
      }
      // Also when the foot is inside a thin piece but P is far compared with the piece's length:
      // polar coordinates about the foot see the long edges edge-on (narrow angular spikes of
      // width ~ thickness / length), which the angular Gauss-Kronrod cannot resolve ("thin 1e-6",
      // P at height 0.5 over a 1 x 1e-6 strip: 1.9e-5 off before, against the exact 1D form).
      const bool far_from_thin = height > LD(1e-2) * std::sqrt(diam2);
      if (std::abs(area2) / 2 < LD(1e-3) * diam2 && (!(center.x == foot.x && center.y == foot.y) || far_from_thin)) {
        const V3 v0_from_p = (o - P) + e1 * poly[0].x + e2 * poly[0].y;
        auto f = [&](LD dx, LD dy) { return integrand_at(v0_from_p + e1 * dx + e2 * dy); };
        for (size_t i = 1; i + 1 < poly.size(); ++i) {
          const LD e1x = poly[i].x - poly[0].x, e1y = poly[i].y - poly[0].y;
          const LD e2x = poly[i + 1].x - poly[0].x, e2y = poly[i + 1].y - poly[0].y;
          const LD jac = e1x * e2y - e1y * e2x;
          auto outer = [&](LD s) {
            auto inner = [&](LD u) { return f(s * (e1x + u * (e2x - e1x)), s * (e1y + u * (e2y - e1y))); };
            return s * gauss_kronrod<LD, 31>::integrate(inner, LD(0), LD(1), 10, q.tolerance * LD(1e-2));
          };
          total += jac * gauss_kronrod<LD, 31>::integrate(outer, LD(0), LD(1), 10, q.tolerance);
        }
        continue;
      }
    }
    const LD center_dist = length(o + e1 * center.x + e2 * center.y - P);  // peak width scale
    const bool has_hit = !splits.empty();
    // a = X - P relative to the center, so the small vectors near the peak do not cancel.
    const V3 center_from_p = (o - P) + e1 * center.x + e2 * center.y;
    auto integrand_polar = [&](LD dx, LD dy) { return integrand_at(center_from_p + e1 * dx + e2 * dy); };
    const LD hit_phi = has_hit ? std::atan2(splits[0].y - center.y, splits[0].x - center.x) : 0;
    const LD hit_rho = has_hit ? std::hypot(splits[0].x - center.x, splits[0].y - center.y) : 0;
    const LD hit_width = has_hit ? length(o + e1 * splits[0].x + e2 * splits[0].y - P) / std::sqrt(m + 1) / 8 : 0;
    for (size_t i = 0; i < poly.size(); ++i) {
      const RefPoint2 a{poly[i].x - center.x, poly[i].y - center.y};
      const RefPoint2 b{poly[(i + 1) % poly.size()].x - center.x, poly[(i + 1) % poly.size()].y - center.y};
      const LD ex = b.x - a.x, ey = b.y - a.y;
      const LD cr = a.x * b.y - a.y * b.x;
      const LD dphi = std::atan2(cr, a.x * b.x + a.y * b.y);
      if (std::abs(dphi) < LD(1e-15) || std::abs(cr) <= LD(1e-16) * std::hypot(ex, ey) * std::hypot(a.x, a.y)) continue;
      const LD phi0 = std::atan2(a.y, a.x);
      const LD a_cross_e = a.x * ey - a.y * ex;
      auto along = [&](LD phi) {  // integral over rho in [0, rho_edge(phi)]
        const LD c = std::cos(phi), sn = std::sin(phi);
        const LD rho_edge = a_cross_e / (c * ey - sn * ex);
        if (!(rho_edge > 0) || !std::isfinite(rho_edge)) return LD(0);
        auto radial = [&](LD rho) { return rho * integrand_polar(rho * c, rho * sn); };
        // Non-adaptive 30-point Gauss-Legendre on geometric segments: [0, d], [d, 2d], ... (d =
        // |P - C|), refined geometrically on both sides of the lobe's hit radius.
        LD cuts[256];
        int nc = 0;
        cuts[nc++] = 0;
        for (LD r = std::max(center_dist, rho_edge * LD(1e-30)); r < rho_edge && nc < 120; r *= 2) cuts[nc++] = r;
        if (has_hit && hit_rho > 0 && hit_rho < rho_edge) {
          cuts[nc++] = hit_rho;
          for (LD w = hit_width; w < rho_edge && nc < 250; w *= 2) {
            if (hit_rho - w > 0) cuts[nc++] = hit_rho - w;
            if (hit_rho + w < rho_edge) cuts[nc++] = hit_rho + w;
          }
        }
        cuts[nc++] = rho_edge;
        std::sort(cuts, cuts + nc);
        LD sum = 0;
        for (int k = 0; k + 1 < nc; ++k)
          if (cuts[k + 1] > cuts[k]) sum += boost::math::quadrature::gauss<LD, 30>::integrate(radial, cuts[k], cuts[k + 1]);
        return sum;
      };
      // phi from phi0 to phi0 + dphi (signed); split at the hit's angle if inside.
      LD sub = 0;
      const LD sign = dphi > 0 ? 1 : -1;
      // Boost's Gauss-Kronrod error estimate has an absolute floor: integrate O(1) values.
      const LD norm = along(phi0 + sign * std::abs(dphi) / 2);
      const LD inv_norm = norm != 0 && std::isfinite(norm) ? 1 / std::abs(norm) : LD(1);
      auto g = [&](LD t) { return along(phi0 + sign * t) * inv_norm; };
      LD cut = -1;
      if (has_hit) {
        LD rel = sign * (hit_phi - phi0);
        while (rel < 0) rel += LD(2 * M_PI);
        while (rel >= LD(2 * M_PI)) rel -= LD(2 * M_PI);
        if (rel > 0 && rel < std::abs(dphi)) cut = rel;
      }
      if (cut > 0) {
        sub = gauss_kronrod<LD, 31>::integrate(g, LD(0), cut, 14, q.tolerance) +
              gauss_kronrod<LD, 31>::integrate(g, cut, std::abs(dphi), 14, q.tolerance);
      } else {
        sub = gauss_kronrod<LD, 31>::integrate(g, LD(0), std::abs(dphi), 14, q.tolerance);
      }
      total += sign * sub / inv_norm;
    }
  }
  return total;
}

}  // namespace vlit::test
