// snap_to_vertices (src/shadow/snap_to_vertices.h): points a few rounding errors off an occluder
// corner are moved exactly onto it, and onto nothing else.
#include <doctest/doctest.h>

#include <cmath>

#include "shadow/snap_to_vertices.h"

using namespace vlit;

namespace {

Vec3d rounded(const Vec3d& p) {
  return {static_cast<float>(p.x), static_cast<float>(p.y), static_cast<float>(p.z)};
}

}  // namespace

TEST_CASE("snap_to_vertices: corners rounded to float (or nudged by more rounding) go back exactly, other points stay") {
  // Corners that no float holds (a rotated asset's world positions); the occluders span about 3.
  const double s = std::sqrt(2.0) / 3;
  OccluderTriangles t;
  t.corners.push_back({Vec3d{s, 0.1, -s}, Vec3d{1 + s, 0.2, 0.3 * s}, Vec3d{-s, 0, 2 * s}});
  t.corners.push_back({Vec3d{1 + s, 0.2, 0.3 * s}, Vec3d{2.5, -0.0, 7 * s}, Vec3d{s, 0.1, -s}});  // shares two
  t.ids.resize(2);
  for (const auto& tri : t.corners)
    for (const Vec3d& c : tri) REQUIRE_FALSE(rounded(c) == c);  // else the test proves nothing
  const double size = 3.2;  // about the diagonal of the corners' box
  std::vector<Vec3d> points = {rounded(t.corners[0][0]),
                               rounded(t.corners[0][1]) + Vec3d{3e-7, -2e-7, 1e-7},  // a float transform's error
                               rounded(t.corners[0][2]),
                               rounded(t.corners[1][1]),
                               Vec3d{0.5, 0.5, 0.5},
                               t.corners[0][0] + Vec3d{2 * kSnapTolerance * size, 0, 0}};  // beyond the tolerance
  const SnapCount n = snap_to_vertices(t, points);
  CHECK(n.snapped == 4);
  CHECK(n.ambiguous == 0);
  CHECK(points[0] == t.corners[0][0]);
  CHECK(points[1] == t.corners[0][1]);
  CHECK(points[2] == t.corners[0][2]);
  CHECK(points[3] == t.corners[1][1]);
  CHECK(points[4] == Vec3d{0.5, 0.5, 0.5});
  CHECK(points[5] == t.corners[0][0] + Vec3d{2 * kSnapTolerance * size, 0, 0});
}

TEST_CASE("snap_to_vertices: a point near two distinct corners is ambiguous and stays") {
  OccluderTriangles t;
  const Vec3d a{0.1, 0.2, 0.3};
  const Vec3d b{0.1 + 1e-9, 0.2, 0.3};  // another vertex within the tolerance of a
  t.corners.push_back({a, Vec3d{1, 0, 0}, Vec3d{0, 1, 0}});
  t.corners.push_back({b, Vec3d{2, 0, 0}, Vec3d{0, 2, 0}});
  t.ids.resize(2);
  std::vector<Vec3d> points = {rounded(a), Vec3d{1, 0, 0}};
  const SnapCount n = snap_to_vertices(t, points);
  CHECK(n.ambiguous == 1);
  CHECK(n.snapped == 1);
  CHECK(points[0] == rounded(a));
  CHECK(points[1] == Vec3d{1, 0, 0});
}
