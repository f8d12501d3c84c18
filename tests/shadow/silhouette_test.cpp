// The silhouette visibility of area lights (src/shadow/area_silhouette.h) against the
// triangle-by-triangle cutting (area_visibility.h), which the other shadow tests hold to shadow
// rays and to exact symmetric answers: the same light on random soups, refined closed spheres,
// boxes in random orientations, a bumpy surface shadowing itself (occluders crossing the slab
// next to P) and a mesh with T-junctions. Each case also checks that the silhouette path answered
// (not its fallback), so a broken fast path cannot hide behind the reference.
#include <doctest/doctest.h>

#include <cmath>
#include <map>
#include <random>

#include "shadow/area_silhouette.h"
#include "shadow_test_util.h"

using namespace vlit;
using namespace vlit::test;

namespace {

// Icosphere: the icosahedron with every triangle split in four `levels` times, vertices pushed
// to the sphere; shared vertices have identical coordinates (midpoint of the same two corners).
std::vector<Tri> icosphere(const Vec3d& center, double radius, int levels) {
  const double g = (1 + std::sqrt(5.0)) / 2;
  std::vector<Vec3d> v{{-1, g, 0}, {1, g, 0}, {-1, -g, 0}, {1, -g, 0}, {0, -1, g}, {0, 1, g},
                       {0, -1, -g}, {0, 1, -g}, {g, 0, -1}, {g, 0, 1}, {-g, 0, -1}, {-g, 0, 1}};
  for (Vec3d& x : v) x = normalize(x);
  std::vector<std::array<int, 3>> f{{0, 11, 5}, {0, 5, 1}, {0, 1, 7}, {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
                                    {11, 10, 2}, {10, 7, 6}, {7, 1, 8}, {3, 9, 4}, {3, 4, 2}, {3, 2, 6}, {3, 6, 8},
                                    {3, 8, 9}, {4, 9, 5}, {2, 4, 11}, {6, 2, 10}, {8, 6, 7}, {9, 8, 1}};
  for (int level = 0; level < levels; ++level) {
    std::map<std::pair<int, int>, int> middle;
    auto mid = [&](int a, int b) {
      const auto key = std::minmax(a, b);
      const auto it = middle.find(key);
      if (it != middle.end()) return it->second;
      v.push_back(normalize(v[key.first] + v[key.second]));
      return middle[key] = static_cast<int>(v.size()) - 1;
    };
    std::vector<std::array<int, 3>> next;
    for (const auto& [a, b, c] : f) {
      const int ab = mid(a, b), bc = mid(b, c), ca = mid(c, a);
      next.push_back({a, ab, ca});
      next.push_back({b, bc, ab});
      next.push_back({c, ca, bc});
      next.push_back({ab, bc, ca});
    }
    f = next;
  }
  std::vector<Tri> tris;
  for (const auto& [a, b, c] : f) tris.push_back({center + v[a] * radius, center + v[b] * radius, center + v[c] * radius});
  return tris;
}

Vec3d rotate(const Vec3d& x, const Vec3d& axis, double angle) {  // Rodrigues
  const Vec3d k = normalize(axis);
  return x * std::cos(angle) + cross(k, x) * std::sin(angle) + k * (dot(k, x) * (1 - std::cos(angle)));
}

struct Agreement {
  double diffuse = 0, specular = 0;  // largest difference / unshadowed value
  int shadowed = 0, cases = 0;
};

// Both methods at one point; differences relative to the unshadowed value.
void compare(const PreparedLight<double>& light, const ShadingPoint<double>& sp, const OccluderBvh& bvh,
             SpecularMethod method, Agreement& out) {
  ShadeOptions fast = options_with(method), cuts = options_with(method);
  cuts.area_shadows = AreaShadowMethod::kTriangleCuts;
  const Response<double> a = shade_shadowed(light, sp, fast, bvh), b = shade_shadowed(light, sp, cuts, bvh);
  const Response<double> open = shade(light, sp, fast);
  REQUIRE(std::isfinite(a.diffuse));
  REQUIRE(std::isfinite(a.specular));
  CHECK(a.diffuse >= 0);
  CHECK(a.diffuse <= open.diffuse * (1 + 1e-9));
  if (open.diffuse > 0) out.diffuse = std::max(out.diffuse, std::abs(a.diffuse - b.diffuse) / open.diffuse);
  if (open.specular > 0) out.specular = std::max(out.specular, std::abs(a.specular - b.specular) / open.specular);
  out.shadowed += b.diffuse < open.diffuse * (1 - 1e-9);
  ++out.cases;
}

// How often the silhouette path decided by itself at these points (1 = always).
double decided_fraction(const PreparedAreaLight<double>& light, const std::vector<ShadingPoint<double>>& points,
                        const OccluderBvh& bvh) {
  AreaSilhouetteScratch scratch;
  int asked = 0, decided = 0;
  for (const ShadingPoint<double>& sp : points) {
    const AreaView<double> view = make_area_view(light, sp.p);
    if (!view.lit) continue;
    ClipPolygon<double> horizon;
    clip_to_horizon(light, view, sp.n, horizon);
    if (horizon.count < 3) continue;
    ++asked;
    decided += visible_area_by_silhouettes(light, view, horizon, sp.p, bvh, scratch) != SilhouetteVisibility::kUndecided;
  }
  return asked ? static_cast<double>(decided) / asked : 1.0;
}

const PreparedAreaLight<double>& area_of(const PreparedLight<double>& l) {
  return std::get<PreparedAreaLight<double>>(l.kernel);
}

}  // namespace

TEST_CASE("silhouettes = triangle cuts: random soups between a panel and a floor") {
  const PreparedLight<double> panel = prepare_light<double>(area_source(square_light(0.7, 2)));
  std::mt19937_64 rng(1505);
  std::uniform_real_distribution<double> u(-1.5, 1.5), z(0.2, 1.8), small(-0.4, 0.4);
  Agreement agree;
  double decided = 0;
  const int trials = 60;
  for (int trial = 0; trial < trials; ++trial) {
    std::vector<Tri> tris;
    const int count = 5 + static_cast<int>(rng() % 40);
    for (int k = 0; k < count; ++k) {
      const Vec3d c{u(rng), u(rng), z(rng)};
      tris.push_back({c, c + Vec3d{small(rng), small(rng), small(rng)}, c + Vec3d{small(rng), small(rng), small(rng)}});
    }
    const OccluderBvh bvh = make_bvh(tris);
    std::vector<ShadingPoint<double>> points;
    for (int k = 0; k < 12; ++k)
      points.push_back(make_shading_point(Vec3d{u(rng), u(rng), 0}, Vec3d{0, 0, 1}, Vec3d{0.3, -0.2, 3}, 20.0));
    for (const auto& sp : points)
      for (SpecularMethod method : {SpecularMethod::kNone, SpecularMethod::kExact, SpecularMethod::kPeak}) {
        INFO("trial " << trial);
        compare(panel, sp, bvh, method, agree);
      }
    decided += decided_fraction(area_of(panel), points, bvh);
  }
  MESSAGE("soups: " << agree.shadowed << " of " << agree.cases << " shadowed; largest difference diffuse "
                    << agree.diffuse << ", specular " << agree.specular << "; decided " << decided / trials);
  CHECK(agree.shadowed > agree.cases / 4);
  CHECK(agree.diffuse <= 1e-9);
  CHECK(agree.specular <= 1e-7);
  CHECK(decided / trials >= 0.95);
}

TEST_CASE("silhouettes = triangle cuts: refined closed spheres and rotated boxes") {
  const PreparedLight<double> panel = prepare_light<double>(area_source(square_light(1, 3)));
  std::mt19937_64 rng(42);
  std::uniform_real_distribution<double> u(-1.2, 1.2), angle(0, 6.283185307179586);
  for (int levels = 0; levels <= 3; ++levels) {
    const std::vector<Tri> sphere = icosphere({0.1, -0.05, 1.4}, 0.55, levels);
    const OccluderBvh bvh = make_bvh(sphere);
    Agreement agree;
    std::vector<ShadingPoint<double>> points;
    for (int k = 0; k < 24; ++k)
      points.push_back(make_shading_point(Vec3d{u(rng), u(rng), 0}, Vec3d{0, 0, 1}, Vec3d{0, 0, 4}, 8.0));
    for (const auto& sp : points) compare(panel, sp, bvh, SpecularMethod::kExact, agree);
    const double decided = decided_fraction(area_of(panel), points, bvh);
    MESSAGE("sphere, " << sphere.size() << " triangles: " << agree.shadowed << " of " << agree.cases
                       << " shadowed; diffuse " << agree.diffuse << ", specular " << agree.specular << "; decided "
                       << decided);
    CHECK(agree.shadowed > 4);
    CHECK(agree.diffuse <= 1e-9);
    CHECK(agree.specular <= 1e-7);
    CHECK(decided == 1.0);
  }
  Agreement boxes;
  for (int trial = 0; trial < 20; ++trial) {
    std::vector<Tri> box;
    add_box(box, {-0.3, -0.25, -0.2}, {0.3, 0.25, 0.2});
    const Vec3d axis{u(rng), u(rng), u(rng)};
    const double a = angle(rng);
    for (Tri& t : box)
      for (Vec3d& x : t) x = rotate(x, axis, a) + Vec3d{0.2 * u(rng) * 0 + 0.1, -0.1, 1.5};
    const OccluderBvh bvh = make_bvh(box);
    for (int k = 0; k < 8; ++k) {
      const ShadingPoint<double> sp = make_shading_point(Vec3d{u(rng), u(rng), 0}, Vec3d{0, 0, 1}, Vec3d{1, 0, 4}, 30.0);
      compare(panel, sp, bvh, SpecularMethod::kExact, boxes);
    }
  }
  MESSAGE("boxes: " << boxes.shadowed << " of " << boxes.cases << " shadowed; diffuse " << boxes.diffuse
                    << ", specular " << boxes.specular);
  CHECK(boxes.shadowed > 20);
  CHECK(boxes.diffuse <= 1e-9);
  CHECK(boxes.specular <= 1e-7);
}

TEST_CASE("silhouettes = triangle cuts: a bumpy surface shadowing its own vertices") {
  // A height field z = f(x, y) lit from low on one side by a steep two-sided panel: occluders
  // cross the slab next to P and the triangles at P are skipped (no acne), the hard case of
  // self-shadowing.
  const PreparedLight<double> panel = prepare_light<double>(
      area_source({{2.4, -0.6, 0.3}, {2.4, 0.6, 0.3}, {2.7, 0.6, 1.2}, {2.7, -0.6, 1.2}}, true));
  const int n = 14;
  auto height = [](double x, double y) { return 0.4 * std::sin(3 * x) * std::cos(2.5 * y) + 0.1 * x; };
  std::vector<Vec3d> grid;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) {
      const double x = -1.5 + 3.0 * i / n, y = -1.5 + 3.0 * j / n;
      grid.push_back({x, y, height(x, y)});
    }
  std::vector<Tri> tris;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const Vec3d& a = grid[j * (n + 1) + i];
      const Vec3d& b = grid[j * (n + 1) + i + 1];
      const Vec3d& c = grid[(j + 1) * (n + 1) + i + 1];
      const Vec3d& d = grid[(j + 1) * (n + 1) + i];
      tris.push_back({a, b, c});
      tris.push_back({a, c, d});
    }
  const OccluderBvh bvh = make_bvh(tris);
  Agreement agree;
  std::vector<ShadingPoint<double>> points;
  for (const Vec3d& p : grid) {
    const double e = 1e-4;
    const Vec3d dx{2 * e, 0, height(p.x + e, p.y) - height(p.x - e, p.y)};
    const Vec3d dy{0, 2 * e, height(p.x, p.y + e) - height(p.x, p.y - e)};
    points.push_back(make_shading_point(p, normalize(cross(dx, dy)), Vec3d{0, 0, 5}, 10.0));
  }
  for (const auto& sp : points) compare(panel, sp, bvh, SpecularMethod::kExact, agree);
  const double decided = decided_fraction(area_of(panel), points, bvh);
  MESSAGE("bumpy surface: " << agree.shadowed << " of " << agree.cases << " shadowed; diffuse " << agree.diffuse
                            << ", specular " << agree.specular << "; decided " << decided);
  CHECK(agree.shadowed > 10);
  CHECK(agree.diffuse <= 1e-9);
  CHECK(agree.specular <= 1e-7);
  CHECK(decided >= 0.95);
}

TEST_CASE("silhouettes: the answer does not depend on how a surface is triangulated") {
  // One plate as 2 triangles (either diagonal) and as a fan with a T-junction on an edge: every
  // triangulation hides the same part of the light.
  const PreparedLight<double> panel = prepare_light<double>(area_source(square_light(0.8, 2)));
  const Vec3d a{-0.4, -0.3, 1}, b{0.5, -0.35, 1.1}, c{0.45, 0.4, 1.05}, d{-0.35, 0.45, 0.95};
  const Vec3d m = (a + b) * 0.5;  // T-junction on edge a-b: its neighbour keeps the long edge
  const std::vector<std::vector<Tri>> ways{
      {{a, b, c}, {a, c, d}}, {{a, b, d}, {b, c, d}}, {{a, m, d}, {m, b, c}, {m, c, d}}};
  std::mt19937_64 rng(9);
  std::uniform_real_distribution<double> u(-1, 1);
  ShadeOptions o = options_with(SpecularMethod::kExact);
  for (int k = 0; k < 40; ++k) {
    const ShadingPoint<double> sp = make_shading_point(Vec3d{u(rng), u(rng), 0}, Vec3d{0, 0, 1}, Vec3d{0, 0, 4}, 8.0);
    const double open = shade(panel, sp, o).diffuse;
    const double first = shade_shadowed(panel, sp, o, make_bvh(ways[0])).diffuse;
    for (const auto& tris : ways) CHECK(std::abs(shade_shadowed(panel, sp, o, make_bvh(tris)).diffuse - first) <= 1e-12 * open);
  }
}
