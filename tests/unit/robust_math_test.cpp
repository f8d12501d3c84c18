#include <doctest/doctest.h>

#include <cmath>
#include <limits>

#include "core/robust_math.h"

using namespace vlit;

TEST_CASE("difference_of_products keeps the digits that a*b - c*d loses") {
  // 4CE - D^2 for a point almost collinear with a segment: C = E = 1 + eps, D = 2.
  const double eps = 1e-9;
  const double c = 1 + eps, e = 1 + eps, d = 2;
  // Exact: 4(1+eps)^2 - 4 = 8 eps + 4 eps^2.
  const double exact = 8 * eps + 4 * eps * eps;
  const double robust = difference_of_products(4 * c, e, d, d);
  CHECK(std::abs(robust - exact) <= 1e-6 * exact);
}

TEST_CASE("angle_between is accurate near 0 and pi where acos(dot) is not") {
  const double tiny = 1e-10;
  const Vec3d a{1, 0, 0};
  const Vec3d b{1, tiny, 0};
  CHECK(angle_between(a, b) == doctest::Approx(tiny).epsilon(1e-6));
  CHECK(angle_between(a, -b) == doctest::Approx(M_PI - tiny).epsilon(1e-12));
  CHECK(angle_between(a, a) == 0.0);
}

TEST_CASE("safe_sqrt clamps rounding residue below zero") {
  CHECK(safe_sqrt(-1e-18) == 0.0);
  CHECK(safe_sqrt(4.0) == 2.0);
}

TEST_CASE("phong_power clamps the back lobe") {
  CHECK(phong_power(-0.5, 10.0) == 0.0);
  CHECK(phong_power(0.5, 2.0) == doctest::Approx(0.25));
  CHECK(phong_power(1.0, 1e4) == 1.0);
}
