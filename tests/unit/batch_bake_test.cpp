// The bake's float batch path (bake/batch_lighting.h): its result does not depend on the number
// of threads, it agrees with the scalar double path within the float bar, and the plan says which
// lights use it.
#include <doctest/doctest.h>

#include <omp.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <optional>

#include "bake/light_vertices.h"
#include "plan/scene_plan.h"

using namespace vlit;

namespace {

// A wavy sheet of side x side vertices with analytic normals, over [-2, 2]^2.
ScenePrimitive wavy_sheet(int side) {
  ScenePrimitive p;
  for (int j = 0; j < side; ++j)
    for (int i = 0; i < side; ++i) {
      const double x = -2 + 4.0 * i / (side - 1), y = -2 + 4.0 * j / (side - 1);
      const double z = 0.2 * std::sin(3 * x) * std::cos(2 * y);
      p.positions.push_back({x, y, z});
      p.normals.push_back(normalize(Vec3d{-0.6 * std::cos(3 * x) * std::cos(2 * y), 0.4 * std::sin(3 * x) * std::sin(2 * y), 1}));
    }
  return p;
}

Scene test_scene() {
  Scene scene;
  scene.primitives.push_back(wavy_sheet(131));  // 17161 vertices: one full chunk of 16384 and a partial one
  auto add = [&](LightSource l, const char* name) {
    l.name = name;
    scene.lights.push_back(std::move(l));
  };
  LightSource quad;
  quad.type = LightType::kArea;
  quad.polygon = {{-1, -1, 2}, {-1, 0, 2}, {0, 0, 2.2}, {0, -1, 2.2}};  // counter-clockwise seen from below
  add(quad, "quad");
  LightSource tri;
  tri.type = LightType::kArea;
  tri.polygon = {{1, 1, 1}, {1.5, 1, 1.2}, {1, 1.6, 1}};
  tri.two_sided = true;
  add(tri, "triangle");
  LightSource l_shape;
  l_shape.type = LightType::kArea;
  l_shape.polygon = {{0, 0, 3}, {0, 2, 3}, {1, 2, 3}, {1, 1, 3}, {2, 1, 3}, {2, 0, 3}};
  add(l_shape, "l-shape");
  LightSource tube;
  tube.type = LightType::kLinear;
  tube.from = {-2, 1, 1};
  tube.to = {2, 1.5, 1.2};
  tube.color = {1, 0.5, 0.25};
  add(tube, "tube2");
  tube.from = {1, -2, 0.8};
  tube.to = {1.2, 2, 0.7};
  tube.falloff = 3;
  add(tube, "tube3");
  tube.falloff = 1;
  add(tube, "tube1");
  LightSource point;
  point.position = {0.3, 0.2, 1.5};
  point.range = 3.0;
  add(point, "point");
  LightSource spot;
  spot.type = LightType::kSpot;
  spot.position = {-0.5, 0.5, 2};
  spot.direction = normalize(Vec3d{0.3, 0, -1});
  spot.cos_inner = std::cos(0.4);
  spot.cos_outer = std::cos(0.7);
  add(spot, "spot");
  LightSource disk;  // tilted, so that the sheet's horizon cuts it for some vertices (scalar arc lanes)
  disk.type = LightType::kDisk;
  disk.center = {-1, 1, 1.4};
  disk.normal = normalize(Vec3d{0.4, -0.3, -1});
  disk.radius = 0.6;
  add(disk, "disk");
  return scene;
}

// A flat tile of 4 vertices at z = 10 facing down, above the tubes, with the default material.
ScenePrimitive tile_above_tubes() {
  ScenePrimitive tile;
  for (int j = 0; j < 2; ++j)
    for (int i = 0; i < 2; ++i) {
      tile.positions.push_back({-1.0 + 2 * i, -1.0 + 2 * j, 10});
      tile.normals.push_back({0, 0, -1});
    }
  tile.triangles = {0, 1, 3, 0, 3, 2};
  return tile;
}

std::vector<VertexLight> light_with_threads(const Scene& scene, int threads, bool float_batch,
                                           std::optional<Vec3d> eye = std::nullopt) {
  const int saved = omp_get_max_threads();
  omp_set_num_threads(threads);
  LightingRequest request;
  request.float_batch = float_batch;
  request.eye = eye;
  auto out = light_scene_vertices(scene, request);
  omp_set_num_threads(saved);
  return out;
}

}  // namespace

TEST_CASE("batch bake: the plan names the float batch kernels and why the others stay scalar") {
  const Scene scene = test_scene();
  const std::string text = describe(plan_lighting(scene, LightingRequest{}), scene);
  CHECK(text.find("light quad: area contour integral (eq. 9), 17161 vertices, float SIMD batch") != std::string::npos);
  CHECK(text.find("light disk: ") != std::string::npos);
  CHECK(text.find("float SIMD batch", text.find("light disk: ")) < text.find('\n', text.find("light disk: ")));
  CHECK(text.find("light l-shape: area contour integral (eq. 9), 17161 vertices, scalar double (non-convex polygon)") !=
        std::string::npos);
  CHECK(text.find("light tube1: linear closed form (eq. 4), 17161 vertices, float SIMD batch") != std::string::npos);
  LightingRequest with_eye;
  with_eye.eye = Vec3d{0, 0, 5};
  const std::string spec = describe(plan_lighting(scene, with_eye), scene);
  CHECK(spec.find("light quad: area contour integral (eq. 9), 17161 vertices, float SIMD batch") != std::string::npos);
  CHECK(spec.find("; specular exact: scalar double (batch area specular not faster than scalar)\n", spec.find("light quad: ")) <
        spec.find('\n', spec.find("light quad: ")));
  CHECK(spec.find("; specular exact: scalar double (batch linear specular needs the inverse-square falloff)\n",
                  spec.find("light tube1: ")) < spec.find('\n', spec.find("light tube1: ")));
  CHECK(spec.find("; specular exact: double SIMD batch", spec.find("light tube2: ")) < spec.find('\n', spec.find("light tube2: ")));
  CHECK(spec.find("; specular exact: double SIMD batch", spec.find("light spot: ")) < spec.find('\n', spec.find("light spot: ")));
  CHECK(spec.find("(non-convex polygon); specular exact: scalar double\n") != std::string::npos);
  LightingRequest scalar;
  scalar.float_batch = false;
  CHECK(describe(plan_lighting(scene, scalar), scene).find("scalar double (double precision requested)") != std::string::npos);
}

TEST_CASE("batch bake: the plan says where the linear batch specular does not cover the materials' shininess") {
  // Roughness 0.6 maps to the real exponent m = 2 / 0.6^4 - 2 = 13.43 (scene/material.h), which
  // the linear kernel (integer m) does not take; the default material (m = 1) it does.
  Scene scene = test_scene();
  Material rough;
  rough.roughness = 0.6;
  scene.materials.push_back(rough);
  scene.primitives[0].material = 0;
  LightingRequest with_eye;
  with_eye.eye = Vec3d{0, 0, 5};
  const std::string all_real = describe(plan_lighting(scene, with_eye), scene);
  std::size_t line = all_real.find("light tube2: ");
  CHECK(all_real.find("; specular exact: scalar double (no batch kernel for the materials' shininess)\n", line) <
        all_real.find('\n', line));
  // A tile above the tubes facing down, with the default material: part of the light's vertices
  // are covered.
  scene.primitives.push_back(tile_above_tubes());
  const std::string mixed = describe(plan_lighting(scene, with_eye), scene);
  line = mixed.find("light tube2: ");
  CHECK(mixed.find(", scalar double for 17161 vertices (no batch kernel for their materials' shininess)\n", line) <
        mixed.find('\n', line));
}

TEST_CASE("batch bake: the plan says which lights' pairs run the shadowed scalar path") {
  Scene scene = test_scene();
  scene.primitives[0].triangles = {0, 1, 131};  // the wavy sheet may shadow itself: every pair shadowed
  LightingRequest shadows;
  shadows.shadows = true;
  const std::string all = describe(plan_lighting(scene, shadows), scene);
  CHECK(all.find("light quad: area contour integral (eq. 9), 17161 vertices, scalar double (shadowed: the visible "
                 "part of the light, eq. 10)\n") != std::string::npos);
  CHECK(all.find("float SIMD batch") == std::string::npos);
  // A flat tile facing down above the tubes, with nothing between them: its pairs stay unshadowed.
  scene.primitives.push_back(tile_above_tubes());
  const std::string some = describe(plan_lighting(scene, shadows), scene);
  const std::size_t line = some.find("light tube2: ");
  CHECK(some.find("light tube2: linear closed form (eq. 4), 17165 vertices, float SIMD batch") != std::string::npos);
  CHECK(some.find("; 17161 of them shadowed: scalar double (eq. 10)\n", line) < some.find('\n', line) + 1);
  const std::string off = describe(plan_lighting(scene, LightingRequest{}), scene);
  CHECK(off.find("of them shadowed") == std::string::npos);
}

TEST_CASE("batch bake: bit-identical on 1 and 2 threads") {
  const Scene scene = test_scene();
  for (bool float_batch : {true, false}) {
    CAPTURE(float_batch);
    const auto one = light_with_threads(scene, 1, float_batch);
    const auto two = light_with_threads(scene, 2, float_batch);
    REQUIRE(one.size() == two.size());
    const auto& a = one[0].diffuse;
    const auto& b = two[0].diffuse;
    REQUIRE(a.size() == b.size());
    CHECK(std::memcmp(a.data(), b.data(), a.size() * sizeof(Vec3f)) == 0);
  }
}

TEST_CASE("batch bake: float batch path within 1e-5 of the scalar double path") {
  const Scene scene = test_scene();
  const auto batch = light_with_threads(scene, 2, true)[0].diffuse;
  const auto scalar = light_with_threads(scene, 2, false)[0].diffuse;
  double max_value = 0;
  for (const Vec3f& c : scalar) max_value = std::max({max_value, double(c.x), double(c.y), double(c.z)});
  double worst = 0;
  for (std::size_t v = 0; v < scalar.size(); ++v)
    for (int k = 0; k < 3; ++k) {
      const double ref = scalar[v][k], got = batch[v][k];
      worst = std::max(worst, std::fabs(got - ref) / std::max(std::fabs(ref), 1e-12 * max_value));
    }
  MESSAGE("batch vs scalar bake: max relative difference " << worst);
  CHECK(worst <= 1e-5);
  CHECK(max_value > 0);
}

namespace {

// The largest relative difference between two per-vertex colour arrays, each value compared with
// max(|reference|, 1e-12 x the reference's largest value).
double worst_relative(const std::vector<Vec3f>& got, const std::vector<Vec3f>& ref) {
  double max_value = 0;
  for (const Vec3f& c : ref) max_value = std::max({max_value, double(c.x), double(c.y), double(c.z)});
  double worst = 0;
  for (std::size_t v = 0; v < ref.size(); ++v)
    for (int k = 0; k < 3; ++k)
      worst = std::max(worst, std::fabs(double(got[v][k]) - ref[v][k]) / std::max(std::fabs(double(ref[v][k])), 1e-12 * max_value));
  return worst;
}

}  // namespace

TEST_CASE("batch bake with specular: diffuse and specular within 1e-5 of the scalar double path, thread-independent") {
  // The float batch diffuse beside the specular must not change the specular, nor the diffuse
  // beyond the float bar; the specular of every light with an eye (exact, the default).
  const Scene scene = test_scene();
  const Vec3d eye{0.5, -1, 4};
  const auto batch = light_with_threads(scene, 2, true, eye)[0];
  const auto scalar = light_with_threads(scene, 2, false, eye)[0];
  REQUIRE(batch.specular.size() == scalar.specular.size());
  REQUIRE_FALSE(scalar.specular.empty());
  const double diffuse_worst = worst_relative(batch.diffuse, scalar.diffuse);
  const double specular_worst = worst_relative(batch.specular, scalar.specular);
  MESSAGE("batch vs scalar bake with specular: diffuse " << diffuse_worst << ", specular " << specular_worst);
  CHECK(diffuse_worst <= 1e-5);
  CHECK(specular_worst <= 1e-5);
  double max_specular = 0;
  for (const Vec3f& c : scalar.specular) max_specular = std::max(max_specular, double(c.x));
  CHECK(max_specular > 0);
  const auto one = light_with_threads(scene, 1, true, eye)[0];
  CHECK(std::memcmp(one.specular.data(), batch.specular.data(), batch.specular.size() * sizeof(Vec3f)) == 0);
  CHECK(std::memcmp(one.diffuse.data(), batch.diffuse.data(), batch.diffuse.size() * sizeof(Vec3f)) == 0);
}

TEST_CASE("batch bake with specular: lanes the batch specular flags (light on the horizon) get the scalar result") {
  // A light 1e-9 above the plane of a flat patch and the eye opposite it: N.L^ ~ 1e-9 flags every
  // lane of the point light's batch specular (punctual_specular_batch.h), while the specular itself
  // is near its maximum (Rv points at the light). The bake must take those lanes from the scalar kernel.
  Scene scene;
  ScenePrimitive patch;
  for (int i = 0; i < 40; ++i) {
    patch.positions.push_back({-0.01 + 0.0005 * i, 0.001 * (i % 3), 0});
    patch.normals.push_back({0, 0, 1});
  }
  scene.primitives.push_back(patch);
  LightSource point;
  point.name = "horizon point";
  point.position = {1, 0, 1e-9};
  scene.lights.push_back(point);
  const Vec3d eye{-1, 0, 1e-9};
  LightingRequest request;
  request.eye = eye;
  REQUIRE(plan_lighting(scene, request).batch_of_light[0].specular_batch);
  const auto batch = light_with_threads(scene, 2, true, eye)[0];
  const auto scalar = light_with_threads(scene, 2, false, eye)[0];
  double max_specular = 0;
  for (const Vec3f& c : scalar.specular) max_specular = std::max(max_specular, double(c.x));
  CHECK(max_specular > 0.5);
  CHECK(worst_relative(batch.specular, scalar.specular) <= 1e-5);
}
