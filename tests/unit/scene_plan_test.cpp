// The scene plan leaves out work that cannot contribute, and leaving it out changes nothing.
#include <doctest/doctest.h>

#include <random>

#include "bake/light_vertices.h"
#include "plan/scene_plan.h"

using namespace vlit;

namespace {

// A flat grid of vertices in the z = 0 plane facing +Z, spanning [x0, x0 + 1] x [0, 1].
ScenePrimitive floor_patch(double x0) {
  ScenePrimitive p;
  for (int j = 0; j <= 4; ++j)
    for (int i = 0; i <= 4; ++i) {
      p.positions.push_back({x0 + i / 4.0, j / 4.0, 0});
      p.normals.push_back({0, 0, 1});
    }
  return p;
}

LightSource panel(double z, bool facing_down) {
  LightSource l;
  l.type = LightType::kArea;
  l.name = facing_down ? "down" : "up";
  l.polygon = {{0, 0, z}, {0, 1, z}, {1, 1, z}, {1, 0, z}};  // counter-clockwise seen from below
  if (!facing_down) std::reverse(l.polygon.begin(), l.polygon.end());
  return l;
}

// Every light at every vertex, no plan: the reference the planned loop must reproduce.
std::vector<Vec3d> brute_force(const Scene& scene, std::size_t prim, const ShadeOptions& options) {
  std::vector<Vec3d> out;
  for (std::size_t v = 0; v < scene.primitives[prim].positions.size(); ++v) {
    const auto sp = make_shading_point(scene.primitives[prim].positions[v], scene.primitives[prim].normals[v],
                                       Vec3d{0, 0, 10}, 1.0);
    Vec3d sum;
    for (const LightSource& l : scene.lights) {
      const PreparedLight<double> pl = prepare_light<double>(l);
      sum += pl.radiance * shade(pl, sp, options).diffuse;
    }
    out.push_back(sum);
  }
  return out;
}

}  // namespace

TEST_CASE("a diffuse-only bake plans no specular work") {
  Scene scene;
  scene.primitives.push_back(floor_patch(0));
  scene.lights.push_back(panel(2, true));
  LightingRequest request;  // no eye
  const ScenePlan plan = plan_lighting(scene, request);
  CHECK_FALSE(plan.shade.with_specular);
  CHECK(plan.shade.specular.method == SpecularMethod::kNone);
  CHECK(describe(plan, scene).find("specular none") != std::string::npos);
  CHECK(light_scene_vertices(scene, request)[0].specular.empty());
  request.eye = Vec3d{0, 0, 5};
  CHECK(plan_lighting(scene, request).shade.with_specular);
}

TEST_CASE("lights and pairs that cannot contribute are skipped, with the reason") {
  Scene scene;
  scene.primitives.push_back(floor_patch(0));
  scene.primitives.push_back(floor_patch(10));
  scene.lights.push_back(panel(2, true));    // shines down on both patches
  scene.lights.push_back(panel(-2, false));  // below the floor facing up: reaches... both boxes? yes, z = 0 > -2
  scene.lights.push_back(panel(2, false));   // above the floor facing up: reaches neither box
  LightSource dark = panel(3, true);
  dark.name = "dark";
  dark.intensity = 0;
  scene.lights.push_back(dark);
  LightSource spot;
  spot.type = LightType::kSpot;
  spot.name = "spot";
  spot.position = {0.5, 0.5, 2};
  spot.direction = {0, 0, -1};
  spot.cos_outer = std::cos(0.3);  // lights patch 0 below it, misses patch 1 ten units away
  scene.lights.push_back(spot);
  LightSource ranged;
  ranged.type = LightType::kPoint;
  ranged.name = "ranged";
  ranged.position = {0.5, 0.5, 1};
  ranged.range = 3.0;  // reaches patch 0, not patch 1
  scene.lights.push_back(ranged);

  const ScenePlan plan = plan_lighting(scene, LightingRequest{});
  CHECK(plan.lights.size() == 5);  // "dark" dropped
  CHECK(plan.pairs_total == 10);
  CHECK(plan.lights_of_primitive[0] == std::vector<int>{0, 1, 3, 4});
  CHECK(plan.lights_of_primitive[1] == std::vector<int>{0, 1});
  const std::string text = describe(plan, scene);
  CHECK(text.find("light dark: zero intensity") != std::string::npos);
  CHECK(text.find("light up x primitive 0: the box is behind the emitting side") != std::string::npos);
  CHECK(text.find("light spot x primitive 1: outside the spot cone") != std::string::npos);
  CHECK(text.find("light ranged x primitive 1: beyond the light's range") != std::string::npos);

  // Skipping changes nothing: the planned loop equals shading every light at every vertex.
  const auto lit = light_scene_vertices(scene, LightingRequest{});
  for (std::size_t p = 0; p < 2; ++p) {
    const auto expected = brute_force(scene, p, ShadeOptions{});
    for (std::size_t v = 0; v < expected.size(); ++v) {
      CHECK(lit[p].diffuse[v].x == doctest::Approx(expected[v].x).epsilon(1e-6));
      CHECK(lit[p].diffuse[v].z == doctest::Approx(expected[v].z).epsilon(1e-6));
    }
  }
}

TEST_CASE("--explain keeps the first skipped pairs word for word and counts the rest by reason") {
  Scene scene;
  for (int p = 0; p < 10; ++p) scene.primitives.push_back(floor_patch(2.0 * p));
  for (int l = 0; l < 10; ++l) {
    LightSource up = panel(2, false);  // above the floor, facing up: reaches no patch
    up.name = "up" + std::to_string(l);
    scene.lights.push_back(up);
  }
  const ScenePlan plan = plan_lighting(scene, LightingRequest{});
  CHECK(plan.skipped.total == 100);
  CHECK(plan.skipped.details.size() == SkipLog::kMaxDetails);
  REQUIRE(plan.skipped.reasons.size() == 1);
  CHECK(plan.skipped.reasons[0].second == 100);
  const std::string text = describe(plan, scene);
  std::size_t lines = 0;
  for (std::size_t at = text.find("plan: skipped "); at != std::string::npos; at = text.find("plan: skipped ", at + 1)) ++lines;
  CHECK(lines == SkipLog::kMaxDetails);
  CHECK(text.find("light up0 x primitive 0: the box is behind the emitting side") != std::string::npos);
  CHECK(text.find("plan: ... and 60 more skipped; all 100 by reason: the box is behind the emitting side (100);") !=
        std::string::npos);
}
