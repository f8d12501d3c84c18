// Area light specular: the peak direction (area_specular_peak.h) against a dense search refined by
// the paper's own 1D formula, the neighbourhood's properties, and the exact lobe integral
// (area_specular_exact.h) against the independent area quadrature (area_reference.h).
#include <doctest/doctest.h>

#include <algorithm>
#include <limits>

#include "area_test_util.h"

using namespace vlit;
using namespace vlit::test;

namespace {

constexpr double kPeakAngleBar = 1e-9;
constexpr double kExactBar = 1e-7;        // kernel tolerance 1e-9 on its (pessimistic) 4x4 estimate
constexpr double kFloatBar = 4e-6;  // float kernel vs double kernel on the same inputs: 3.7e-7 measured

// Reference peak: smallest angle between Rv and a direction toward the horizon-clipped (convex)
// light, by (a) the ray/plane hit inside the clipped polygon, (b) on each clipped edge, 400
// samples plus the sidebar's stationary point t = (BD - 2CE) / (BE - 2AD) (Picott, linear-light
// specular sidebar) in long double, plus the endpoints.
struct RefPeak { LD angle; V3 dir; };

RefPeak reference_peak(const std::vector<Vec3d>& poly_d, const ShadingPoint<double>& sp) {
  const V3 P = static_cast<V3>(sp.p), N = static_cast<V3>(sp.n), S = static_cast<V3>(sp.rv);
  std::vector<V3> poly;
  for (const auto& v : poly_d) poly.push_back(static_cast<V3>(v));
  const V3 o = poly[0];
  V3 newell{};
  for (size_t i = 0; i < poly.size(); ++i) newell += cross(poly[i] - o, poly[(i + 1) % poly.size()] - o);
  const V3 nl = newell / length(newell);
  V3 e1 = (poly[1] - o) / length(poly[1] - o);
  const V3 e2 = cross(nl, e1);
  std::vector<RefPoint2> p2;
  for (const auto& v : poly) p2.push_back({dot(e1, v - o), dot(e2, v - o)});
  p2 = clip_convex_2d(p2, dot(N, e1), dot(N, e2), dot(N, o - P));
  RefPeak best{LD(10), {}};
  if (p2.size() < 3) return best;
  auto to3 = [&](LD x, LD y) { return o + e1 * x + e2 * y; };
  // (a) inside
  const LD toward = -dot(nl, S);
  if (toward > 0) {
    const V3 hit = P + S * (dot(nl, P - o) / toward);
    const LD hx = dot(e1, hit - o), hy = dot(e2, hit - o);
    bool inside = true;
    for (size_t i = 0; i < p2.size(); ++i) {
      const auto& a = p2[i];
      const auto& b = p2[(i + 1) % p2.size()];
      if ((b.x - a.x) * (hy - a.y) - (b.y - a.y) * (hx - a.x) < 0) inside = false;
    }
    if (inside) return {LD(0), S};
  }
  auto consider = [&](const V3& l) {
    const LD ang = angle_between(S, l);
    if (ang < best.angle) best = {ang, l / length(l)};
  };
  for (size_t i = 0; i < p2.size(); ++i) {
    const V3 q0 = to3(p2[i].x, p2[i].y), q1 = to3(p2[(i + 1) % p2.size()].x, p2[(i + 1) % p2.size()].y);
    const V3 L0 = q0 - P, Ld = q1 - q0;
    for (int k = 0; k <= 400; ++k) consider(L0 + Ld * (LD(k) / 400));
    const LD A = dot(Ld, Ld), B = 2 * dot(L0, Ld), C = dot(L0, L0), D = dot(S, L0), E = dot(S, Ld);
    const LD den = B * E - 2 * A * D;
    if (den != 0) {
      const LD t = (B * D - 2 * C * E) / den;
      if (t > 0 && t < 1) consider(L0 + Ld * t);
    }
  }
  return best;
}

// A random convex polygon about the origin (size 1e-2..1e2) and a point P in front of it, its
// normal roughly toward the polygon: the draws of the random exact-specular tests, in their order.
struct RandomPolygonCase {
  std::vector<Vec3d> poly;
  Vec3d p, n;
  double size;
};
RandomPolygonCase random_polygon_case(Rng& rng) {
  RandomPolygonCase c;
  c.size = rng.log_uniform(1e-2, 1e2);
  const Vec3d nl = rng.unit();
  c.poly = random_convex_polygon(rng, {0, 0, 0}, nl, c.size, rng.log_uniform(0.2, 1), 6);
  Vec3d dir = rng.unit();
  if (dot(dir, nl) < 0.1) dir = normalize(dir + nl * (0.2 - dot(dir, nl)));
  c.p = dir * (c.size * rng.log_uniform(0.3, 30));
  c.n = normalize(-c.p + rng.unit() * (c.size * rng.uniform(0, 2)));
  return c;
}

}  // namespace

TEST_CASE("area specular peak: random configurations vs dense search + sidebar refinement") {
  double worst_angle = 0, worst_dir = 0;
  int inside = 0, boundary = 0;
  for (uint64_t seed = 1; seed <= 300; ++seed) {
    Rng rng(seed);
    const double size = rng.log_uniform(1e-2, 1e2);
    const Vec3d nl = rng.unit();
    const Vec3d center{0, 0, 0};
    const auto poly = random_convex_polygon(rng, center, nl, size, rng.log_uniform(0.1, 1), 8);
    Vec3d dir = rng.unit();
    if (dot(dir, nl) < 0.05) dir = normalize(dir + nl * (0.1 - dot(dir, nl)));
    const Vec3d p = center + dir * (size * rng.log_uniform(0.1, 100));
    Vec3d n = normalize(center - p + rng.unit() * (size * rng.uniform(0, 3)));
    // Rv aimed near the light (sometimes inside it), sometimes anywhere.
    Vec3d rv = seed % 4 == 0 ? rng.unit() : normalize(center + rng.unit() * (size * rng.uniform(0, 2)) - p);
    const ShadingPoint<double> sp{p, n, rv, rng.log_uniform(1, 1e4)};
    const auto pl = prepare_area_light(light_of(poly));
    const auto view = make_area_view(pl, sp.p);
    ClipPolygon<double> vis;
    clip_to_horizon(pl, view, sp.n, vis);
    const AreaPeak<double> k = area_specular_peak_direction(vis, view, sp.rv);
    const RefPeak r = reference_peak(poly, sp);
    INFO("seed=", seed, " ", describe(poly, sp));
    INFO("kernel angle=", k.angle, " reference angle=", static_cast<double>(r.angle));
    if (!k.visible) {
      CHECK(r.angle == LD(10));
      continue;
    }
    REQUIRE(r.angle < LD(10));
    const double da = std::abs(k.angle - static_cast<double>(r.angle));
    CHECK(da <= kPeakAngleBar);
    worst_angle = std::max(worst_angle, da);
    // The direction: exact within the bar (the dense search's argmin is itself refined by the
    // sidebar's closed form, so it is exact unless two edges tie).
    const double dd = angle_between(k.direction, static_cast<Vec3d>(r.dir));
    CHECK(dd <= 1e-7);  // reference direction from 400 samples + closed form; ties excluded below
    worst_dir = std::max(worst_dir, dd);
    CHECK(std::abs(angle_between(k.direction, sp.rv) - k.angle) <= 1e-12);
    (k.angle == 0 ? inside : boundary)++;
  }
  MESSAGE("area peak: ", inside, " inside + ", boundary, " boundary cases, max |angle - ref| = ", worst_angle,
          " rad, max direction difference = ", worst_dir, " rad");
}

TEST_CASE("area specular peak: stiff cases") {
  const SpecularOptions peak = spec_options(SpecularMethod::kPeak);
  const auto sq = square_down(1, 1);
  auto shade = [&](const std::vector<Vec3d>& poly, Vec3d p, Vec3d n, Vec3d rv, double m) {
    const ShadingPoint<double> sp{p, normalize(n), normalize(rv), m};
    const Response<double> r = shade_area(light_of(poly), sp, peak);
    CHECK(all_finite(r));
    return r.specular;
  };
  SUBCASE("Rv inside: the lobe's maximum, 1, for every m") {
    for (double m : {0.0, 1.0, 10.0, 100.0, 1e4}) CHECK(shade(sq, {0, 0, 0}, {0, 0, 1}, {0.3, 0.2, 1}, m) == 1.0);
  }
  SUBCASE("Rv toward a vertex exactly") {
    CHECK(shade(sq, {0, 0, 0}, {0, 0, 1}, {1, 1, 1}, 1e4) == doctest::Approx(1.0).epsilon(1e-12));
  }
  SUBCASE("Rv parallel to the light's plane, and grazing it") {
    const double v = shade(sq, {0, 0, 0}, {0, 0, 1}, {1, 0, 0}, 10);
    // Closest direction: (1, 0, 1) on the edge x = 1, at 45 degrees.
    CHECK(v == doctest::Approx(std::pow(std::sqrt(0.5), 10)).epsilon(1e-12));
    const double g = shade(sq, {0, 0, 0}, {0, 0, 1}, {1, 0, 1e-9}, 10);
    CHECK(g >= v);
  }
  SUBCASE("light crossing the horizon: the peak is taken on the visible part") {
    // N = +x: only x >= 0 of the square is visible; Rv toward (-1, 0, 1) (hidden part).
    const double v = shade(sq, {0, 0, 0}, {1, 0, 0.0}, {-1, 0, 1}, 1);
    // Closest visible direction: (0, 0, 1) at 45 degrees.
    CHECK(v == doctest::Approx(std::cos(M_PI / 4)).epsilon(1e-12));
  }
  SUBCASE("behind the emitter and below the horizon: 0") {
    CHECK(shade(sq, {0, 0, 2}, {0, 0, -1}, {0, 0, -1}, 1) == 0);
    CHECK(shade(sq, {0, 0, 0}, {0, 0, -1}, {0, 0, 1}, 1) == 0);
  }
  SUBCASE("shininess 1 .. 1e4 near the peak: lobe from the angle, no cancellation") {
    for (double m : {1.0, 10.0, 100.0, 1e3, 1e4}) {
      const double a = 1e-3;
      const double v = shade(sq, {0, 0, 0}, {0, 0, 1}, {std::sin(a) + 0, 0, std::cos(a) - 0}, m);
      CHECK(v == 1.0);  // inside
      const double outside = shade(square_down(1, 1, 3, 0), {0, 0, 0}, {0, 0, 1}, {std::sin(a), 0, std::cos(a)}, m);
      const double alpha = std::atan2(2.0, 1.0) - a;
      CHECK(outside == doctest::Approx(std::pow(std::cos(alpha), m)).epsilon(1e-10));
    }
  }
  SUBCASE("N-gon and non-convex: the peak lies on the notch's edge") {
    const std::vector<Vec3d> l{{0, 0, 1}, {0, 2, 1}, {1, 2, 1}, {1, 1, 1}, {2, 1, 1}, {2, 0, 1}};
    // Rv toward (1.5, 1.5, 1) (the notch): closest light direction is on the notch's boundary.
    const double v = shade(l, {0.2, 0.2, 0}, {0, 0, 1}, Vec3d{1.5, 1.5, 1} - Vec3d{0.2, 0.2, 0}, 1e4);
    CHECK(v > 0);
    CHECK(v < 1);
  }
}

TEST_CASE("area specular neighbourhood: properties") {
  const auto sq = square_down(1, 1);
  const ShadingPoint<double> sp{{0.1, 0, 0}, {0, 0, 1}, normalize(Vec3d{0.2, 0.1, 1}), 50};
  const double peak = shade_area(light_of(sq), sp, spec_options(SpecularMethod::kPeak)).specular;
  SUBCASE("K = 0 is the peak; a light covering the neighbourhood gives the peak") {
    CHECK(shade_area(light_of(sq), sp, spec_options(SpecularMethod::kNeighborhood, 1e-9, 0)).specular == peak);
    CHECK(shade_area(light_of(sq), sp, spec_options(SpecularMethod::kNeighborhood, 1e-9, 8)).specular == peak);
  }
  SUBCASE("bounded by the peak, finite for m up to 1e4, the spread shrinks with m") {
    for (double m : {0.0, 1.0, 10.0, 1e3, 1e4}) {
      ShadingPoint<double> s2 = sp;
      s2.shininess = m;
      s2.rv = normalize(Vec3d{2, 0.3, 1});  // outside the light: peak on the boundary
      const double p = shade_area(light_of(sq), s2, spec_options(SpecularMethod::kPeak)).specular;
      const Response<double> r = shade_area(light_of(sq), s2, spec_options(SpecularMethod::kNeighborhood, 1e-9, 6));
      CHECK(all_finite(r));
      CHECK(r.specular <= p);
      CHECK(r.specular >= p / 7);
    }
    CHECK(neighborhood_half_angle(1e4) < neighborhood_half_angle(10.0));
    CHECK(neighborhood_half_angle(10.0) <= neighborhood_half_angle(1.0));
  }
}

TEST_CASE("area specular exact: random configurations vs area quadrature") {
  double worst = 0, worst_float = 0;
  int cases = 0;
  for (uint64_t seed = 1; seed <= 40; ++seed) {
    Rng rng(seed);
    // Named fields, not a structured binding: INFO below captures them in a lambda (clang 14
    // does not capture structured bindings).
    const RandomPolygonCase c = random_polygon_case(rng);
    const std::vector<Vec3d>& poly = c.poly;
    const Vec3d &p = c.p, &n = c.n;
    const Vec3d rv = normalize(rng.unit() * (c.size * rng.uniform(0, 1.5)) - p);
    const ShadingPoint<double> sp{p, n, rv, std::round(rng.log_uniform(1, 1e3))};
    const Response<double> k = shade_area(light_of(poly), sp, spec_options(SpecularMethod::kExact, 1e-9));
    const double ref = reference_specular({poly}, sp);
    const ErrorMeasure e = measure(k.specular, ref, contour_scale(poly, sp.p));
    INFO("seed=", seed, " ", describe(poly, sp));
    INFO("kernel=", k.specular, " reference=", ref, " rel.err=", e.rel);
    CHECK(all_finite(k));
    CHECK(e.within(kExactBar));
    worst = std::max(worst, e.effective(kExactBar));
    const Response<float> kf = shade_area(to_float(light_of(poly)), to_float(sp), spec_options(SpecularMethod::kExact, 1e-9));
    const Response<double> kd = shade_area(to_double(to_float(light_of(poly))), to_double(to_float(sp)), spec_options(SpecularMethod::kExact, 1e-9));
    const ErrorMeasure ef = measure(kf.specular, kd.specular, contour_scale(poly, sp.p));
    // Seed 37 (m = 916) differed by 1.5e-5 with the former 2D cubature at -O2 (GCC 12.2 dropped
    // the double->float rounding of rv.z in to_double(to_float(sp)); docs/area-lights.md); the
    // bar, 10x the worst case measured now, would catch that again.
    INFO("float kernel=", kf.specular, " double kernel on float inputs=", kd.specular);
    CHECK(ef.within(kFloatBar));
    worst_float = std::max(worst_float, ef.effective(kFloatBar));
    ++cases;
  }
  MESSAGE("area exact specular random: ", cases, " cases, max rel.err double = ", worst, ", float = ", worst_float);
}

TEST_CASE("area specular exact: stiff cases") {
  auto run = [&](const char* name, const std::vector<Vec3d>& poly, const ShadingPoint<double>& sp) {
    const Response<double> k = shade_area(light_of(poly), sp, spec_options(SpecularMethod::kExact, 1e-9));
    const double ref = reference_specular({poly}, sp, false, 1e-10L);  // 1000x below the bar
    const ErrorMeasure e = measure(k.specular, ref, contour_scale(poly, sp.p));
    INFO(name, " ", describe(poly, sp));
    INFO("kernel=", k.specular, " reference=", ref, " rel.err=", e.rel);
    CHECK(all_finite(k));
    CHECK(e.within(kExactBar));
    MESSAGE("area exact specular stiff '", std::string(name), "': kernel=", k.specular, " reference=", ref,
            " rel.err=", e.rel);
  };
  const Vec3d up{0, 0, 1};
  SUBCASE("shininess 1 .. 1e4, Rv inside the light") {
    for (double m : {1.0, 10.0, 100.0, 1e3, 1e4}) run("m-sweep", square_down(1, 1), {{0.1, 0, 0}, up, normalize(Vec3d{0.2, 0.1, 1}), m});
  }
  SUBCASE("shininess 1e4, Rv just outside the light") {
    // The area reference does not resolve a lobe of width 0.01 rad lying along an edge (a one-off
    // measurement of an earlier session found it 3.0e-7 off at every tolerance; this test does
    // not rerun it), so the check is against an independent 1D form: the
    // lobe (width ~0.01 rad) sees only the edge x = 1 (the other edges are >= 40 degrees away,
    // where cos^1e4 < 1e-300), i.e. the half-space k.w <= 0, k = (1, 0, -1)/sqrt(2). In polar
    // coordinates (theta, phi) about Rv that half-space is phi in a window of width
    // 2 acos(min(1, kappa cot theta)), kappa = (k.Rv) / |k - (k.Rv) Rv|, so
    //   Is = ∫_theta0^{pi/2} cos^m(theta) sin(theta) 2 acos(min(1, kappa cot theta)) dtheta.
    const ShadingPoint<double> sp{{0, 0, 0}, up, normalize(Vec3d{1.01, 0.2, 1}), 1e4};
    const V3 rv = static_cast<V3>(sp.rv), k = normalize(V3{1, 0, -1});
    const LD kr = dot(k, rv), kappa = kr / length(k - rv * kr), theta0 = std::atan(kappa);
    auto f = [&](LD t) {
      return std::exp(LD(1e4) * std::log(std::cos(t))) * std::sin(t) * 2 * std::acos(std::min(LD(1), kappa / std::tan(t)));
    };
    LD expect = 0;
    LD lo = theta0;
    for (LD w = LD(1e-7); lo < LD(0.3); w *= 2) {  // graded: acos' square-root edge at theta0, peak ~0.01
      const LD hi = std::min(theta0 + w, LD(0.3));
      expect += boost::math::quadrature::gauss_kronrod<LD, 61>::integrate(f, lo, hi, 5, LD(1e-17));
      lo = hi;
    }
    const double k_value = shade_area(light_of(square_down(1, 1)), sp, spec_options(SpecularMethod::kExact, 1e-9)).specular;
    const double rel = double((LD(k_value) - expect) / expect);
    MESSAGE("area exact specular stiff 'm1e4-outside': kernel=", k_value, " half-space lobe form=", double(expect),
            " rel.err=", rel);
    CHECK(std::abs(rel) <= kExactBar);
  }
  SUBCASE("tiny") {
    run("tiny", square_down(1e-6, 1), {{0, 0, 0}, up, normalize(Vec3d{0, 0, 1}), 100});
  }
  // "distant" (light 1e4 away) is not in this table: the reference quadrature does not finish in
  // reasonable time there (docs/area-lights.md, open items); the small-solid-angle regime is
  // covered by "tiny" and by the random cases (distance up to 30x the size).
  SUBCASE("thin aspect 1e-6") {
    const std::vector<Vec3d> p{{-1, -1e-6, 2}, {-1, 1e-6, 2}, {1, 1e-6, 2}, {1, -1e-6, 2}};
    run("thin", p, {{0.2, 0.1, 0}, up, normalize(Vec3d{0, -0.05, 1}), 10});
  }
  SUBCASE("huge light close to P") {
    run("huge", square_down(1e3, 1), {{0, 0, 0}, up, normalize(Vec3d{0.5, 0, 1}), 100});
    // P 1e-6 above the light (over its inside, and over an edge): the lobe over the plane is the
    // whole lobe 2 pi / (m + 1), or exactly half of it over the edge (Rv.x = 0: symmetric).
    const double m = 100, full = 2 * M_PI / (m + 1);
    const auto near = [&](Vec3d p, Vec3d rv) {
      return shade_area(light_of(square_down(0.5, 0)), {p, {0, 0, 1}, normalize(rv), m},
                        spec_options(SpecularMethod::kExact, 1e-9)).specular;
    };
    const double inside = near({0.1, 0.2, -1e-6}, {0.3, 0, 1}), over_edge = near({0.5, 0.1, -1e-6}, {0, 0.3, 1});
    MESSAGE("area exact specular stiff 'near 1e-6': inside rel.err=", (inside - full) / full,
            ", over an edge rel.err=", (over_edge - full / 2) / (full / 2));
    CHECK(inside == doctest::Approx(full).epsilon(1e-9));
    CHECK(over_edge == doctest::Approx(full / 2).epsilon(1e-9));
  }
  SUBCASE("crossing the horizon, and grazing") {
    run("horizon", square_down(1, 1), {{0, 0, 0.5}, normalize(Vec3d{1, 0.2, 0.1}), normalize(Vec3d{1, 0, 0.5}), 20});
    run("grazing", square_down(1, 1, 3, 0), {{0, 0, 1 - 1e-3}, up, normalize(Vec3d{1, 0, 0.01}), 50});
  }
  SUBCASE("behind: 0; m = 0 is the solid angle") {
    CHECK(shade_area(light_of(square_down(1, 1)), {{0, 0, 2}, {0, 0, -1}, {0, 0, -1}, 1}, spec_options(SpecularMethod::kExact)).specular == 0);
    run("m0-solid-angle", square_down(1, 1), {{0, 0, 0}, up, up, 0});
    // Solid angle of a 2x2 square at distance 1 seen from below its center:
    // 4 asin(ab / sqrt((a^2 + 4d^2)(b^2 + 4d^2))) = 4 asin(1/2) = 2 pi / 3.
    const double k = shade_area(light_of(square_down(1, 1)), {{0, 0, 0}, up, up, 0}, spec_options(SpecularMethod::kExact)).specular;
    CHECK(k == doctest::Approx(4 * std::asin(0.5)).epsilon(1e-9));
  }
  SUBCASE("non-convex U clipped into two pieces") {
    const std::vector<Vec3d> u{{0, 0, 1}, {0, 3, 1}, {1, 3, 1}, {1, 1, 1}, {2, 1, 1}, {2, 3, 1}, {3, 3, 1}, {3, 0, 1}};
    const std::vector<std::vector<Vec3d>> pieces{{{0, 0, 1}, {0, 3, 1}, {1, 3, 1}, {1, 0, 1}},
                                                 {{1, 0, 1}, {1, 1, 1}, {2, 1, 1}, {2, 0, 1}},
                                                 {{2, 0, 1}, {2, 1, 1}, {2, 3, 1}, {3, 3, 1}, {3, 0, 1}}};
    const ShadingPoint<double> sp{{1.5, 2, 0.5}, {0, 1, 0}, normalize(Vec3d{0.3, 1, 0.4}), 5};
    const double k = shade_area(light_of(u), sp, spec_options(SpecularMethod::kExact, 1e-10)).specular;
    const double ref = reference_specular(pieces, sp, false, 1e-10L);
    INFO("kernel=", k, " reference=", ref);
    CHECK(std::abs(k - ref) <= kExactBar * ref);
  }
}

// Rv off the light by more than a lobe width: the tail form, whose pieces are evaluated only where
// their bound (area_specular_exact.h) says they can matter, with the kernel's absolute target
// tol eps 2 pi / (m + 1). Against every piece evaluated at the relative tolerance alone (the
// same integrand) and, up to m = 1e3, against the area quadrature. Rv leaves the square past its
// edge x = 1 (k lobe widths beyond it) or past its corner (1, 1); at k = 20 the values (~1e-90)
// are far below the absolute target.
namespace {

// P at the origin under `poly` (the unit square at z = 1 of the tail tests), Rv at the angle beta
// from the normal toward the edge x = 1 or the corner (1, 1); the view and the horizon-clipped light.
struct SquareLobeCase {
  ShadingPoint<double> sp;
  AreaView<double> view;
  ClipPolygon<double> visible;
};

SquareLobeCase square_lobe_case(const std::vector<Vec3d>& poly, double beta, bool corner, double m) {
  const Vec3d up{0, 0, 1};
  const Vec3d toward = corner ? normalize(Vec3d{1, 1, 0}) : normalize(Vec3d{1, 0.05, 0});
  SquareLobeCase c;
  c.sp = {{0, 0, 0}, up, normalize(toward * std::sin(beta) + up * std::cos(beta)), m};
  const PreparedAreaLight<double> light = prepare_area_light(light_of(poly));
  c.view = make_area_view(light, c.sp.p);
  clip_to_horizon(light, c.view, c.sp.n, c.visible);
  return c;
}

}  // namespace

TEST_CASE("area specular exact: lobe tails, deferred pieces vs every piece evaluated and vs the area quadrature") {
  const Vec3d up{0, 0, 1};
  const auto poly = square_down(1, 1);
  // The documented absolute error target for a relative tolerance tol.
  const auto floor_of = [](double tol, double m) { return tol * std::numeric_limits<double>::epsilon() * 2 * M_PI / (m + 1); };
  double worst_eager = 0, worst_ref = 0;
  int nonzero = 0;
  for (double m : {10.0, 100.0, 1e3, 1e4}) {
    const double lobe = 1 / std::sqrt(m + 1);
    for (const double k : {1.5, 3.0, 8.0, 20.0}) {
      for (const bool corner : {false, true}) {
        const double beta = (corner ? std::atan(std::sqrt(2.0)) : M_PI / 4) + k * lobe;
        if (beta > 1.5) continue;  // Rv near or past P's horizon: P sees no lobe there
        const auto [sp, view, visible] = square_lobe_case(poly, beta, corner, m);
        const double deferred = area_specular_exact(visible, view, sp.rv, m, 1e-9);
        const double eager = area_specular_exact(visible, view, sp.rv, m, 1e-9, false);
        INFO("m=", m, " k=", k, std::string(corner ? " corner" : " edge"), ": deferred=", deferred, " eager=", eager);
        REQUIRE(eager > 0);
        CHECK(deferred >= 0);
        CHECK(std::abs(deferred - eager) <= std::max(2e-9 * eager, floor_of(1e-9, m)));
        if (eager < floor_of(1e-9, m)) continue;
        const double rel = std::abs(deferred - eager) / eager;
        worst_eager = std::max(worst_eager, rel);
        // At a loose tolerance the bounds decide which pieces are left out. Each is charged 1000
        // times its bound (kDeferredCharge), so together they add at most tol / 1000: within
        // tol / 100 (a bound that is too small fails here).
        for (const double tol : {1e-2, 1e-4, 1e-6}) {
          const double loose = area_specular_exact(visible, view, sp.rv, m, tol);
          INFO("tolerance ", tol, ": ", loose);
          CHECK(std::abs(loose - eager) <= std::max(tol / 100 * eager, floor_of(tol, m)));
        }
        ++nonzero;
        if (m <= 1e3) {
          const double ref = reference_specular({poly}, sp, false, 1e-11L);
          const double rel_ref = std::abs(deferred - ref) / ref;
          INFO("reference=", ref);
          CHECK(rel_ref <= 1e-9);  // the stiff-case bar of the exact specular (3.2e-13 measured)
          worst_ref = std::max(worst_ref, rel_ref);
        }
      }
    }
  }
  // Random convex polygons with Rv off them (the accuracy report's kind of case): the bounded form
  // keeps the accuracy of evaluating every piece, 1e-11 at tol 1e-9 (with each bound charged once,
  // not 1000 times, this fails).
  double worst_random = 0;  // largest difference over the allowed one
  for (uint64_t seed = 1; seed <= 200; ++seed) {
    Rng rng(seed);
    const auto [random_poly, p, n, size] = random_polygon_case(rng);
    const Vec3d rv = normalize(rng.unit() * (size * rng.uniform(1.2, 3)) - p);
    const double m = std::round(rng.log_uniform(1, 1e3));
    const PreparedAreaLight<double> light = prepare_area_light(light_of(random_poly));
    const AreaView<double> view = make_area_view(light, p);
    if (!view.lit) continue;
    ClipPolygon<double> visible;
    clip_to_horizon(light, view, n, visible);
    const double eager = area_specular_exact(visible, view, rv, m, 1e-9, false);
    if (!(eager > 0)) continue;
    const double diff = std::abs(area_specular_exact(visible, view, rv, m, 1e-9) - eager);
    INFO("seed ", seed, " m ", m, ": eager ", eager, " rel.diff ", diff / eager);
    CHECK(diff <= std::max(1e-11 * eager, floor_of(1e-9, m)));
    worst_random = std::max(worst_random, diff / std::max(1e-11 * eager, floor_of(1e-9, m)));
  }
  MESSAGE("area exact specular tails, random polygons: deferred vs eager, largest difference / allowed ", worst_random);
  // Far enough off that the lobe underflows everywhere on the light: 0 without evaluating.
  const ShadingPoint<double> far{{0, 0, 0}, up, normalize(Vec3d{1, 0, 0.2}), 1e4};
  CHECK(shade_area(light_of(poly), far, spec_options(SpecularMethod::kExact, 1e-9)).specular == 0);
  MESSAGE("area exact specular tails: ", nonzero, " cases above the absolute target, deferred vs eager max rel.diff ", worst_eager,
          ", vs the area quadrature (m <= 1e3) ", worst_ref);
}

TEST_CASE("area specular exact: Rv inside the light, the lobe outside it integrated as a correction") {
  // With Rv inside the light and every edge's great circle more than a lobe width away, the
  // adaptive form takes the whole lobe's part 2 pi k / (m + 1) exactly and integrates only the lobe
  // outside the light, as deferred tail pieces (area_specular_exact.h). Against the full form with
  // every piece evaluated (bounded_tails = false, which keeps the full contour form inside), at
  // loose tolerances, and against the area quadrature.
  const auto poly = square_down(1, 1);
  double worst_eager = 0, worst_ref = 0;
  int cases = 0;
  for (double m : {300.0, 1e3, 3e3, 1e4}) {
    const double lobe = 1 / std::sqrt(m + 1);
    for (const double k : {1.5, 3.0, 8.0}) {
      for (const bool corner : {false, true}) {
        // Rv k lobe widths inside the edge x = 1 (or the corner (1, 1)), seen from P = 0 at z = 1
        const double inside = (corner ? std::atan(std::sqrt(2.0)) : M_PI / 4) - k * lobe;
        const auto [sp, view, visible] = square_lobe_case(poly, inside, corner, m);
        const double deferred = area_specular_exact(visible, view, sp.rv, m, 1e-9);
        const double eager = area_specular_exact(visible, view, sp.rv, m, 1e-13, false);
        INFO("m=", m, " k=", k, std::string(corner ? " corner" : " edge"), ": deferred=", deferred, " eager=", eager);
        REQUIRE(eager > 0);
        const double rel = std::abs(deferred - eager) / eager;
        CHECK(rel <= 2e-9);
        worst_eager = std::max(worst_eager, rel);
        for (const double tol : {1e-2, 1e-4, 1e-6}) {
          const double loose = area_specular_exact(visible, view, sp.rv, m, tol);
          INFO("tolerance ", tol, ": ", loose);
          CHECK(std::abs(loose - eager) <= tol / 100 * eager);  // as for the tails: deferred pieces charged 1000x
        }
        ++cases;
        if (m <= 1e3) {
          const double ref = reference_specular({poly}, sp, false, 1e-11L);
          const double rel_ref = std::abs(deferred - ref) / ref;
          INFO("reference=", ref);
          CHECK(rel_ref <= 1e-9);
          worst_ref = std::max(worst_ref, rel_ref);
        }
      }
    }
  }
  // Random convex polygons with Rv inside (aimed within 0.3 sizes of the centre), m log-uniform
  // in [30, 1e4], integer and real alternately.
  double worst_random = 0;
  int random_cases = 0;
  for (uint64_t seed = 501; seed <= 800; ++seed) {
    const RandomAreaCase c = random_area_case(seed, 30, 1e4, 0.3, seed % 2 == 0);
    const PreparedAreaLight<double> light = prepare_area_light(light_of(c.poly));
    const AreaView<double> view = make_area_view(light, c.sp.p);
    if (!view.lit) continue;
    ClipPolygon<double> visible;
    clip_to_horizon(light, view, c.sp.n, visible);
    if (visible.count < 3 || !ray_hits_polygon(visible, view, normalize(c.sp.rv))) continue;
    const double m = c.sp.shininess;
    const double eager = area_specular_exact(visible, view, c.sp.rv, m, 1e-13, false);
    const double deferred = area_specular_exact(visible, view, c.sp.rv, m, 1e-9);
    INFO("seed ", seed, " ", describe(c.poly, c.sp), ": eager ", eager, " deferred ", deferred);
    REQUIRE(eager > 0);
    const double rel = std::abs(deferred - eager) / eager;
    CHECK(rel <= 2e-9);
    worst_random = std::max(worst_random, rel);
    ++random_cases;
  }
  MESSAGE("area exact specular, Rv inside: ", cases, " named cases, deferred vs eager max rel.diff ", worst_eager,
          ", vs the area quadrature (m <= 1e3) ", worst_ref, "; ", random_cases, " random cases, max rel.diff ", worst_random);
  CHECK(random_cases >= 100);
}

// m -> 0 continuity: the lobe at m = 0 is the limit m -> 0+, [Rv.w > 0] (core/robust_math.h), so the
// exact specular at m = 0 is the solid angle of the part of the light in front of the lobe's
// half-space, and m = 1e-12 gives the same to ~1e-11. Against the area quadrature (which clips to
// the half-space Rv.(x - P) >= 0 itself) in front of, behind and straddling that half-space.
TEST_CASE("area specular exact: m -> 0 continuity at m = 0, 1e-12, 1, 1e4") {
  const Vec3d up{0, 0, 1};
  struct Case { const char* where; std::vector<Vec3d> poly; Vec3d rv; };
  const std::vector<Case> cases{
      {"front", square_down(1, 1), normalize(Vec3d{0.2, 0.1, 1})},           // Rv.w > 0 on all of it
      {"behind", square_down(1, 1, -3, 0), normalize(Vec3d{1, 0, 0.05})},     // Rv.w < 0 on all of it
      {"straddling", square_down(1, 1), normalize(Vec3d{1, 0, 0.2})}};        // Rv.w = 0 at x = -0.2
  for (const Case& c : cases) {
    for (double m : {0.0, 1e-12, 1.0, 1e4}) {
      const ShadingPoint<double> sp{{0, 0, 0}, up, c.rv, m};
      const double k = shade_area(light_of(c.poly), sp, spec_options(SpecularMethod::kExact, 1e-11)).specular;
      const double ref = reference_specular({c.poly}, sp, false, 1e-13L);
      const ErrorMeasure e = measure(k, ref, contour_scale(c.poly, sp.p));
      INFO(std::string(c.where), " m=", m, ": kernel=", k, " reference=", ref, " rel.err=", e.rel);
      CHECK(std::isfinite(k));
      if (ref == 0) CHECK(k == 0); else CHECK(e.rel <= 1e-9);
      MESSAGE("area exact specular m->0 '", std::string(c.where), "' m=", m, ": kernel=", k, " reference=", ref, " rel.err=", e.rel);
    }
  }
  // The front case at m = 0 is the solid angle of the whole 2x2 square at distance 1: 2 pi / 3.
  const double front0 = shade_area(light_of(cases[0].poly), {{0, 0, 0}, up, cases[0].rv, 0},
                                   spec_options(SpecularMethod::kExact, 1e-11)).specular;
  CHECK(front0 == doctest::Approx(4 * std::asin(0.5)).epsilon(1e-10));
  // Straddling: m = 0 and m = 1e-12 agree; behind: 0 at m = 0 (formerly the whole solid angle).
  const auto at = [&](const Case& c, double m) {
    return shade_area(light_of(c.poly), {{0, 0, 0}, up, c.rv, m}, spec_options(SpecularMethod::kExact, 1e-11)).specular;
  };
  CHECK(std::abs(at(cases[2], 0) - at(cases[2], 1e-12)) <= 1e-10 * at(cases[2], 0));
  CHECK(at(cases[1], 0) == 0);
  // The peak at m = 0: 1 if any of the light is in front of the half-space, else 0.
  CHECK(shade_area(light_of(cases[1].poly), {{0, 0, 0}, up, cases[1].rv, 0}, spec_options(SpecularMethod::kPeak)).specular == 0);
  CHECK(shade_area(light_of(cases[2].poly), {{0, 0, 0}, up, cases[2].rv, 0}, spec_options(SpecularMethod::kPeak)).specular == 1);
}
