// Independent long-double reference for the disk light (diffuse and exact specular), used by the
// disk tests and the accuracy report: Boost.Math adaptive Gauss-Kronrod over the disk in polar
// coordinates (rho, phi) about its centre, neither through polygons nor through the contour
// integral of shaders_cpu/disk_diffuse_contour.h.
//
// For a fixed phi the horizon N.(x - P) = 0 and the lobe's zero Rv.(x - P) = 0 are linear in rho:
// the radial integral is split at their roots, so max(0, .) never puts a kink inside a piece, and
// graded around the point of the ray closest to the foot of P (the factor h / r^3 is peaked there
// when P is close to the disk). The angular integral is split where those lines cross the rim, at
// the angle of the foot (graded when the foot is near the rim) and at the hit point of P + t Rv.
// Integrands: diffuse max(0, N.a)/r * cos_l / r^2, specular [N.a > 0] max(0, Rv.â)^m cos_l / r^2,
// a = x - P, cos_l = h / r (one-sided: P behind the disk or in its plane gets 0).
#pragma once

#include <algorithm>
#include <cmath>
#include <vector>

#include <boost/math/quadrature/gauss_kronrod.hpp>

#include "core/vec3.h"

namespace vlit::test {

struct DiskQuery {
  Vec3d center, normal;
  double radius = 1;
  Vec3d p, n, rv;
  double m = 1;
  bool specular = false;
};

// Gauss-Kronrod 31 on [a, b] mapped to [-1, 1], bisected while its error estimate exceeds
// rel_tol times the piece's L1 norm. (Boost's own recursion is not used: in Boost 1.74 it compares
// the unscaled sub-interval error with the scaled tolerance and bisects short pieces to max_depth.)
template <class F>
long double gk_bisect(const F& f, long double a, long double b, long double rel_tol, int depth,
                      long double abs_tol = 0) {
  using LD = long double;
  const LD mid = (a + b) / 2, half = (b - a) / 2;
  auto g = [&](LD x) { return f(mid + half * x) * half; };
  LD err = 0, l1 = 0;
  const LD r = boost::math::quadrature::gauss_kronrod<LD, 31>::integrate(g, LD(-1), LD(1), 0, LD(0), &err, &l1);
  if (depth <= 0 || err <= rel_tol * l1 || err <= abs_tol) return r;
  return gk_bisect(f, a, mid, rel_tol, depth - 1, abs_tol / 2) + gk_bisect(f, mid, b, rel_tol, depth - 1, abs_tol / 2);
}

inline long double disk_reference(const DiskQuery& q) {
  using LD = long double;
  using V = Vec3<LD>;
  const V c = static_cast<V>(q.center), p = static_cast<V>(q.p), n = static_cast<V>(q.n);
  const V rv = normalize(static_cast<V>(q.rv));  // the lobe's Rv is a unit vector by definition
  V nl = static_cast<V>(q.normal);
  nl = nl / std::sqrt(dot(nl, nl));
  const LD big_r = q.radius, m = q.m;
  const LD h = dot(nl, p - c);
  if (!(h > 0)) return 0;
  // In-plane frame (e1, e2), its own construction (Gram-Schmidt from the smallest axis).
  V axis{1, 0, 0};
  if (std::fabs(nl.y) < std::fabs(nl.x) && std::fabs(nl.y) <= std::fabs(nl.z)) axis = {0, 1, 0};
  else if (std::fabs(nl.z) < std::fabs(nl.x)) axis = {0, 0, 1};
  V e1 = axis - nl * dot(nl, axis);
  e1 = e1 / std::sqrt(dot(e1, e1));
  const V e2 = cross(nl, e1);
  const V cp = c - p;  // a = cp + rho dir(phi)
  const LD foot_x = -dot(e1, cp), foot_y = -dot(e2, cp);  // foot of P in plane coordinates
  const LD foot_rho = std::hypot(foot_x, foot_y), foot_phi = std::atan2(foot_y, foot_x);

  auto integrand = [&](LD rho, LD cs, LD sn) -> LD {
    const V a = cp + (e1 * cs + e2 * sn) * rho;
    const LD r2 = dot(a, a), r = std::sqrt(r2);
    const LD cos_n = dot(n, a) / r;
    if (!(cos_n > 0)) return 0;
    const LD cos_l = h / r;
    if (!q.specular) return cos_n * cos_l / r2;
    const LD cr = dot(rv, a) / r;
    return cr > 0 ? std::pow(std::min(cr, LD(1)), m) * cos_l / r2 : 0;
  };
  // Radial integral at angle phi.
  auto radial = [&](LD phi) -> LD {
    const LD cs = std::cos(phi), sn = std::sin(phi);
    const V dir = e1 * cs + e2 * sn;
    std::vector<LD> cuts{0, big_r};
    auto add = [&](LD x) { if (x > 0 && x < big_r) cuts.push_back(x); };
    const LD nd = dot(n, dir), rd = dot(rv, dir);
    if (nd != 0) add(-dot(n, cp) / nd);
    if (q.specular && rd != 0) add(-dot(rv, cp) / rd);
    const LD closest = foot_x * cs + foot_y * sn;  // rho of the point nearest the foot
    const LD perp = std::fabs(-foot_x * sn + foot_y * cs);
    const LD width = std::max(std::hypot(h, perp), big_r * LD(1e-30));
    add(closest);
    for (LD w = width; w < 2 * big_r; w *= 4) { add(closest - w); add(closest + w); }
    std::sort(cuts.begin(), cuts.end());
    LD sum = 0;
    for (std::size_t i = 0; i + 1 < cuts.size(); ++i) {
      if (!(cuts[i + 1] > cuts[i])) continue;
      auto f = [&](LD rho) { return rho * integrand(rho, cs, sn); };
      sum += gk_bisect(f, cuts[i], cuts[i + 1], LD(1e-14), 8);
    }
    return sum;
  };
  // Angular breakpoints (relative to foot_phi, in [0, 2 pi]).
  std::vector<LD> cuts{0, 2 * LD(M_PI)};
  const LD two_pi = 2 * LD(M_PI);
  auto add_angle = [&](LD phi) {
    LD x = std::fmod(phi - foot_phi, two_pi);
    if (x < 0) x += two_pi;
    if (x > 0 && x < two_pi) cuts.push_back(x);
  };
  // Rim crossings of a line K.(x - P) = 0: K.cp + R (K.e1 cos + K.e2 sin) = 0.
  auto add_line = [&](const V& k) {
    const LD ku = dot(k, e1), kv = dot(k, e2), amp = std::hypot(ku, kv);
    if (!(amp > 0)) return;
    const LD ratio = -dot(k, cp) / (big_r * amp);
    if (std::fabs(ratio) > 1) return;
    const LD base = std::atan2(kv, ku), off = std::acos(ratio);
    add_angle(base + off);
    add_angle(base - off);
  };
  add_line(n);
  if (q.specular) {
    add_line(rv);
    const LD toward = -dot(nl, rv);
    if (toward > 0) {
      const V hit = rv * (h / toward) + (p - c);
      add_angle(std::atan2(dot(e2, hit), dot(e1, hit)));
    }
  }
  if (foot_rho > 0) {  // grading around the foot's angle, for P close to the rim
    const LD w0 = std::max(h / std::max(foot_rho, big_r), LD(1e-30));
    for (LD w = w0; w < LD(M_PI); w *= 4) { add_angle(foot_phi + w); add_angle(foot_phi - w); }
  }
  std::sort(cuts.begin(), cuts.end());
  // The inner integrals carry rounding noise of ~1e-16 relative, so the outer error estimate is
  // also accepted below an absolute floor of 1e-14 of a first, unrefined estimate of the total.
  auto g = [&](LD x) { return radial(foot_phi + x); };
  LD rough = 0;
  for (std::size_t i = 0; i + 1 < cuts.size(); ++i)
    if (cuts[i + 1] > cuts[i]) rough += std::fabs(gk_bisect(g, cuts[i], cuts[i + 1], LD(1), 0));
  LD total = 0;
  for (std::size_t i = 0; i + 1 < cuts.size(); ++i)
    if (cuts[i + 1] > cuts[i]) total += gk_bisect(g, cuts[i], cuts[i + 1], LD(1e-13), 10, LD(1e-14) * rough);
  return total;
}

}  // namespace vlit::test
