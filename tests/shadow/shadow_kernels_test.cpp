// Shadowed lights against an independent shadow-ray reference, and the exact cases: fully
// hidden, half hidden by symmetry, watertight occluders, degenerate occluders.
#include <doctest/doctest.h>

#include <cmath>
#include <random>

#include "shadow_test_util.h"

using namespace vlit;
using namespace vlit::test;

namespace {

ShadingPoint<double> point_up(const Vec3d& p, const Vec3d& eye = {0.3, 0.2, 5}, double m = 8) {
  return make_shading_point(p, Vec3d{0, 0, 1}, eye, m);
}

// A tilted triangle and a quad partly between P and the light: a real penumbra.
std::vector<Tri> penumbra_occluders() {
  std::vector<Tri> tris;
  tris.push_back({Vec3d{-0.3, -0.8, 1.0}, Vec3d{0.9, -0.1, 1.2}, Vec3d{-0.1, 0.7, 0.9}});
  add_quad(tris, Vec3d{-1.2, 0.3, 1.5}, Vec3d{0.8, 0.1, 0.05}, Vec3d{0.0, 0.6, 0.1});
  return tris;
}

}  // namespace

TEST_CASE("area light in a penumbra matches the dense shadow-ray reference (diffuse and exact specular)") {
  const std::vector<Vec3d> light = square_light(1.0, 2.0);
  const std::vector<Tri> tris = penumbra_occluders();
  const OccluderBvh bvh = make_bvh(tris);
  const PreparedLight<double> prepared = prepare_light<double>(area_source(light));
  const Vec3d points[] = {{0, 0, 0}, {0.4, -0.3, 0}, {-0.5, 0.6, 0.1}};
  int case_index = 0;
  for (const Vec3d& p : points) {
    const ShadingPoint<double> sp = point_up(p);
    const Response<double> r = shade_shadowed(prepared, sp, options_with(SpecularMethod::kExact), bvh);
    const Response<double> open = shade(prepared, sp, options_with(SpecularMethod::kExact));
    const auto ref = reference_area(light, {sp.p, sp.n, sp.rv, sp.shininess}, tris, 160, 1234u + case_index);
    MESSAGE("point " << case_index << ": diffuse " << r.diffuse << " reference " << ref[0].value << " ± "
                     << ref[0].standard_error << " (unshadowed " << open.diffuse << "); specular " << r.specular
                     << " reference " << ref[1].value << " ± " << ref[1].standard_error);
    CHECK(r.diffuse < open.diffuse);  // the occluders do hide part of the light
    CHECK(std::abs(r.diffuse - ref[0].value) <= 4 * ref[0].standard_error);
    CHECK(std::abs(r.specular - ref[1].value) <= 4 * ref[1].standard_error + 1e-9);
    ++case_index;
  }
}

TEST_CASE("linear light in a penumbra matches the dense shadow-ray reference") {
  const Vec3d q0{-1.5, 0.2, 2.0}, q1{1.5, -0.1, 2.1};
  const std::vector<Tri> tris = penumbra_occluders();
  const OccluderBvh bvh = make_bvh(tris);
  for (double falloff : {0.0, 2.0, 2.5}) {
    const PreparedLight<double> prepared = prepare_light<double>(linear_source(q0, q1, falloff));
    const ShadingPoint<double> sp = point_up({0.1, 0.05, 0});
    const Response<double> r = shade_shadowed(prepared, sp, options_with(SpecularMethod::kNone), bvh);
    const Estimate ref = reference_linear(q0, q1, falloff, {sp.p, sp.n, sp.rv, sp.shininess}, tris, 200000, 99u);
    MESSAGE("n=" << falloff << ": diffuse " << r.diffuse << " reference " << ref.value << " ± " << ref.standard_error);
    CHECK(std::abs(r.diffuse - ref.value) <= 4 * ref.standard_error);
  }
}

TEST_CASE("a fully hidden light gives exactly zero") {
  std::vector<Tri> tris;
  add_quad(tris, Vec3d{-10, -10, 1}, Vec3d{20, 0, 0}, Vec3d{0, 20, 0});
  const OccluderBvh bvh = make_bvh(tris);
  const ShadingPoint<double> sp = point_up({0.2, 0.1, 0});
  const ShadeOptions o = options_with(SpecularMethod::kExact);
  CHECK(shade_shadowed(prepare_light<double>(area_source(square_light(1, 2))), sp, o, bvh).diffuse == 0);
  CHECK(shade_shadowed(prepare_light<double>(area_source(square_light(1, 2))), sp, o, bvh).specular == 0);
  CHECK(shade_shadowed(prepare_light<double>(linear_source({-1, 0, 2}, {1, 0, 2}, 2)), sp, o, bvh).diffuse == 0);
  LightSource point;
  point.position = {0, 0, 3};
  CHECK(shade_shadowed(prepare_light<double>(point), sp, o, bvh).diffuse == 0);
  LightSource spot;
  spot.type = LightType::kSpot;
  spot.position = {0, 0, 3};
  spot.direction = {0, 0, -1};
  CHECK(shade_shadowed(prepare_light<double>(spot), sp, o, bvh).diffuse == 0);
  LightSource sun;
  sun.type = LightType::kDirectional;
  sun.direction = normalize(Vec3d{0.1, 0, -1});
  CHECK(shade_shadowed(prepare_light<double>(sun), sp, o, bvh).diffuse == 0);
  LightSource disk;
  disk.type = LightType::kDisk;
  disk.center = {0, 0, 2};
  disk.normal = {0, 0, -1};
  disk.radius = 1;
  CHECK(shade_shadowed(prepare_light<double>(disk), sp, o, bvh).diffuse == 0);
}

TEST_CASE("a light half hidden by a large plane through its middle gives half (symmetric setup)") {
  // P at the origin under the centre of a square light; the occluder covers x >= 0 at z = 1, so
  // its projection from P covers exactly the half x >= 0 of the light. Mirror symmetry x -> -x
  // (of the light, P, N and Rv) makes both halves equal: the visible half gives half.
  std::vector<Tri> tris;
  add_quad(tris, Vec3d{0, -50, 1}, Vec3d{50, 0, 0}, Vec3d{0, 100, 0});
  const OccluderBvh bvh = make_bvh(tris);
  const ShadingPoint<double> sp = make_shading_point(Vec3d{0, 0, 0}, Vec3d{0, 0, 1}, Vec3d{0, 0.7, 3}, 20.0);
  {
    const PreparedLight<double> light = prepare_light<double>(area_source(square_light(1, 2)));
    const ShadeOptions o = options_with(SpecularMethod::kExact);
    const Response<double> half = shade_shadowed(light, sp, o, bvh), full = shade(light, sp, o);
    CHECK(half.diffuse == doctest::Approx(0.5 * full.diffuse).epsilon(1e-12));
    CHECK(half.specular == doctest::Approx(0.5 * full.specular).epsilon(1e-7));
  }
  {
    const PreparedLight<double> light = prepare_light<double>(linear_source({-1, 0, 2}, {1, 0, 2}, 2));
    const ShadeOptions o = options_with(SpecularMethod::kExact);
    const Response<double> half = shade_shadowed(light, sp, o, bvh), full = shade(light, sp, o);
    CHECK(half.diffuse == doctest::Approx(0.5 * full.diffuse).epsilon(1e-12));
    CHECK(half.specular == doctest::Approx(0.5 * full.specular).epsilon(1e-8));
  }
}

TEST_CASE("watertight occluders never leak") {
  // A closed box, turned to many orientations, always covering the light as seen from P: the
  // result must be exactly zero (a crack between two triangles would let light through).
  const std::vector<Vec3d> light = square_light(0.5, 3);
  const PreparedLight<double> prepared = prepare_light<double>(area_source(light));
  const PreparedLight<double> tube = prepare_light<double>(linear_source({-0.5, 0.1, 3}, {0.5, -0.1, 3}, 2));
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> angle(0, 2 * M_PI);
  for (int trial = 0; trial < 40; ++trial) {
    std::vector<Tri> box;
    add_box(box, Vec3d{-0.6, -0.6, -0.6}, Vec3d{0.6, 0.6, 0.6});
    const double a = angle(rng), b = angle(rng);
    for (Tri& t : box)
      for (Vec3d& v : t) {
        const Vec3d r1{v.x * std::cos(a) - v.y * std::sin(a), v.x * std::sin(a) + v.y * std::cos(a), v.z};
        const Vec3d r2{r1.x, r1.y * std::cos(b) - r1.z * std::sin(b), r1.y * std::sin(b) + r1.z * std::cos(b)};
        // Centred between P and the light (z in [0.46, 2.54] whatever the turn); its inscribed
        // ball (radius 0.6) meets every ray from P to the light.
        v = r2 + Vec3d{0, 0, 1.5};
      }
    const OccluderBvh bvh = make_bvh(box);
    const ShadingPoint<double> sp = point_up({0.01 * trial, -0.005 * trial, 0});
    const Response<double> r = shade_shadowed(prepared, sp, options_with(SpecularMethod::kPeak), bvh);
    INFO("trial " << trial);
    CHECK(r.diffuse == 0);
    CHECK(r.specular == 0);
    CHECK(shade_shadowed(tube, sp, options_with(SpecularMethod::kPeak), bvh).diffuse == 0);
  }
}

TEST_CASE("degenerate occluders give finite non-negative results and hide nothing they should not") {
  const std::vector<Vec3d> light = square_light(1, 2);
  const PreparedLight<double> prepared = prepare_light<double>(area_source(light));
  const PreparedLight<double> tube = prepare_light<double>(linear_source({-1, 0.2, 2}, {1, -0.2, 2}, 2));
  const ShadingPoint<double> sp = point_up({0.1, 0.2, 0});
  const ShadeOptions o = options_with(SpecularMethod::kNeighborhood);
  const Response<double> open = shade(prepared, sp, o), open_tube = shade(tube, sp, o);
  struct Case { const char* name; std::vector<Tri> tris; bool hides_nothing; };
  const Case cases[] = {
      {"zero-area (collinear corners)", {{Vec3d{-1, 0, 1}, Vec3d{0, 0, 1}, Vec3d{1, 0, 1}}}, true},
      {"zero-area (repeated corner)", {{Vec3d{-1, 0, 1}, Vec3d{-1, 0, 1}, Vec3d{1, 0.5, 1}}}, true},
      {"coincident with the light", {{light[0], light[1], light[2]}, {light[0], light[2], light[3]}}, true},
      {"touching the vertex", {{sp.p, Vec3d{1, 1, 1.5}, Vec3d{-1, 1, 1.5}}}, true},
      {"edge-on seen from P", {{sp.p + Vec3d{0, 0, 0.5}, sp.p + Vec3d{0, 0, 1.5}, sp.p + Vec3d{0.5, 0, 1.0}}}, true},
      {"crossing P's level", {{Vec3d{-3, -3, -1}, Vec3d{3, -3, 1}, Vec3d{0, 3, 0.0}}}, false},
      {"crossing the light's plane", {{Vec3d{-0.5, -0.5, 1.5}, Vec3d{0.5, -0.5, 2.5}, Vec3d{0, 0.5, 2.5}}}, false},
      {"sliver", {{Vec3d{-1, 0, 1}, Vec3d{1, 1e-12, 1}, Vec3d{1, 0, 1}}}, false},
  };
  for (const Case& c : cases) {
    const OccluderBvh bvh = make_bvh(c.tris);
    for (const auto* l : {&prepared, &tube}) {
      const Response<double> r = shade_shadowed(*l, sp, o, bvh);
      const Response<double> full = l == &prepared ? open : open_tube;
      INFO(c.name);
      CHECK(std::isfinite(r.diffuse));
      CHECK(std::isfinite(r.specular));
      CHECK(r.diffuse >= 0);
      CHECK(r.specular >= 0);
      CHECK(r.diffuse <= full.diffuse * (1 + 1e-12));
      if (c.hides_nothing) CHECK(r.diffuse == doctest::Approx(full.diffuse).epsilon(1e-12));
    }
  }
}

TEST_CASE("a vertex is not shadowed by the triangles that contain it (no acne)") {
  // A closed box lit from above: the top face's vertices see the whole light. Their own
  // triangles (and a duplicate of the corner in a second primitive, split normals) are skipped.
  std::vector<Tri> box;
  add_box(box, Vec3d{-1, -1, -1}, Vec3d{1, 1, 0});
  box.push_back({Vec3d{1, 1, 0}, Vec3d{1, 1, -0.5}, Vec3d{1, 0.5, 0}});  // another primitive's triangle at the corner
  const OccluderBvh bvh = make_bvh(box);
  const PreparedLight<double> light = prepare_light<double>(area_source(square_light(3, 2)));
  for (const Vec3d& corner : {Vec3d{1, 1, 0}, Vec3d{-1, 1, 0}, Vec3d{-1, -1, 0}}) {
    const ShadingPoint<double> sp = point_up(corner);
    const ShadeOptions o = options_with(SpecularMethod::kPeak);
    CHECK(shade_shadowed(light, sp, o, bvh).diffuse == shade(light, sp, o).diffuse);
  }
}

TEST_CASE("a light nothing reaches gives the unshadowed kernel's value bit for bit") {
  std::vector<Tri> far_away;
  add_box(far_away, Vec3d{10, 10, 10}, Vec3d{11, 11, 11});
  const OccluderBvh bvh = make_bvh(far_away);
  const ShadingPoint<double> sp = point_up({0.3, 0.1, 0});
  const ShadeOptions o = options_with(SpecularMethod::kExact);
  for (const LightSource& l : {area_source(square_light(1, 2)), linear_source({-1, 0, 2}, {1, 0, 2}, 1.5)}) {
    const PreparedLight<double> p = prepare_light<double>(l);
    CHECK(shade_shadowed(p, sp, o, bvh).diffuse == shade(p, sp, o).diffuse);
    CHECK(shade_shadowed(p, sp, o, bvh).specular == shade(p, sp, o).specular);
  }
}

TEST_CASE("back faces of a closed mesh are skipped without changing the result") {
  // A box as a scene primitive with split vertices (4 per face, as with per-face normals): closed
  // by position. The same triangles without the closed flag are the reference.
  std::vector<Tri> tris;
  add_box(tris, Vec3d{-0.4, -0.3, 0.8}, Vec3d{0.3, 0.4, 1.3});
  ScenePrimitive box;
  for (const Tri& t : tris)
    for (const Vec3d& c : t) {
      box.triangles.push_back(static_cast<std::uint32_t>(box.positions.size()));
      box.positions.push_back(c);
      box.normals.push_back({0, 0, 1});
    }
  CHECK(is_closed_surface({&box}));
  ScenePrimitive open_box = box;
  open_box.triangles.resize(open_box.triangles.size() - 6);  // drop one face
  CHECK_FALSE(is_closed_surface({&open_box}));
  Scene scene;
  scene.primitives.push_back(box);
  const OccluderTriangles culled_triangles = occluders_of(scene);
  REQUIRE(culled_triangles.solid.size() == 12);
  CHECK(culled_triangles.solid[0] == 0);
  const OccluderBvh culled(culled_triangles), plain = make_bvh(tris);
  const PreparedLight<double> area = prepare_light<double>(area_source(square_light(1, 2)));
  const PreparedLight<double> tube = prepare_light<double>(linear_source({-1, 0.2, 2}, {1, -0.1, 2}, 2));
  std::mt19937_64 rng(12);
  std::uniform_real_distribution<double> pos(-1, 1);
  for (int i = 0; i < 50; ++i) {
    // 40 points under the box, 10 inside it (a vertex of something the box stands on or
    // intersects: back faces must not be skipped there).
    const ShadingPoint<double> sp = point_up({pos(rng) * (i < 40 ? 1 : 0.2), pos(rng) * (i < 40 ? 1 : 0.2), i < 40 ? 0 : 1.0});
    for (const PreparedLight<double>* l : {&area, &tube}) {
      const ShadeOptions o = options_with(SpecularMethod::kExact);
      const Response<double> a = shade_shadowed(*l, sp, o, culled), b = shade_shadowed(*l, sp, o, plain);
      const double open = shade(*l, sp, o).diffuse;
      CHECK(std::abs(a.diffuse - b.diffuse) <= 1e-12 * open);
      CHECK(a.specular == doctest::Approx(b.specular).epsilon(1e-7));
    }
  }
}

TEST_CASE("a closed mesh wound inward (a room modelled from inside) hides a light inside it") {
  // The box's faces point inward. Seen from below, a segment to the light inside enters through
  // a face that faces away from the point: culling "back faces" would let the light out.
  std::vector<Tri> tris;
  add_box(tris, Vec3d{-1.5, -1.5, 0.5}, Vec3d{1.5, 1.5, 3});
  for (Tri& t : tris) std::swap(t[1], t[2]);  // wound inward
  ScenePrimitive room;
  for (const Tri& t : tris)
    for (const Vec3d& c : t) {
      room.triangles.push_back(static_cast<std::uint32_t>(room.positions.size()));
      room.positions.push_back(c);
      room.normals.push_back({0, 0, 1});
    }
  REQUIRE(is_closed_surface({&room}));
  Scene scene;
  scene.primitives.push_back(room);
  const OccluderBvh bvh(occluders_of(scene));
  const PreparedLight<double> area = prepare_light<double>(area_source(square_light(0.5, 2)));
  const PreparedLight<double> tube = prepare_light<double>(linear_source({-1, 0.2, 2}, {1, -0.1, 2}, 2));
  LightSource point_light;  // a point light (the default type), for comparison: one shadow ray
  point_light.position = {0.1, 0.2, 2};
  const PreparedLight<double> point = prepare_light<double>(point_light);
  for (const Vec3d& p : {Vec3d{0, 0, 0}, Vec3d{0.7, -0.4, 0}, Vec3d{2, 1, 0}}) {
    const ShadingPoint<double> sp = point_up(p);
    for (const PreparedLight<double>* l : {&area, &tube, &point}) {
      const ShadeOptions o = options_with(SpecularMethod::kExact);
      CHECK(shade(*l, sp, o).diffuse > 0);
      CHECK(shade_shadowed(*l, sp, o, bvh).diffuse == 0);
    }
  }
}
