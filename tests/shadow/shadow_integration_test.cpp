// Shadows in the pipeline: LIGHTS.json "shadows", the scene plan's proof that nothing can occlude
// (no BVH then), the vertex loop with shadows on and off, and `vlit probe --occluders`.
#include <doctest/doctest.h>

#include <fstream>
#include <sstream>

#include "bake/light_vertices.h"
#include "core/input_error.h"
#include "io/lights_json.h"
#include "support/gltf_builder.h"
#include "support/run_command.h"
#include "shadow_test_util.h"

using namespace vlit;
using namespace vlit::test;

namespace {

// A square of side 2 centred at (0, 0, z), normal +z, 5 x 5 vertices.
ScenePrimitive floor_at(double z, double half = 1) {
  ScenePrimitive p;
  const int n = 5;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      p.positions.push_back({-half + 2 * half * i / (n - 1), -half + 2 * half * j / (n - 1), z});
      p.normals.push_back({0, 0, 1});
    }
  for (int i = 0; i + 1 < n; ++i)
    for (int j = 0; j + 1 < n; ++j) {
      const std::uint32_t a = i * n + j, b = (i + 1) * n + j, c = (i + 1) * n + j + 1, d = i * n + j + 1;
      p.triangles.insert(p.triangles.end(), {a, b, c, a, c, d});
    }
  return p;
}

Scene floor_scene() {
  Scene s;
  s.primitives.push_back(floor_at(0));
  LightSource light = area_source(square_light(0.5, 2));
  s.lights.push_back(light);
  return s;
}

}  // namespace

TEST_CASE("LIGHTS.json \"shadows\": default true, false turns a light's shadows off, other values are errors") {
  const auto lights = parse_lights_json(
      R"({"lights": [{"type": "point", "position": [0, 0, 1]}, {"type": "point", "position": [0, 0, 1], "shadows": false}]})",
      "l.json");
  CHECK(lights[0].casts_shadows);
  CHECK_FALSE(lights[1].casts_shadows);
  CHECK_THROWS_AS(parse_lights_json(R"({"lights": [{"type": "point", "position": [0, 0, 1], "shadows": 1}]})", "l.json"),
                  InputError);
}

TEST_CASE("the plan proves a lone planar floor unoccluded: no shadowed pair, no BVH, results identical") {
  const Scene scene = floor_scene();
  LightingRequest request;
  request.shade.with_specular = false;
  request.shadows = true;
  const ScenePlan plan = plan_lighting(scene, request);
  CHECK(plan.shadowed_pairs == 0);
  CHECK_FALSE(plan.needs_occluders);
  CHECK(describe(plan, scene).find("nothing can lie between them") != std::string::npos);
  request.shadows = false;
  const auto off = light_scene_vertices(scene, request);
  request.shadows = true;
  const auto on = light_scene_vertices(scene, request);
  for (std::size_t v = 0; v < off[0].diffuse.size(); ++v) CHECK(on[0].diffuse[v] == off[0].diffuse[v]);
}

TEST_CASE("a blocker between floor and light is planned and darkens the floor under it only") {
  Scene scene = floor_scene();
  scene.primitives.push_back(floor_at(1, 0.3));  // a small plate at z = 1 over the floor's centre
  LightingRequest request;
  request.shade.with_specular = false;
  request.shadows = true;
  const ScenePlan plan = plan_lighting(scene, request);
  CHECK(plan.needs_occluders);
  CHECK(describe(plan, scene).find("BVH over 64 triangles") != std::string::npos);  // 2 x 4 x 4 quads x 2
  CHECK(describe(plan, scene).find("area lights: visible part from silhouette edges") != std::string::npos);
  CHECK(describe(plan, scene).find("linear lights: visible intervals from silhouette edges") != std::string::npos);
  CHECK(plan.shadowed_of_primitive[0][0] == 1);  // floor: the plate may lie between
  CHECK(plan.shadowed_of_primitive[1][0] == 0);  // plate: planar, and nothing above it
  const auto on = light_scene_vertices(scene, request);
  request.shadows = false;
  const auto off = light_scene_vertices(scene, request);
  // Each floor vertex (corner 0, edge 7, centre 12) gets the direct shadowed evaluation with
  // every triangle of the scene as occluder; the centre is under the plate.
  OccluderTriangles tris = occluders_of(scene);
  const OccluderBvh all(std::move(tris));
  const PreparedLight<double> light = prepare_light<double>(scene.lights[0]);
  ShadeOptions o;
  o.with_specular = false;
  o.specular.method = SpecularMethod::kNone;
  for (std::size_t v : {0u, 12u, 7u}) {
    const ShadingPoint<double> sp =
        make_shading_point(scene.primitives[0].positions[v], scene.primitives[0].normals[v], Vec3d{0, 0, 5}, 1.0);
    CHECK(on[0].diffuse[v].x == doctest::Approx(shade_shadowed(light, sp, o, all).diffuse).epsilon(1e-6));
  }
  CHECK(on[0].diffuse[12].x < 0.5 * off[0].diffuse[12].x);
  scene.lights[0].casts_shadows = false;
  const ScenePlan no_shadow = plan_lighting(scene, request);
  CHECK_FALSE(no_shadow.needs_occluders);
}

TEST_CASE("vlit probe --occluders: the scene's triangles (transforms applied) hide the lights") {
  const auto dir = temp_dir("probe-occluders");
  // A 4 x 4 quad in the plane z = 0 of its mesh, moved to z = 1 by its node.
  GltfBuilder b;
  const int mesh = b.add_mesh({-2, -2, 0, 2, -2, 0, 2, 2, 0, -2, 2, 0}, {}, {0, 1, 2, 0, 2, 3});
  b.add_node(mesh, {0, 0, 1});
  const std::string scene = (dir / "blocker.glb").string();
  b.write(scene);
  {
    std::ofstream(dir / "lights.json")
        << R"({"lights": [{"type": "area", "polygon": [[-0.5, -0.5, 2], [-0.5, 0.5, 2], [0.5, 0.5, 2], [0.5, -0.5, 2]]},)"
        << R"( {"type": "point", "position": [0, 0, 3], "shadows": false}]})";
    std::ofstream(dir / "points.csv") << "px,py,pz,nx,ny,nz,ex,ey,ez,m\n0,0,0,0,0,1,0,0,5,10\n";
  }
  const std::string vlit = VLIT_BINARY;
  const std::string common = vlit + " probe --lights '" + (dir / "lights.json").string() + "' --points '" +
                             (dir / "points.csv").string() + "'";
  const CommandResult open = run_command(common);
  const CommandResult hidden = run_command(common + " --occluders '" + scene + "'");
  REQUIRE(open.exit_code == 0);
  REQUIRE(hidden.exit_code == 0);
  // The area light is hidden; the point light (shadows: false) still counts: diffuse 1/3^2.
  CHECK(hidden.out.find("0,0.1111111111111111") != std::string::npos);
  CHECK(open.out != hidden.out);
  const CommandResult bad = run_command(common + " --occluders '" + scene + "' --precision float");
  CHECK(bad.exit_code != 0);
  CHECK(bad.err.find("blocker.glb") != std::string::npos);
  // --snap-to-vertices: the point is no vertex of the quad (corners (+-2, +-2, 1)), nothing moves;
  // without --occluders it is an error naming the points file.
  const CommandResult snapped = run_command(common + " --occluders '" + scene + "' --snap-to-vertices");
  REQUIRE(snapped.exit_code == 0);
  CHECK(snapped.out == hidden.out);
  CHECK(snapped.err.find("probe: 0 of 1 points on a vertex of") != std::string::npos);
  const CommandResult alone = run_command(common + " --snap-to-vertices");
  CHECK(alone.exit_code != 0);
  CHECK(alone.err.find("points.csv") != std::string::npos);
  CHECK(alone.err.find("--snap-to-vertices needs --occluders") != std::string::npos);
  std::filesystem::remove_all(dir);
}

TEST_CASE("vlit probe --snap-to-vertices: a point on a crease vertex takes the wedges of the vertex its normal names") {
  const auto dir = temp_dir("probe-crease");
  // A floor (z = 0, x in [0, 1]) and a wall (x = 0, facing +x) as two meshes sharing the vertices
  // on the y axis; the probe points stand on (0, 0, 0), one with the floor's normal, one with the wall's.
  GltfBuilder b;
  const int floor = b.add_mesh({0, -1, 0, 1, -1, 0, 1, 0, 0, 0, 0, 0, 1, 1, 0, 0, 1, 0}, {},
                               {0, 1, 2, 0, 2, 3, 3, 2, 4, 3, 4, 5});
  const int wall = b.add_mesh({0, -1, 0, 0, 0, 0, 0, 1, 0, 0, -1, 1, 0, 0, 1, 0, 1, 1}, {},
                              {0, 1, 4, 0, 4, 3, 1, 2, 5, 1, 5, 4});
  b.add_node(floor, {0, 0, 0});
  b.add_node(wall, {0, 0, 0});
  const std::string scene = (dir / "crease.glb").string();
  b.write(scene);
  {
    // A panel above the crease, partly behind the wall's plane (x < 0).
    std::ofstream(dir / "lights.json")
        << R"({"lights": [{"type": "area", "polygon": [[-0.7, -0.5, 2], [-0.7, 0.5, 2], [0.3, 0.5, 2], [0.3, -0.5, 2]]}]})";
    std::ofstream(dir / "points.csv") << "px,py,pz,nx,ny,nz,ex,ey,ez,m\n0,0,0,0,0,1,0,0,5,10\n0,0,0,1,0,0,5,0,0,10\n";
  }
  const std::string common = std::string(VLIT_BINARY) + " probe --specular none --lights '" +
                             (dir / "lights.json").string() + "' --points '" + (dir / "points.csv").string() +
                             "' --occluders '" + scene + "'";
  const CommandResult plain = run_command(common);
  const CommandResult snapped = run_command(common + " --snap-to-vertices");
  REQUIRE(plain.exit_code == 0);
  REQUIRE(snapped.exit_code == 0);
  CHECK(snapped.err.find("probe: 2 of 2 points on a vertex of") != std::string::npos);
  auto diffuse = [](const std::string& out, int row) {
    std::istringstream in(out);
    std::string line;
    for (int i = 0; i <= row + 1; ++i) std::getline(in, line);
    return std::stod(line.substr(line.find(',') + 1));
  };
  // The floor's point: without wedges the wall (its triangles touch the point) hides nothing;
  // with them it hides the part of the panel behind its plane, 0.7 of the panel's width and the
  // larger part of its light.
  MESSAGE("floor point: " << diffuse(plain.out, 0) << " without wedges, " << diffuse(snapped.out, 0) << " with");
  CHECK(diffuse(snapped.out, 0) < 0.5 * diffuse(plain.out, 0));
  CHECK(diffuse(snapped.out, 0) > 0);
  // The wall's point: the floor's wedge lies below its horizon; nothing changes.
  CHECK(diffuse(snapped.out, 1) == diffuse(plain.out, 1));
  CHECK(diffuse(plain.out, 1) > 0);
  std::filesystem::remove_all(dir);
}
