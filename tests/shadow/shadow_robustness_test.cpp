// Robustness of the light-cutting on degenerate and coincident geometry: occluders snapped to a
// coarse grid (shared edges, edges whose projection runs along the light's edges, corners on cone
// planes, coplanar with P or the light) must give finite, non-negative light, never more than
// the unshadowed light, identical with the BVH on and off; and splitting an occluder into two
// triangles along a shared edge must not change the result (no crack lets light through).
#include <doctest/doctest.h>

#include <random>

#include "shadow_test_util.h"

using namespace vlit;
using namespace vlit::test;

namespace {

double snap(double x) { return std::round(x * 4) / 4; }  // multiples of 0.25

}  // namespace

TEST_CASE("snapped (coincident, degenerate) occluders: finite, >= 0, <= unshadowed, BVH on = off") {
  const std::vector<Vec3d> light = square_light(0.5, 2);  // corners on the 0.25 grid
  const PreparedLight<double> area = prepare_light<double>(area_source(light));
  const PreparedLight<double> tube = prepare_light<double>(linear_source({-0.5, 0, 2}, {0.5, 0, 2}, 2));
  std::mt19937_64 rng(2026);
  std::uniform_real_distribution<double> u(-1.2, 1.2), z(-0.3, 2.3);
  int shadowed = 0;
  for (int trial = 0; trial < 300; ++trial) {
    std::vector<Tri> tris;
    const int count = 1 + static_cast<int>(rng() % 6);
    for (int k = 0; k < count; ++k)
      tris.push_back({Vec3d{snap(u(rng)), snap(u(rng)), snap(z(rng))}, Vec3d{snap(u(rng)), snap(u(rng)), snap(z(rng))},
                      Vec3d{snap(u(rng)), snap(u(rng)), snap(z(rng))}});
    if (trial % 3 == 0) tris.push_back({tris[0][1], tris[0][0], Vec3d{snap(u(rng)), snap(u(rng)), 1.0}});  // shared edge
    const OccluderBvh bvh = make_bvh(tris), brute = make_bvh(tris, true);
    const Vec3d p{snap(u(rng)) * 0.5, snap(u(rng)) * 0.5, 0};
    const ShadingPoint<double> sp = make_shading_point(p, Vec3d{0, 0, 1}, Vec3d{0.25, 0, 3}, 16.0);
    for (SpecularMethod method : {SpecularMethod::kPeak, SpecularMethod::kNeighborhood, SpecularMethod::kExact}) {
      const ShadeOptions o = options_with(method);
      for (const PreparedLight<double>* l : {&area, &tube}) {
        const Response<double> r = shade_shadowed(*l, sp, o, bvh), rb = shade_shadowed(*l, sp, o, brute);
        const Response<double> open = shade(*l, sp, o);
        INFO("trial " << trial);
        REQUIRE(std::isfinite(r.diffuse));
        REQUIRE(std::isfinite(r.specular));
        CHECK(r.diffuse >= 0);
        CHECK(r.specular >= 0);
        CHECK(r.diffuse <= open.diffuse * (1 + 1e-12));
        CHECK(r.specular <= open.specular * (1 + 1e-9) + 1e-15);
        CHECK(r.diffuse == rb.diffuse);
        CHECK(r.specular == rb.specular);
        shadowed += r.diffuse < open.diffuse * (1 - 1e-9);
      }
    }
  }
  CHECK(shadowed > 100);
}

TEST_CASE("an occluder split along a shared edge hides exactly what the whole hides (no cracks)") {
  const std::vector<Vec3d> light = square_light(1, 2);
  const PreparedLight<double> area = prepare_light<double>(area_source(light));
  const PreparedLight<double> tube = prepare_light<double>(linear_source({-1, 0.1, 2}, {1, -0.2, 2}, 1));
  std::mt19937_64 rng(77);
  std::uniform_real_distribution<double> u(-1, 1), z(0.5, 1.5), t(0.2, 0.8);
  for (int trial = 0; trial < 100; ++trial) {
    const Tri whole{Vec3d{u(rng), u(rng), z(rng)}, Vec3d{u(rng), u(rng), z(rng)}, Vec3d{u(rng), u(rng), z(rng)}};
    const Vec3d m = whole[1] + (whole[2] - whole[1]) * t(rng);  // a point on edge 1-2
    const std::vector<Tri> halves{{whole[0], whole[1], m}, {whole[0], m, whole[2]}};
    const OccluderBvh one = make_bvh({whole}), two = make_bvh(halves);
    const ShadingPoint<double> sp = make_shading_point(Vec3d{u(rng) * 0.5, u(rng) * 0.5, 0}, Vec3d{0, 0, 1},
                                                       Vec3d{0, 0, 4}, 8.0);
    const ShadeOptions o = options_with(SpecularMethod::kExact);
    for (const PreparedLight<double>* l : {&area, &tube}) {
      const Response<double> a = shade_shadowed(*l, sp, o, one), b = shade_shadowed(*l, sp, o, two);
      INFO("trial " << trial);
      const double scale = shade(*l, sp, o).diffuse;
      CHECK(std::abs(a.diffuse - b.diffuse) <= 1e-12 * scale);
      CHECK(std::abs(a.specular - b.specular) <= 1e-6 * std::max(a.specular, 1e-12));
    }
  }
}
