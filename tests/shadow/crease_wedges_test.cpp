// Crease wedges (src/shadow/crease_wedges.h): a triangle that touches a vertex across a crease
// hides what it hides from the points of the vertex's own fan next to it. The scene: a floor
// (x in [0, 1], normal +z) meeting a wall (the plane x = 0, facing +x, 1 high) along the
// y axis, as two primitives whose vertices on the crease share their positions. A light above
// and partly behind the wall: from every floor point near the crease the wall hides exactly the
// part of the light behind its plane (x < 0).
#include <doctest/doctest.h>

#include "bake/light_vertices.h"
#include "shadow/crease_wedges.h"
#include "shadow/light_meter.h"
#include "shadow/point_wedges.h"
#include "shadow_test_util.h"

using namespace vlit;
using namespace vlit::test;

namespace {

// An n x n grid of vertices origin + e1 s + e2 t, s, t in [0, 1], front faces toward e1 x e2.
ScenePrimitive grid(const Vec3d& origin, const Vec3d& e1, const Vec3d& e2, int n = 5) {
  ScenePrimitive p;
  const Vec3d normal = normalize(cross(e1, e2));
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      p.positions.push_back(origin + e1 * (double(i) / (n - 1)) + e2 * (double(j) / (n - 1)));
      p.normals.push_back(normal);
    }
  for (int i = 0; i + 1 < n; ++i)
    for (int j = 0; j + 1 < n; ++j) {
      const std::uint32_t a = i * n + j, b = (i + 1) * n + j, c = (i + 1) * n + j + 1, d = i * n + j + 1;
      p.triangles.insert(p.triangles.end(), {a, b, c, a, c, d});
    }
  return p;
}

ScenePrimitive crease_floor() { return grid({0, -1, 0}, {1, 0, 0}, {0, 2, 0}); }
ScenePrimitive crease_wall() { return grid({0, -1, 0}, {0, 2, 0}, {0, 0, 1}); }
constexpr std::size_t kCreaseVertex = 2;  // floor vertex (0, 0, 0), on the crease
constexpr std::size_t kWallFoot = 10;     // wall vertex (0, 0, 0)

// A square panel of half-size 0.5 at height 2 centred at x = cx, emitting down.
std::vector<Vec3d> panel(double cx, double x_min = -1e300) {
  std::vector<Vec3d> p = square_light(0.5, 2.0);
  for (Vec3d& v : p) v.x = std::max(v.x + cx, x_min);
  return p;
}

// A point with normal +z, seen from an eye above.
ShadingPoint<double> point_up(const Vec3d& p) { return make_shading_point(p, Vec3d{0, 0, 1}, Vec3d{0.3, 0.2, 5}, 8.0); }

std::vector<Tri> triangles_of(const ScenePrimitive& prim) {
  std::vector<Tri> out;
  for (std::size_t t = 0; t < prim.triangles.size(); t += 3)
    out.push_back({prim.positions[prim.triangles[t]], prim.positions[prim.triangles[t + 1]],
                   prim.positions[prim.triangles[t + 2]]});
  return out;
}

std::vector<VertexLight> bake(const Scene& scene, bool shadows, bool wedges = true) {
  LightingRequest request;
  request.shade.with_specular = false;
  request.shadows = shadows;
  request.shade.crease_wedges = wedges;
  request.float_batch = false;  // double kernels everywhere: the references are compared to 1e-6
  return light_scene_vertices(scene, request);
}

}  // namespace

TEST_CASE("crease wedges: a floor vertex at the foot of a wall does not see the light behind the wall") {
  Scene scene;
  scene.primitives = {crease_floor(), crease_wall()};
  scene.lights.push_back(area_source(panel(-0.2)));
  const auto on = bake(scene, true);
  const auto without = bake(scene, true, false);
  // The reference: the same floor, no wall, lit by the part of the panel in front of the wall's
  // plane (the panel clipped to x >= 0 as a light of its own).
  Scene clipped;
  clipped.primitives = {crease_floor()};
  clipped.lights.push_back(area_source(panel(-0.2, 0.0)));
  const auto ref = bake(clipped, false);
  const float got = on[0].diffuse[kCreaseVertex].x, want = ref[0].diffuse[kCreaseVertex].x;
  MESSAGE("crease vertex: " << got << ", panel clipped to the wall's plane " << want << ", without wedges "
                            << without[0].diffuse[kCreaseVertex].x);
  CHECK(std::abs(got - want) <= 1e-6f * want);
  CHECK(without[0].diffuse[kCreaseVertex].x > 1.5f * want);  // the leak the wedges close
  // Floor vertices off the crease see the wall as an ordinary occluder: unchanged by the wedges.
  for (std::size_t v = 5; v < on[0].diffuse.size(); ++v) CHECK(on[0].diffuse[v] == without[0].diffuse[v]);
  // The wall's own vertex at the same position: the floor's wedge lies below its horizon.
  CHECK(on[1].diffuse[kWallFoot] == without[1].diffuse[kWallFoot]);
}

TEST_CASE("crease wedges: the value at the crease is the limit of the floor's points next to it (independent ray cast)") {
  const ScenePrimitive floor = crease_floor(), wall = crease_wall();
  Scene scene;
  scene.primitives = {floor, wall};
  const SharedPositions shared(scene);
  const CreaseWedges wedges = shared.wedges_of(0);
  CHECK(wedges.of(kCreaseVertex).size() > 0);
  CHECK(wedges.of(12).empty());  // (0.5, 0, 0): no other vertex there
  std::vector<Tri> occluders = triangles_of(floor);
  for (const Tri& t : triangles_of(wall)) occluders.push_back(t);
  const OccluderBvh bvh = make_bvh(occluders);
  const ShadingPoint<double> sp = point_up(floor.positions[kCreaseVertex]);
  ShadeOptions options = options_with(SpecularMethod::kExact);
  for (const double cx : {-0.2, 0.3, -0.45}) {
    CAPTURE(cx);
    const std::vector<Vec3d> light = panel(cx);
    const PreparedLight<double> prepared = prepare_light<double>(area_source(light));
    const auto& area = std::get<PreparedAreaLight<double>>(prepared.kernel);
    const Response<double> r = shade_kernel_shadowed(area, sp, options, bvh, nullptr, wedges.of(kCreaseVertex));
    // Shadow rays from a point of the floor 1e-7 from the vertex, against every triangle.
    ReferencePoint pt{sp.p + Vec3d{1e-7, 0, 0}, sp.n, sp.rv, sp.shininess};
    const auto ref = reference_area(light, pt, occluders, 200, 7u);
    MESSAGE("diffuse " << r.diffuse << " reference " << ref[0].value << " ± " << ref[0].standard_error << "; specular "
                       << r.specular << " reference " << ref[1].value << " ± " << ref[1].standard_error);
    CHECK(std::abs(r.diffuse - ref[0].value) <= 4 * ref[0].standard_error + 1e-6 * ref[0].value);
    CHECK(std::abs(r.specular - ref[1].value) <= 4 * ref[1].standard_error + 1e-6 * ref[1].value);
  }
}

TEST_CASE("crease wedges: tube and point lights behind the wall are hidden at the crease, in front they are not") {
  const ScenePrimitive floor = crease_floor(), wall = crease_wall();
  Scene scene;
  scene.primitives = {floor, wall};
  const CreaseWedges wedges = SharedPositions(scene).wedges_of(0);
  std::vector<Tri> occluders = triangles_of(floor);
  for (const Tri& t : triangles_of(wall)) occluders.push_back(t);
  const OccluderBvh bvh = make_bvh(occluders);
  const ShadingPoint<double> sp = point_up(floor.positions[kCreaseVertex]);
  const ShadeOptions options = options_with(SpecularMethod::kNone);
  // A tube across the wall's plane: the half with x < 0 is hidden (intensity per unit t).
  const Vec3d q0{-0.5, 0.1, 2}, q1{0.5, -0.1, 2};
  for (const double falloff : {0.0, 2.0}) {
    const PreparedLight<double> whole = prepare_light<double>(linear_source(q0, q1, falloff));
    const PreparedLight<double> front = prepare_light<double>(linear_source((q0 + q1) * 0.5, q1, falloff));
    const auto& tube = std::get<LinearLight<double>>(whole.kernel);
    const double got = shade_kernel_shadowed(tube, sp, options, bvh, nullptr, wedges.of(kCreaseVertex)).diffuse;
    const double want = 0.5 * shade(front, sp, options).diffuse;
    const Estimate ref = reference_linear(q0, q1, falloff, {sp.p + Vec3d{1e-7, 0, 0}, sp.n, sp.rv, 1}, occluders, 100000, 5u);
    MESSAGE("n=" << falloff << ": tube " << got << ", front half " << want << ", ray cast " << ref.value << " ± "
                 << ref.standard_error);
    CHECK(std::abs(got - want) <= 1e-12 * want);
    CHECK(std::abs(got - ref.value) <= 4 * ref.standard_error);
  }
  for (const double x : {-0.3, 0.3}) {
    PointLight<double> point;
    point.position = {x, 0, 2};
    const double got = shade_kernel_shadowed(point, sp, options, bvh, nullptr, wedges.of(kCreaseVertex)).diffuse;
    CHECK((got == 0) == (x < 0));
  }
}

TEST_CASE("crease wedges: a convex edge, a flat seam and a smooth vertex change nothing") {
  // Convex: a box's top (the floor, z = 0, x in [0, 1]) and its side (x = 0, z in [-1, 0],
  // facing -x) as two primitives. Flat seam: the top continued by another primitive past x = 1.
  Scene scene;
  scene.primitives = {crease_floor(), grid({0, -1, 0}, {0, 2, 0}, {0, 0, -1}), grid({1, -1, 0}, {1, 0, 0}, {0, 2, 0})};
  scene.lights.push_back(area_source(panel(-0.2)));
  scene.lights.push_back(linear_source({-0.5, 0.1, 2}, {0.5, -0.1, 2}, 2));
  const auto on = bake(scene, true);
  const auto without = bake(scene, true, false);
  for (std::size_t p = 0; p < scene.primitives.size(); ++p)
    for (std::size_t v = 0; v < on[p].diffuse.size(); ++v) {
      CAPTURE(p);
      CAPTURE(v);
      CHECK(on[p].diffuse[v] == without[p].diffuse[v]);
    }
  // The side's triangles touch the top's edge vertices but lie behind the top's plane, and the
  // seam's are flat: no wedges at all.
  const SharedPositions shared(scene);
  CHECK(shared.wedges_of(0).of(kCreaseVertex).empty());
  CHECK(shared.wedges_of(0).of(22).empty());  // (1, 0, 0): the flat seam's wedges are dropped
}

TEST_CASE("crease wedges: a position shared by more than 64 vertices gets none, 64 get theirs") {
  // k thin triangles around the z axis, each with its own copy of the apex at the origin: a
  // pole split into k copies. Every copy sees the others' triangles.
  for (const int k : {64, 65}) {
    CAPTURE(k);
    ScenePrimitive fan;
    for (int i = 0; i < k; ++i) {
      const double a = 2 * M_PI * i / k, b = 2 * M_PI * (i + 0.5) / k;
      const auto base = static_cast<std::uint32_t>(fan.positions.size());
      fan.positions.insert(fan.positions.end(), {{0, 0, 0}, {std::cos(a), std::sin(a), 1}, {std::cos(b), std::sin(b), 1}});
      fan.normals.insert(fan.normals.end(), 3, Vec3d{0, 0, -1});
      fan.triangles.insert(fan.triangles.end(), {base, base + 1, base + 2});
    }
    Scene scene;
    scene.primitives = {fan};
    const CreaseWedges wedges = SharedPositions(scene).wedges_of(0);
    CHECK(wedges.of(0).size() == (k <= 64 ? static_cast<std::size_t>(k - 1) : 0u));
  }
}

namespace {

// A sheet crossing the floor at the crease vertex: one triangle in the plane x = 0 with a corner
// at the origin, one side rising above the floor and one going under it.
ScenePrimitive crossing_sheet() {
  ScenePrimitive p;
  p.positions = {{0, 0, 0}, {0, -1, 1}, {0, -1, -1}};
  p.normals.assign(3, Vec3d{1, 0, 0});
  p.triangles = {0, 1, 2};
  return p;
}

// The crease floor, its crease vertex's normal set to `tilted`, and the crossing sheet: the
// vertex's one wedge and the BVH of both primitives' triangles.
struct SheetScene {
  Vec3d tilted;
  ScenePrimitive floor = crease_floor(), sheet = crossing_sheet();
  CreaseWedges wedges;
  OccluderBvh bvh;
  explicit SheetScene(const Vec3d& normal) : tilted(normal), bvh(make_bvh({})) {
    floor.normals[kCreaseVertex] = tilted;
    Scene scene;
    scene.primitives = {floor, sheet};
    wedges = SharedPositions(scene).wedges_of(0);
    REQUIRE(wedges.of(kCreaseVertex).size() == 1);
    std::vector<Tri> occluders = triangles_of(floor);
    for (const Tri& t : triangles_of(sheet)) occluders.push_back(t);
    bvh = make_bvh(occluders);
  }
};

// A panel in the plane y = -2 emitting toward +y, x in [x0, x1], z in [z0, z1].
std::vector<Vec3d> wall_panel(double x0, double x1, double z0, double z1) {
  return {{x0, -2, z0}, {x0, -2, z1}, {x1, -2, z1}, {x1, -2, z0}};
}

}  // namespace

TEST_CASE("crease wedges: a wedge partly behind the fan's face hides only its part in front of it") {
  // The floor's crease vertex gets a normal tilted toward -y, so its horizon lets in light from
  // under the floor's plane. The sheet's wedge spans directions with x < 0 and |z| <= -y on both
  // sides of the floor's plane; only its part above the floor (z >= 0, in front of the fan's face)
  // hides anything: below it, the fan's points are reached only through the fan itself.
  const SheetScene s(normalize(Vec3d{0, -1, 1}));
  const CreaseWedges& wedges = s.wedges;
  const OccluderBvh& bvh = s.bvh;
  const ShadingPoint<double> sp = make_shading_point(s.floor.positions[kCreaseVertex], s.tilted, Vec3d{0.3, -4, 1}, 8.0);
  const ShadeOptions options = options_with(SpecularMethod::kExact);

  SUBCASE("area light across the floor's plane: the part under it stays lit") {
    const std::vector<Vec3d> light = wall_panel(-1, -0.2, -0.5, 0.5);
    const auto whole = prepare_light<double>(area_source(light));
    const auto lower = prepare_light<double>(area_source(wall_panel(-1, -0.2, -0.5, 0)));
    const auto& area = std::get<PreparedAreaLight<double>>(whole.kernel);
    const Response<double> got = shade_kernel_shadowed(area, sp, options, bvh, nullptr, wedges.of(kCreaseVertex));
    const Response<double> want = shade(lower, sp, options);
    const Response<double> unhidden = shade(whole, sp, options);
    MESSAGE("crease vertex " << got.diffuse << " / " << got.specular << "; the panel's part under the floor "
                             << want.diffuse << " / " << want.specular << "; whole panel " << unhidden.diffuse);
    REQUIRE(want.diffuse > 0.2 * unhidden.diffuse);
    REQUIRE(want.diffuse < 0.8 * unhidden.diffuse);
    CHECK(std::abs(got.diffuse - want.diffuse) <= 1e-12 * unhidden.diffuse);
    CHECK(std::abs(got.specular - want.specular) <= 1e-9 * (unhidden.specular + 1e-300));
  }
  SUBCASE("tube across the floor's plane: the half under it stays lit") {
    const Vec3d q0{-0.6, -2, -0.5}, q1{-0.6, -2, 0.5};
    const auto whole = prepare_light<double>(linear_source(q0, q1, 2));
    const auto lower = prepare_light<double>(linear_source(q0, (q0 + q1) * 0.5, 2));
    const auto& tube = std::get<LinearLight<double>>(whole.kernel);
    const double got = shade_kernel_shadowed(tube, sp, options_with(SpecularMethod::kNone), bvh, nullptr,
                                             wedges.of(kCreaseVertex)).diffuse;
    const double want = 0.5 * shade(lower, sp, options_with(SpecularMethod::kNone)).diffuse;
    MESSAGE("tube " << got << ", its half under the floor " << want);
    REQUIRE(want > 0);
    CHECK(std::abs(got - want) <= 1e-12 * want);
  }
  SUBCASE("point lights: under the floor's plane lit, above it hidden") {
    for (const double z : {-0.3, 0.3}) {
      PointLight<double> point;
      point.position = {-0.5, -2, z};
      const double unhidden = shade_kernel(point, sp, options_with(SpecularMethod::kNone)).diffuse;
      const double got =
          shade_kernel_shadowed(point, sp, options_with(SpecularMethod::kNone), bvh, nullptr, wedges.of(kCreaseVertex)).diffuse;
      CAPTURE(z);
      REQUIRE(unhidden > 0);
      CHECK(got == (z < 0 ? unhidden : 0.0));
    }
  }
}

TEST_CASE("crease wedges: a tube that meets a wedge only under the horizon takes the unshadowed kernel") {
  // The crease vertex's normal tilts toward +x: its horizon is x + z = 0. The tube runs along
  // z = -0.3 x: its points in the sheet's wedge (x < 0, z > 0) are all under the horizon, its
  // points over the horizon (x > 0) lie under the floor's plane, outside the wedge. Nothing is
  // removed, and the value is the unshadowed kernel's, bit for bit.
  const SheetScene s(normalize(Vec3d{1, 0, 1}));
  const CreaseWedges& wedges = s.wedges;
  const OccluderBvh& bvh = s.bvh;
  const ShadingPoint<double> sp = make_shading_point(s.floor.positions[kCreaseVertex], s.tilted, Vec3d{3, -4, 1}, 8.0);
  for (const double falloff : {0.0, 2.0}) {
    CAPTURE(falloff);
    const auto prepared = prepare_light<double>(linear_source({-1, -2, 0.3}, {1, -2, -0.3}, falloff));
    const auto& tube = std::get<LinearLight<double>>(prepared.kernel);
    const ShadeOptions options = options_with(SpecularMethod::kExact);
    const Response<double> got = shade_kernel_shadowed(tube, sp, options, bvh, nullptr, wedges.of(kCreaseVertex));
    const Response<double> want = shade(prepared, sp, options);
    REQUIRE(want.diffuse > 0);
    CHECK(got.diffuse == want.diffuse);
    CHECK(got.specular == want.specular);
  }
}

TEST_CASE("crease wedges: a probe point on a vertex takes that vertex's wedges (probe --snap-to-vertices)") {
  Scene scene;
  scene.primitives = {crease_floor(), crease_wall()};
  scene.lights.push_back(area_source(panel(-0.2)));
  const auto baked = bake(scene, true);
  const auto unwedged = bake(scene, true, false);
  std::vector<Tri> occluders = triangles_of(scene.primitives[0]);
  for (const Tri& t : triangles_of(scene.primitives[1])) occluders.push_back(t);
  const OccluderBvh bvh = make_bvh(occluders);
  const std::vector<PreparedLight<double>> lights = {prepare_light<double>(scene.lights[0])};
  ShadeOptions options;
  options.with_specular = false;
  // Every vertex of both primitives, at its own position, with a normal a little off its own (as a
  // renderer's single-precision corner normal is): the probe gives the bake's value.
  std::vector<Vec3d> positions, normals;
  std::vector<float> want, without;
  for (std::size_t pi = 0; pi < 2; ++pi)
    for (std::size_t v = 0; v < scene.primitives[pi].positions.size(); ++v) {
      positions.push_back(scene.primitives[pi].positions[v]);
      normals.push_back(scene.primitives[pi].normals[v] + Vec3d{0, 0.01, 0});
      want.push_back(baked[pi].diffuse[v].x);
      without.push_back(unwedged[pi].diffuse[v].x);
    }
  // A point 1e-9 off the crease vertex stands on no vertex: no wedges.
  positions.push_back(scene.primitives[0].positions[kCreaseVertex] + Vec3d{1e-9, 0, 0});
  normals.push_back({0, 0, 1});
  const PointWedges wedges(scene, positions, normals);
  CHECK(wedges.on_vertex() == positions.size() - 1);
  CHECK(wedges.of(positions.size() - 1).empty());
  const double intensity = scene.lights[0].intensity;
  for (std::size_t i = 0; i + 1 < positions.size(); ++i) {
    CAPTURE(i);
    const ShadingPoint<double> sp = make_shading_point(positions[i], normalize(scene.primitives[i < 25 ? 0 : 1].normals[i % 25]),
                                                       Vec3d{0.3, 0.2, 5}, 8.0);
    const double got = light_meter(lights, scene.lights, sp, options, &bvh, wedges.of(i)).diffuse / intensity;
    CHECK(std::abs(got - want[i]) <= 1e-6 * std::max(double(want[i]), 1e-3));
  }
  // The crease vertex really is darker with its wedges; the wall's foot, at the same position, is not.
  CHECK(want[kCreaseVertex] < 0.7f * without[kCreaseVertex]);
  CHECK(want[25 + kWallFoot] == without[25 + kWallFoot]);
}
