// Disk light (disk_light.h, disk_diffuse_contour.h): the analytic diffuse against an independent
// 2D quadrature over the disk (disk_reference.h: polar Gauss-Kronrod in long double) and against
// closed forms derived here by hand, on random and stiff cases; the specular bracket; float.
#include <doctest/doctest.h>

#include <algorithm>
#include <cstdio>
#include <vector>
#include <string>

#include "area_test_util.h"
#include "disk_light.h"
#include "disk_reference.h"

using namespace vlit;
using namespace vlit::test;

namespace {

DiskQuery query(const DiskLight<double>& d, const ShadingPoint<double>& sp, bool specular = false) {
  DiskQuery q;
  q.center = d.center;
  q.normal = d.normal;
  q.radius = d.radius;
  q.p = sp.p;
  q.n = sp.n;
  q.rv = sp.rv;
  q.m = sp.shininess;
  q.specular = specular;
  return q;
}

double diffuse(const DiskLight<double>& d, const ShadingPoint<double>& sp) {
  return shade_disk(d, sp, spec_options(SpecularMethod::kNone)).diffuse;
}

// The same closed form evaluated in long double (rounding diagnosis, not a reference).
long double diffuse_long_double(const DiskLight<double>& d, const ShadingPoint<double>& sp) {
  const PreparedAreaLight<long double> pl =
      disk_polygon(DiskLight<long double>{static_cast<V3>(d.center), static_cast<V3>(d.normal), d.radius}, 3, 1);
  const AreaView<LD> view = make_area_view(pl, static_cast<V3>(sp.p));
  return disk_diffuse_contour(view, LD(d.radius), static_cast<V3>(sp.n));
}

// Eq. 9's contour integral of the whole circle by 1D quadrature in long double: -1/2 ∮ N.(r x r') / |r|^2
// dtheta, r = d + R e(theta), graded around the rim point nearest to P (where the integrand peaks
// with width ~ dist(P, rim) / R); good to ~1e-12 there. Independent of the closed-form antiderivative; valid when the
// whole disk is above the horizon.
double contour_quadrature(const DiskLight<double>& d, const ShadingPoint<double>& sp) {
  using boost::math::quadrature::gauss_kronrod;
  const V3 c = static_cast<V3>(d.center), P = static_cast<V3>(sp.p), N = static_cast<V3>(sp.n);
  V3 nl = static_cast<V3>(d.normal);
  nl = nl / std::sqrt(dot(nl, nl));
  const V3 helper = std::abs(nl.x) < 0.6L ? V3{1, 0, 0} : V3{0, 1, 0};
  V3 u = cross(helper, nl);
  u = u / std::sqrt(dot(u, u));
  const V3 v = cross(nl, u), dv = c - P;
  const LD R = d.radius;
  auto f = [&](LD t) {
    const V3 e = u * std::cos(t) + v * std::sin(t), de = v * std::cos(t) - u * std::sin(t);
    const V3 r = dv + e * R;
    return dot(N, cross(r, de * R)) / dot(r, r);
  };
  const LD nearest = std::atan2(-dot(dv, v), -dot(dv, u));
  const LD h = std::abs(dot(nl, dv));
  const LD width = std::max(std::sqrt(h * h + std::pow(std::hypot(dot(dv, u), dot(dv, v)) - R, 2)) / R, LD(1e-30));
  std::vector<LD> cuts{nearest - LD(M_PI), nearest, nearest + LD(M_PI)};
  for (LD w = width; w < LD(M_PI); w *= 4) { cuts.push_back(nearest - w); cuts.push_back(nearest + w); }
  std::sort(cuts.begin(), cuts.end());
  LD sum = 0;
  for (std::size_t i = 0; i + 1 < cuts.size(); ++i) sum += gauss_kronrod<LD, 61>::integrate(f, cuts[i], cuts[i + 1], 8, LD(1e-17));
  return static_cast<double>(-sum / 2);
}

// The magnitude of the unclipped contour: the diffuse of the whole disk for a normal facing it
// (N = -n_l), the scale of the absolute floor where a horizon clip leaves a sliver.
double unclipped_scale(const DiskLight<double>& d, const ShadingPoint<double>& sp) {
  ShadingPoint<double> facing = sp;
  facing.n = -normalize(d.normal);
  return diffuse(d, facing);
}

}  // namespace

TEST_CASE("disk diffuse: analytic contour vs polar quadrature on random disks") {
  Rng rng(4242);
  double worst_full = 0, worst_clipped = 0;
  int clipped = 0;
  for (int i = 0; i < 200; ++i) {
    const double scale = rng.log_uniform(1e-3, 1e3);
    const Vec3d p = rng.unit() * rng.uniform(0, 1);
    DiskLight<double> d{p + rng.unit() * (scale * rng.uniform(0.05, 3)), rng.unit(), scale * rng.uniform(0.1, 1.1)};
    const ShadingPoint<double> sp{p, rng.unit(), rng.unit(), 1};
    const double ref = static_cast<double>(disk_reference(query(d, sp)));
    const double v = diffuse(d, sp);
    const ErrorMeasure e = measure(v, ref, unclipped_scale(d, sp));
    INFO("case ", i, " value ", v, " reference ", ref);
    // Is the disk cut by the horizon? (the rim crosses the tangent plane of P)
    const Vec3d nl = normalize(d.normal);
    const double nd = dot(sp.n, d.center - p), mu = length(sp.n - nl * dot(sp.n, nl));
    const bool cut = std::abs(nd) < d.radius * mu;
    CHECK(e.within(cut ? 1e-7 : 1e-10));
    if (cut) { ++clipped; worst_clipped = std::max(worst_clipped, e.effective(1e-7)); }
    else worst_full = std::max(worst_full, e.rel);
  }
  MESSAGE("disk diffuse, 200 random disks (", clipped, " cut by the horizon): max rel. err. uncut ", worst_full,
          ", cut (rel. or abs/scale <= 1e-12) ", worst_clipped);
}

TEST_CASE("disk diffuse: closed forms derived by hand") {
  SUBCASE("on the axis: pi R^2 / (h^2 + R^2), every scale") {
    for (double r : {1e-6, 1e-3, 1.0, 1e3, 1e6})
      for (double h : {1e-6, 1e-2, 1.0, 1e2, 1e6}) {
        const DiskLight<double> d{{0, 0, 0}, {0, 0, 1}, r};
        const double v = diffuse(d, {{0, 0, h}, {0, 0, -1}, {0, 0, -1}, 1});
        const double expect = M_PI * r * r / (h * h + r * r);
        INFO("R=", r, " h=", h);
        CHECK(std::abs(v - expect) <= 4e-16 * expect);
      }
  }
  SUBCASE("near 1e-6 above an inside point: pi - pi h^2 / (1 - |f|^2)^2 + O(h^4)") {
    // The whole plane gives pi; the part outside the unit disk, for P at height h over f:
    // h^2 ∫_{|x|>1} |x - f|^-4 dA (1 + O(h^2)) = pi h^2 / (1 - |f|^2)^2 (Poisson kernel of the disk).
    const double h = 1e-6;
    const Vec3d f{0.2, 0.1, 0};
    const double v = diffuse({{0, 0, 0}, {0, 0, 1}, 1}, {{f.x, f.y, h}, {0, 0, -1}, {0, 0, -1}, 1});
    const double f2 = length_squared(f);
    const double expect = M_PI - M_PI * h * h / ((1 - f2) * (1 - f2));
    MESSAGE("disk near 1e-6: rel. err. vs the asymptotic form ", (v - expect) / expect);
    CHECK(std::abs(v - expect) <= 2e-15 * expect);
  }
  SUBCASE("tiny and far: a point light of intensity pi R^2 cos(theta_l)") {
    const Vec3d n_l = normalize(Vec3d{0, 0.2, -1});
    for (double dist : {1e3, 1e6}) {
      const DiskLight<double> d{{0, 0, dist}, n_l, 1};
      const ShadingPoint<double> sp{{0, 0, 0}, normalize(Vec3d{0.1, 0, 1}), {0, 0, 1}, 1};
      const double cos_l = -n_l.z, cos_t = sp.n.z;
      // relative correction of the point-light limit is O((R / dist)^2)
      CHECK(diffuse(d, sp) == doctest::Approx(M_PI * cos_l * cos_t / (dist * dist)).epsilon(3.0 / (dist * dist)));
    }
    const DiskLight<double> tiny{{0, 0, 1}, n_l, 1e-6};
    const ShadingPoint<double> sp{{0, 0, 0}, {0, 0, 1}, {0, 0, 1}, 1};
    CHECK(diffuse(tiny, sp) == doctest::Approx(M_PI * 1e-12 * -n_l.z).epsilon(1e-11));
  }
  SUBCASE("half the disk behind the horizon through its centre: by symmetry half the facing value") {
    // P on the axis, N in the disk's plane direction: the tangent plane of P contains the axis,
    // cuts the disk in half; the integrand cos theta = N.a / r is odd under the reflection, so
    // the visible half gives ∫_half (N.a) h / r^4 dA = (h / (h^2+R^2)... computed by hand:
    // ∫_0^R ∫_{-pi/2}^{pi/2} rho cos(phi) h / (rho^2 + h^2)^2 rho dphi drho
    //   = 2 h ∫_0^R rho^2 / (rho^2 + h^2)^2 drho = atan(R/h) - R h / (R^2 + h^2).
    for (double h : {1e-3, 0.5, 1.0, 30.0}) {
      const DiskLight<double> d{{0, 0, 0}, {0, 0, 1}, 1};
      const double v = diffuse(d, {{0, 0, h}, {1, 0, 0}, {1, 0, 0}, 1});
      const double expect = std::atan(1 / h) - h / (1 + h * h);
      INFO("h=", h);
      CHECK(std::abs(v - expect) <= 1e-14 * expect);
    }
  }
}

TEST_CASE("disk diffuse: stiff cases against the quadrature") {
  struct Case { const char* name; DiskLight<double> d; ShadingPoint<double> sp; double bar; };
  const Vec3d down{0, 0, -1};
  auto sp = [](Vec3d p, Vec3d n) { return ShadingPoint<double>{p, normalize(n), {0, 0, -1}, 1}; };
  const DiskLight<double> unit{{0, 0, 0}, {0, 0, 1}, 1};
  const Case cases[] = {
      {"rim outside, height 1e-4", unit, sp({1.001, 0, 1e-4}, {-0.2, 0, -1}), 1e-11},
      {"rim inside, height 1e-4", unit, sp({0.999, 0, 1e-4}, down), 1e-11},
      {"rim outside 1e-4, N toward the disk", unit, sp({1.001, 0, 1e-4}, {-1, 0, -0.01}), 1e-11},
      {"grazing: N 1e-6 off the plane", unit, sp({0, 0, 1}, {1, 0, -1e-6}), 1e-10},
      {"grazing: P 1e-3 above the plane, beside", unit, sp({2, 0, 1e-3}, {-1, 0, 1e-6}), 1e-10},
      {"far 1e6", unit, sp({3e5, 0, 1e6}, {-0.3, 0, -1}), 1e-12},
      // The 2D reference itself is good to ~1e-10 on these two (the 1D contour check below: 1e-13)
      {"near 1e-6, inside", unit, sp({0.3, -0.5, 1e-6}, {0, 0.3, -1}), 2e-10},
      {"huge radius 1e6, off-centre", {{0, 0, 0}, {0, 0, 1}, 1e6}, sp({5e5, 0, 1}, {0.5, 0, -1}), 2e-10},
      {"tiny radius 1e-6", {{0, 0, 0}, {0, 0, 1}, 1e-6}, sp({1e-6, 0, 1e-6}, {-0.3, 0.2, -1}), 1e-11},
      {"crossing the horizon", unit, sp({0.3, 0.2, 0.3}, {1, 1, -0.5}), 1e-11},
      {"crossing the horizon near the rim", unit, sp({0.9, 0, 1e-2}, {0.3, 0.2, -0.1}), 1e-11},
      {"crossing, P on the axis", unit, sp({0, 0, 0.5}, {1, 0, 0}), 1e-11},
  };
  for (const Case& c : cases) {
    const double ref = static_cast<double>(disk_reference(query(c.d, c.sp)));
    const double v = diffuse(c.d, c.sp);
    const ErrorMeasure e = measure(v, ref, unclipped_scale(c.d, c.sp));
    INFO(c.name, ": value ", v, " reference ", ref);
    CHECK(e.within(c.bar));
    const double vs_long = double((LD(v) - diffuse_long_double(c.d, c.sp)) / LD(v));
    CHECK(std::abs(vs_long) <= 2e-15);
    MESSAGE("disk stiff '", std::string(c.name), "': rel. err. ", e.rel, " (abs/scale ", e.abs_scaled,
            "); double vs long double kernel ", vs_long);
    // float: computed in double on the same (float-rounded) inputs, rounded once
    const DiskLight<float> df{static_cast<Vec3f>(c.d.center), static_cast<Vec3f>(c.d.normal), float(c.d.radius)};
    const ShadingPoint<float> sf{static_cast<Vec3f>(c.sp.p), static_cast<Vec3f>(c.sp.n), static_cast<Vec3f>(c.sp.rv), 1};
    const DiskLight<double> dd{static_cast<Vec3d>(df.center), static_cast<Vec3d>(df.normal), double(df.radius)};
    const ShadingPoint<double> sd{static_cast<Vec3d>(sf.p), static_cast<Vec3d>(sf.n), static_cast<Vec3d>(sf.rv), 1};
    const double vd = diffuse(dd, sd);
    const float vf = shade_disk(df, sf, spec_options(SpecularMethod::kNone)).diffuse;
    CHECK(std::abs(double(vf) - vd) <= 1e-7 * vd + 1e-30);
  }
}

TEST_CASE("disk diffuse: stiff full circles against a 1D quadrature of the contour (eq. 9)") {
  // Where the 2D quadrature is slow or loses digits (P 1e-9 over the rim: 1e-7 after 450 s).
  // The kernel in long double agrees with the double kernel to 2e-16 on all of these.
  struct Case { const char* name; DiskLight<double> d; ShadingPoint<double> sp; };
  const DiskLight<double> unit{{0, 0, 0}, {0, 0, 1}, 1};
  const Vec3d down{0, 0, -1};
  const Case cases[] = {
      {"over the rim, height 1e-9", unit, {{1, 0, 1e-9}, down, down, 1}},
      {"1e-7 outside the rim, height 1e-9", unit, {{1 + 1e-7, 0, 1e-9}, normalize(Vec3d{-0.01, 0, -1}), down, 1}},
      {"1e-7 inside the rim, height 1e-9", unit, {{0, 1 - 1e-7, 1e-9}, down, down, 1}},
      {"near 1e-6, inside", unit, {{0.3, -0.5, 1e-6}, down, down, 1}},
      {"huge radius 1e6, off-centre", {{0, 0, 0}, {0, 0, 1}, 1e6}, {{5e5, 0, 1}, down, down, 1}},
      {"P 1e-6 above the plane beside the disk", unit, {{1.5, 0, 1e-6}, normalize(Vec3d{-1, 0, -0.1}), down, 1}},
  };
  for (const Case& c : cases) {
    const double ref = contour_quadrature(c.d, c.sp);
    const double v = diffuse(c.d, c.sp);
    INFO(c.name, ": value ", v, " 1D contour quadrature ", ref);
    CHECK(std::abs(v - ref) <= 1e-11 * std::abs(ref));  // the quadrature's own accuracy (rounding ~1e-16 x O(1) terms)
    const double vs_long = double((LD(v) - diffuse_long_double(c.d, c.sp)) / LD(v));
    CHECK(std::abs(vs_long) <= 2e-15);
    MESSAGE("disk full circle '", std::string(c.name), "': rel. err. vs 1D contour quadrature ", (v - ref) / ref,
            "; double vs long double kernel ", vs_long);
  }
}

TEST_CASE("disk diffuse: P in the plane, behind, two-sided, invalid") {
  const SpecularOptions none = spec_options(SpecularMethod::kNone);
  const DiskLight<double> d{{0, 0, 1}, {0, 0, -1}, 1};
  CHECK(shade_disk(d, {{0, 0, 2}, {0, 0, -1}, {0, 0, -1}, 1}, none).diffuse == 0);     // behind
  CHECK(shade_disk(d, {{2, 0, 1}, {-1, 0, 0}, {-1, 0, 0}, 1}, none).diffuse == 0);     // in the plane, outside
  CHECK(shade_disk(d, {{0.5, 0, 1}, {0, 0, -1}, {0, 0, -1}, 1}, none).diffuse == 0);   // in the plane, inside
  CHECK(shade_disk(d, {{0, 0, 0}, {0, 0, -1}, {0, 0, -1}, 1}, none).diffuse == 0);     // facing away
  DiskLight<double> two = d;
  two.two_sided = true;
  const double front = shade_disk(two, {{0.2, 0.1, 0.4}, normalize(Vec3d{0.1, 0, 1}), {0, 0, 1}, 1}, none).diffuse;
  const double back = shade_disk(two, {{0.2, 0.1, 1.6}, normalize(Vec3d{0.1, 0, -1}), {0, 0, -1}, 1}, none).diffuse;
  CHECK(front > 0);
  CHECK(back == doctest::Approx(front).epsilon(1e-14));  // mirror image through the disk's plane
  CHECK_THROWS_AS(shade_disk(DiskLight<double>{{0, 0, 1}, {0, 0, 0}, 1}, {{0, 0, 0}, {0, 0, 1}, {0, 0, 1}, 1}, none),
                  std::invalid_argument);
  CHECK_THROWS_AS(shade_disk(DiskLight<double>{{0, 0, 1}, {0, 0, -1}, 0}, {{0, 0, 0}, {0, 0, 1}, {0, 0, 1}, 1}, none),
                  std::invalid_argument);
}

TEST_CASE("disk specular: exact on the disk, and the polygon bracket, vs the quadrature") {
  struct Case { const char* name; DiskLight<double> d; ShadingPoint<double> sp; };
  const Case cases[] = {
      {"overhead m=10", {{0, 0, 1}, {0, 0, -1}, 1}, {{0.2, 0.1, 0}, {0, 0, 1}, normalize(Vec3d{0.1, 0, 1}), 10}},
      {"tilted m=100", {{1, 0, 3}, {-0.3, 0.1, -1}, 1}, {{0, 0, 0}, normalize(Vec3d{0.2, 0, 1}), normalize(Vec3d{0.3, 0, 1}), 100}},
      {"crossing the horizon m=5", {{0, 0, 1}, {0, 0, -1}, 1}, {{0.3, 0, 0.5}, {1, 0, 0}, normalize(Vec3d{1, 0, 1}), 5}},
  };
  SpecularOptions ex = spec_options(SpecularMethod::kExact);
  ex.exact_tolerance = 1e-9;
  for (const Case& c : cases) {
    const double ref = static_cast<double>(disk_reference(query(c.d, c.sp, true)));
    const DiskSpecularBracket<double> b = disk_specular_bracket(prepare_disk_light(c.d), c.sp, ex);
    INFO(c.name, " reference ", ref);
    CHECK(b.inscribed <= ref * (1 + 1e-8));
    CHECK(b.circumscribed >= ref * (1 - 1e-8));
    CHECK(std::abs(b.estimate - ref) <= 1e-5 * ref);
    MESSAGE("disk specular '", std::string(c.name), "': (2 out + in)/3 rel. err. ", (b.estimate - ref) / ref,
            ", bracket width ", (b.circumscribed - b.inscribed) / ref);
    const double exact = shade_disk(c.d, c.sp, ex).specular;  // on the disk itself (disk_specular_exact.h)
    MESSAGE("disk exact specular '", std::string(c.name), "': rel. err. ", (exact - ref) / ref);
    CHECK(std::abs(exact - ref) <= 1e-8 * ref);
    const Response<double> peak = shade_disk(c.d, c.sp, spec_options(SpecularMethod::kPeak));
    CHECK(all_finite(peak));
    CHECK(peak.specular > 0);
    CHECK(peak.specular <= 1);
  }
}

TEST_CASE("disk exact specular: random disks vs the quadrature, and closed-form limits") {
  const SpecularOptions ex = spec_options(SpecularMethod::kExact, 1e-9);
  Rng rng(777);
  double worst = 0;
  int cut = 0;
  for (int i = 0; i < 30; ++i) {
    const Vec3d p = rng.unit() * rng.uniform(0, 1);
    const Vec3d to_light = rng.unit();
    const DiskLight<double> d{p + to_light * rng.uniform(1, 3), normalize(-to_light + rng.unit() * 0.6), rng.uniform(0.2, 1.5)};
    const ShadingPoint<double> sp{p, normalize(to_light + rng.unit() * 0.7), normalize(to_light + rng.unit() * 0.4),
                                  std::round(rng.log_uniform(1, 1e3))};
    const double ref = static_cast<double>(disk_reference(query(d, sp, true)));
    const double v = shade_disk(d, sp, ex).specular;
    const ErrorMeasure e = measure(v, ref, 2 * M_PI / (sp.shininess + 1));  // floor: the whole lobe
    INFO("case ", i, " value ", v, " reference ", ref);
    CHECK(e.within(1e-7));
    worst = std::max(worst, e.effective(1e-7));
    const Vec3d nl = normalize(d.normal);
    if (std::abs(dot(sp.n, d.center - p)) < d.radius * length(sp.n - nl * dot(sp.n, nl))) ++cut;
  }
  MESSAGE("disk exact specular, 30 random disks (", cut, " cut by the horizon): max rel. err. ", worst);
  const double m = 100, lobe = 2 * M_PI / (m + 1);
  const DiskLight<double> unit{{0, 0, 0}, {0, 0, 1}, 1};
  const Vec3d down{0, 0, -1};
  // P 1e-6 above the inside of the disk, or 1 above a disk of radius 1e6: the whole lobe.
  const double near = shade_disk(unit, ShadingPoint<double>{{0.2, 0.1, 1e-6}, down, normalize(Vec3d{0.3, 0, -1}), m}, ex).specular;
  const double huge = shade_disk(DiskLight<double>{{0, 0, 0}, {0, 0, 1}, 1e6},
                                 ShadingPoint<double>{{5e5, 0, 1}, down, normalize(Vec3d{0.2, 0.1, -1}), m}, ex).specular;
  // P 1e-6 above the rim, Rv tangent to it: half the lobe (the rim's curvature is invisible at 1e-6).
  const double rim = shade_disk(unit, ShadingPoint<double>{{1, 0, 1e-6}, down, normalize(Vec3d{0, 0.3, -1}), m}, ex).specular;
  // On the axis, Rv along it: 2 pi (1 - cos^{m+1} Theta) / (m + 1), tan Theta = R / d (polar
  // coordinates about the axis); m = 1e4, far and tiny (Theta = 1e-3: the lobe is not flat on it).
  const DiskLight<double> far{{0, 0, 1e3}, {0, 0, -1}, 1};
  const double far_v = shade_disk(far, ShadingPoint<double>{{0, 0, 0}, {0, 0, 1}, {0, 0, 1}, 1e4}, ex).specular;
  const double cos_t = 1e3 / std::hypot(1e3, 1.0);
  const double far_expect = -2 * M_PI * std::expm1(10001 * std::log(cos_t)) / 10001;
  MESSAGE("disk exact specular limits: near 1e-6 ", (near - lobe) / lobe, ", huge 1e6 ", (huge - lobe) / lobe,
          ", over the rim ", (rim - lobe / 2) / (lobe / 2), ", on the axis far, m=1e4 ", (far_v - far_expect) / far_expect);
  CHECK(near == doctest::Approx(lobe).epsilon(1e-9));
  CHECK(huge == doctest::Approx(lobe).epsilon(1e-9));
  CHECK(rim == doctest::Approx(lobe / 2).epsilon(1e-5));
  CHECK(far_v == doctest::Approx(far_expect).epsilon(1e-9));
}
