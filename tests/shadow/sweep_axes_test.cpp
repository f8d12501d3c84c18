// The silhouette sweep's axes (sweep_axes.h): the light's bounding rectangle in them against the
// smallest over a fine scan of directions, the frame's orientation on both sides of a two-sided
// light, and the per-thread memory of the last light.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <stdexcept>
#include <vector>

#include "shadow/sweep_axes.h"

using namespace vlit;

namespace {

double bounding_area(const PreparedAreaLight<double>& light, const Vec3d& u, const Vec3d& v) {
  Rect2 r;
  for (int k = 0; k < light.count; ++k) r.grow(dot(u, light.d[k]), dot(v, light.d[k]));
  return (r.x1 - r.x0) * (r.y1 - r.y0);
}

// A w x h rectangle centred at `center` in the plane spanned by the unit vectors a and b, turned
// by `angle` in that plane.
std::vector<Vec3d> rectangle(const Vec3d& center, const Vec3d& a, const Vec3d& b, double w, double h, double angle) {
  const Vec3d x = a * std::cos(angle) + b * std::sin(angle), y = b * std::cos(angle) - a * std::sin(angle);
  return {center - x * (w / 2) - y * (h / 2), center + x * (w / 2) - y * (h / 2), center + x * (w / 2) + y * (h / 2),
          center - x * (w / 2) + y * (h / 2)};
}

void check_frame(const SweepAxes& axes, const Vec3d& normal) {
  CHECK(std::abs(length(axes.u) - 1) < 1e-14);
  CHECK(std::abs(length(axes.v) - 1) < 1e-14);
  CHECK(std::abs(dot(axes.u, axes.v)) < 1e-14);
  CHECK(length(cross(axes.u, axes.v) - normal) < 1e-14);
}

}  // namespace

TEST_CASE("sweep axes: a square panel whose own frame runs along its diagonal is bounded by itself") {
  // bench/helmet-panel.json's panel: the light's own u points at a corner.
  const PreparedAreaLight<double> light = prepare_area_light(AreaLight<double>{
      {{-0.6, 2.0, -0.6}, {0.6, 2.0, -0.6}, {0.6, 2.0, 0.6}, {-0.6, 2.0, 0.6}}, false});
  const double own = bounding_area(light, light.u, light.v);
  CHECK(own == doctest::Approx(2 * light.area).epsilon(1e-12));
  const SweepAxes axes = sweep_axes(light);
  check_frame(axes, light.normal);
  CHECK(bounding_area(light, axes.u, axes.v) == doctest::Approx(light.area).epsilon(1e-12));
}

TEST_CASE("sweep axes: random convex lights, no direction of a fine scan bounds them smaller") {
  // For a convex polygon the smallest bounding rectangle has a side along an edge, so the axes
  // must do at least as well as every direction of a 7200-step scan of [0, pi), unless the light's
  // own frame is kept (within kSweepAxesMinGain of them).
  std::mt19937_64 rng(20261129);
  std::uniform_real_distribution<double> unit(0, 1);
  constexpr int kScan = 7200;
  int better_than_own = 0, lights = 0;
  for (int trial = 0; trial < 200; ++trial) {
    const int n = 3 + static_cast<int>(unit(rng) * 10);
    const double size = std::pow(10.0, -3 + 6 * unit(rng));
    const double stretch = 0.05 + unit(rng);  // an ellipse's aspect: thin lights too
    std::vector<double> angle(n);
    for (double& t : angle) t = 2 * M_PI * unit(rng);
    std::sort(angle.begin(), angle.end());
    // The ellipse's plane: a random orientation; the light far from the origin on some trials.
    const Vec3d a = normalize(Vec3d{unit(rng) - 0.5, unit(rng) - 0.5, unit(rng) - 0.5});
    const Vec3d b = normalize(cross(a, normalize(Vec3d{unit(rng) - 0.5, unit(rng) - 0.5, unit(rng) - 0.5})));
    const Vec3d center = Vec3d{unit(rng), unit(rng), unit(rng)} * std::pow(10.0, 4 * unit(rng));
    std::vector<Vec3d> polygon;
    for (double t : angle) polygon.push_back(center + (a * std::cos(t) + b * (stretch * std::sin(t))) * size);
    AreaLight<double> source{polygon, false};
    PreparedAreaLight<double> light;
    try {
      light = prepare_area_light(source);
    } catch (const std::invalid_argument&) {
      continue;  // two angles too close: no area
    }
    ++lights;
    const SweepAxes axes = sweep_axes(light);
    check_frame(axes, light.normal);
    const double chosen = bounding_area(light, axes.u, axes.v);
    double scanned = 1e300;
    for (int k = 0; k < kScan; ++k) {
      const double t = M_PI * k / kScan;
      const Vec3d u = light.u * std::cos(t) + light.v * std::sin(t);
      scanned = std::min(scanned, bounding_area(light, u, cross(light.normal, u)));
    }
    INFO("trial ", trial, ", ", n, " vertices, size ", size, ": chosen ", chosen, ", scanned ", scanned);
    const bool own = axes.u == light.u && axes.v == light.v;
    if (own) CHECK(chosen * (1 - kSweepAxesMinGain) <= scanned * (1 + 1e-12));  // kept: within 5 % of the best
    else CHECK(chosen <= scanned * (1 + 1e-12));
    better_than_own += !own;
  }
  MESSAGE(lights, " lights; the axes bound ", better_than_own, " of them more tightly than the light's own frame (by 5 % or more)");
  CHECK(lights >= 190);
}

TEST_CASE("sweep axes: a regular 64-gon (a disk's polygon) keeps the light's own frame") {
  std::vector<Vec3d> polygon;
  for (int k = 0; k < 64; ++k) polygon.push_back({std::cos(2 * M_PI * k / 64), 3.0, -std::sin(2 * M_PI * k / 64)});
  const PreparedAreaLight<double> light = prepare_area_light(AreaLight<double>{polygon, false});
  const SweepAxes axes = sweep_axes(light);
  CHECK(axes.u == light.u);
  CHECK(axes.v == light.v);
  // ... where an edge would have been a little tighter.
  const Vec3d edge = normalize(light.d[1] - light.d[0]);
  CHECK(bounding_area(light, edge, cross(light.normal, edge)) < bounding_area(light, light.u, light.v));
}

TEST_CASE("sweep axes: the back of a two-sided light keeps the view's orientation") {
  const PreparedAreaLight<double> light = prepare_area_light(AreaLight<double>{
      rectangle({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, 2, 1, 0.4), true});
  for (const Vec3d p : {Vec3d{0.3, -0.2, 2}, Vec3d{0.3, -0.2, -2}}) {
    const AreaView<double> view = make_area_view(light, p);
    REQUIRE(view.lit);
    const AreaView<double> turned = in_sweep_axes(view, sweep_axes(light));
    CHECK(length(cross(turned.u, turned.v) - view.normal) < 1e-14);
    CHECK(turned.D == view.D);
    CHECK(turned.height == view.height);
    CHECK(turned.orient == view.orient);
  }
}

TEST_CASE("sweep axes: lights taken in turn each get their own axes") {
  // Two rectangles with the same centre, plane and vertex count, turned differently: the memory
  // of the last light must tell them apart by their corners.
  const PreparedAreaLight<double> first = prepare_area_light(AreaLight<double>{
      rectangle({1, 2, 3}, {0, 0, 1}, {1, 0, 0}, 3, 1, 0.3), false});
  const PreparedAreaLight<double> second = prepare_area_light(AreaLight<double>{
      rectangle({1, 2, 3}, {0, 0, 1}, {1, 0, 0}, 3, 1, 1.1), false});
  REQUIRE(first.normal == second.normal);
  for (int round = 0; round < 3; ++round) {
    for (const PreparedAreaLight<double>* light : {&first, &second, &second, &first}) {
      const SweepAxes axes = sweep_axes(*light);
      CHECK(bounding_area(*light, axes.u, axes.v) == doctest::Approx(light->area).epsilon(1e-12));
    }
  }
}
