// Tests of core/mat4.h: inverse, glTF projections, look_at.
#include <doctest/doctest.h>

#include <cmath>
#include <random>

#include "core/mat4.h"

using namespace vlit;

TEST_CASE("mat4: inverse of random well-conditioned matrices gives the identity") {
  std::mt19937 rng(12345);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int trial = 0; trial < 200; ++trial) {
    Mat4d a;
    for (auto& row : a.m)
      for (double& v : row) v = u(rng);
    for (int i = 0; i < 4; ++i) a.m[i][i] += 4.0;  // diagonally dominant: well conditioned
    const auto inv = inverse(a);
    REQUIRE(inv);
    const Mat4d p = a * *inv, q = *inv * a;
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j) {
        CHECK(p.m[i][j] == doctest::Approx(i == j ? 1.0 : 0.0).epsilon(1e-12).scale(1.0));
        CHECK(q.m[i][j] == doctest::Approx(i == j ? 1.0 : 0.0).epsilon(1e-12).scale(1.0));
      }
  }
}

TEST_CASE("mat4: singular and non-finite matrices have no inverse") {
  Mat4d a = Mat4d::identity();
  a.m[2][2] = 0;
  CHECK_FALSE(inverse(a));
  Mat4d b = Mat4d::identity();
  b.m[0][1] = NAN;
  CHECK_FALSE(inverse(b));
}

TEST_CASE("mat4: from_column_major reads glTF order") {
  const double gltf[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 5, 6, 7, 1};  // translation (5,6,7)
  const Mat4d m = Mat4d::from_column_major(gltf);
  CHECK(m == Mat4d::translation({5, 6, 7}));
  const Vec3d p = transform_point(m, Vec3d{1, 1, 1});
  CHECK(p == Vec3d{6, 7, 8});
}

TEST_CASE("mat4: glTF perspective maps znear to -1, zfar to +1, infinity to +1") {
  const double n = 0.1, f = 50, yfov = 0.9, aspect = 1.5;
  const Mat4d finite = perspective_gltf(aspect, yfov, n, std::optional<double>(f));
  const Mat4d infinite = perspective_gltf(aspect, yfov, n, std::optional<double>());
  CHECK(transform_point(finite, Vec3d{0, 0, -n}).z == doctest::Approx(-1.0));
  CHECK(transform_point(finite, Vec3d{0, 0, -f}).z == doctest::Approx(1.0));
  CHECK(transform_point(infinite, Vec3d{0, 0, -n}).z == doctest::Approx(-1.0));
  CHECK(transform_point(infinite, Vec3d{0, 0, -1e9}).z == doctest::Approx(1.0).epsilon(1e-9));
  // The top of the frustum at distance d is d tan(yfov/2) and maps to y = 1; the side to x = 1.
  const double d = 7.0, t = std::tan(0.5 * yfov);
  CHECK(transform_point(finite, Vec3d{0, d * t, -d}).y == doctest::Approx(1.0));
  CHECK(transform_point(finite, Vec3d{d * t * aspect, 0, -d}).x == doctest::Approx(1.0));
  CHECK(transform_point_h(finite, Vec3d{0, 0, -d}).w == doctest::Approx(d));
}

TEST_CASE("mat4: glTF orthographic maps the box to the clip cube") {
  const Mat4d o = orthographic_gltf(2.0, 3.0, 0.5, 10.0);
  const Vec3d p = transform_point(o, Vec3d{2, -3, -0.5});
  CHECK(p.x == doctest::Approx(1.0));
  CHECK(p.y == doctest::Approx(-1.0));
  CHECK(p.z == doctest::Approx(-1.0));
  CHECK(transform_point(o, Vec3d{0, 0, -10}).z == doctest::Approx(1.0));
}

TEST_CASE("mat4: look_at puts the eye at the origin and the target on -Z") {
  const Vec3d eye{3, 4, 5}, target{-1, 2, 0.5};
  const Mat4d world_from_camera = look_at(eye, target, Vec3d{0, 1, 0});
  const Mat4d camera_from_world = *inverse(world_from_camera);
  const Vec3d e = transform_point(camera_from_world, eye);
  const Vec3d t = transform_point(camera_from_world, target);
  CHECK(length(e) == doctest::Approx(0.0).scale(1.0));
  CHECK(t.x == doctest::Approx(0.0).scale(1.0));
  CHECK(t.y == doctest::Approx(0.0).scale(1.0));
  CHECK(t.z == doctest::Approx(-length(target - eye)));
  // World up stays up: a point above the target projects to camera +Y.
  CHECK(transform_point(camera_from_world, target + Vec3d{0, 1, 0}).y > 0);
}
