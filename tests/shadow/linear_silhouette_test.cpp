// The silhouette visibility of linear lights (src/shadow/linear_silhouette.h) against every
// occluder triangle's hidden interval (linear_visibility.h), which the other shadow tests hold to
// shadow rays and to exact symmetric answers: the visible intervals themselves and the shaded
// values, on random soups, refined closed spheres, boxes in random orientations, a bumpy surface
// shadowing its own vertices and one plate triangulated three ways. Each case also checks that the
// silhouette path answered (not its fallback), so a broken fast path cannot hide behind the
// reference, and the spheres check that its work follows the silhouette, not the triangles.
#include <doctest/doctest.h>

#include <cmath>
#include <random>
#include <string>

#include "shadow/linear_silhouette.h"
#include "shadow/linear_visibility.h"
#include "shadow_test_util.h"

using namespace vlit;
using namespace vlit::test;

namespace {

struct Agreement {
  double interval = 0;               // largest difference of the visible length, in t
  double diffuse = 0, specular = 0;  // largest difference / unshadowed value
  long asked = 0, decided = 0, shadowed = 0, cases = 0;
};

double visible_length(const std::vector<std::pair<double, double>>& visible) {
  double sum = 0;
  for (const auto& [a, b] : visible) sum += b - a;
  return sum;
}

// The visible set from both methods at P (as the symmetric difference's length), and the shaded
// values with exact specular.
void compare(const PreparedLight<double>& prepared, const ShadingPoint<double>& sp, const OccluderBvh& bvh,
             Agreement& out) {
  const LinearLight<double>& light = std::get<LinearLight<double>>(prepared.kernel);
  LinearSilhouetteScratch silhouette;
  LinearShadowScratch intervals;
  const LinearSilhouetteVisibility fast = visible_linear_by_silhouettes(light, sp.p, bvh, silhouette);
  const bool open_by_intervals = visible_linear_intervals(light, sp.p, bvh, intervals) == LinearVisibility::kUnoccluded;
  std::vector<std::pair<double, double>> reference = intervals.visible;
  if (open_by_intervals) reference.assign(1, {0.0, 1.0});
  ++out.asked;
  if (fast != LinearSilhouetteVisibility::kUndecided) {
    ++out.decided;
    std::vector<std::pair<double, double>> mine = silhouette.visible;
    if (fast == LinearSilhouetteVisibility::kUnoccluded) mine.assign(1, {0.0, 1.0});
    // |A xor B| = |A| + |B| - 2 |A and B|, the intersection from the two sorted lists.
    double both = 0;
    for (const auto& [a, b] : mine)
      for (const auto& [c, d] : reference) both += std::max(0.0, std::min(b, d) - std::max(a, c));
    out.interval = std::max(out.interval, visible_length(mine) + visible_length(reference) - 2 * both);
  }
  ShadeOptions fast_options = options_with(SpecularMethod::kExact), slow = fast_options;
  slow.linear_shadows = LinearShadowMethod::kTriangleIntervals;
  const Response<double> a = shade_shadowed(prepared, sp, fast_options, bvh), b = shade_shadowed(prepared, sp, slow, bvh);
  const Response<double> open = shade(prepared, sp, fast_options);
  record_agreement(a, b, open, out.diffuse, out.specular);
  out.shadowed += visible_length(reference) < 1 - 1e-9;
  ++out.cases;
}

void report(const std::string& what, const Agreement& agree) {
  MESSAGE(what << ": " << agree.shadowed << " of " << agree.cases << " shadowed; decided " << agree.decided << " of "
               << agree.asked << "; largest difference visible length " << agree.interval << ", diffuse "
               << agree.diffuse << ", specular " << agree.specular);
}

}  // namespace

TEST_CASE("linear silhouettes = triangle intervals: random soups between a tube and a floor") {
  const PreparedLight<double> tube = prepare_light<double>(linear_source({-1.2, -0.3, 2}, {1.1, 0.4, 2.1}, 2));
  std::mt19937_64 rng(2107);
  std::uniform_real_distribution<double> u(-1.5, 1.5);
  Agreement agree;
  for (int trial = 0; trial < 60; ++trial) {
    std::vector<Tri> tris;
    add_random_triangles(tris, rng, 5 + static_cast<int>(rng() % 40));
    const OccluderBvh bvh = make_bvh(tris);
    for (int k = 0; k < 12; ++k) {
      INFO("trial " << trial << ", point " << k);
      compare(tube, make_shading_point(Vec3d{u(rng), u(rng), 0}, Vec3d{0, 0, 1}, Vec3d{0.3, -0.2, 3}, 20.0), bvh,
              agree);
    }
  }
  report("soups", agree);
  CHECK(agree.shadowed > agree.cases / 4);
  CHECK(agree.interval <= 1e-12);
  CHECK(agree.diffuse <= 1e-9);
  CHECK(agree.specular <= 1e-7);
  CHECK(agree.decided >= 0.95 * agree.asked);
}

TEST_CASE("linear silhouettes = triangle intervals: refined closed spheres (work follows the silhouette) and boxes") {
  const PreparedLight<double> tube = prepare_light<double>(linear_source({-1.5, 0.2, 3}, {1.5, -0.1, 3}, 2));
  std::mt19937_64 rng(77);
  std::uniform_real_distribution<double> u(-1.2, 1.2);
  for (int levels = 0; levels <= 5; ++levels) {
    const std::vector<Tri> sphere = icosphere({0.1, -0.05, 1.4}, 0.55, levels);
    const OccluderBvh bvh = make_bvh(sphere);
    Agreement agree;
    const LinearLight<double>& light = std::get<LinearLight<double>>(tube.kernel);
    LinearSilhouetteScratch silhouette;
    LinearShadowScratch intervals;
    long hidden_intervals = 0;
    for (int k = 0; k < 24; ++k) {
      const ShadingPoint<double> sp =
          make_shading_point(Vec3d{u(rng), 0.4 * u(rng), 0}, Vec3d{0, 0, 1}, Vec3d{0, 0, 4}, 8.0);
      compare(tube, sp, bvh, agree);
      visible_linear_by_silhouettes(light, sp.p, bvh, silhouette);
      visible_linear_intervals(light, sp.p, bvh, intervals);
      hidden_intervals += static_cast<long>(intervals.hidden.size());
    }
    report(std::to_string(sphere.size()) + "-triangle sphere", agree);
    MESSAGE("  steps " << silhouette.silhouette_steps << " vs triangle intervals " << hidden_intervals);
    CHECK(agree.shadowed > 4);
    CHECK(agree.interval <= 1e-12);
    CHECK(agree.diffuse <= 1e-9);
    CHECK(agree.specular <= 1e-7);
    CHECK(agree.decided == agree.asked);
    // A convex closed surface's silhouette crosses the plane of P and the tube twice: at most two
    // steps per point whatever the triangles, where every triangle crossing that plane gives an
    // interval.
    CHECK(silhouette.silhouette_steps <= 2 * 24);
    if (levels >= 4) CHECK(hidden_intervals > 10 * silhouette.silhouette_steps);
  }
  Agreement boxes;
  for (int trial = 0; trial < 20; ++trial) {
    const OccluderBvh bvh = make_bvh(turned_box(rng));
    for (int k = 0; k < 8; ++k)
      compare(tube, make_shading_point(Vec3d{u(rng), 0.4 * u(rng), 0}, Vec3d{0, 0, 1}, Vec3d{1, 0, 4}, 30.0), bvh,
              boxes);
  }
  report("boxes", boxes);
  CHECK(boxes.shadowed > 20);
  CHECK(boxes.interval <= 1e-12);
  CHECK(boxes.diffuse <= 1e-9);
  CHECK(boxes.specular <= 1e-7);
  CHECK(boxes.decided == boxes.asked);
}

TEST_CASE("linear silhouettes = triangle intervals: a bumpy surface shadowing its own vertices") {
  // A height field lit by a low tube on one side: occluders cross the strip next to P and the
  // triangles at P hide nothing (no acne).
  const PreparedLight<double> tube = prepare_light<double>(linear_source({2.4, -0.8, 0.5}, {2.6, 0.9, 0.9}, 2));
  const BumpySurface surface = bumpy_surface(14, 0.4);
  const OccluderBvh bvh = make_bvh(surface.tris);
  Agreement agree;
  for (const auto& sp : surface.points) compare(tube, sp, bvh, agree);
  report("bumpy surface", agree);
  CHECK(agree.shadowed > 10);
  CHECK(agree.interval <= 1e-12);
  CHECK(agree.diffuse <= 1e-9);
  CHECK(agree.specular <= 1e-7);
  CHECK(agree.decided >= 0.95 * agree.asked);
}

TEST_CASE("linear silhouettes: the answer does not depend on how a surface is triangulated") {
  // One plate as 2 triangles (either diagonal) and as a fan with a T-junction on an edge.
  const PreparedLight<double> tube = prepare_light<double>(linear_source({-1, -0.2, 2}, {1, 0.3, 2}, 2));
  const LinearLight<double>& light = std::get<LinearLight<double>>(tube.kernel);
  const std::vector<std::vector<Tri>> ways = plate_triangulations();
  std::mt19937_64 rng(9);
  std::uniform_real_distribution<double> u(-1, 1);
  ShadeOptions o = options_with(SpecularMethod::kExact);
  int partly = 0;
  for (int k = 0; k < 40; ++k) {
    const ShadingPoint<double> sp = make_shading_point(Vec3d{u(rng), u(rng), 0}, Vec3d{0, 0, 1}, Vec3d{0, 0, 4}, 8.0);
    const double open = shade(tube, sp, o).diffuse;
    const double first = shade_shadowed(tube, sp, o, make_bvh(ways[0])).diffuse;
    partly += first > 1e-3 * open && first < (1 - 1e-3) * open;
    for (const auto& tris : ways) {
      CHECK(std::abs(shade_shadowed(tube, sp, o, make_bvh(tris)).diffuse - first) <= 1e-12 * open);
      LinearSilhouetteScratch s;
      CHECK(visible_linear_by_silhouettes(light, sp.p, make_bvh(tris), s) != LinearSilhouetteVisibility::kUndecided);
    }
  }
  CHECK(partly > 5);
}

TEST_CASE("linear silhouettes: a plate lying in the plane of P and the tube goes to the intervals") {
  // Seen edge-on from P the plate weighs nothing, but it covers part of the rays to the tube.
  const PreparedLight<double> tube = prepare_light<double>(linear_source({-1, 0, 2}, {1, 0, 2}, 2));
  const LinearLight<double>& light = std::get<LinearLight<double>>(tube.kernel);
  const OccluderBvh bvh = make_bvh({{Vec3d{-0.2, 0, 0.5}, Vec3d{0.3, 0, 0.5}, Vec3d{0.1, 0, 1.2}}});
  LinearSilhouetteScratch s;
  CHECK(visible_linear_by_silhouettes(light, {0, 0, 0}, bvh, s) == LinearSilhouetteVisibility::kUndecided);
  ShadeOptions o = options_with(SpecularMethod::kNone), intervals = o;
  intervals.linear_shadows = LinearShadowMethod::kTriangleIntervals;
  const ShadingPoint<double> sp = make_shading_point({0, 0, 0}, {0, 0, 1}, {0, 0, 4}, 8.0);
  CHECK(shade_shadowed(tube, sp, o, bvh).diffuse == shade_shadowed(tube, sp, intervals, bvh).diffuse);
  CHECK(shade_shadowed(tube, sp, o, bvh).diffuse < 0.9 * shade(tube, sp, o).diffuse);
}

TEST_CASE("linear silhouettes: a plate the tube passes through hides the part of the tube behind it") {
  // The tube runs along x at height 2 through the plate x = 0.3 (|y| <= 1, 1 <= z <= 3). From P on
  // the floor with x <= -0.4, a ray to a point of the tube beyond the plate crosses x = 0.3 at
  // height 2 (0.3 - x_P) / (x_Q - x_P) >= 1: inside the plate. So P sees exactly t in [0, 0.65].
  // The plate leaves the strip through its plane next to the light: only its chord there closes
  // what it hides.
  const PreparedLight<double> tube = prepare_light<double>(linear_source({-1, 0, 2}, {1, 0, 2}, 2));
  const LinearLight<double>& light = std::get<LinearLight<double>>(tube.kernel);
  std::mt19937_64 rng(31);
  std::uniform_real_distribution<double> x(-1, -0.4), y(-0.5, 0.5);
  for (const bool flipped : {false, true}) {
    std::vector<Tri> plate;
    add_quad(plate, {0.3, -1, 1}, {0, 2, 0}, {0, 0, 2});
    if (flipped)
      for (Tri& t : plate) std::swap(t[1], t[2]);
    const OccluderBvh bvh = make_bvh(plate);
    for (int k = 0; k < 20; ++k) {
      const Vec3d p{x(rng), y(rng), 0};
      LinearSilhouetteScratch s;
      REQUIRE(visible_linear_by_silhouettes(light, p, bvh, s) == LinearSilhouetteVisibility::kIntervals);
      REQUIRE(s.visible.size() == 1);
      CHECK(s.visible[0].first == 0);
      // The strip ends kLinearNearLight h before the light, so the chord lies there, not on the
      // tube: the edge of the visible part moves by about that much.
      CHECK(std::abs(s.visible[0].second - 0.65) <= 1e-6);
      LinearShadowScratch intervals;
      REQUIRE(visible_linear_intervals(light, p, bvh, intervals) == LinearVisibility::kIntervals);
      REQUIRE(intervals.visible.size() == 1);
      CHECK(std::abs(s.visible[0].second - intervals.visible[0].second) <= 1e-12);
    }
  }
}

TEST_CASE("linear shadows: P on the tube's line and a tube of no length are decided by one shadow ray") {
  // P on the line beyond Q0 (every ray runs along the line) and a tube shrunk to its midpoint: the
  // silhouettes leave both to the intervals, which ask one ray to the nearer end (the midpoint).
  auto tube = [](const Vec3d& q0, const Vec3d& q1) {
    return std::get<LinearLight<double>>(prepare_light<double>(linear_source(q0, q1, 2)).kernel);
  };
  const LinearLight<double> along = tube({1, 0, 0}, {2, 0, 0}), dot_light = tube({0, 0, 2}, {0, 0, 2});
  std::vector<Tri> between_p_and_q0, beyond_q0, over_p;
  add_quad(between_p_and_q0, {0.5, -1, -1}, {0, 2, 0}, {0, 0, 2});  // the plane x = 0.5
  add_quad(beyond_q0, {1.5, -1, -1}, {0, 2, 0}, {0, 0, 2});         // x = 1.5: hides only the far part
  add_quad(over_p, {-1, -1, 1}, {2, 0, 0}, {0, 2, 0});              // z = 1, between P and the dot
  const Vec3d p{0, 0, 0};
  auto decide = [&](const LinearLight<double>& light, const std::vector<Tri>& tris) {
    const OccluderBvh bvh = make_bvh(tris);
    LinearSilhouetteScratch s;
    CHECK(visible_linear_by_silhouettes(light, p, bvh, s) == LinearSilhouetteVisibility::kUndecided);
    LinearShadowScratch intervals;
    const LinearVisibility v = visible_linear_intervals(light, p, bvh, intervals);
    return v == LinearVisibility::kUnoccluded ? 1 : intervals.visible.empty() ? 0 : -1;
  };
  CHECK(decide(along, between_p_and_q0) == 0);
  CHECK(decide(along, beyond_q0) == 1);
  CHECK(decide(dot_light, over_p) == 0);
  CHECK(decide(dot_light, beyond_q0) == 1);
}
