// Shadowed disk lights are the disk itself (src/shadow/disk_pieces.h): the visible pieces of the
// disk's circumscribed polygon intersected with the disk, their diffuse from straight edges and
// rim arcs. Checked against exact values that need no disk-piece code (the open disk kernel
// minus a projected square's polygon kernel; half the open disk by symmetry) and against
// independent shadow rays over the disk.
#include <doctest/doctest.h>

#include <random>

#include "shadow/disk_pieces.h"
#include "shadow/shadowed_light.h"
#include "shadow_reference.h"
#include "shadow_test_util.h"

using namespace vlit;
using namespace vlit::test;

namespace {

constexpr double kRadius = 0.5, kHeight = 2;

PreparedLight<double> overhead_disk() { return prepare_light<double>(disk_source({0, 0, kHeight}, {0, 0, -1}, kRadius)); }

ShadeOptions diffuse_only() { return options_with(SpecularMethod::kNone); }

// A square occluder at height 1.2 between P and the disk, and its projection from P onto the
// disk's plane (a light facing down, of the disk's radiance).
struct HiddenSquare {
  OccluderBvh bvh;
  std::vector<Vec3d> shadow;
};

HiddenSquare hidden_square(const Vec3d& p) {
  const double z0 = 1.2, half = 0.05;
  const Vec3d middle = p + (Vec3d{0.1, 0.05, kHeight} - p) * ((z0 - p.z) / (kHeight - p.z));
  std::vector<Tri> tris;
  add_quad(tris, middle + Vec3d{-half, -half, 0}, {2 * half, 0, 0}, {0, 2 * half, 0});
  HiddenSquare h{make_bvh(tris), {}};
  for (const Vec3d& corner : {Vec3d{-half, -half, 0}, Vec3d{-half, half, 0}, Vec3d{half, half, 0}, Vec3d{half, -half, 0}})
    h.shadow.push_back(p + (middle + corner - p) * ((kHeight - p.z) / (z0 - p.z)));
  return h;
}

}  // namespace

TEST_CASE("a shadowed disk: a small square hidden in its middle takes exactly that square's light away") {
  // A square occluder (hidden_square) whose projection from P onto the disk's plane lies inside the
  // disk: the visible part is the disk minus that projected square, so the value is the open disk's
  // minus the square's own light (a polygon light of the same radiance). The visible pieces the
  // silhouettes make reach the rim, so their arcs carry the result.
  for (const Vec3d p : {Vec3d{0, 0, 0}, Vec3d{0.3, -0.2, 0}, Vec3d{-0.6, 0.1, 0.5}}) {
    CAPTURE(p);
    const ShadingPoint<double> sp = make_shading_point(p, Vec3d{0, 0, 1}, Vec3d{0, 0, 5}, 10.0);
    const auto [bvh, shadow] = hidden_square(p);
    for (const Vec3d& x : shadow) REQUIRE(std::hypot(x.x, x.y) < kRadius);
    const double open = shade(overhead_disk(), sp, diffuse_only()).diffuse;
    const double square = shade(prepare_light<double>(area_source(shadow)), sp, diffuse_only()).diffuse;
    for (const AreaShadowMethod method : {AreaShadowMethod::kSilhouette, AreaShadowMethod::kTriangleCuts}) {
      ShadeOptions o = diffuse_only();
      o.area_shadows = method;
      const double got = shade_shadowed(overhead_disk(), sp, o, bvh).diffuse;
      MESSAGE("disk " << open << " - square " << square << " = " << open - square << "; shadowed " << got);
      REQUIRE(square > 0.01 * open);
      CHECK(std::abs(got - (open - square)) <= 1e-12 * open);
    }
  }
}

TEST_CASE("a shadowed disk: a plate over half of it leaves exactly half (mirror symmetry)") {
  std::vector<Tri> tris;
  add_quad(tris, {0, -3, 1}, {3, 0, 0}, {0, 6, 0});  // x >= 0 at height 1
  const OccluderBvh bvh = make_bvh(tris);
  for (const double z : {0.0, 1.0, 1.9}) {
    CAPTURE(z);
    const ShadingPoint<double> sp = make_shading_point(Vec3d{0, 0, z - 1e-3 * (z > 0.5)}, Vec3d{0, 0, 1}, Vec3d{0, 0, 5}, 10.0);
    const double open = shade(overhead_disk(), sp, diffuse_only()).diffuse;
    if (sp.p.z >= 1) continue;  // above the plate: nothing hides the disk
    const double got = shade_shadowed(overhead_disk(), sp, diffuse_only(), bvh).diffuse;
    CHECK(std::abs(got - 0.5 * open) <= 1e-12 * open);
  }
}

TEST_CASE("a shadowed disk agrees with shadow rays over the disk (random occluders, tilted disk)") {
  std::mt19937_64 rng(977);
  std::uniform_real_distribution<double> u(-1.2, 1.2), z(0.4, 1.6), small(-0.3, 0.3);
  const Vec3d c{0.2, -0.1, 2.2}, nl = normalize(Vec3d{0.2, 0.1, -1});
  const double r = 0.8;
  const PreparedLight<double> disk = prepare_light<double>(disk_source(c, nl, r));
  int partly = 0;
  for (int trial = 0; trial < 4; ++trial) {
    std::vector<Tri> tris;
    for (int k = 0; k < 12; ++k) {
      const Vec3d a{u(rng), u(rng), z(rng)};
      tris.push_back({a, a + Vec3d{small(rng), small(rng), small(rng)}, a + Vec3d{small(rng), small(rng), small(rng)}});
    }
    const OccluderBvh bvh = make_bvh(tris);
    for (int k = 0; k < 4; ++k) {
      const ShadingPoint<double> sp = make_shading_point(Vec3d{u(rng), u(rng), 0}, Vec3d{0, 0, 1}, Vec3d{0, 0, 5}, 10.0);
      const double open = shade(disk, sp, diffuse_only()).diffuse;
      const double got = shade_shadowed(disk, sp, diffuse_only(), bvh).diffuse;
      const Estimate ref = reference_disk(c, nl, r, {sp.p, sp.n, sp.rv, 1}, tris, 400, 31u + trial * 7 + k);
      CAPTURE(trial);
      CAPTURE(k);
      MESSAGE("open " << open << " shadowed " << got << " rays " << ref.value << " +- " << ref.standard_error);
      CHECK(std::abs(got - ref.value) <= 4 * ref.standard_error + 1e-9 * open);
      partly += got < 0.99 * open && got > 0.01 * open;
    }
  }
  CHECK(partly >= 4);
}

// The exact specular of a shadowed disk is the disk's (arcs, not a polygon standing for it):
// checked against the open disk's exact specular (disk_specular_exact.h) minus the projected
// square's, a polygon light (area_specular_exact_dispatch), neither of which reads disk pieces.
// Eyes with the mirror direction on the disk (the full contour form) and far off it (the tail
// form); m from 0 (the limit m -> 0+) to 1e3.
TEST_CASE("a shadowed disk's exact specular: a small square hidden in its middle takes exactly that square's lobe away") {
  const ShadeOptions exact = options_with(SpecularMethod::kExact);
  const double tol = exact.specular.exact_tolerance;
  int tails = 0;
  for (const Vec3d p : {Vec3d{0, 0, 0}, Vec3d{0.3, -0.2, 0}, Vec3d{-0.6, 0.1, 0.5}})
    for (const Vec3d eye : {Vec3d{0.1, 0.2, 5}, Vec3d{-6, 1, 2.5}})
      for (const double m : {0.0, 1.0, 10.0, 40.5, 1000.0}) {
        CAPTURE(p);
        CAPTURE(eye);
        CAPTURE(m);
        const ShadingPoint<double> sp = make_shading_point(p, Vec3d{0, 0, 1}, eye, m);
        const auto [bvh, shadow] = hidden_square(p);
        const double open = shade(overhead_disk(), sp, exact).specular;
        const double square = shade(prepare_light<double>(area_source(shadow)), sp, exact).specular;
        const Vec3d hit = p + sp.rv * ((kHeight - p.z) / sp.rv.z);
        const bool tail = std::hypot(hit.x, hit.y) > 2 * kRadius;
        tails += tail;
        // A tail at m = 1e3 lies below what the kernels resolve (0; area_specular_exact.h).
        REQUIRE((open > 0 || (tail && m == 1000.0)));
        for (const AreaShadowMethod method : {AreaShadowMethod::kSilhouette, AreaShadowMethod::kTriangleCuts}) {
          ShadeOptions o = exact;
          o.area_shadows = method;
          const double got = shade_shadowed(overhead_disk(), sp, o, bvh).specular;
          MESSAGE("disk " << open << " - square " << square << " = " << open - square << "; shadowed " << got);
          CHECK(std::abs(got - (open - square)) <= 4 * tol * open);
        }
      }
  CHECK(tails == 15);  // the far eye's mirror direction misses the disk at every point
}

TEST_CASE("a shadowed disk's exact specular: a plate over half of it leaves exactly half (mirror symmetry)") {
  std::vector<Tri> tris;
  add_quad(tris, {0, -3, 1}, {3, 0, 0}, {0, 6, 0});  // x >= 0 at height 1
  const OccluderBvh bvh = make_bvh(tris);
  const ShadeOptions exact = options_with(SpecularMethod::kExact);
  for (const double z : {0.0, 0.9})
    for (const Vec3d eye : {Vec3d{0, 0, 5}, Vec3d{0, 3, 4}, Vec3d{0, -8, 1}})
      for (const double m : {0.0, 1e-12, 1.0, 7.5, 100.0, 1e4}) {
        CAPTURE(z);
        CAPTURE(eye);
        CAPTURE(m);
        // P and the eye in the plane x = 0, so Rv is too: the lobe is symmetric under x -> -x.
        const ShadingPoint<double> sp = make_shading_point(Vec3d{0, 0, z}, Vec3d{0, 0, 1}, eye, m);
        const double open = shade(overhead_disk(), sp, exact).specular;
        const double got = shade_shadowed(overhead_disk(), sp, exact, bvh).specular;
        MESSAGE("open " << open << " shadowed " << got);
        if (!(open > 1e-300)) continue;  // a lobe that misses the disk: nothing to halve
        CHECK(std::abs(got - 0.5 * open) <= 4 * exact.specular.exact_tolerance * open);
      }
}

TEST_CASE("a shadowed disk's exact specular is 0 when the mirror direction points away from the disk, also at m = 0") {
  // The eye below P's surface: Rv points down, and the lobe's half-space (its limit at m -> 0+
  // included) holds none of the disk. Unclipped, the contour's winding about Rv would count the
  // visible part whose direction is -Rv.
  std::vector<Tri> tris;
  add_quad(tris, {-0.05, -0.05, 1}, {0.1, 0, 0}, {0, 0.1, 0});
  const OccluderBvh bvh = make_bvh(tris);
  const ShadeOptions exact = options_with(SpecularMethod::kExact);
  for (const double m : {0.0, 1e-12, 1.0, 40.5}) {
    CAPTURE(m);
    const ShadingPoint<double> sp = make_shading_point(Vec3d{0.1, 0, 0}, Vec3d{0, 0, 1}, Vec3d{0.4, 0.3, -5}, m);
    REQUIRE(sp.rv.z < 0);
    REQUIRE(shade_shadowed(overhead_disk(), sp, options_with(SpecularMethod::kNone), bvh).diffuse <
            0.99 * shade(overhead_disk(), sp, options_with(SpecularMethod::kNone)).diffuse);  // the plate hides some
    CHECK(shade(overhead_disk(), sp, exact).specular == 0);
    CHECK(shade_shadowed(overhead_disk(), sp, exact, bvh).specular == 0);
  }
}

TEST_CASE("a shadowed disk seen through a small hole is the hole's polygon light (a piece inside the disk)") {
  // A plate at height 1.2 with a square hole whose projection from P lies inside the disk: the
  // only visible piece is that projection, a polygon light of the disk's radiance, diffuse and
  // exact specular (mirror direction on the hole and off it).
  const Vec3d p{0.1, -0.1, 0};
  const double z0 = 1.2, half = 0.05, big = 3;
  const Vec3d middle = p + (Vec3d{0.1, 0.05, kHeight} - p) * ((z0 - p.z) / (kHeight - p.z));
  std::vector<Tri> tris;
  const Vec3d lo = middle - Vec3d{half, half, 0};
  add_quad(tris, {-big, -big, z0}, {2 * big, 0, 0}, {0, lo.y + big, 0});                          // below the hole
  add_quad(tris, {-big, lo.y + 2 * half, z0}, {2 * big, 0, 0}, {0, big - lo.y - 2 * half, 0});     // above
  add_quad(tris, {-big, lo.y, z0}, {lo.x + big, 0, 0}, {0, 2 * half, 0});                           // left
  add_quad(tris, {lo.x + 2 * half, lo.y, z0}, {big - lo.x - 2 * half, 0, 0}, {0, 2 * half, 0});     // right
  const OccluderBvh bvh = make_bvh(tris);
  std::vector<Vec3d> hole;
  for (const Vec3d& corner : {Vec3d{-half, -half, 0}, Vec3d{-half, half, 0}, Vec3d{half, half, 0}, Vec3d{half, -half, 0}})
    hole.push_back(p + (middle + corner - p) * ((kHeight - p.z) / (z0 - p.z)));
  for (const Vec3d& x : hole) REQUIRE(std::hypot(x.x, x.y) < kRadius);
  const PreparedLight<double> hole_light = prepare_light<double>(area_source(hole));
  const ShadeOptions exact = options_with(SpecularMethod::kExact);
  for (const Vec3d eye : {Vec3d{0.4, -0.1, 5}, Vec3d{-6, 1, 2.5}})
    for (const double m : {0.0, 1.0, 40.5}) {
      CAPTURE(eye);
      CAPTURE(m);
      const ShadingPoint<double> sp = make_shading_point(p, Vec3d{0, 0, 1}, eye, m);
      const Response<double> want = shade(hole_light, sp, exact);
      const Response<double> got = shade_shadowed(overhead_disk(), sp, exact, bvh);
      MESSAGE("hole " << want.diffuse << " " << want.specular << "; shadowed " << got.diffuse << " " << got.specular);
      REQUIRE(want.specular > 0);
      CHECK(std::abs(got.diffuse - want.diffuse) <= 1e-12 * want.diffuse);
      CHECK(std::abs(got.specular - want.specular) <= 4 * exact.specular.exact_tolerance * want.specular);
    }
}
