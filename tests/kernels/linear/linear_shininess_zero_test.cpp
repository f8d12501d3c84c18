// Shininess m -> 0 continuity of the linear specular: the lobe at m = 0 is the limit m -> 0+,
// [Rv.L > 0] (core/robust_math.h phong_power), so the exact specular at m = 0 is the part of the
// light in front of the lobe's half-space, and m = 1e-12 gives the same value to ~1e-11.
// Checked against the long-double reference (linear_reference.h) with the light in front of,
// behind and straddling the half-space Rv.L > 0, at m = 0, 1e-12, 1, 1e4.
#include <doctest/doctest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "linear_cases.h"

using namespace vlit;
using namespace vlit::linear_test;

namespace {

// P at the origin, N = +z, the segment 1 above the tangent plane along x.
Config half_space_case(const std::string& where, double m) {
  Config c;
  c.p = {0, 0, 0};
  c.n = {0, 0, 1};
  c.shininess = m;
  char buf[32];
  std::snprintf(buf, sizeof buf, " m=%g", m);
  c.name = where + buf;
  if (where == "front") {  // Rv.L > 0 on the whole segment; the lobe's axis meets it at x = 0.1
    c.q0 = {-1, 0.3, 1};
    c.q1 = {1, 0.3, 1};
    c.rv = normalize(Vec3d{0.1, 0.3, 1});
  } else if (where == "behind") {  // Rv.L = x + 0.05 - 0.06 < 0 on the whole segment
    c.q0 = {-3, 0.3, 1};
    c.q1 = {-1, 0.3, 1};
    c.rv = normalize(Vec3d{1, -0.2, 0.05});
  } else {  // straddling: Rv.L = x + 0.2 changes sign at x = -0.2
    c.q0 = {-2, 0, 1};
    c.q1 = {2, 0, 1};
    c.rv = normalize(Vec3d{1, 0, 0.2});
  }
  return c;
}

double exact_specular(const Config& c, double tol, SpecularFalloff falloff = SpecularFalloff::kAsDiffuse) {
  const Typed<double> x = typed<double>(c, 2);
  SpecularOptions o{SpecularMethod::kExact};
  o.exact_tolerance = tol;
  o.falloff = falloff;
  return shade_linear(x.light, x.sp, o).specular;
}

}  // namespace

TEST_CASE("m -> 0 continuity: exact specular at m = 0, 1e-12, 1, 1e4 in front of, behind and across the lobe") {
  for (const char* where : {"front", "behind", "straddling"}) {
    for (double m : {0.0, 1e-12, 1.0, 1e4}) {
      const Config c = half_space_case(where, m);
      const Typed<double> x = typed<double>(c, 2);
      const LD ref = ref_specular_exact(x);
      const double k = exact_specular(c, 1e-10);
      const double err = rel_err(k, ref, LD(1e-300));
      INFO(c.name, ": kernel ", k, ", reference ", double(ref), ", rel.err ", err);
      CHECK(std::isfinite(k));
      CHECK(err <= 1e-9);
      MESSAGE("linear exact specular ", c.name, ": kernel=", k, " reference=", double(ref), " rel.err=", err);
    }
  }
}

TEST_CASE("m -> 0 continuity: the values at m = 0 and m = 1e-12 agree, and equal the part in front") {
  // Straddling: the part in front is x in [-0.2, 2] of [-2, 2] (t = (x + 2) / 4) at height 1.
  // With the falloff 1/|L|^2 = 1/(1 + x^2): (atan 2 + atan 0.2) / 4; without it (the paper's
  // form, exact-no-falloff), its length 2.2 / 4 of the unit t range.
  const double m0 = exact_specular(half_space_case("straddling", 0), 1e-10);
  const double m12 = exact_specular(half_space_case("straddling", 1e-12), 1e-10);
  CHECK(m0 == doctest::Approx((std::atan(2.0) + std::atan(0.2)) / 4).epsilon(1e-12));
  CHECK(std::abs(m12 - m0) <= 1e-10 * m0);
  const double paper0 = exact_specular(half_space_case("straddling", 0), 1e-10, SpecularFalloff::kNone);
  const double paper12 = exact_specular(half_space_case("straddling", 1e-12), 1e-10, SpecularFalloff::kNone);
  CHECK(paper0 == doctest::Approx(2.2 / 4).epsilon(1e-12));
  CHECK(std::abs(paper12 - paper0) <= 1e-10 * paper0);
  // Behind: 0 at every m, including m = 0 (formerly the whole light, 1).
  CHECK(exact_specular(half_space_case("behind", 0), 1e-10) == 0);
  CHECK(exact_specular(half_space_case("behind", 1e-12), 1e-10) == 0);
  CHECK(exact_specular(half_space_case("behind", 0), 1e-10, SpecularFalloff::kNone) == 0);
  // Front: the whole light at m = 0: x in [-1, 1] at distance^2 x^2 + 1.09 from P, t = (x + 1) / 2,
  // so (1/2) ∫ dx / (x^2 + 1.09) = atan(1 / sqrt 1.09) / sqrt 1.09; without falloff, 1.
  const double r = std::sqrt(1.09);
  CHECK(exact_specular(half_space_case("front", 0), 1e-10) == doctest::Approx(std::atan(1 / r) / r).epsilon(1e-13));
  CHECK(exact_specular(half_space_case("front", 0), 1e-10, SpecularFalloff::kNone) == doctest::Approx(1).epsilon(1e-14));
  // The peak at m = 0 is the lobe's maximum over the light: 1 if any of it is in front, else 0.
  const Typed<double> behind = typed<double>(half_space_case("behind", 0), 2);
  const Typed<double> straddling = typed<double>(half_space_case("straddling", 0), 2);
  CHECK(shade_linear(behind.light, behind.sp, SpecularOptions{SpecularMethod::kPeak}).specular == 0);
  CHECK(shade_linear(straddling.light, straddling.sp, SpecularOptions{SpecularMethod::kPeak}).specular == 1);
}
