// The accuracy report's Blender Cycles comparison (reference/accuracy_blender.h): reading Cycles'
// per-corner bakes and matching them to a scene's vertices, the error measure, the comparison
// lights as LIGHTS.json and as Cycles' point chains. Blender itself is not needed: the Cycles
// files are written here by hand.
#include <doctest/doctest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "accuracy_blender.h"
#include "io/lights_json.h"

using namespace vlit;
using namespace vlit::bench;

namespace {

Scene four_vertex_scene() {
  Scene s;
  ScenePrimitive p;
  // v0 and v1: same position and normal (glTF vertices split by a texture seam); v2: same
  // position, another normal (a hard edge); v3: elsewhere, no Cycles corner.
  p.positions = {{0, 0, 0}, {0, 0, 0}, {0, 0, 0}, {1, 0, 0}};
  p.normals = {{0, 1, 0}, {0, 1, 0}, {1, 0, 0}, {0, 1, 0}};
  p.triangles = {0, 2, 3};
  s.primitives.push_back(p);
  return s;
}

}  // namespace

TEST_CASE("Cycles corners: matched by position and normal, averaged, seams shared, misses counted") {
  const auto dir = std::filesystem::temp_directory_path() / "vlit_cycles_comparison_test";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  std::ofstream(dir / "cycles-times.txt") << "import 0.5\n4 1.25\n";
  std::ofstream(dir / "blender-version.txt") << "3.4.1\n";
  // Lines: x y z nx ny nz value. Two corners on v0/v1 (mean 3), one on v2, one nowhere.
  std::ofstream(dir / "cycles-4.txt") << "0 0 0 0 1 0 2\n"
                                         "0 0 0 0 1 0 4\n"
                                         "0.0000001 0 0 1 0 0 7\n"
                                         "5 5 5 0 1 0 100\n";
  const CyclesData d = read_cycles(dir, four_vertex_scene());
  REQUIRE(d.available);
  CHECK(d.version == "3.4.1");
  CHECK(d.import_seconds == 0.5);
  REQUIRE(d.runs.size() == 1);
  const CyclesRun& r = d.runs[0];
  CHECK(r.samples == 4);
  CHECK(r.seconds == 1.25);
  REQUIRE(r.value.size() == 4);
  CHECK(r.value[0] == 3.0f);
  CHECK(r.value[1] == 3.0f);
  CHECK(r.value[2] == 7.0f);
  CHECK(std::isnan(r.value[3]));
  CHECK(r.unmatched == 1);
  std::filesystem::remove_all(dir);
}

TEST_CASE("Cycles comparison: missing results say why") {
  const CyclesData d = read_cycles(std::filesystem::temp_directory_path() / "vlit_no_such_cycles_dir", four_vertex_scene());
  CHECK_FALSE(d.available);
  CHECK(d.why_not.find("no Cycles results") != std::string::npos);
}

TEST_CASE("Cycles comparison: error measure as in the end-to-end table, unmatched vertices left out") {
  // ref top = 4. Vertex 0 exact, vertex 1 off by 2 (max/top 0.5, relative 0.5), vertex 2
  // unmatched (NaN). Relative errors {0, 0.5}: median = the upper middle = 0.5.
  const DiffuseError e = diffuse_error({1.0f, 2.0f, NAN}, {1.0f, 4.0f, 2.0f});
  CHECK(e.vertices == 2);
  CHECK(e.max_rel_to_max == doctest::Approx(0.5));
  CHECK(e.med_rel == doctest::Approx(0.5));
  CHECK(e.p99_rel == doctest::Approx(0.5));
}

TEST_CASE("Cycles comparison: a tube becomes K point lights at the midpoints of K pieces") {
  LightSource tube;
  tube.type = LightType::kLinear;
  tube.from = {0, 0, 0};
  tube.to = {4, 0, 0};
  tube.intensity = 2;
  LightSource point;
  point.type = LightType::kPoint;
  point.position = {0, 5, 0};
  const auto chain = as_point_chains({tube, point}, 4);
  REQUIRE(chain.size() == 5);
  for (int k = 0; k < 4; ++k) {
    CHECK(chain[k].type == LightType::kPoint);
    CHECK(chain[k].position.x == doctest::Approx(0.5 + k));  // midpoints of [0,1], [1,2], ...
    CHECK(chain[k].intensity == doctest::Approx(0.5));       // 2 / 4: the total stays Ip
  }
  CHECK(chain[4].position.y == 5);
}

TEST_CASE("Cycles comparison: the comparison lights' LIGHTS.json reads back as the same lights") {
  Scene s = four_vertex_scene();
  const auto lights = blender_comparison_lights(s);
  const auto back = parse_lights_json(lights_json(lights), "comparison.json");
  REQUIRE(back.size() == lights.size());
  for (std::size_t i = 0; i < lights.size(); ++i) {
    CHECK(back[i].type == lights[i].type);
    CHECK(back[i].intensity == lights[i].intensity);
    CHECK(length(back[i].from - lights[i].from) == 0);
    CHECK(length(back[i].position - lights[i].position) == 0);
    REQUIRE(back[i].polygon.size() == lights[i].polygon.size());
    for (std::size_t k = 0; k < lights[i].polygon.size(); ++k) CHECK(length(back[i].polygon[k] - lights[i].polygon[k]) == 0);
  }
  // The area light is a rectangle facing down (towards the asset): bench/blender_bake.py maps
  // only rectangles, and one-sided lights emit along (q1 - q0) x (q2 - q0).
  for (const auto& l : lights)
    if (l.type == LightType::kArea) {
      REQUIRE(l.polygon.size() == 4);
      const Vec3d e1 = l.polygon[1] - l.polygon[0], e2 = l.polygon[3] - l.polygon[0];
      CHECK(std::fabs(dot(e1, e2)) < 1e-12 * length(e1) * length(e2));
      CHECK(cross(e1, l.polygon[2] - l.polygon[0]).y < 0);
    }
}
