// The margins next to the shaded point: an occluder close above a vertex must hide the light.
//
// The area visibility (src/shadow/area_visibility.cpp, kApexMargin) and the linear visibility
// (src/shadow/linear_visibility.h, kLinearNearP) ignore whatever lies within margin x h of P, where h
// is P's distance to the light's plane (area) or line (linear). The margin exists so that P's own
// triangles and rounding at P (about 1e-16 x the coordinates' size) do not shadow P; but it also
// hides real occluders. The bound they rely on:
//
//   rounding at P  <<  margin x h  <  the gap between P and the nearest occluder that must shadow.
//
// With a light 2 m away and a plate 1 mm above the vertex, the margin must stay below 5e-4 (the
// 1 cm plate alone: 5e-3). At 1e-9 a light 1 km away still sees a plate 1 um above the vertex.
// Raising either margin to 1e-2 (2 cm at h = 2 m) lets the light through the plates below:
// these tests then fail. They use only the public entry (shade_shadowed), so they hold whatever
// the inside of the visibility code becomes.
#include <doctest/doctest.h>

#include "shadow_test_util.h"

using namespace vlit;
using namespace vlit::test;

namespace {

// A square plate of half-size `half` at height z above the origin, facing down (towards P).
std::vector<Tri> plate_at(double z, double half) {
  std::vector<Tri> tris;
  add_quad(tris, Vec3d{-half, -half, z}, Vec3d{0, 2 * half, 0}, Vec3d{2 * half, 0, 0});
  return tris;
}

ShadingPoint<double> vertex_up() { return make_shading_point(Vec3d{0, 0, 0}, Vec3d{0, 0, 1}, Vec3d{0.3, 0.2, 5}, 8.0); }

}  // namespace

TEST_CASE("a plate 1 cm (and 1 mm) above a vertex hides an area light 2 m away") {
  const ShadingPoint<double> sp = vertex_up();
  const PreparedLight<double> light = prepare_light<double>(area_source(square_light(0.5, 2.0)));
  const ShadeOptions o = options_with(SpecularMethod::kExact);
  const Response<double> open = shade(light, sp, o);
  REQUIRE(open.diffuse > 0.1);
  REQUIRE(open.specular > 0);
  // The plate's shadow cone from P covers the light with room to spare: at height z it must reach
  // 0.5 z / 2 = z / 4 from the axis; it reaches 5 z.
  for (double z : {1e-2, 1e-3}) {
    CAPTURE(z);
    const OccluderBvh bvh = make_bvh(plate_at(z, 5 * z));
    const Response<double> r = shade_shadowed(light, sp, o, bvh);
    CHECK(r.diffuse == 0);
    CHECK(r.specular == 0);
  }
  // The same plate with a hole over P (four strips around a gap): the light comes back, so the
  // zeros above are the plate's doing and not a broken light.
  std::vector<Tri> frame;
  const double z = 1e-2, half = 5e-2, gap = 2e-3;
  add_quad(frame, Vec3d{-half, -half, z}, Vec3d{0, 2 * half, 0}, Vec3d{half - gap, 0, 0});
  add_quad(frame, Vec3d{gap, -half, z}, Vec3d{0, 2 * half, 0}, Vec3d{half - gap, 0, 0});
  add_quad(frame, Vec3d{-gap, -half, z}, Vec3d{0, half - gap, 0}, Vec3d{2 * gap, 0, 0});
  add_quad(frame, Vec3d{-gap, gap, z}, Vec3d{0, half - gap, 0}, Vec3d{2 * gap, 0, 0});
  const Response<double> through = shade_shadowed(light, sp, o, make_bvh(frame));
  CHECK(through.diffuse > 0);
  CHECK(through.diffuse < open.diffuse);
}

TEST_CASE("a plate 1 cm (and 1 mm) above a vertex hides a linear light 2 m away") {
  const ShadingPoint<double> sp = vertex_up();
  const ShadeOptions o = options_with(SpecularMethod::kExact);
  for (double falloff : {0.0, 2.0}) {
    CAPTURE(falloff);
    const PreparedLight<double> light = prepare_light<double>(linear_source({-0.5, 0.1, 2}, {0.5, -0.1, 2}, falloff));
    const Response<double> open = shade(light, sp, o);
    REQUIRE(open.diffuse > 0.1);
    for (double z : {1e-2, 1e-3}) {
      CAPTURE(z);
      const Response<double> r = shade_shadowed(light, sp, o, make_bvh(plate_at(z, 5 * z)));
      CHECK(r.diffuse == 0);
      CHECK(r.specular == 0);
    }
  }
}

TEST_CASE("a plate 1 cm above a vertex hides a disk light and a point light 2 m away") {
  const ShadingPoint<double> sp = vertex_up();
  const ShadeOptions o = options_with(SpecularMethod::kExact);
  const OccluderBvh bvh = make_bvh(plate_at(1e-2, 5e-2));
  const PreparedLight<double> disk = prepare_light<double>(disk_source({0, 0, 2}, {0, 0, -1}, 0.5));
  REQUIRE(shade(disk, sp, o).diffuse > 0.1);
  CHECK(shade_shadowed(disk, sp, o, bvh).diffuse == 0);
  LightSource point;
  point.position = {0.1, 0, 2};
  const PreparedLight<double> pl = prepare_light<double>(point);
  REQUIRE(shade(pl, sp, o).diffuse > 0);
  CHECK(shade_shadowed(pl, sp, o, bvh).diffuse == 0);
}
