// Area light diffuse (area_diffuse_contour.h) against an independent area quadrature
// (area_reference.h), on seeded random configurations and a named table of stiff cases.
#include <doctest/doctest.h>

#include <algorithm>
#include <cstdio>

#include "area_test_util.h"

using namespace vlit;
using namespace vlit::test;

namespace {

constexpr double kOrdinaryBar = 1e-10;
constexpr double kStiffBar = 1e-7;
constexpr double kFloatOrdinaryBar = 1e-5;
constexpr double kFloatStiffBar = 1e-3;

struct DiffuseCheck {
  double err_double = 0, err_float = 0, value = 0, ref = 0, abs_scaled = 0;
};

// Checks double against the reference and float against the double kernel on the float-rounded
// inputs (whose double result is itself checked against the reference when `float_ref` is set).
DiffuseCheck check_diffuse(const char* name, uint64_t seed, const AreaLight<double>& light,
                           const std::vector<std::vector<Vec3d>>& pieces, const ShadingPoint<double>& sp,
                           double bar, double float_bar) {
  DiffuseCheck c;
  const SpecularOptions none = spec_options(SpecularMethod::kNone);
  const Response<double> r = shade_area(light, sp, none);
  c.value = r.diffuse;
  c.ref = reference_diffuse(pieces, sp, light.two_sided);
  const ErrorMeasure e = measure(r.diffuse, c.ref, contour_scale(light.polygon, sp.p));
  c.err_double = e.effective(bar);
  c.abs_scaled = e.abs_scaled;
  INFO(name, " seed=", seed, " ", describe(light.polygon, sp));
  INFO("kernel=", r.diffuse, " reference=", c.ref, " rel.err=", e.rel, " abs.err/scale=", e.abs_scaled);
  CHECK(all_finite(r));
  CHECK(r.diffuse >= 0);
  CHECK(e.within(bar));
  // float: inputs rounded to float, compared with the double kernel on the same rounded inputs.
  const AreaLight<float> lf = to_float(light);
  const ShadingPoint<float> spf = to_float(sp);
  try {
    const Response<float> rf = shade_area(lf, spf, none);
    const Response<double> rd = shade_area(to_double(lf), to_double(spf), none);
    const ErrorMeasure ef = measure(rf.diffuse, rd.diffuse, contour_scale(to_double(lf).polygon, to_double(spf).p));
    c.err_float = ef.effective(float_bar);
    INFO("float kernel=", rf.diffuse, " double kernel on float inputs=", rd.diffuse, " rel.err=", ef.rel);
    CHECK(all_finite(rf));
    CHECK(ef.within(float_bar));
  } catch (const std::invalid_argument&) {
    // A polygon that is thin at float precision may not survive rounding to float: not a kernel case.
  }
  return c;
}

std::vector<std::vector<Vec3d>> one_piece(const std::vector<Vec3d>& p) { return {p}; }

ShadingPoint<double> point_up(Vec3d p, Vec3d n = {0, 0, 1}) { return {p, normalize(n), normalize(n), 1}; }

}  // namespace

TEST_CASE("area diffuse: random convex polygons vs area quadrature (double and float)") {
  double worst = 0, worst_float = 0;
  int cases = 0;
  for (uint64_t seed = 1; seed <= 120; ++seed) {
    Rng rng(seed);
    const double size = rng.log_uniform(1e-3, 1e3);
    const double ratio = rng.log_uniform(1e-2, 1e3);  // distance / size
    const Vec3d nl = rng.unit();
    const Vec3d center{rng.uniform(-1, 1) * size, rng.uniform(-1, 1) * size, rng.uniform(-1, 1) * size};
    const auto poly = random_convex_polygon(rng, center, nl, size, rng.log_uniform(0.1, 1), 8);
    Vec3d dir = rng.unit();
    if (dot(dir, nl) < 0.05) dir = normalize(dir + nl * (0.1 - dot(dir, nl)));
    const Vec3d p = center + dir * (size * ratio);
    Vec3d n = rng.unit();
    if (dot(n, center - p) < 0 && seed % 3 != 0) n = -n;  // most cases face the light; some cross
    const ShadingPoint<double> sp{p, n, n, 1};
    const DiffuseCheck c = check_diffuse("random", seed, light_of(poly), one_piece(poly), sp, kOrdinaryBar, kFloatOrdinaryBar);
    worst = std::max(worst, c.err_double);
    worst_float = std::max(worst_float, c.err_float);
    ++cases;
  }
  MESSAGE("area diffuse random: ", cases, " cases, max rel.err double = ", worst, ", float = ", worst_float);
}

TEST_CASE("area diffuse: stiff cases") {
  double worst = 0, worst_float = 0;
  auto run = [&](const char* name, const AreaLight<double>& l, const std::vector<std::vector<Vec3d>>& pieces,
                 const ShadingPoint<double>& sp) {
    const DiffuseCheck c = check_diffuse(name, 0, l, pieces, sp, kStiffBar, kFloatStiffBar);
    worst = std::max(worst, c.err_double);
    worst_float = std::max(worst_float, c.err_float);
    MESSAGE("area diffuse stiff '", std::string(name), "': kernel=", c.value, " reference=", c.ref, " rel.err=",
            std::abs(c.value - c.ref) / std::abs(c.ref), " abs.err/scale=", c.abs_scaled);
    return c;
  };
  SUBCASE("tiny: 1e-6 square at distance 1") {
    const auto p = square_down(1e-6, 1);
    run("tiny", light_of(p), one_piece(p), point_up({0.3, 0.2, 0}, {0.1, 0.2, 1}));
  }
  SUBCASE("distant: unit square at distance 1e9") {
    const auto p = square_down(0.5, 1e9, 3e8, -2e8);
    run("distant", light_of(p), one_piece(p), point_up({0, 0, 0}, {0.3, -0.2, 1}));
  }
  SUBCASE("distant and tiny: 1e-3 square at 1e4, stressing the small-light form") {
    const auto p = square_down(1e-3, 1e4, 1e3, 0);
    run("distant-tiny", light_of(p), one_piece(p), point_up({0, 0, 0}, {0.3, -0.2, 1}));
  }
  SUBCASE("thin: aspect 1e-6") {
    const std::vector<Vec3d> p{{-1, -1e-6, 2}, {-1, 1e-6, 2}, {1, 1e-6, 2}, {1, -1e-6, 2}};
    run("thin", light_of(p), one_piece(p), point_up({0.2, 0.1, 0}, {0, 0.3, 1}));
  }
  SUBCASE("huge: 1e6 square 1 above P") {
    const auto p = square_down(1e6, 1, 1e5, 0);
    run("huge", light_of(p), one_piece(p), point_up({0, 0, 0}, {0.2, 0, 1}));
  }
  SUBCASE("vertex in the light's plane, outside it: exactly 0") {
    const auto p = square_down(1, 1);
    const auto sp = point_up({3, 0, 1}, {-1, 0, 0});
    const auto r = shade_area(light_of(p), sp, spec_options(SpecularMethod::kExact));
    CHECK(r.diffuse == 0);
    CHECK(r.specular == 0);
    const auto r2 = shade_area(light_of(p, true), sp, spec_options(SpecularMethod::kExact));
    CHECK(r2.diffuse == 0);
  }
  SUBCASE("vertex on an edge of the light: exactly 0") {
    const auto p = square_down(1, 1);
    const auto r = shade_area(light_of(p), point_up({1, 0.3, 1}, {-1, 0, -1}), spec_options(SpecularMethod::kPeak));
    CHECK(all_finite(r));
    CHECK(r.diffuse == 0);
    CHECK(r.specular == 0);
  }
  SUBCASE("vertex 1e-9 off the plane, 1e-9 outside an edge") {
    const auto p = square_down(1, 1);
    run("near-edge", light_of(p), one_piece(p), point_up({1 + 1e-9, 0.3, 1 - 1e-9}, {-1, 0, 0.2}));
  }
  SUBCASE("vertex 1e-9 below the plane, over the middle: half of the hemisphere") {
    const auto p = square_down(1, 1);
    run("near-plane-inside", light_of(p), one_piece(p), point_up({0.1, 0.3, 1 - 1e-9}, {0, 0, 1}));
  }
  SUBCASE("crossing the horizon") {
    const auto p = square_down(1, 1);
    run("horizon", light_of(p), one_piece(p), point_up({0.2, 0, 0.5}, {1, 0.3, 0.1}));
  }
  SUBCASE("grazing: P 1e-6 below the light's plane, beside it") {
    const auto p = square_down(1, 1, 3, 0);
    run("grazing-plane", light_of(p), one_piece(p), point_up({0, 0, 1 - 1e-6}, {0, 0, 1}));
  }
  SUBCASE("grazing: the normal 1e-6 from the light's direction's horizon") {
    const auto p = square_down(1, 1);
    run("grazing-normal", light_of(p), one_piece(p), point_up({0, 0, 0}, {1, 0, 1e-6}));
  }
  SUBCASE("behind the emitter: exactly 0; two-sided: the mirror value") {
    const auto p = square_down(1, 1);
    const auto sp = point_up({0.1, 0.2, 2}, {0, 0, -1});
    CHECK(shade_area(light_of(p), sp, spec_options(SpecularMethod::kExact)).diffuse == 0);
    CHECK(shade_area(light_of(p), sp, spec_options(SpecularMethod::kExact)).specular == 0);
    run("behind-two-sided", light_of(p, true), one_piece(p), sp);
    const auto front = shade_area(light_of(p), point_up({0.1, 0.2, 0}, {0, 0, 1}), spec_options(SpecularMethod::kNone));
    const auto back = shade_area(light_of(p, true), sp, spec_options(SpecularMethod::kNone));
    CHECK(back.diffuse == doctest::Approx(front.diffuse).epsilon(1e-14));
  }
  SUBCASE("non-convex L-shape crossing the horizon") {
    // L in z = 1 emitting down; convex pieces for the reference.
    const std::vector<Vec3d> l{{0, 0, 1}, {0, 2, 1}, {1, 2, 1}, {1, 1, 1}, {2, 1, 1}, {2, 0, 1}};
    const std::vector<std::vector<Vec3d>> pieces{{{0, 0, 1}, {0, 2, 1}, {1, 2, 1}, {1, 0, 1}},
                                                 {{1, 0, 1}, {1, 1, 1}, {2, 1, 1}, {2, 0, 1}}};
    run("L-horizon", light_of(l), pieces, point_up({0.5, 0.5, 0.3}, {1, 1, 0.4}));
    run("L-above", light_of(l), pieces, point_up({1.5, 1.5, 0.2}, {0, 0, 1}));
  }
  SUBCASE("U-shape clipped into two pieces (Sutherland-Hodgman bridge edges)") {
    // U opening toward +y in z = 1; the horizon plane x-ish cuts both arms.
    const std::vector<Vec3d> u{{0, 0, 1}, {0, 3, 1}, {1, 3, 1}, {1, 1, 1}, {2, 1, 1}, {2, 3, 1}, {3, 3, 1}, {3, 0, 1}};
    const std::vector<std::vector<Vec3d>> pieces{{{0, 0, 1}, {0, 3, 1}, {1, 3, 1}, {1, 0, 1}},
                                                 {{1, 0, 1}, {1, 1, 1}, {2, 1, 1}, {2, 0, 1}},
                                                 {{2, 0, 1}, {2, 1, 1}, {2, 3, 1}, {3, 3, 1}, {3, 0, 1}}};
    // Horizon keeps y > 2: cuts both arms, the base is below.
    run("U-two-pieces", light_of(u), pieces, point_up({1.5, 2, 0.5}, {0, 1, 0}));
    run("U-tilted", light_of(u), pieces, point_up({1.5, 2, 0.5}, {0.2, 1, 0.3}));
  }
  SUBCASE("N-gon: 64 vertices") {
    std::vector<Vec3d> p;
    for (int k = 0; k < 64; ++k) {
      const double a = -2 * M_PI * k / 64;  // CW seen from above = CCW from below
      p.push_back({std::cos(a), std::sin(a), 1});
    }
    run("64-gon", light_of(p), one_piece(p), point_up({0.4, 0.1, 0.2}, {1, 0, 1}));
  }
}

TEST_CASE("area diffuse: properties") {
  const SpecularOptions none = spec_options(SpecularMethod::kNone);
  SUBCASE("small-light limit: a tiny light far away is a point light of intensity A cos(theta_l)") {
    const double s = 1e-3, d = 10;
    const Vec3d nl = normalize(Vec3d{0.3, 0.1, -1});
    Rng rng(7);
    const auto poly = random_convex_polygon(rng, {1, 2, d}, nl, s, 0.5, 6);
    const auto pl = prepare_area_light(light_of(poly));
    const auto sp = point_up({0, 0, 0}, {0.1, 0.2, 1});
    const Vec3d l = pl.center - sp.p;
    const double point = pl.area * dot(-nl, normalize(l)) * dot(sp.n, normalize(l)) / length_squared(l);
    const double area = shade_area(light_of(poly), sp, none).diffuse;
    CHECK(area == doctest::Approx(point).epsilon(1e-6));  // O((s/d)^2) = 1e-8 apart
  }
  SUBCASE("split into two polygons gives the sum; a square equals its two triangles") {
    const auto sq = square_down(1, 1);
    const std::vector<Vec3d> t1{sq[0], sq[1], sq[2]}, t2{sq[0], sq[2], sq[3]};
    for (const auto& sp : {point_up({0.2, 0.1, 0}, {0.1, 0, 1}), point_up({0.5, 0, 0.6}, {1, 0.2, 0.1})}) {
      const double whole = shade_area(light_of(sq), sp, none).diffuse;
      const double parts = shade_area(light_of(t1), sp, none).diffuse + shade_area(light_of(t2), sp, none).diffuse;
      CHECK(whole == doctest::Approx(parts).epsilon(1e-13));
    }
    // Pentagon split into a triangle and a quad.
    const std::vector<Vec3d> pent{{0, 0, 1}, {0, 2, 1}, {1, 3, 1}, {2, 2, 1}, {2, 0, 1}};
    const std::vector<Vec3d> a{pent[0], pent[1], pent[3], pent[4]}, b{pent[1], pent[2], pent[3]};
    const auto sp = point_up({0.3, 1, 0.4}, {0.5, 1, 0.2});
    CHECK(shade_area(light_of(pent), sp, none).diffuse ==
          doctest::Approx(shade_area(light_of(a), sp, none).diffuse + shade_area(light_of(b), sp, none).diffuse).epsilon(1e-13));
  }
  SUBCASE("reversing the winding turns a one-sided light off") {
    auto sq = square_down(1, 1);
    const auto sp = point_up({0.2, 0.1, 0}, {0, 0, 1});
    CHECK(shade_area(light_of(sq), sp, none).diffuse > 0);
    std::reverse(sq.begin(), sq.end());
    const auto r = shade_area(light_of(sq), sp, spec_options(SpecularMethod::kExact));
    CHECK(r.diffuse == 0);
    CHECK(r.specular == 0);
  }
  SUBCASE("moving the whole scene changes nothing") {
    const auto sq = square_down(1, 1);
    const auto sp = point_up({0.2, 0.1, 0}, {0.3, 0, 1});
    const double here = shade_area(light_of(sq), sp, none).diffuse;
    const Vec3d shift{1000, -500, 250};
    std::vector<Vec3d> moved;
    for (const auto& v : sq) moved.push_back(v + shift);
    ShadingPoint<double> sp2 = sp;
    sp2.p = sp.p + shift;
    CHECK(shade_area(light_of(moved), sp2, none).diffuse == doctest::Approx(here).epsilon(1e-12));
  }
  SUBCASE("invalid lights are rejected when built") {
    CHECK_THROWS_AS(prepare_area_light(light_of({{0, 0, 0}, {1, 0, 0}})), std::invalid_argument);
    CHECK_THROWS_AS(prepare_area_light(light_of({{0, 0, 0}, {1, 0, 0}, {2, 0, 0}})), std::invalid_argument);
    CHECK_THROWS_AS(prepare_area_light(light_of({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0.5}})), std::invalid_argument);
    std::vector<Vec3d> many;
    for (int k = 0; k < kMaxAreaVertices + 1; ++k) many.push_back({std::cos(k * 0.01), std::sin(k * 0.01), 0});
    CHECK_THROWS_AS(prepare_area_light(light_of(many)), std::invalid_argument);
  }
}
