// The wireframe debug view (render.h, WireframeOptions): wire samples lie within the stated line
// width of a projected triangle edge, and every visible sample that close to an edge is wire;
// edges made by near-plane clipping are not drawn; hidden edges stay hidden; the image is
// bit-identical on any thread count. The projected edges are computed here from the glTF
// orthographic/perspective definitions, not with the rasterizer's matrices.
#include <doctest/doctest.h>
#include <omp.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <vector>

#include "raster/raster.h"

using namespace vlit;
using namespace vlit::raster;

namespace {

struct Point2 {
  double x, y;
};

// Distance from p to the line through a and b.
double line_distance(Point2 p, Point2 a, Point2 b) {
  const double ex = b.x - a.x, ey = b.y - a.y;
  return std::abs(ex * (p.y - a.y) - ey * (p.x - a.x)) / std::hypot(ex, ey);
}

// Whether p is inside triangle abc (either winding), with a margin in pixels (negative = shrink).
double inside_margin(Point2 p, Point2 a, Point2 b, Point2 c) {
  const auto signed_dist = [](Point2 q, Point2 u, Point2 v) {
    return ((v.x - u.x) * (q.y - u.y) - (v.y - u.y) * (q.x - u.x)) / std::hypot(v.x - u.x, v.y - u.y);
  };
  const double area = (b.x - a.x) * (c.y - a.y) - (c.x - a.x) * (b.y - a.y);
  const double s = area > 0 ? 1 : -1;
  return std::min({s * signed_dist(p, a, b), s * signed_dist(p, b, c), s * signed_dist(p, c, a)});
}

bool is_color(const float* px, const Vec3f& c) { return px[0] == c.x && px[1] == c.y && px[2] == c.z; }

}  // namespace

TEST_CASE("wireframe: wire pixels lie on projected edges, and pixels near an edge are wire (orthographic)") {
  // An irregular 4 x 3 grid of triangles in the plane z = 0, seen by an orthographic camera whose
  // view maps x in [-xmag, xmag] to [0, W] and y in [-ymag, ymag] to [H, 0] (glTF orthographic).
  constexpr int kW = 160, kH = 120, kCols = 4, kRows = 3;
  const double xmag = 2.0, ymag = 1.5;
  DrawMesh mesh;
  for (int j = 0; j <= kRows; ++j)
    for (int i = 0; i <= kCols; ++i) {
      const double jitter_x = 0.13 * std::sin(3.1 * i + 1.7 * j), jitter_y = 0.11 * std::cos(2.3 * i - 0.9 * j);
      mesh.positions.push_back({float(-1.7 + 3.4 * i / kCols + jitter_x), float(-1.2 + 2.4 * j / kRows + jitter_y), 0.0f});
    }
  for (int j = 0; j < kRows; ++j)
    for (int i = 0; i < kCols; ++i) {
      const uint32_t a = j * (kCols + 1) + i, b = a + 1, c = a + kCols + 2, d = a + kCols + 1;
      mesh.indices.insert(mesh.indices.end(), {a, b, c, a, c, d});
    }
  mesh.colors.assign(mesh.positions.size(), Vec3f{0.2f, 0.2f, 0.2f});
  Camera camera;
  camera.orthographic = true;
  camera.xmag = xmag;
  camera.ymag = ymag;
  camera.znear = 0.1;
  camera.zfar = 10;
  camera.world_from_camera = look_at(Vec3d{0, 0, 5}, Vec3d{0, 0, 0}, Vec3d{0, 1, 0});
  RenderOptions options;
  options.width = kW;
  options.height = kH;
  options.samples = 1;
  options.background = {0, 0, 1};
  options.wireframe.enabled = true;
  options.wireframe.color = {1, 1, 1};
  for (double width : {0.5, 1.5}) {
    CAPTURE(width);
    options.wireframe.width = width;
    const Image image = render({mesh}, camera, options);
    const auto to_pixel = [&](const Vec3f& p) {
      return Point2{(p.x / xmag + 1) * 0.5 * kW, (1 - p.y / ymag) * 0.5 * kH};
    };
    constexpr double kSnap = 1.0 / 256;  // vertices move by at most half of this when snapped
    int wire = 0, near_edge = 0, wrong = 0;
    for (int y = 0; y < kH; ++y)
      for (int x = 0; x < kW; ++x) {
        const Point2 centre{x + 0.5, y + 0.5};
        const float* px = image.pixel(x, y);
        // The triangle that owns this centre (the one it is inside of by the largest margin) and
        // its distance to that triangle's nearest edge.
        double best_margin = -1e30, edge_distance = 1e30;
        for (size_t t = 0; t < mesh.indices.size(); t += 3) {
          const Point2 a = to_pixel(mesh.positions[mesh.indices[t]]), b = to_pixel(mesh.positions[mesh.indices[t + 1]]),
                       c = to_pixel(mesh.positions[mesh.indices[t + 2]]);
          const double margin = inside_margin(centre, a, b, c);
          if (margin > best_margin) {
            best_margin = margin;
            edge_distance = std::min({line_distance(centre, a, b), line_distance(centre, b, c), line_distance(centre, c, a)});
          }
        }
        const bool is_wire = is_color(px, options.wireframe.color);
        wire += is_wire;
        if (best_margin < -kSnap) {  // outside the mesh: background
          wrong += !is_color(px, options.background);
          continue;
        }
        if (best_margin < kSnap) continue;  // on the mesh border, too close to call coverage
        if (edge_distance < width - kSnap) {
          ++near_edge;
          wrong += !is_wire;
        } else if (edge_distance > width + kSnap) {
          wrong += is_wire;
        }
      }
    MESSAGE("width " << width << ": " << wire << " wire pixels, " << near_edge << " centres within the width of an edge");
    CHECK(wire > 400);
    CHECK(near_edge > 400);
    CHECK(wrong == 0);
  }
}

TEST_CASE("wireframe: edges made by near-plane clipping are not drawn, hidden edges are not drawn") {
  // A huge floor triangle 0.02 below a camera looking along -Z: the near plane (znear 0.1) cuts it
  // inside the image (at 0.02 / (0.1 tan(0.45)) = 41% of the half height below the centre), and
  // its own edges are more than 900 units to the sides, outside the bottom half of the image.
  DrawMesh floor;
  floor.positions = {{-1000, -0.02f, 5}, {1000, -0.02f, 5}, {0, -0.02f, -1000}};
  floor.colors.assign(3, Vec3f{0.3f, 0.3f, 0.3f});
  floor.indices = {0, 1, 2};
  Camera camera;
  camera.world_from_camera = look_at(Vec3d{0, 0, 0}, Vec3d{0, 0, -1}, Vec3d{0, 1, 0});
  camera.yfov = 0.9;
  camera.znear = 0.1;
  RenderOptions options;
  options.width = 120;
  options.height = 90;
  options.samples = 4;
  options.wireframe.enabled = true;
  options.wireframe.width = 1.0;
  options.wireframe.color = {1, 0, 0};
  // A small quad in front of the floor's far part, with its own edges.
  DrawMesh quad;
  quad.positions = {{-0.3f, -0.01f, -2}, {0.3f, -0.01f, -2}, {0.3f, 0.4f, -2}, {-0.3f, 0.4f, -2}};
  quad.colors.assign(4, Vec3f{0, 0.5f, 0});
  quad.indices = {0, 1, 2, 0, 2, 3};
  // The same quad hidden behind a large occluder (one triangle whose bottom edge projects to row
  // 45.9 and whose other edges are outside the image): the quad's edges must not show through.
  DrawMesh occluder;
  occluder.positions = {{-50, -0.015f, -1.5f}, {50, -0.015f, -1.5f}, {0, 50, -1.5f}};
  occluder.colors.assign(3, Vec3f{0, 0, 0.5f});
  occluder.indices = {0, 1, 2};

  const Image image = render({floor, quad}, camera, options);
  int covered = 0, red_bottom = 0, red_quad = 0;
  for (int y = options.height / 2 + 2; y < options.height; ++y)
    for (int x = 0; x < options.width; ++x) {
      covered += image.pixel(x, y)[1] > 0;
      red_bottom += image.pixel(x, y)[0] > image.pixel(x, y)[1];
    }
  for (int y = 0; y < options.height / 2; ++y)
    for (int x = 0; x < options.width; ++x) red_quad += image.pixel(x, y)[0] > 0.5f;
  CHECK(covered > 500);     // the floor is drawn down to the near-plane cut...
  CHECK(red_bottom == 0);   // ...without a wire along the cut or along the fan's diagonals
  CHECK(red_quad > 50);     // the quad's own edges are drawn

  const Image hidden = render({floor, quad, occluder}, camera, options);
  int red_hidden = 0;
  for (int y = 0; y < options.height / 2 - 2; ++y)
    for (int x = 0; x < options.width; ++x) {
      const float* px = hidden.pixel(x, y);
      // Inside the occluder's interior only its own colour (its edges are outside the image).
      red_hidden += px[0] > 0;
    }
  CHECK(red_hidden == 0);
}

TEST_CASE("wireframe: bit-identical images on 1, 2 and 3 threads") {
  DrawMesh mesh;
  constexpr int n = 40;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) {
      const float u = float(i) / n, v = float(j) / n;
      mesh.positions.push_back({u * 2 - 1, v * 2 - 1, 0.3f * std::sin(6 * u) * std::cos(5 * v) - 2});
      mesh.colors.push_back({u, v, 1 - u});
    }
  for (uint32_t j = 0; j < n; ++j)
    for (uint32_t i = 0; i < n; ++i) {
      const uint32_t a = j * (n + 1) + i;
      mesh.indices.insert(mesh.indices.end(), {a, a + 1, a + n + 2, a, a + n + 2, a + n + 1});
    }
  Camera camera;
  camera.world_from_camera = look_at(Vec3d{0.4, 0.9, 0.5}, Vec3d{0, 0, -2}, Vec3d{0, 1, 0});
  camera.znear = 0.05;
  RenderOptions options;
  options.width = 97;
  options.height = 131;
  options.samples = 4;
  options.wireframe.enabled = true;
  const int saved = omp_get_max_threads();
  std::vector<Image> images;
  for (int threads : {1, 2, 3}) {
    omp_set_num_threads(threads);
    images.push_back(render({mesh}, camera, options));
  }
  omp_set_num_threads(saved);
  for (size_t k = 1; k < images.size(); ++k)
    CHECK(std::memcmp(images[0].rgb.data(), images[k].rgb.data(), images[0].rgb.size() * sizeof(float)) == 0);
  // And the wire changed the picture.
  options.wireframe.enabled = false;
  const Image shaded = render({mesh}, camera, options);
  CHECK(std::memcmp(images[0].rgb.data(), shaded.rgb.data(), shaded.rgb.size() * sizeof(float)) != 0);
}

TEST_CASE("wireframe: a bad line width is refused by validate_render_options") {
  RenderOptions options;
  options.wireframe.enabled = true;
  options.wireframe.width = 0;
  CHECK(!validate_render_options(options).empty());
  options.wireframe.width = std::nan("");
  CHECK(!validate_render_options(options).empty());
  options.wireframe.width = 1;
  CHECK(validate_render_options(options).empty());
}
