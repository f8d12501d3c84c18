// Coverage tests of the scanline loop: hand-counted triangles, agreement with an independent
// half-space (edge function) test with the top-left rule on every pixel centre, and
// watertightness (every interior pixel centre covered exactly once) of meshes sharing edges,
// both in screen space and through the whole geometry stage (camera, near-plane clipping).
#include <doctest/doctest.h>

#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

#include "raster/fixed_point.h"
#include "raster/geometry_stage.h"
#include "raster/rasterize_triangle.h"
#include "raster/triangle_setup.h"

using namespace vlit;
using namespace vlit::raster;

namespace {

// A coverage counter over a grid: every emitted span adds one to its pixels.
struct CoverageGrid {
  int width, height;
  std::vector<int> count;
  CoverageGrid(int w, int h) : width(w), height(h), count(size_t(w) * h, 0) {}
  int& at(int x, int y) { return count[size_t(y) * width + x]; }
  void add(const SetupTriangle& t) {
    scan_triangle(t, 0, height, width, [&](int row, int c0, int c1) {
      for (int c = c0; c < c1; ++c) ++at(c, row);
    });
  }
};

ScreenVertex fixed_vertex(int64_t x, int64_t y) { return ScreenVertex{x, y, 0.5, 1.0, Vec3d{}}; }
ScreenVertex pixel_vertex(double x, double y) { return fixed_vertex(snap_to_fixed(x), snap_to_fixed(y)); }

std::optional<SetupTriangle> setup(const ScreenVertex& a, const ScreenVertex& b, const ScreenVertex& c, int w, int h) {
  return setup_triangle(a, b, c, false, w, h);
}

// Independent reference: edge functions on exact integers, D3D top-left rule.
bool covers_reference(ScreenVertex a, ScreenVertex b, ScreenVertex c, int64_t px, int64_t py) {
  const auto edge = [](const ScreenVertex& p, const ScreenVertex& q, int64_t x, int64_t y) {
    return (q.x - p.x) * (y - p.y) - (q.y - p.y) * (x - p.x);
  };
  if (edge(a, b, c.x, c.y) < 0) std::swap(b, c);  // interior on the positive side of every edge
  if (edge(a, b, c.x, c.y) == 0) return false;
  const ScreenVertex* v[3] = {&a, &b, &c};
  for (int i = 0; i < 3; ++i) {
    const ScreenVertex& p = *v[i];
    const ScreenVertex& q = *v[(i + 1) % 3];
    const int64_t e = edge(p, q, px, py);
    const int64_t dx = q.x - p.x, dy = q.y - p.y;
    const bool top_left = (dy == 0 && dx > 0) || dy < 0;  // y down: top edge, or left edge
    if (e < 0 || (e == 0 && !top_left)) return false;
  }
  return true;
}

}  // namespace

TEST_CASE("coverage: right triangle with vertices on pixel corners, hand count") {
  // Legs of n pixels along the pixel grid: centres (i+.5, j+.5) with i + j + 1 < n are strictly
  // inside; those with i + j + 1 == n lie on the hypotenuse, a right edge, so they are excluded:
  // n(n-1)/2 centres. The complementary triangle of the square owns the hypotenuse (a left edge for
  // it): n(n+1)/2. Together they cover the n x n square exactly once.
  for (int n : {1, 2, 3, 8, 31}) {
    CAPTURE(n);
    CoverageGrid grid(n + 2, n + 2);
    const auto lower = setup(pixel_vertex(0, 0), pixel_vertex(n, 0), pixel_vertex(0, n), n + 2, n + 2);
    const auto upper = setup(pixel_vertex(n, n), pixel_vertex(0, n), pixel_vertex(n, 0), n + 2, n + 2);
    int lower_count = 0, upper_count = 0;
    if (lower) scan_triangle(*lower, 0, n + 2, n + 2, [&](int, int c0, int c1) { lower_count += c1 - c0; });
    if (upper) scan_triangle(*upper, 0, n + 2, n + 2, [&](int, int c0, int c1) { upper_count += c1 - c0; });
    CHECK(lower_count == n * (n - 1) / 2);
    CHECK(upper_count == n * (n + 1) / 2);
    if (lower) grid.add(*lower);
    if (upper) grid.add(*upper);
    for (int y = 0; y < n + 2; ++y)
      for (int x = 0; x < n + 2; ++x) CHECK(grid.at(x, y) == (x < n && y < n ? 1 : 0));
  }
}

TEST_CASE("coverage: matches an independent half-space test on every pixel centre") {
  std::mt19937 rng(2024);
  const int w = 48, h = 40;
  // Coordinates in fixed point, often on pixel centres / corners / edges to exercise the ties.
  std::uniform_int_distribution<int64_t> coord(-8 * kSubpixelOne, 56 * kSubpixelOne);
  std::uniform_int_distribution<int> kind(0, 3);
  const auto random_coord = [&]() {
    int64_t v = coord(rng);
    switch (kind(rng)) {
      case 0: return (v >> kSubpixelBits) * kSubpixelOne;                   // pixel corner
      case 1: return (v >> kSubpixelBits) * kSubpixelOne + kSubpixelHalf;   // pixel centre
      default: return v;                                                    // anywhere
    }
  };
  int triangles = 0, mismatches = 0;
  for (int trial = 0; trial < 3000; ++trial) {
    const ScreenVertex a = fixed_vertex(random_coord(), random_coord());
    ScreenVertex b = fixed_vertex(random_coord(), random_coord());
    ScreenVertex c = fixed_vertex(random_coord(), random_coord());
    if (trial % 5 == 0) b.y = a.y;  // horizontal edges (flat top / flat bottom)
    if (trial % 7 == 0) c.x = b.x;  // vertical edges
    CoverageGrid grid(w, h);
    if (auto t = setup(a, b, c, w, h)) grid.add(*t);
    ++triangles;
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) {
        const int expected = covers_reference(a, b, c, pixel_center(x), pixel_center(y)) ? 1 : 0;
        if (grid.at(x, y) != expected) {
          ++mismatches;
          if (mismatches < 5)
            MESSAGE("trial " << trial << " pixel " << x << "," << y << " got " << grid.at(x, y) << " expected "
                             << expected << " tri (" << a.x << "," << a.y << ") (" << b.x << "," << b.y << ") ("
                             << c.x << "," << c.y << ")");
        }
      }
  }
  CHECK(triangles == 3000);
  CHECK(mismatches == 0);
}

TEST_CASE("coverage: jittered grid mesh covers every interior pixel exactly once") {
  std::mt19937 rng(7);
  const int cells = 24, size = 96;  // 24 x 24 cells over 96 x 96 pixels, 1152 triangles
  const double step = double(size) / cells;
  // Jitter up to 0.2 cells per vertex: every quad stays strictly convex (the cross product of
  // consecutive edges (1 + a, b) x (c, 1 + d) with |a|..|d| <= 0.4 is >= 0.36 - 0.16 > 0), so
  // either diagonal splits it into two triangles that do not overlap.
  std::uniform_real_distribution<double> jitter(-0.2 * step, 0.2 * step);
  std::uniform_int_distribution<int> coin(0, 1);
  std::vector<ScreenVertex> v((cells + 1) * (cells + 1));
  for (int j = 0; j <= cells; ++j)
    for (int i = 0; i <= cells; ++i) {
      const bool border_x = i == 0 || i == cells, border_y = j == 0 || j == cells;
      double x = i * step + (border_x ? 0 : jitter(rng)), y = j * step + (border_y ? 0 : jitter(rng));
      if ((i + j) % 5 == 0 && !border_x && !border_y) {  // some vertices exactly on pixel centres
        x = std::floor(x) + 0.5;
        y = std::floor(y) + 0.5;
      }
      v[j * (cells + 1) + i] = pixel_vertex(x, y);
    }
  CoverageGrid grid(size, size);
  int drawn = 0;
  for (int j = 0; j < cells; ++j)
    for (int i = 0; i < cells; ++i) {
      const ScreenVertex& p00 = v[j * (cells + 1) + i];
      const ScreenVertex& p10 = v[j * (cells + 1) + i + 1];
      const ScreenVertex& p01 = v[(j + 1) * (cells + 1) + i];
      const ScreenVertex& p11 = v[(j + 1) * (cells + 1) + i + 1];
      // Random diagonal and random winding: neither may matter for coverage.
      const bool diag = coin(rng), flip = coin(rng);
      const ScreenVertex* tris[2][3] = {{&p00, &p10, diag ? &p11 : &p01}, {diag ? &p00 : &p10, &p11, &p01}};
      for (auto& t : tris) {
        auto s = flip ? setup(*t[0], *t[2], *t[1], size, size) : setup(*t[0], *t[1], *t[2], size, size);
        if (s) {
          grid.add(*s);
          ++drawn;
        }
      }
    }
  CHECK(drawn > 2 * cells * cells * 9 / 10);  // a sliver covering no centre is dropped at setup
  int wrong = 0;
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x) wrong += grid.at(x, y) != 1;
  CHECK(wrong == 0);
}

TEST_CASE("coverage: fan around a pixel centre covers every pixel exactly once") {
  // 64 triangles meeting at a vertex placed exactly on a pixel centre, rim on the border of a
  // 40 x 40 square with its corners on pixel corners; rim points land on corners and centres.
  const int size = 40;
  const ScreenVertex centre = pixel_vertex(17.5, 22.5);
  std::vector<ScreenVertex> rim;
  for (int k = 0; k < 16; ++k) rim.push_back(pixel_vertex(k * 2.5, 0));
  for (int k = 0; k < 16; ++k) rim.push_back(pixel_vertex(size, k * 2.5));
  for (int k = 0; k < 16; ++k) rim.push_back(pixel_vertex(size - k * 2.5, size));
  for (int k = 0; k < 16; ++k) rim.push_back(pixel_vertex(0, size - k * 2.5));
  CoverageGrid grid(size, size);
  for (size_t k = 0; k < rim.size(); ++k)
    if (auto t = setup(centre, rim[k], rim[(k + 1) % rim.size()], size, size)) grid.add(*t);
  int wrong = 0;
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x) wrong += grid.at(x, y) != 1;
  CHECK(wrong == 0);
}

TEST_CASE("coverage: a world-space ground grid through camera and near-plane clipping is watertight") {
  // A 40 x 40 grid of quads on the plane y = -1 spanning [-200, 200]^2, seen from the origin
  // looking down -Z: many triangles cross the near plane and lie partly behind the eye.
  DrawMesh mesh;
  const int cells = 40;
  std::mt19937 rng(99);
  std::uniform_real_distribution<float> jitter(-3.0f, 3.0f);
  for (int j = 0; j <= cells; ++j)
    for (int i = 0; i <= cells; ++i) {
      const bool border = i == 0 || j == 0 || i == cells || j == cells;
      mesh.positions.push_back({-200.0f + 10.0f * i + (border ? 0 : jitter(rng)), -1.0f,
                                -200.0f + 10.0f * j + (border ? 0 : jitter(rng))});
    }
  for (int j = 0; j < cells; ++j)
    for (int i = 0; i < cells; ++i) {
      const uint32_t a = j * (cells + 1) + i, b = a + 1, c = a + cells + 1, d = c + 1;
      mesh.indices.insert(mesh.indices.end(), {a, c, b, b, c, d});
    }
  const int w = 160, h = 120;
  const Mat4d clip_from_world = perspective_gltf(double(w) / h, 1.2, 0.05, std::optional<double>(1000.0));
  GeometryOptions options;
  options.grid_width = w;
  options.grid_height = h;
  options.has_far_plane = true;
  const auto triangles = setup_meshes({mesh}, clip_from_world, options);
  CHECK(triangles.size() > 100);  // the half behind the eye and far slivers without centres are gone
  CoverageGrid grid(w, h);
  for (const auto& t : triangles) grid.add(t);
  int double_hits = 0, holes = 0;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      double_hits += grid.at(x, y) > 1;
      // Rows well below the horizon (the middle row) see the plane everywhere: the plane's far
      // edge at 200 projects just under the horizon, its side edges outside the view.
      if (y >= h / 2 + 4) holes += grid.at(x, y) != 1;
    }
  CHECK(double_hits == 0);
  CHECK(holes == 0);
  // Above the horizon nothing is drawn (no wrap-around from vertices behind the eye).
  int above = 0;
  for (int y = 0; y < h / 2 - 1; ++y)
    for (int x = 0; x < w; ++x) above += grid.at(x, y);
  CHECK(above == 0);
}

TEST_CASE("coverage: huge triangles are cut by the guard band and stay watertight") {
  // A fan of triangles reaching 1e9 units sideways at 1 unit from the eye: projected, their
  // vertices are ~1e11 pixels away, far outside the fixed-point range, so the guard-band planes
  // cut them. Every pixel must still be covered exactly once (no overflow, no crack).
  DrawMesh mesh;
  mesh.positions.push_back({0.013f, -0.021f, -1.0f});  // the hub, inside the view
  const int spokes = 12;
  for (int k = 0; k < spokes; ++k) {
    const double angle = 2 * 3.14159265358979 * (k + 0.37) / spokes;
    mesh.positions.push_back({float(1e9 * std::cos(angle)), float(1e9 * std::sin(angle)), -1.0f});
  }
  for (int k = 0; k < spokes; ++k)
    mesh.indices.insert(mesh.indices.end(), {0u, uint32_t(1 + k), uint32_t(1 + (k + 1) % spokes)});
  const int w = 200, h = 150;
  for (const bool perspective : {true, false}) {
    CAPTURE(perspective);
    const Mat4d clip_from_world = perspective ? perspective_gltf(double(w) / h, 0.8, 0.01, std::optional<double>())
                                              : orthographic_gltf(2.0, 1.5, 0.0, 10.0);
    GeometryOptions options;
    options.grid_width = w;
    options.grid_height = h;
    options.has_far_plane = !perspective;
    const auto triangles = setup_meshes({mesh}, clip_from_world, options);
    CoverageGrid grid(w, h);
    for (const auto& t : triangles) grid.add(t);
    int wrong = 0;
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) wrong += grid.at(x, y) != 1;
    CHECK(wrong == 0);
  }
}
