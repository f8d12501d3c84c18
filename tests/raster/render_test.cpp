// End-to-end tests of render(): depth order, perspective-correct interpolation against an
// independent ray cast, near-plane clipping, orthographic coverage, culling, degenerate input,
// supersampling, determinism across thread counts, and frame_bounds.
#include <doctest/doctest.h>
#include <omp.h>

#include <cmath>
#include <cstring>
#include <algorithm>
#include <random>

#include "raster/fixed_point.h"
#include "raster/raster.h"

using namespace vlit;
using namespace vlit::raster;

namespace {

Camera camera_at(const Vec3d& eye, const Vec3d& target, double yfov = 0.9) {
  Camera c;
  c.world_from_camera = look_at(eye, target, Vec3d{0, 1, 0});
  c.yfov = yfov;
  c.znear = 0.1;
  return c;
}

DrawMesh quad(float z, float half, const Vec3f& color) {
  DrawMesh m;
  m.positions = {{-half, -half, z}, {half, -half, z}, {half, half, z}, {-half, half, z}};
  m.colors.assign(4, color);
  m.indices = {0, 1, 2, 0, 2, 3};
  return m;
}

const float* pixel(const Image& image, int x, int y) { return image.pixel(x, y); }

// Independent perspective-correct reference: cast the ray through a pixel centre (built from the
// camera's fov, not from the projection matrix) and intersect it with the triangle in world space.
// Returns the barycentric coordinates and the ray distance, or nothing if the ray is parallel.
struct Hit {
  double b0, b1, b2, t;
};
std::optional<Hit> ray_cast(const Camera& cam, int w, int h, double px, double py, const Vec3d& p0, const Vec3d& p1,
                            const Vec3d& p2) {
  const double tan_half = std::tan(0.5 * cam.yfov), aspect = double(w) / h;
  const Vec3d dir_cam{(2 * px / w - 1) * tan_half * aspect, (1 - 2 * py / h) * tan_half, -1};
  const Vec3d origin = transform_point(cam.world_from_camera, Vec3d{0, 0, 0});
  const Vec3d dir = transform_vector(cam.world_from_camera, dir_cam);
  const Vec3d e1 = p1 - p0, e2 = p2 - p0, n = cross(e1, e2);
  const double denom = dot(n, dir);
  if (std::abs(denom) < 1e-15) return std::nullopt;
  const double t = dot(n, p0 - origin) / denom;
  const Vec3d q = origin + dir * t;
  const double area = dot(n, n);
  // q - p0 = b1 e1 + b2 e2, so (q - p0) x e2 = b1 n and e1 x (q - p0) = b2 n.
  const double b1 = dot(cross(q - p0, e2), n) / area;
  const double b2 = dot(cross(e1, q - p0), n) / area;
  return Hit{1 - b1 - b2, b1, b2, t};
}

bool same_pixels(const Image& a, const Image& b) {
  return a.width == b.width && a.height == b.height && a.rgb.size() == b.rgb.size() &&
         std::memcmp(a.rgb.data(), b.rgb.data(), a.rgb.size() * sizeof(float)) == 0;
}

}  // namespace

TEST_CASE("render: the near triangle hides the far one whatever the draw order") {
  const Camera cam = camera_at({0, 0, 5}, {0, 0, 0});
  RenderOptions options;
  options.width = 64;
  options.height = 48;
  const DrawMesh near_quad = quad(0.5f, 1.0f, {1, 0, 0});
  const DrawMesh far_quad = quad(-0.5f, 1.5f, {0, 0, 1});
  for (const auto& order : {std::vector<DrawMesh>{near_quad, far_quad}, std::vector<DrawMesh>{far_quad, near_quad}}) {
    const Image image = render(order, cam, options);
    REQUIRE(image.rgb.size() == size_t(64 * 48 * 3));
    const float* centre = pixel(image, 32, 24);
    CHECK(centre[0] == 1.0f);
    CHECK(centre[2] == 0.0f);
    // The far quad is larger: it shows around the near one (near quad: 11 px above the centre,
    // far quad: 13.5 px).
    CHECK(pixel(image, 32, 24 - 12)[2] == 1.0f);
    CHECK(pixel(image, 32, 24 - 12)[0] == 0.0f);
    CHECK(pixel(image, 0, 0)[0] == 0.0f);  // background
  }
}

TEST_CASE("render: colour at pixel centres is the perspective-correct barycentric interpolation") {
  // A strongly tilted triangle (depth ratio ~ 8) so affine interpolation would be visibly wrong.
  const Vec3d p0{-2, -1, -1}, p1{3, -1, -15}, p2{-1, 2.5, -8};
  const Vec3f c0{1, 0, 0}, c1{0, 1, 0}, c2{0, 0, 1};
  DrawMesh mesh;
  mesh.positions = {Vec3f(p0), Vec3f(p1), Vec3f(p2)};
  mesh.colors = {c0, c1, c2};
  mesh.indices = {0, 1, 2};
  Camera cam = camera_at({0, 0, 1}, {0, 0, -5});
  RenderOptions options;
  options.width = 96;
  options.height = 64;
  const Image image = render({mesh}, cam, options);
  int checked = 0;
  double max_error = 0;
  for (int y = 0; y < options.height; ++y)
    for (int x = 0; x < options.width; ++x) {
      const auto hit = ray_cast(cam, options.width, options.height, x + 0.5, y + 0.5, p0, p1, p2);
      if (!hit || hit->b0 < 0.02 || hit->b1 < 0.02 || hit->b2 < 0.02) continue;  // clear of the edges
      const Vec3d expected = Vec3d(c0) * hit->b0 + Vec3d(c1) * hit->b1 + Vec3d(c2) * hit->b2;
      const float* got = pixel(image, x, y);
      for (int k = 0; k < 3; ++k) max_error = std::max(max_error, std::abs(got[k] - expected[k]));
      ++checked;
    }
  MESSAGE("checked " << checked << " pixel centres, max |error| " << max_error);
  CHECK(checked > 300);
  CHECK(max_error < 2e-3);  // vertex snapping moves vertices by <= 1/512 px
}

TEST_CASE("render: a triangle crossing the near plane draws its visible part, nothing wraps around") {
  // A large floor triangle with one vertex far behind the camera.
  const Vec3d p0{-4, -1, -20}, p1{4, -1, -20}, p2{0, -1, 30};
  DrawMesh mesh;
  mesh.positions = {Vec3f(p0), Vec3f(p1), Vec3f(p2)};
  mesh.colors.assign(3, Vec3f{1, 1, 1});
  mesh.indices = {0, 1, 2};
  const Camera cam = camera_at({0, 0, 0}, {0, 0, -1});
  RenderOptions options;
  options.width = 80;
  options.height = 60;
  const Image image = render({mesh}, cam, options);
  int covered = 0, mismatches = 0;
  for (int y = 0; y < options.height; ++y)
    for (int x = 0; x < options.width; ++x) {
      const auto hit = ray_cast(cam, options.width, options.height, x + 0.5, y + 0.5, p0, p1, p2);
      const bool drawn = pixel(image, x, y)[0] > 0.5f;
      covered += drawn;
      if (!hit) continue;
      const double margin = std::min({hit->b0, hit->b1, hit->b2});
      if (std::abs(margin) < 1e-3) continue;  // too close to an edge to call
      const bool visible = margin > 0 && hit->t > 0.1;
      if (visible != drawn) ++mismatches;
    }
  CHECK(covered > 200);
  CHECK(mismatches == 0);
}

TEST_CASE("render: an orthographic square on pixel corners covers exactly its pixels") {
  Camera cam;
  cam.orthographic = true;
  cam.xmag = 1;
  cam.ymag = 1;
  cam.znear = 0;
  cam.zfar = 10;
  RenderOptions options;
  options.width = 64;
  options.height = 64;
  const Image image = render({quad(-1.0f, 0.5f, {1, 1, 1})}, cam, options);
  int covered = 0, outside = 0;
  for (int y = 0; y < 64; ++y)
    for (int x = 0; x < 64; ++x) {
      const bool drawn = pixel(image, x, y)[0] == 1.0f;
      covered += drawn;
      outside += drawn != (x >= 16 && x < 48 && y >= 16 && y < 48);
    }
  CHECK(covered == 32 * 32);
  CHECK(outside == 0);
  // Beyond zfar: clipped away.
  const Image far_image = render({quad(-11.0f, 0.5f, {1, 1, 1})}, cam, options);
  CHECK(pixel(far_image, 32, 32)[0] == 0.0f);
}

TEST_CASE("render: back faces are culled only in single-sided meshes with culling on") {
  const Camera cam = camera_at({0, 0, 5}, {0, 0, 0});
  DrawMesh back = quad(0, 1, {1, 1, 1});
  back.indices = {0, 2, 1, 0, 3, 2};  // clockwise as seen from the camera
  DrawMesh front = quad(0, 1, {1, 1, 1});
  RenderOptions options;
  options.width = options.height = 32;
  const auto centre = [&](const DrawMesh& m, bool cull, bool double_sided) {
    DrawMesh copy = m;
    copy.double_sided = double_sided;
    RenderOptions o = options;
    o.cull_back_faces = cull;
    return pixel(render({copy}, cam, o), 16, 16)[0];
  };
  CHECK(centre(back, true, false) == 0.0f);
  CHECK(centre(back, true, true) == 1.0f);
  CHECK(centre(back, false, false) == 1.0f);
  CHECK(centre(front, true, false) == 1.0f);
}

TEST_CASE("render: degenerate triangles are skipped without crashing") {
  const Camera cam = camera_at({0, 0, 5}, {0, 0, 0});
  DrawMesh mesh = quad(0, 1, {0, 1, 0});
  const float inf = std::numeric_limits<float>::infinity(), nan = std::numeric_limits<float>::quiet_NaN();
  const uint32_t base = uint32_t(mesh.positions.size());
  mesh.positions.insert(mesh.positions.end(), {{nan, 0, 0}, {inf, 1, 0}, {0, -inf, 0}, {1e38f, 1e38f, -1e38f},
                                               {0.2f, 0.2f, 0.2f}});
  mesh.colors.resize(mesh.positions.size(), Vec3f{1, 0, 0});
  mesh.indices.insert(mesh.indices.end(), {base, 0, 1, base + 1, 1, 2, base + 2, base + 3, 0,
                                           base + 4, base + 4, base + 4,   // a point
                                           0, 2, 0,                         // a segment
                                           0, 1, 999});                     // out of range
  mesh.indices.push_back(0);  // a dangling index (not a multiple of 3)
  RenderOptions options;
  options.width = 40;
  options.height = 30;
  options.samples = 4;
  RenderWorkspace workspace;
  Image image;
  render({mesh}, cam, options, workspace, image);
  REQUIRE(image.rgb.size() == size_t(40 * 30 * 3));
  for (float v : image.rgb) REQUIRE(std::isfinite(v));
  CHECK(pixel(image, 20, 15)[1] == 1.0f);  // the valid quad still renders
  CHECK(workspace.bad_index_triangles() == 1);  // 0, 1, 999 is counted, not silently dropped
  render({quad(0, 1, {0, 1, 0})}, cam, options, workspace, image);
  CHECK(workspace.bad_index_triangles() == 0);  // per frame
  // Empty meshes and empty scene.
  CHECK(render({DrawMesh{}}, cam, options).rgb.size() == size_t(40 * 30 * 3));
  CHECK(render({}, cam, options).rgb.size() == size_t(40 * 30 * 3));
}

TEST_CASE("render: invalid options are refused with a message, render returns an empty image") {
  const Camera cam = camera_at({0, 0, 5}, {0, 0, 0});
  RenderOptions options;
  options.width = 0;
  CHECK_FALSE(validate_render_options(options).empty());
  CHECK(render({quad(0, 1, {1, 1, 1})}, cam, options).rgb.empty());
  options.width = 10;
  options.samples = 3;
  CHECK_FALSE(validate_render_options(options).empty());
  options.samples = 16;
  CHECK(validate_render_options(options).empty());
  options.width = kMaxGridSize;  // times 4 samples per side: too large
  CHECK_FALSE(validate_render_options(options).empty());
  Camera bad = cam;
  bad.znear = 0;
  CHECK_FALSE(validate_camera(bad).empty());
  bad = cam;
  bad.orthographic = true;  // no zfar
  CHECK_FALSE(validate_camera(bad).empty());
  CHECK(validate_camera(cam).empty());
}

TEST_CASE("render: supersampling resolves a half-covered pixel to the box-filter average") {
  // Orthographic, 4 x 4 pixels spanning [-1, 1]; a quad covering x in [-1, 0.25] covers pixel 2
  // (x from 0 to 0.5) exactly half: with 16 samples (4 x 4 grid), 2 of 4 sample columns.
  Camera cam;
  cam.orthographic = true;
  cam.znear = 0;
  cam.zfar = 10;
  DrawMesh m;
  m.positions = {{-1, -1, -1}, {0.25f, -1, -1}, {0.25f, 1, -1}, {-1, 1, -1}};
  m.colors.assign(4, Vec3f{1, 0.5f, 0.25f});
  m.indices = {0, 1, 2, 0, 2, 3};
  RenderOptions options;
  options.width = options.height = 4;
  options.samples = 16;
  options.background = {0, 0, 1};
  const Image image = render({m}, cam, options);
  for (int y = 0; y < 4; ++y) {
    CHECK(pixel(image, 1, y)[0] == 1.0f);
    CHECK(pixel(image, 2, y)[0] == 0.5f);
    CHECK(pixel(image, 2, y)[1] == 0.25f);
    CHECK(pixel(image, 2, y)[2] == doctest::Approx(0.5 * 0.25 + 0.5 * 1.0));
    CHECK(pixel(image, 3, y)[2] == 1.0f);
  }
}

TEST_CASE("render: output is bit-identical whatever the thread count") {
  std::mt19937 rng(31337);
  std::uniform_real_distribution<float> pos(-3, 3), col(0, 1);
  DrawMesh mesh;
  for (int i = 0; i < 3000; ++i) {
    mesh.positions.push_back({pos(rng), pos(rng), pos(rng) - 1});
    mesh.colors.push_back({col(rng), col(rng), col(rng)});
  }
  for (int i = 0; i < 2000; ++i) {
    std::uniform_int_distribution<uint32_t> idx(0, 2999);
    mesh.indices.insert(mesh.indices.end(), {idx(rng), idx(rng), idx(rng)});
  }
  const Camera cam = camera_at({0.5, 1, 3}, {0, 0, -1});  // some triangles cross the near plane
  RenderOptions options;
  options.width = 173;  // bands of uneven size
  options.height = 131;
  options.samples = 4;
  const int saved = omp_get_max_threads();
  omp_set_num_threads(1);
  const Image one = render({mesh}, cam, options);
  omp_set_num_threads(2);
  const Image two = render({mesh}, cam, options);
  omp_set_num_threads(3);
  const Image three = render({mesh}, cam, options);
  omp_set_num_threads(saved);
  CHECK(same_pixels(one, two));
  CHECK(same_pixels(one, three));
}

TEST_CASE("frame_bounds: the whole box lands inside the image, filling 90% of it") {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> log_scale(-3, 6), unit(-1, 1);
  for (int trial = 0; trial < 200; ++trial) {
    const double scale = std::pow(10.0, log_scale(rng));
    const Vec3d centre{unit(rng) * scale * 10, unit(rng) * scale * 10, unit(rng) * scale * 10};
    const Vec3d half{scale * (0.01 + std::abs(unit(rng))), scale * (0.01 + std::abs(unit(rng))),
                     scale * (trial % 10 == 0 ? 0.0 : std::abs(unit(rng)))};  // some flat boxes
    const double aspect = std::pow(2.0, unit(rng) * 2);
    const Camera cam = frame_bounds(centre - half, centre + half, aspect);
    REQUIRE(validate_camera(cam).empty());
    const auto clip_from_world_m = clip_from_world(cam, aspect);
    REQUIRE(clip_from_world_m);
    double widest = 0;
    for (int corner = 0; corner < 8; ++corner) {
      const Vec3d p{centre.x + (corner & 1 ? half.x : -half.x), centre.y + (corner & 2 ? half.y : -half.y),
                    centre.z + (corner & 4 ? half.z : -half.z)};
      const Vec4d h = transform_point_h(*clip_from_world_m, p);
      CAPTURE(trial);
      CHECK(h.w > 0);
      CHECK(std::abs(h.x / h.w) < 1.0);
      CHECK(std::abs(h.y / h.w) < 1.0);
      CHECK(std::abs(h.z / h.w) < 1.0);
      widest = std::max({widest, std::abs(h.x / h.w), std::abs(h.y / h.w)});
    }
    CHECK(widest == doctest::Approx(0.9).epsilon(1e-6));  // tight: the box fills 90% of one axis
  }
  // Degenerate boxes still give a usable camera.
  CHECK(validate_camera(frame_bounds({0, 0, 0}, {0, 0, 0}, 1.5)).empty());
  CHECK(validate_camera(frame_bounds({1, 1, 1}, {-1, -1, -1}, 1.5)).empty());
  CHECK(validate_camera(frame_bounds({NAN, 0, 0}, {1, 1, 1}, 0)).empty());
}

TEST_CASE("render: reversed float depth separates surfaces far away with an infinite projection") {
  // Two quads 1000.0 and 1000.5 units away, znear = 0.01, no zfar: stored depths znear/distance =
  // 1.0e-5 and 0.9995e-5 differ by 5e-4 relative, far above float resolution. A conventional
  // [0, 1] window depth (1 - znear/distance) would round both to the same float.
  Camera cam = camera_at({0, 0, 0}, {0, 0, -1});
  cam.znear = 0.01;
  cam.zfar.reset();
  RenderOptions options;
  options.width = options.height = 16;
  const DrawMesh near_quad = quad(-1000.0f, 400.0f, {1, 0, 0});
  const DrawMesh far_quad = quad(-1000.5f, 400.0f, {0, 1, 0});
  CHECK(float(1.0 - 0.01 / 1000.0) == float(1.0 - 0.01 / 1000.5));  // why reversed depth is needed
  for (const auto& order : {std::vector<DrawMesh>{near_quad, far_quad}, std::vector<DrawMesh>{far_quad, near_quad}}) {
    const Image image = render(order, cam, options);
    CHECK(pixel(image, 8, 8)[0] == 1.0f);
    CHECK(pixel(image, 8, 8)[1] == 0.0f);
  }
}

TEST_CASE("render: a very wide image with 16 samples (one-row bands) resolves correctly") {
  Camera cam;
  cam.orthographic = true;
  cam.znear = 0;
  cam.zfar = 10;
  DrawMesh m;  // covers the left half of the view: x in [-1, 0]
  m.positions = {{-1, -1, -1}, {0, -1, -1}, {0, 1, -1}, {-1, 1, -1}};
  m.colors.assign(4, Vec3f{1, 1, 1});
  m.indices = {0, 1, 2, 0, 2, 3};
  RenderOptions options;
  options.width = kMaxGridSize / 4;  // 131072 pixels, 524288 samples wide
  options.height = 3;
  options.samples = 16;
  REQUIRE(validate_render_options(options).empty());
  const Image image = render({m}, cam, options);
  REQUIRE(image.width == options.width);
  for (int y = 0; y < 3; ++y) {
    CHECK(pixel(image, 0, y)[0] == 1.0f);
    CHECK(pixel(image, options.width / 2 - 1, y)[0] == 1.0f);
    CHECK(pixel(image, options.width / 2, y)[0] == 0.0f);
    CHECK(pixel(image, options.width - 1, y)[0] == 0.0f);
  }
}
