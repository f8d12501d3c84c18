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
  scene.lights.push_back(panel(-2, false));  // below the floor facing up: in front of both boxes, but every vertex faces away
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
  CHECK(plan.lights_of_primitive[0] == std::vector<int>{0, 3, 4});
  CHECK(plan.lights_of_primitive[1] == std::vector<int>{0});
  const std::string text = describe(plan, scene);
  CHECK(text.find("light dark: zero intensity") != std::string::npos);
  CHECK(text.find("light up x primitive 0: the box is behind the emitting side") != std::string::npos);
  CHECK(text.find("light spot x primitive 1: outside the spot cone") != std::string::npos);
  CHECK(text.find("light ranged x primitive 1: beyond the light's range") != std::string::npos);
  CHECK(text.find("light up x primitive 0: every vertex facing away from the light") != std::string::npos);

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

TEST_CASE("pairs whose box may be lit but none of whose vertices can be are skipped vertex by vertex, exactly") {
  // A strip on the diagonal x + z = 1 (y in [0, 1]) facing (1, 0, 1): its bounding box reaches the
  // corner (1, y, 1), which none of its vertices is near. Each light below is placed so that the
  // box test lets it through while no vertex can receive its light, for one reason each.
  Scene scene;
  ScenePrimitive strip;
  for (int j = 0; j <= 4; ++j)
    for (int i = 0; i <= 4; ++i) {
      strip.positions.push_back({i / 4.0, j / 4.0, 1 - i / 4.0});
      strip.normals.push_back(normalize(Vec3d{1, 0, 1}));
    }
  scene.primitives.push_back(strip);
  LightSource good;
  good.name = "good";
  good.position = {1, 0.5, 1};
  scene.lights.push_back(good);
  LightSource behind;  // plane x + z = 1.5, emitting toward +x+z: the strip (x + z = 1) is behind it
  behind.type = LightType::kArea;
  behind.name = "behind";
  behind.polygon = {{1.5, 1, 0}, {0, 1, 1.5}, {0, 0, 1.5}, {1.5, 0, 0}};  // counter-clockwise seen from +x+z
  scene.lights.push_back(behind);
  LightSource ranged = good;  // 0.707 from the strip's line; the box's sphere comes within 0.6
  ranged.name = "ranged";
  ranged.range = 0.6;
  scene.lights.push_back(ranged);
  LightSource sideways = good;  // a narrow cone along +y from a point 0.707 off the strip
  sideways.type = LightType::kSpot;
  sideways.name = "sideways";
  sideways.direction = {0, 1, 0};
  sideways.cos_outer = std::cos(0.3);
  scene.lights.push_back(sideways);
  LightSource under = good;  // behind the strip's tangent planes
  under.name = "under";
  under.position = {0, 0.5, 0};
  scene.lights.push_back(under);

  LightingRequest request;
  request.float_batch = false;  // double kernels: the reference below is the same arithmetic
  const ScenePlan plan = plan_lighting(scene, request);
  CHECK(plan.pairs_total == 5);
  CHECK(plan.pairs_kept == 1);
  CHECK(plan.lights_of_primitive[0] == std::vector<int>{0});
  const std::vector<std::string> warnings = unreached_light_warnings(plan, scene);
  REQUIRE(warnings.size() == 4);
  CHECK(warnings[0] == "light behind reaches no vertex: every vertex behind the emitting side (it emits toward the side "
                       "from which its polygon runs counter-clockwise; reverse the polygon or make it two-sided)");
  CHECK(warnings[1] == "light ranged reaches no vertex: every vertex beyond the light's range");
  CHECK(warnings[2] == "light sideways reaches no vertex: every vertex outside the spot cone");
  CHECK(warnings[3] == "light under reaches no vertex: every vertex facing away from the light");
  const std::string text = describe(plan, scene);
  CHECK(text.find("1 of 5 light x primitive pairs lit") != std::string::npos);
  CHECK(text.find("plan: light ranged reaches no vertex") != std::string::npos);

  // Leaving them out changes no bit: every skipped light gives exactly 0 at every vertex.
  const auto lit = light_scene_vertices(scene, plan, request);
  const auto expected = brute_force(scene, 0, ShadeOptions{});
  for (std::size_t v = 0; v < expected.size(); ++v) {
    CHECK(lit[0].diffuse[v].x == static_cast<float>(expected[v].x));  // the lighting loop stores floats
    CHECK(lit[0].diffuse[v].x > 0);
  }
  for (std::size_t l = 1; l < scene.lights.size(); ++l) {
    Scene alone = scene;
    alone.lights = {scene.lights[l]};
    for (const Vec3d& c : brute_force(alone, 0, ShadeOptions{})) CHECK(c.x == 0);
  }

  SUBCASE("one reached vertex keeps the pair") {
    // In front of "behind" and facing it (and "under"); 1.41 from "ranged", across the cone of "sideways".
    scene.primitives[0].positions.push_back({2, 0.5, 2});
    scene.primitives[0].normals.push_back(normalize(Vec3d{-1, 0, -1}));
    const ScenePlan again = plan_lighting(scene, request);
    CHECK(again.lights_of_primitive[0] == std::vector<int>{0, 1, 4});
    CHECK(unreached_light_warnings(again, scene).size() == 2);
  }
}
