// Property: no NaN or Inf in any output colour, for random and degenerate scenes (docs/robustness.md).
// Seeded random glTF meshes through the real pipeline (build_scene -> light_scene_vertices ->
// bake_vertex_colors, float COLOR_0 read back): degenerate triangles (repeated indices, collinear
// and coincident vertices), unreferenced vertices, coordinates from 1e-30 to 1e30, lights placed
// exactly on vertices, every light type of docs/lights-json.md. A failure prints the seed and case.
#include <doctest/doctest.h>

#include <cmath>
#include <omp.h>
#include <random>
#include <map>
#include <set>
#include <sstream>

#include "bake/light_vertices.h"
#include "bake/vertex_color_bake.h"
#include "gltf/accessor_reader.h"
#include "gltf/gltf_scene.h"
#include "support/gltf_builder.h"

using namespace vlit;
using vlit::test::GltfBuilder;

namespace {

struct RandomCase {
  std::uint32_t seed;
  double scale;
  tinygltf::Model model;
  std::vector<Vec3d> vertices;  // model space = world space (one root node, no transform)
};

RandomCase make_case(std::uint32_t seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> unit(-1, 1);
  const double exponents[] = {-30, -12, -3, 0, 3, 12, 30};
  const double scale = std::pow(10.0, exponents[seed % 7]);
  const int n = 3 + int(rng() % 30);
  std::vector<float> positions;
  std::vector<Vec3d> vertices, unit_vertices;
  for (int i = 0; i < n; ++i) {
    Vec3d p{unit(rng), unit(rng), unit(rng)};
    switch (rng() % 6) {
      case 0: if (i > 0) p = unit_vertices[rng() % i]; break;                                  // coincident
      case 1: if (i > 1) p = (unit_vertices[i - 1] + unit_vertices[i - 2]) * 0.5; break;       // collinear
      case 2: p = p * 1e-7; break;                                                             // tiny offsets
      default: break;
    }
    unit_vertices.push_back(p);
    vertices.push_back(Vec3d(static_cast<Vec3f>(p * scale)));
    for (double c : {vertices.back().x, vertices.back().y, vertices.back().z}) positions.push_back(float(c));
  }
  std::vector<std::uint32_t> indices;
  const int triangles = 1 + int(rng() % 40);
  for (int t = 0; t < triangles; ++t) {
    std::uint32_t a = rng() % n, b = rng() % n, c = rng() % n;
    if (rng() % 4 == 0) b = a;  // repeated index: zero area
    indices.insert(indices.end(), {a, b, c});
  }
  std::vector<float> normals;
  const bool with_normals = rng() % 2;
  if (with_normals)
    for (int i = 0; i < n; ++i) {
      const bool zero = rng() % 5 == 0;
      for (int k = 0; k < 3; ++k) normals.push_back(zero ? 0.f : float(unit(rng)));
    }
  const int modes[] = {TINYGLTF_MODE_TRIANGLES, TINYGLTF_MODE_TRIANGLE_STRIP, TINYGLTF_MODE_TRIANGLE_FAN};
  GltfBuilder b;
  b.add_node(b.add_mesh(positions, normals, indices, modes[rng() % 3]));
  return {seed, scale, b.model(), vertices};
}

// Every light type of docs/lights-json.md, placed on and around the case's vertices.
std::vector<LightSource> lights_for(const RandomCase& c, std::mt19937& rng) {
  std::uniform_real_distribution<double> unit(-1, 1);
  const Vec3d on_vertex = c.vertices[rng() % c.vertices.size()];
  const Vec3d other = c.vertices[rng() % c.vertices.size()];
  const Vec3d near{unit(rng) * c.scale, unit(rng) * c.scale, unit(rng) * c.scale};
  std::vector<LightSource> lights;
  LightSource l;
  l.intensity = std::pow(10.0, unit(rng) * 6);
  l.type = LightType::kPoint;
  for (double falloff : {0.0, 1.0, 2.0, 3.0, 2.5}) {
    l.falloff = falloff;
    l.position = on_vertex;
    lights.push_back(l);
    l.position = near;
    lights.push_back(l);
  }
  l.falloff = 2;
  l.type = LightType::kDirectional;
  l.direction = normalize(Vec3d{unit(rng), unit(rng), unit(rng)});
  if (is_finite(l.direction) && length(l.direction) > 0) lights.push_back(l);
  l.type = LightType::kSpot;
  l.position = on_vertex;
  l.direction = Vec3d{0, 0, -1};
  lights.push_back(l);
  l.type = LightType::kLinear;
  for (double falloff : {0.0, 1.0, 2.0, 3.0}) {
    l.falloff = falloff;
    l.from = on_vertex;  // an end on a vertex
    l.to = other;        // possibly the same point: a zero-length segment
    lights.push_back(l);
    l.from = on_vertex - Vec3d{c.scale, 0, 0};  // through a vertex
    l.to = on_vertex + Vec3d{c.scale, 0, 0};
    lights.push_back(l);
  }
  l.type = LightType::kArea;
  l.polygon = {on_vertex, on_vertex + Vec3d{c.scale, 0, 0}, on_vertex + Vec3d{c.scale, c.scale, 0},
               on_vertex + Vec3d{0, c.scale, 0}};
  lights.push_back(l);
  l.type = LightType::kDisk;
  l.center = on_vertex;
  l.normal = {0, 0, 1};
  l.radius = c.scale;
  lights.push_back(l);
  return lights;
}

}  // namespace

TEST_CASE("no NaN or Inf in any output colour: random, degenerate and extreme scenes, every light type") {
  // Meshes of a few dozen vertices: threads only add OpenMP start-up and spin-waiting, which
  // made this test 30x slower on a loaded machine.
  omp_set_num_threads(1);
  std::size_t vertices_checked = 0, cases = 0;
  // Cases generated and cases lit, per light type: every type generated must be lit in every case
  // (a type the dispatch refuses is a failure, never a silent skip).
  std::map<std::string, std::size_t> generated, lit_by_type;
  for (std::uint32_t seed = 1; seed <= 200; ++seed) {
    RandomCase c = make_case(seed);
    std::mt19937 rng(seed * 7919u);
    const GltfFile file{"random.glb", c.model, {}};
    std::vector<std::string> warnings;
    Scene scene = build_scene(file, warnings);
    for (const LightSource& light : lights_for(c, rng)) {
      scene.lights = {light};
      std::ostringstream what;
      what << "seed " << seed << ", scale " << c.scale << ", light " << light_type_name(light.type) << " falloff "
           << light.falloff;
      CAPTURE(what.str());
      std::vector<VertexLight> lit;
      ++generated[light_type_name(light.type)];
      try {
        LightingRequest request;
        request.eye = c.vertices[0] + Vec3d{0, 0, 3 * c.scale};
        lit = light_scene_vertices(scene, request);
      } catch (const std::invalid_argument& e) {  // a light model missing from the dispatch
        FAIL_CHECK("light type " << std::string(light_type_name(light.type)) << " refused: " << std::string(e.what()));
        continue;
      }
      ++lit_by_type[light_type_name(light.type)];
      ++cases;
      // The light before encoding (float): never NaN, never Inf. Where the exact double value
      // exceeds FLT_MAX (a light 1e-30 from a vertex) it saturates at FLT_MAX.
      for (std::size_t pi = 0; pi < lit.size(); ++pi) {
        const VertexLight& v = lit[pi];
        for (std::size_t vi = 0; vi < v.diffuse.size(); ++vi) {
          const Vec3f& d = v.diffuse[vi];
          ++vertices_checked;
          const Vec3d& p = scene.primitives[pi].positions[vi];
          const Vec3d& nrm = scene.primitives[pi].normals[vi];
          REQUIRE_MESSAGE(!(std::isnan(d.x) || std::isnan(d.y) || std::isnan(d.z)),
                          "diffuse " << d.x << " " << d.y << " " << d.z << " at vertex " << vi << " (" << p.x << ", "
                                     << p.y << ", " << p.z << "), normal (" << nrm.x << ", " << nrm.y << ", " << nrm.z
                                     << "), light at (" << light.position.x << ", " << light.position.y << ", "
                                     << light.position.z << ")");
          REQUIRE_MESSAGE(is_finite(d), "diffuse overflowed float at vertex " << vi);
        }
        for (const Vec3f& sp : v.specular)
          REQUIRE_MESSAGE(!(std::isnan(sp.x) || std::isnan(sp.y) || std::isnan(sp.z)), "specular " << sp.x << " " << sp.y << " " << sp.z);
      }
      // The stored colours, float format (no clamping to hide a NaN), read back from the model.
      tinygltf::Model model = c.model;
      BakeOptions options;
      options.format = ColorFormat::kFloat;
      bake_vertex_colors(model, scene, lit, options);
      for (const auto& mesh : model.meshes)
        for (const auto& prim : mesh.primitives) {
          const auto color = prim.attributes.find("COLOR_0");
          REQUIRE(color != prim.attributes.end());
          for (double x : read_accessor_as_doubles(model, color->second, "random.glb")) REQUIRE(std::isfinite(x));
        }
    }
  }
  std::ostringstream summary;
  summary << cases << " scene x light cases, " << vertices_checked << " vertex colours checked finite";
  for (const auto& [type, n] : generated) summary << "\n  " << type << ": " << lit_by_type[type] << " of " << n << " lit";
  MESSAGE(summary.str());
  CHECK(cases > 4000);
  CHECK(generated.size() >= 6);  // point, spot, directional, linear, area, disk
  for (const auto& item : generated) {
    // Named, not bound: CAPTURE's lambda captures it (clang 14 does not capture structured bindings).
    const auto& type = item.first;
    CAPTURE(type);
    CHECK(lit_by_type[type] == item.second);
  }
}
