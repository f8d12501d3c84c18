#include <doctest/doctest.h>

#include <cmath>
#include <limits>

#include "core/robust_math.h"

using namespace vlit;

// 4 C E - 4 for C, E close to 1 (D = 2), exactly from the double inputs themselves: with
// C = 1 + dc and E = 1 + de, dc and de are exact in double (Sterbenz: C - 1 has no rounding), and
// 4 C E - 4 = 4 (dc + de) + 4 dc de. dc and de have at most 53 - 27 = 26 significant bits for
// |dc|, |de| >= 2^-27 (fewer for the cases below), so dc + de and dc de are exact in long double's
// 64-bit significand; the reference's only error is the final addition (relative 5e-20), where a
// long double product 4 C * E would already be off by 2e-19 absolute (relative 3e-11 here).
long double exact_4ce_minus_4(double c, double e) {
  const long double dc = c - 1.0, de = e - 1.0;
  return 4 * (dc + de) + 4 * (dc * de);
}

// The naive form, each product rounded to double on its own (volatile: no FMA contraction).
double naive_difference_of_products(double a, double b, double c, double d) {
  volatile double ab = a * b, cd = c * d;
  return ab - cd;
}

TEST_CASE("difference_of_products keeps the digits that a*b - c*d loses") {
  // 4CE - D^2 for a point almost collinear with a segment: C = E = 1 + eps, D = 2. The input
  // 1 + 1e-9 is itself rounded: C - 1 = 1.000000082740371e-9, so the value to compare against is
  // 8 (C - 1) + 4 (C - 1)^2 with the rounded C, not 8e-9 + 4e-18 (which is 1e-7 away).
  const double c = 1 + 1e-9, e = c, d = 2;
  const long double exact = exact_4ce_minus_4(c, e);
  CHECK(static_cast<double>(exact) != 8e-9 + 4e-18);  // the rounding of the input matters
  const double robust = difference_of_products(4 * c, e, d, d);
  const double naive = naive_difference_of_products(4 * c, e, d, d);
  const double tol = 4 * std::numeric_limits<double>::epsilon();  // a few units in the last place
  CHECK(std::abs(robust - exact) <= tol * std::abs(exact));
  // The naive form drops 4 (C - 1)^2 (relative 5e-10): far outside the bar the FMA form meets.
  CHECK(std::abs(naive - exact) > 1e5 * tol * std::abs(exact));

  // C = 1 + 2^-30, E = 1 - 2^-30: 4CE - 4 = -4 * 2^-60 exactly; the naive form rounds 4CE to 4
  // and returns 0, the FMA form returns the exact value.
  const double c2 = 1 + std::ldexp(1.0, -30), e2 = 1 - std::ldexp(1.0, -30);
  const long double exact2 = exact_4ce_minus_4(c2, e2);
  CHECK(exact2 == -std::ldexp(1.0L, -58));
  CHECK(difference_of_products(4 * c2, e2, d, d) == static_cast<double>(exact2));
  CHECK(naive_difference_of_products(4 * c2, e2, d, d) == 0.0);

  // A sweep of near-collinear inputs: C = 1 + k 2^-40, E = 1 + j 2^-41, every result within a few
  // ulps of the exact one.
  for (int k = 1; k <= 50; ++k)
    for (int j = -50; j <= 50; ++j) {
      const double ck = 1 + k * std::ldexp(1.0, -40), ej = 1 + j * std::ldexp(1.0, -41);
      const long double x = exact_4ce_minus_4(ck, ej);
      const double r = difference_of_products(4 * ck, ej, d, d);
      CAPTURE(k);
      CAPTURE(j);
      CHECK(std::abs(r - x) <= tol * std::abs(x));
    }
}

int sign_of(double x) { return (x > 0) - (x < 0); }

TEST_CASE("orient2_sign is orient2's sign, also where plain products lose it, and fast_orient2_sign is it or 0") {
  // Near-collinear points: a = (0.5, 0.5) moved by i, j units in the last place, on the line
  // through b = (12, 12) and c = (24, 24). Plain products round to equal values at some of them
  // where the determinant is not 0 (rounding is monotone, so they give 0, not the opposite sign);
  // orient2_sign must then take orient2's answer, and fast_orient2_sign must say 0 (undecided),
  // never a sign other than orient2's.
  const double ulp = std::ldexp(1.0, -53);
  int naive_lost = 0, checked = 0, undecided = 0;
  for (int i = 0; i < 256; ++i)
    for (int j = 0; j < 256; ++j) {
      const double ax = 0.5 + i * ulp, ay = 0.5 + j * ulp;
      const int s = sign_of(orient2(ax, ay, 12, 12, 24, 24));
      volatile double p = (12 - ax) * (24 - ay), q = (12 - ay) * (24 - ax);  // no FMA contraction
      const bool lost = sign_of(p - q) != s;
      naive_lost += lost;
      const int fast = fast_orient2_sign(ax, ay, 12, 12, 24, 24);
      undecided += fast == 0;
      CAPTURE(i);
      CAPTURE(j);
      REQUIRE(orient2_sign(ax, ay, 12, 12, 24, 24) == s);
      REQUIRE((fast == 0 || fast == s));
      if (lost) REQUIRE(fast == 0);
      ++checked;
    }
  CHECK(checked == 65536);
  CHECK(naive_lost > 1000);  // so the fallback is exercised, not only the fast path
  CHECK(undecided >= naive_lost);

  // Exactly collinear (0), shared endpoints (0), ordinary (clear sign), and tiny and huge scales
  // where the products underflow or come near overflow.
  CHECK(orient2_sign(0, 0, 1, 1, 3, 3) == 0);
  CHECK(orient2_sign(0.1, 0.7, 0.3, 0.2, 0.1, 0.7) == 0);
  CHECK(orient2_sign(0.1, 0.7, 0.3, 0.2, 0.3, 0.2) == 0);
  CHECK(orient2_sign(0, 0, 1, 0, 0, 1) == 1);
  CHECK(orient2_sign(0, 0, 1, 0, 0, -1) == -1);
  for (double scale : {1e-160, 1e-300, 1e150}) {
    CAPTURE(scale);
    CHECK(orient2_sign(0, 0, scale, 0, 0, scale) == sign_of(orient2(0, 0, scale, 0, 0, scale)));
    CHECK(orient2_sign(0, 0, scale, scale, 2 * scale, 2 * scale + scale * 1e-15) ==
          sign_of(orient2(0, 0, scale, scale, 2 * scale, 2 * scale + scale * 1e-15)));
  }
  // Random points, some snapped to a coarse grid so that many are exactly collinear; the fast
  // sign decides nearly all of the others.
  unsigned state = 12345;
  auto next = [&] {
    state = state * 1664525u + 1013904223u;
    return (state >> 8) / 16777216.0;
  };
  int off_grid = 0, decided = 0;
  for (int k = 0; k < 20000; ++k) {
    double x[6];
    for (double& v : x) v = k % 2 ? std::round(next() * 8) / 8 : next() * 2 - 1;
    const int s = sign_of(orient2(x[0], x[1], x[2], x[3], x[4], x[5]));
    const int fast = fast_orient2_sign(x[0], x[1], x[2], x[3], x[4], x[5]);
    CHECK(orient2_sign(x[0], x[1], x[2], x[3], x[4], x[5]) == s);
    CHECK((fast == 0 || fast == s));
    off_grid += k % 2 == 0;
    decided += k % 2 == 0 && fast != 0;
  }
  CHECK(decided > off_grid - off_grid / 100);
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
