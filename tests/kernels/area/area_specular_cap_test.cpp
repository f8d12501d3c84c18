// The narrow lobe's cap (area_specular_cap.h) against the independent area quadrature
// (area_reference.h, Boost.Math Gauss-Kronrod over the polygon) and against the adaptive contour
// form (area_specular_exact.h) in the same test; its refusals beside an edge, beside the horizon
// and off the light; and the dispatch that uses it.
#include <doctest/doctest.h>

#include <algorithm>

#include "area_light.h"
#include "area_test_util.h"

using namespace vlit;
using namespace vlit::test;

namespace {

// The cap form beside the adaptive form (area_test_util.h).
FormAndAdaptive evaluate(const std::vector<Vec3d>& poly, const ShadingPoint<double>& sp, bool compare_refused = true) {
  return form_and_adaptive(
      poly, sp, [](const auto& visible, const auto& view, const auto& rv, double m) { return area_specular_cap(visible, view, rv, m); },
      compare_refused);
}

double full_lobe(double m) { return 2 * M_PI / (m + 1); }

// Where a narrow lobe can lie inside the light: P at 0.2..2 sizes from it, well above its plane.
constexpr AreaCaseRanges kNear{0.2, 2, 0.3, 1.5};

}  // namespace

TEST_CASE("cap form: random configurations, m in [200, 1e4], vs the area quadrature and the adaptive form") {
  const uint64_t kSeeds = 3000;
  const int kReferenced = 20;
  int accepted = 0, referenced = 0;
  double worst_adaptive = 0, worst_ref = 0, worst_ratio = 0;
  for (uint64_t seed = 1; seed <= kSeeds; ++seed) {
    // Integer and real m alternately.
    const RandomAreaCase c = random_area_case(seed, 200, 1e4, 0.5, seed % 2 == 0, kNear);
    const FormAndAdaptive b = evaluate(c.poly, c.sp, false);
    if (!b.lit) continue;
    CHECK(std::isfinite(b.form.value));
    if (!b.form.accepted) continue;
    ++accepted;
    INFO("seed=", seed, " ", describe(c.poly, c.sp));
    INFO("cap=", b.form.value, " adaptive=", b.adaptive, " bound=", b.form.condition);
    CHECK(b.form.value == full_lobe(c.sp.shininess));
    // The cap's value is never below Is, and above it by at most the bound (plus the adaptive
    // form's own 1e-13).
    const double vs_adaptive = (b.form.value - b.adaptive) / b.adaptive;
    CHECK(vs_adaptive >= -1e-13);
    CHECK(vs_adaptive <= b.form.condition + 1e-13);
    CHECK(vs_adaptive <= kAreaClosedBound);
    worst_adaptive = std::max(worst_adaptive, std::abs(vs_adaptive));
    // The area quadrature resolves lobes up to m ~ 1e3 in reasonable time (it splits its polar
    // mesh at Rv's hit point itself); above that the adaptive form is the comparison.
    if (referenced < kReferenced && c.sp.shininess <= 1000) {
      ++referenced;
      const double ref = reference_specular({c.poly}, c.sp, false, 1e-13L);
      const double err = (b.form.value - ref) / ref;
      INFO("reference=", ref, " rel.err=", err);
      CHECK(std::abs(err) <= std::max(b.form.condition, 0.0) + 1e-12);
      CHECK(std::abs(err) <= kAreaClosedBound);
      worst_ref = std::max(worst_ref, std::abs(err));
      if (b.form.condition > 1e-13) worst_ratio = std::max(worst_ratio, std::abs(err) / b.form.condition);
    }
  }
  MESSAGE("cap form: ", accepted, " of ", kSeeds, " accepted; max rel. difference ", worst_adaptive,
          " from the adaptive form at tol 1e-13; ", referenced, " against the area quadrature: max ", worst_ref,
          ", error / bound <= ", worst_ratio);
  CHECK(accepted >= 150);
  CHECK(referenced == kReferenced);
}

TEST_CASE("cap form: named cases, accepted well inside, refused beside an edge, the horizon or off the light") {
  const Vec3d up{0, 0, 1};
  const double m = 1e4;  // the cap needs about 4.1 degrees from every edge
  // A square of half-side 0.25 at height 1: its edges 14 degrees from Rv = up.
  {
    const FormAndAdaptive b = evaluate(square_down(0.25, 1), {{0, 0, 0}, up, up, m});
    REQUIRE(b.form.accepted);
    CHECK(b.form.value == full_lobe(m));
    CHECK(std::abs(b.form.value - b.adaptive) <= 1e-13 * b.adaptive);
  }
  // Rv 2 degrees from an edge (x = 0.25): refused; the lobe really reaches past the edge.
  {
    const Vec3d rv = normalize(Vec3d{std::tan(std::atan(0.25) - 2 * M_PI / 180), 0, 1});
    const FormAndAdaptive b = evaluate(square_down(0.25, 1), {{0, 0, 0}, up, rv, m});
    CHECK_FALSE(b.form.accepted);
    CHECK(full_lobe(m) - b.adaptive > 1e-6 * full_lobe(m));
  }
  // Rv 10 degrees off the light: refused.
  const Vec3d off = normalize(Vec3d{std::tan(std::atan(0.25) + 10 * M_PI / 180), 0, 1});
  CHECK_FALSE(evaluate(square_down(0.25, 1), {{0, 0, 0}, up, off, m}).form.accepted);
  // The horizon 3 degrees from Rv (N tilted toward +x; the light, half-side 2, reaches 63 degrees
  // from Rv): refused, and the lobe really reaches below the horizon; 6 degrees: accepted.
  for (const double degrees : {3.0, 6.0}) {
    const double t = degrees * M_PI / 180;
    const FormAndAdaptive b = evaluate(square_down(2, 1), {{0, 0, 0}, Vec3d{std::cos(t), 0, std::sin(t)}, up, m});
    INFO("horizon ", degrees, " degrees from Rv: adaptive ", b.adaptive, " bound ", b.form.condition);
    if (degrees < 4) {
      CHECK_FALSE(b.form.accepted);
      CHECK(full_lobe(m) - b.adaptive > 1e-8 * full_lobe(m));  // the half-space beyond 5.2 lobe widths: ~8e-8
    } else {
      CHECK(b.form.accepted);
      CHECK(std::abs(b.form.value - b.adaptive) <= kAreaClosedBound * b.adaptive);
    }
  }
  // A pentagram (a self-overlapping light) winds twice about its centre: refused there, where the
  // contour forms count the centre twice.
  {
    std::vector<Vec3d> star;
    for (int k = 0; k < 5; ++k) {
      const double a = 2 * M_PI * (2 * k) / 5;
      star.push_back({0.5 * std::cos(a), -0.5 * std::sin(a), 1});  // clockwise from above: emits down
    }
    const FormAndAdaptive b = evaluate(star, {{0, 0, 0}, up, up, m});
    INFO("pentagram: adaptive ", b.adaptive, " = ", b.adaptive / full_lobe(m), " full lobes");
    CHECK_FALSE(b.form.accepted);
    CHECK(std::abs(b.adaptive - 2 * full_lobe(m)) <= 1e-12 * b.adaptive);
  }
  // m = 0 and m = 100: never (the cap would need the whole hemisphere, or 41 degrees).
  CHECK_FALSE(evaluate(square_down(0.25, 1), {{0, 0, 0}, up, up, 0}).form.accepted);
  CHECK_FALSE(evaluate(square_down(0.25, 1), {{0, 0, 0}, up, up, 100}).form.accepted);
}

TEST_CASE("cap form: --specular exact takes it above kAreaCapDispatchMinShininess, real and integer m") {
  const Vec3d up{0, 0, 1};
  const auto poly = square_down(0.5, 1);  // edges 27 degrees from Rv (the cap needs 19 at m = 500)
  for (const double m : {500.0, 1000.0, 2345.6, 1e4}) {
    const ShadingPoint<double> sp{{0, 0, 0}, up, normalize(Vec3d{0.02, -0.03, 1}), m};
    const double e = shade_area(light_of(poly), sp, spec_options(SpecularMethod::kExact, 1e-9)).specular;
    const FormAndAdaptive b = evaluate(poly, sp);
    INFO("m=", m, " exact=", e, " adaptive=", b.adaptive);
    REQUIRE(b.form.accepted);
    CHECK(e == full_lobe(m));
    CHECK(std::abs(e - b.adaptive) <= kAreaClosedBound * b.adaptive);
  }
}
