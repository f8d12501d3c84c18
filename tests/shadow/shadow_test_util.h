// Small builders shared by the shadow tests.
#pragma once

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <random>
#include <vector>

#include "shading/prepared_light.h"
#include "shadow/occluder_bvh.h"
#include "shadow/shadowed_light.h"
#include "shadow_reference.h"
#include "light_sources.h"

namespace vlit::test {

inline OccluderBvh make_bvh(const std::vector<Tri>& tris, bool brute_force = false) {
  OccluderTriangles t;
  for (std::size_t i = 0; i < tris.size(); ++i) {
    t.corners.push_back(tris[i]);
    t.ids.push_back({0, static_cast<std::uint32_t>(i)});
  }
  return OccluderBvh(std::move(t), brute_force);
}

// The triangles as one scene primitive with split vertices (three per triangle, as with
// per-face normals): joined by position only.
inline ScenePrimitive primitive_of(const std::vector<Tri>& tris) {
  ScenePrimitive prim;
  for (const Tri& t : tris)
    for (const Vec3d& c : t) {
      prim.triangles.push_back(static_cast<std::uint32_t>(prim.positions.size()));
      prim.positions.push_back(c);
      prim.normals.push_back({0, 0, 1});
    }
  return prim;
}

// The primitive's vertices as shading points (their own normals), seen from `eye` with shininess m.
inline std::vector<ShadingPoint<double>> vertex_points(const ScenePrimitive& prim, const Vec3d& eye, double m) {
  std::vector<ShadingPoint<double>> points;
  for (std::size_t v = 0; v < prim.positions.size(); ++v)
    points.push_back(make_shading_point(prim.positions[v], prim.normals[v], eye, m));
  return points;
}

// Two triangles covering the rectangle corner + s e1 + t e2, s, t in [0, 1].
inline void add_quad(std::vector<Tri>& tris, const Vec3d& corner, const Vec3d& e1, const Vec3d& e2) {
  tris.push_back({corner, corner + e1, corner + e1 + e2});
  tris.push_back({corner, corner + e1 + e2, corner + e2});
}

// Closed axis-aligned box, 12 triangles, consistently wound (outward normals).
inline void add_box(std::vector<Tri>& tris, const Vec3d& lo, const Vec3d& hi) {
  const Vec3d s = hi - lo;
  const Vec3d ex{s.x, 0, 0}, ey{0, s.y, 0}, ez{0, 0, s.z};
  add_quad(tris, lo, ey, ex);                 // bottom
  add_quad(tris, lo + ez, ex, ey);            // top
  add_quad(tris, lo, ex, ez);                 // front
  add_quad(tris, lo + ey, ez, ex);            // back
  add_quad(tris, lo, ez, ey);                 // left
  add_quad(tris, lo + ex, ey, ez);            // right
}

// x turned by `angle` about `axis` (Rodrigues).
inline Vec3d rotate(const Vec3d& x, const Vec3d& axis, double angle) {
  const Vec3d k = normalize(axis);
  return x * std::cos(angle) + cross(k, x) * std::sin(angle) + k * (dot(k, x) * (1 - std::cos(angle)));
}

// A closed 0.6 x 0.5 x 0.4 box turned by a random angle about a random axis, centred near
// (0.1, -0.1, 1.5).
inline std::vector<Tri> turned_box(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(-1.2, 1.2), angle(0, 6.283185307179586);
  std::vector<Tri> box;
  add_box(box, {-0.3, -0.25, -0.2}, {0.3, 0.25, 0.2});
  const Vec3d axis{u(rng), u(rng), u(rng)};
  const double a = angle(rng);
  for (Tri& t : box)
    for (Vec3d& x : t) x = rotate(x, axis, a) + Vec3d{0.1, -0.1, 1.5};
  return box;
}

// One tilted plate about 1 above the floor, triangulated three ways: two triangles along either
// diagonal, and a fan with a T-junction on an edge (its neighbour keeps the long edge).
inline std::vector<std::vector<Tri>> plate_triangulations() {
  const Vec3d a{-0.4, -0.3, 1}, b{0.5, -0.35, 1.1}, c{0.45, 0.4, 1.05}, d{-0.35, 0.45, 0.95};
  const Vec3d m = (a + b) * 0.5;
  return {{{a, b, c}, {a, c, d}}, {{a, b, d}, {b, c, d}}, {{a, m, d}, {m, b, c}, {m, c, d}}};
}

// `count` random triangles between a floor at z = 0 and a light at z = 2: a corner anywhere over
// [-1.5, 1.5]^2 at height 0.2 .. 1.8, the other two within 0.4 of it on each axis.
inline void add_random_triangles(std::vector<Tri>& tris, std::mt19937_64& rng, int count) {
  std::uniform_real_distribution<double> u(-1.5, 1.5), z(0.2, 1.8), small(-0.4, 0.4);
  for (int k = 0; k < count; ++k) {
    const Vec3d c{u(rng), u(rng), z(rng)};
    tris.push_back({c, c + Vec3d{small(rng), small(rng), small(rng)}, c + Vec3d{small(rng), small(rng), small(rng)}});
  }
}

// A fast method's shaded value `a` against its reference's `b` at one point: `a` is finite, >= 0
// and not above the unshadowed value `open`; the largest differences seen so far, relative to
// `open`, grow to this point's.
inline void record_agreement(const Response<double>& a, const Response<double>& b, const Response<double>& open,
                             double& diffuse, double& specular) {
  REQUIRE(std::isfinite(a.diffuse));
  REQUIRE(std::isfinite(a.specular));
  CHECK(a.diffuse >= 0);
  CHECK(a.diffuse <= open.diffuse * (1 + 1e-9));
  if (open.diffuse > 0) diffuse = std::max(diffuse, std::abs(a.diffuse - b.diffuse) / open.diffuse);
  if (open.specular > 0) specular = std::max(specular, std::abs(a.specular - b.specular) / open.specular);
}

inline ShadeOptions options_with(SpecularMethod method) {
  ShadeOptions o;
  o.with_specular = method != SpecularMethod::kNone;
  o.specular.method = method;
  return o;
}

// A square light of half-size `half` centred at (0, 0, height), emitting down (-z).
inline std::vector<Vec3d> square_light(double half, double height) {
  return {{-half, -half, height}, {-half, half, height}, {half, half, height}, {half, -half, height}};
}

// Icosphere: the icosahedron with every triangle split in four `levels` times, vertices pushed
// to the sphere; shared vertices have identical coordinates (midpoint of the same two corners).
inline std::vector<Tri> icosphere(const Vec3d& center, double radius, int levels) {
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

// A height field z = amplitude sin(3x) cos(2.5y) + 0.1x over [-1.5, 1.5]^2 on an n x n grid: its
// triangles, and its grid points as shading points (analytic normal, eye (0, 0, 5), m = 10).
struct BumpySurface {
  std::vector<Tri> tris;
  std::vector<ShadingPoint<double>> points;
};

inline BumpySurface bumpy_surface(int n, double amplitude) {
  auto height = [&](double x, double y) { return amplitude * std::sin(3 * x) * std::cos(2.5 * y) + 0.1 * x; };
  std::vector<Vec3d> grid;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) {
      const double x = -1.5 + 3.0 * i / n, y = -1.5 + 3.0 * j / n;
      grid.push_back({x, y, height(x, y)});
    }
  BumpySurface s;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const Vec3d& a = grid[j * (n + 1) + i];
      const Vec3d& b = grid[j * (n + 1) + i + 1];
      const Vec3d& c = grid[(j + 1) * (n + 1) + i + 1];
      const Vec3d& d = grid[(j + 1) * (n + 1) + i];
      s.tris.push_back({a, b, c});
      s.tris.push_back({a, c, d});
    }
  for (const Vec3d& p : grid) {
    const double e = 1e-4;
    const Vec3d dx{2 * e, 0, height(p.x + e, p.y) - height(p.x - e, p.y)};
    const Vec3d dy{0, 2 * e, height(p.x, p.y + e) - height(p.x, p.y - e)};
    s.points.push_back(make_shading_point(p, normalize(cross(dx, dy)), Vec3d{0, 0, 5}, 10.0));
  }
  return s;
}

}  // namespace vlit::test
