// Merging coplanar triangles into polygons (mesh/planar_polygons.h): grids, L-shapes, holes,
// pinched regions, folds, and the vertex limit.
#include <doctest/doctest.h>

#include <cmath>

#include "mesh/planar_polygons.h"

using namespace vlit;

namespace {

// An n x m grid of unit quads in z = 0, two triangles each, counter-clockwise seen from +Z;
// `skip(i, j)` leaves cell (i, j) out.
template <class Skip>
void grid(int n, int m, Skip skip, std::vector<Vec3d>& positions, std::vector<std::uint32_t>& tris) {
  for (int j = 0; j <= m; ++j)
    for (int i = 0; i <= n; ++i) positions.push_back({double(i), double(j), 0});
  auto at = [&](int i, int j) { return static_cast<std::uint32_t>(j * (n + 1) + i); };
  for (int j = 0; j < m; ++j)
    for (int i = 0; i < n; ++i)
      if (!skip(i, j)) tris.insert(tris.end(), {at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j), at(i + 1, j + 1), at(i, j + 1)});
}

double signed_area_z(const std::vector<Vec3d>& poly) {
  double a = 0;
  for (std::size_t i = 0; i < poly.size(); ++i) a += cross(poly[i], poly[(i + 1) % poly.size()]).z;
  return a / 2;
}

}  // namespace

TEST_CASE("a 4 x 3 grid merges into one rectangle, counter-clockwise, collinear vertices dropped") {
  std::vector<Vec3d> p;
  std::vector<std::uint32_t> t;
  grid(4, 3, [](int, int) { return false; }, p, t);
  PlanarMergeStats stats;
  const auto polys = merge_coplanar_triangles(p, t, 64, &stats);
  REQUIRE(polys.size() == 1);
  CHECK(polys[0].size() == 4);
  CHECK(signed_area_z(polys[0]) == doctest::Approx(12));
  CHECK(stats.triangles == 24);
  CHECK(stats.regions == 1);
}

TEST_CASE("an L-shape is one non-convex hexagon, a hole or a pinch falls back to triangles") {
  std::vector<Vec3d> p;
  std::vector<std::uint32_t> t;
  grid(2, 2, [](int i, int j) { return i == 1 && j == 1; }, p, t);  // L of 3 cells
  auto polys = merge_coplanar_triangles(p, t, 64);
  REQUIRE(polys.size() == 1);
  CHECK(polys[0].size() == 6);
  CHECK(signed_area_z(polys[0]) == doctest::Approx(3));

  p.clear(); t.clear();
  grid(3, 3, [](int i, int j) { return i == 1 && j == 1; }, p, t);  // ring around a hole
  PlanarMergeStats stats;
  polys = merge_coplanar_triangles(p, t, 64, &stats);
  CHECK(polys.size() == 16);
  CHECK(stats.merged_regions == 0);
  double area = 0;
  for (const auto& poly : polys) area += signed_area_z(poly);
  CHECK(area == doctest::Approx(8));

  p.clear(); t.clear();
  grid(2, 2, [](int i, int j) { return i != j; }, p, t);  // two cells touching at one corner: two regions
  polys = merge_coplanar_triangles(p, t, 64);
  CHECK(polys.size() == 2);

  p.clear(); t.clear();
  // One region whose boundary touches itself at vertex (1, 1): the notch at cell (0, 0) meets
  // the hole at cell (1, 1). Pinched: its 7 cells fall back to 14 triangles.
  grid(3, 3, [](int i, int j) { return (i == 0 && j == 0) || (i == 1 && j == 1); }, p, t);
  polys = merge_coplanar_triangles(p, t, 64);
  CHECK(polys.size() == 14);
}

TEST_CASE("a fold, opposite facing and the vertex limit stop a merge") {
  // Two triangles sharing an edge, folded by 90 degrees: two polygons.
  const std::vector<Vec3d> fold = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  CHECK(merge_coplanar_triangles(fold, {0, 1, 2, 0, 3, 1}, 64).size() == 2);
  // A quad whose two triangles face opposite ways (inconsistent winding): not merged.
  const std::vector<Vec3d> quad = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  CHECK(merge_coplanar_triangles(quad, {0, 1, 2, 0, 3, 2}, 64).size() == 2);
  // A fan approximating a disk with 40 rim vertices: one 40-gon, or 40 triangles above the limit.
  std::vector<Vec3d> fan = {{0, 0, 0}};
  std::vector<std::uint32_t> tris;
  for (int i = 0; i < 40; ++i) fan.push_back({std::cos(2 * M_PI * i / 40), std::sin(2 * M_PI * i / 40), 0});
  for (std::uint32_t i = 0; i < 40; ++i) tris.insert(tris.end(), {0, 1 + i, 1 + (i + 1) % 40});
  CHECK(merge_coplanar_triangles(fan, tris, 64).front().size() == 40);
  CHECK(merge_coplanar_triangles(fan, tris, 32).size() == 40);
  // Degenerate triangles are dropped.
  CHECK(merge_coplanar_triangles(quad, {0, 1, 1, 0, 0, 0}, 64).empty());
}
