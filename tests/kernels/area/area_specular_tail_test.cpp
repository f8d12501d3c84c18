// The tail closed form (area_specular_tail.h) against the independent area quadrature
// (area_reference.h, Boost.Math Gauss-Kronrod over the polygon) and against the adaptive contour
// form (area_specular_exact.h) in the same test; its refusals; and the dispatch that uses it.
#include <doctest/doctest.h>

#include <algorithm>
#include <limits>

#include "area_specular_tail.h"
#include "area_test_util.h"

using namespace vlit;
using namespace vlit::test;

namespace {

// The adaptive form's absolute target at tolerance 1e-13 (area_specular_exact.h): values below it
// are astronomically small tails that it does not resolve.
double adaptive_floor(double m) { return 1e-13 * std::numeric_limits<double>::epsilon() * 2 * M_PI / (m + 1); }

// a and b agree to `rel`, or both lie within 1e3 adaptive floors of each other.
bool agree(double a, double b, double rel, double m) {
  return std::abs(a - b) <= rel * std::max(std::abs(a), std::abs(b)) || std::abs(a - b) <= 1e3 * adaptive_floor(m);
}

struct TailAndAdaptive {
  AreaSpecularClosed<double> tail{0, 0, false};  // refused unless evaluate() reaches the form
  double adaptive = 0;
  bool misses = false;  // Rv misses the visible light (after the lobe clip)
  std::vector<std::vector<Vec3d>> pieces;  // the polygon fanned from the lobe's peak on it
};

// The convex polygon as triangles fanned from the point x inside it or on its boundary.
std::vector<std::vector<Vec3d>> fan_from(const std::vector<Vec3d>& poly, const Vec3d& x) {
  std::vector<std::vector<Vec3d>> pieces;
  for (std::size_t i = 0; i < poly.size(); ++i) {
    const Vec3d& a = poly[i];
    const Vec3d& b = poly[(i + 1) % poly.size()];
    if (length(cross(a - x, b - x)) > 1e-14 * length_squared(b - a)) pieces.push_back({x, a, b});
  }
  return pieces;
}

// relative_only: the adaptive form without its absolute target (bounded_tails = false), which
// resolves the tiny tails this form gives to full relative accuracy, at a cost.
TailAndAdaptive evaluate(const std::vector<Vec3d>& poly, const ShadingPoint<double>& sp, double tol,
                         bool relative_only = false) {
  const PreparedAreaLight<double> pl = prepare_area_light(light_of(poly));
  const AreaView<double> view = make_area_view(pl, sp.p);
  TailAndAdaptive r;
  if (!view.lit) return r;
  ClipPolygon<double> visible, lobe;
  clip_to_horizon(pl, view, sp.n, visible);
  if (visible.count < 3) return r;
  const Vec3d rv = normalize(sp.rv);
  clip_halfspace(visible.d.data(), visible.count, rv, dot(rv, view.D), lobe);
  r.misses = lobe.count < 3 || !ray_hits_polygon(lobe, view, rv);
  // For the area quadrature (area_reference.h), the light fanned from the point where the lobe
  // peaks on it, so that the tail's peak sits on a vertex of its mesh (only where to cut: the
  // value is the quadrature's own).
  r.pieces = {poly};
  const AreaPeak<double> peak = area_specular_peak_direction(lobe, view, rv);
  const double toward = -dot(view.normal, peak.direction);
  if (peak.visible && toward > 0) r.pieces = fan_from(poly, sp.p + peak.direction * (view.height / toward));
  r.tail = area_specular_tail(visible, view, sp.rv, sp.shininess);
  r.adaptive = area_specular_exact(visible, view, sp.rv, sp.shininess, tol, !relative_only);
  return r;
}

struct Tally {
  int misses = 0, accepted = 0, compared = 0;  // compared: accepted and above the adaptive form's floor
  double worst_ref = 0, worst_adaptive = 0, worst_ratio = 0;
};

void run_random(uint64_t first, uint64_t last, double m_lo, double m_hi, bool integer, int with_reference, Tally& t,
                bool relative_only = false) {
  for (uint64_t seed = first; seed <= last; ++seed) {
    // Rv aimed up to 4 sizes from the light's centre: it misses the light in most cases.
    const RandomAreaCase c = random_area_case(seed, m_lo, m_hi, 4, integer);
    const TailAndAdaptive b = evaluate(c.poly, c.sp, 1e-13, relative_only);
    CHECK(std::isfinite(b.tail.value));
    if (b.tail.accepted) CHECK(b.misses);  // never where Rv hits the light
    if (!b.misses) continue;
    ++t.misses;
    if (!b.tail.accepted) continue;
    ++t.accepted;
    const double vs_adaptive = std::abs(b.tail.value - b.adaptive) / std::max(b.adaptive, 1e-300);
    INFO("seed=", seed, " ", describe(c.poly, c.sp));
    INFO("tail=", b.tail.value, " adaptive=", b.adaptive, " condition=", b.tail.condition);
    const double floor = relative_only ? 0.0 : adaptive_floor(c.sp.shininess);
    if (b.adaptive > floor * 1e6 && b.adaptive > 1e-250) {
      CHECK(vs_adaptive <= 1e-11);
      ++t.compared;
      t.worst_adaptive = std::max(t.worst_adaptive, vs_adaptive);
    } else {
      CHECK(std::abs(b.tail.value - b.adaptive) <= std::max(floor * 1e3, 1e-240));
    }
    // The area quadrature is slower: the first seeds only; and below m = 1.5 it is itself up to
    // 1e-6 off (c^m's branch along the lobe clip's line, as area_specular_closed_test.cpp's real-m
    // case says), so there the adaptive form is the comparison.
    if (static_cast<int>(seed - first) < with_reference && c.sp.shininess >= 1.5) {
      const double ref = reference_specular(b.pieces, c.sp, false, 1e-13L);
      const double err = std::abs(b.tail.value - ref) / std::max(ref, 1e-300);
      INFO("reference=", ref, " rel.err=", err);
      if (ref > floor * 1e6) {
        CHECK(err <= 1e-12);
        t.worst_ref = std::max(t.worst_ref, err);
        if (b.tail.condition > 0) t.worst_ratio = std::max(t.worst_ratio, err / b.tail.condition);
      } else {  // below what an output can hold: the quadrature's own relative accuracy is not 1e-12 there
        CHECK(std::abs(b.tail.value - ref) <= floor * 1e3);
      }
    }
  }
}

// One MESSAGE line for a random set of 3000 cases checked against the quadrature too.
void report(const std::string& set, const Tally& t) {
  MESSAGE("tail closed form, ", set, ": Rv misses the light in ", t.misses, " of 3000, accepted ", t.accepted,
          "; max rel.err vs reference (first 60 seeds) ", t.worst_ref, ", vs adaptive (tol 1e-13) ",
          t.worst_adaptive, ", max error / condition ", t.worst_ratio);
}

}  // namespace

TEST_CASE("tail closed form: random configurations, integer m, vs the area quadrature and the adaptive form") {
  Tally t;
  run_random(1, 3000, 1, 1e3, true, 60, t);
  report("integer m in [1, 1e3]", t);
  CHECK(t.accepted >= t.misses / 2);
}

TEST_CASE("tail closed form: random configurations, real m, vs the area quadrature and the adaptive form") {
  Tally t;
  run_random(10001, 13000, 0.5, 1e3, false, 60, t);
  report("real m in [0.5, 1e3]", t);
  CHECK(t.accepted >= t.misses / 8);
}

TEST_CASE("tail closed form: random configurations with m in [1e3, 1e4]") {
  // Against the adaptive form only (the area quadrature does not resolve lobes this narrow), with
  // relative tolerance only: at these m the accepted tails are below its default absolute target.
  Tally t;
  run_random(20001, 20400, 1e3, 1e4, false, 0, t, true);
  MESSAGE("tail closed form, real m in [1e3, 1e4]: Rv misses the light in ", t.misses, " of 400, accepted ", t.accepted,
          ", of which ", t.compared, " above 1e-250: max rel. diff vs adaptive (relative tolerance only) ",
          t.worst_adaptive);
  CHECK(t.accepted > 0);
}

TEST_CASE("tail closed form: Rv beside a square, where the forward closed form cancels") {
  // Rv 0.3 rad outside a unit square at distance 1 (area_specular_closed_test.cpp refuses the
  // forward form there from m = 100 on). The edge facing Rv holds the lobe's peak: the upward
  // recurrence, integer m only; at m = 100 and 300 its m / 2 steps on two edges and the others'
  // downward runs exceed kAreaTailMaxSteps and the form refuses (the adaptive form takes them).
  const Vec3d up{0, 0, 1};
  const auto poly = square_down(0.5, 1);
  for (double m : {1.0, 2.0, 30.0, 100.0, 300.0, 1000.0, 2.5, 77.7}) {
    const ShadingPoint<double> sp{{0, 0, 0}, up, normalize(Vec3d{std::tan(std::atan(0.5) + 0.3), 0, 1}), m};
    const TailAndAdaptive b = evaluate(poly, sp, 1e-13);
    INFO("m=", m, " tail=", b.tail.value, " adaptive=", b.adaptive, " condition=", b.tail.condition);
    REQUIRE(b.misses);
    if (m <= 30 && m == std::floor(m)) CHECK(b.tail.accepted);
    if (m != std::floor(m)) CHECK_FALSE(b.tail.accepted);
    if (!b.tail.accepted) continue;
    CHECK(agree(b.tail.value, b.adaptive, 1e-12, m));
    CHECK(agree(b.tail.value, reference_specular({poly}, sp, false, 1e-15L), 1e-12, m));
  }
}

TEST_CASE("tail closed form: Rv beyond a corner, every edge's maximum at an end, real m") {
  // Rv well past the corner of a square of side 0.5 at distance 1: on every edge c peaks at an
  // end, the downward recurrence runs alone (at most 100 steps per edge), and real m is accepted.
  const Vec3d up{0, 0, 1};
  const auto poly = square_down(0.25, 1);
  for (double m : {0.5, 1.0, 2.5, 77.7, 1000.0, 1e4}) {
    const ShadingPoint<double> sp{{0, 0, 0}, up, normalize(Vec3d{3, 2.5, 1}), m};
    const TailAndAdaptive b = evaluate(poly, sp, 1e-13);
    INFO("m=", m, " tail=", b.tail.value, " adaptive=", b.adaptive, " condition=", b.tail.condition);
    REQUIRE(b.misses);
    CHECK(b.tail.accepted);
    CHECK(agree(b.tail.value, b.adaptive, 1e-12, m));
    if (m >= 1.5 && m <= 100) CHECK(agree(b.tail.value, reference_specular({poly}, sp, false, 1e-15L), 1e-12, m));
  }
}

TEST_CASE("tail closed form: refused where Rv hits the light or grazes its boundary") {
  const Vec3d up{0, 0, 1};
  const auto poly = square_down(0.5, 1);
  // Rv through the light: the "1" parts do not vanish.
  CHECK_FALSE(evaluate(poly, {{0, 0, 0}, up, normalize(Vec3d{0.2, 0.1, 1}), 30}, 1e-9).tail.accepted);
  // Rv 1e-6 (in tan) outside the edge x = 0.5: the winding would be decided by rounding.
  CHECK_FALSE(evaluate(poly, {{0, 0, 0}, up, normalize(Vec3d{0.5 + 1e-6, 0.1, 1}), 30}, 1e-9).tail.accepted);
  // ... and 1e-6 inside it.
  CHECK_FALSE(evaluate(poly, {{0, 0, 0}, up, normalize(Vec3d{0.5 - 1e-6, 0.1, 1}), 30}, 1e-9).tail.accepted);
  // Rv next to a corner, outside.
  CHECK_FALSE(evaluate(poly, {{0, 0, 0}, up, normalize(Vec3d{0.5 + 1e-9, 0.5 + 1e-9, 1}), 30}, 1e-9).tail.accepted);
}

TEST_CASE("tail closed form: --specular exact takes it, and agrees with the adaptive form") {
  // Through shade_area (area_light.h's dispatch), Rv beyond the corner where the forward closed
  // form is refused: the value is the tail form's (m <= kAreaTailDispatchMaxShininess), and above
  // that m the adaptive form's. At m = 100 the value (2.7e-30) lies below the adaptive form's
  // absolute target at tolerance 1e-9 (tol eps 2 pi / (m + 1) = 1.4e-26), and the dispatch gives 0
  // at once, as the adaptive form would.
  const Vec3d up{0, 0, 1};
  const auto poly = square_down(0.25, 1);
  const PreparedAreaLight<double> pl = prepare_area_light(light_of(poly));
  ClipPolygon<double> visible;
  bool seen_refused_closed = false;
  for (double m : {10.0, 30.0, 77.7, 100.0, 1000.0}) {
    const ShadingPoint<double> sp{{0, 0, 0}, up, normalize(Vec3d{3, 2.5, 1}), m};
    const double e = shade_area(light_of(poly), sp, spec_options(SpecularMethod::kExact, 1e-9)).specular;
    const TailAndAdaptive b = evaluate(poly, sp, 1e-13);
    const AreaView<double> view = make_area_view(pl, sp.p);
    clip_to_horizon(pl, view, sp.n, visible);
    INFO("m=", m, " exact=", e, " tail=", b.tail.value, " adaptive=", b.adaptive);
    const bool integer = m == std::floor(m) && m <= kAreaClosedDispatchMaxShininess;
    const bool closed = integer && area_specular_closed(visible, view, sp.rv, int(m)).accepted;
    seen_refused_closed |= integer && !closed;
    REQUIRE(b.tail.accepted);
    const double floor = 1e-9 * std::numeric_limits<double>::epsilon() * 2 * M_PI / (m + 1);
    if (!closed && m <= kAreaTailDispatchMaxShininess) CHECK(e == (b.tail.value < floor ? 0.0 : b.tail.value));
    if (m == 100) CHECK(e == 0);
    if (m > kAreaTailDispatchMaxShininess) CHECK(e == area_specular_exact(visible, view, sp.rv, m, 1e-9));
    CHECK(agree(e, b.adaptive, 1e-9, m));
  }
  CHECK(seen_refused_closed);
}
