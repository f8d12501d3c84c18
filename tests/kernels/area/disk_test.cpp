// Disk light (disk_light.h): the inscribed/circumscribed bracket, the point-light limit, and the
// measured error against edge count (printed for docs/area-lights.md).
#include <doctest/doctest.h>

#include <cstdio>

#include "area_test_util.h"
#include "disk_light.h"

using namespace vlit;
using namespace vlit::test;

namespace {

// Reference for a disk fully above the horizon: polar quadrature about its center (independent
// of the polygon bracket), long double.
double reference_disk_diffuse(const DiskLight<double>& d, const ShadingPoint<double>& sp) {
  using boost::math::quadrature::gauss_kronrod;
  const V3 c = static_cast<V3>(d.center), P = static_cast<V3>(sp.p), N = static_cast<V3>(sp.n);
  const V3 nl = normalize(static_cast<V3>(d.normal));
  const V3 helper = std::abs(nl.x) < 0.6L ? V3{1, 0, 0} : V3{0, 1, 0};
  const V3 e1 = normalize(cross(helper, nl)), e2 = cross(nl, e1);
  const LD h = dot(nl, P - c);
  if (h <= 0) return 0;
  const LD R = d.radius;
  auto f = [&](LD phi) {
    auto g = [&](LD rho) {
      const V3 a = c + e1 * (rho * std::cos(phi)) + e2 * (rho * std::sin(phi)) - P;
      const LD r2 = length_squared(a), r = std::sqrt(r2);
      const LD cos_t = dot(N, a) / r;
      return cos_t > 0 ? rho * cos_t * (h / r) / r2 : LD(0);
    };
    return gauss_kronrod<LD, 31>::integrate(g, LD(0), R, 12, LD(1e-13));
  };
  return static_cast<double>(gauss_kronrod<LD, 31>::integrate(f, LD(0), LD(2 * M_PI), 12, LD(1e-12)));
}

}  // namespace

TEST_CASE("disk light: bracket contains the reference; measured error vs edge count") {
  const SpecularOptions none = spec_options(SpecularMethod::kNone);
  struct Case { const char* name; DiskLight<double> d; ShadingPoint<double> sp; };
  const Case cases[] = {
      {"overhead d=1", {{0, 0, 1}, {0, 0, -1}, 1}, {{0.2, 0.1, 0}, {0, 0, 1}, {0, 0, 1}, 1}},
      {"tilted d=3", {{1, 0, 3}, {-0.3, 0.1, -1}, 1}, {{0, 0, 0}, normalize(Vec3d{0.2, 0, 1}), {0, 0, 1}, 1}},
      {"near the rim", {{0, 0, 1}, {0, 0, -1}, 1}, {{1.05, 0, 0.9}, {0, 0, 1}, {0, 0, 1}, 1}},
      {"far d=100", {{0, 0, 100}, {0, 0, -1}, 1}, {{0, 0, 0}, {0, 0, 1}, {0, 0, 1}, 1}},
  };
  for (const auto& c : cases) {
    const double ref = reference_disk_diffuse(c.d, c.sp);
    INFO(c.name, " reference=", ref);
    for (int n = 8; n <= 64; n *= 2) {
      const DiskBracket<double> b = shade_disk_bracket(c.d, c.sp, none, 0.0, n, n);
      CHECK(b.inscribed.diffuse <= ref * (1 + 1e-12));
      CHECK(b.circumscribed.diffuse >= ref * (1 - 1e-12));
      MESSAGE("disk '", std::string(c.name), "' n=", n, ": inscribed rel.err=", (b.inscribed.diffuse - ref) / ref,
              " (2 out + in)/3 rel.err=", (b.estimate.diffuse - ref) / ref,
              " bracket width=", (b.circumscribed.diffuse - b.inscribed.diffuse) / ref);
    }
    const Response<double> r = shade_disk(c.d, c.sp, spec_options(SpecularMethod::kPeak));
    CHECK(all_finite(r));
    CHECK(std::abs(r.diffuse - ref) <= 1e-2 * ref);
  }
}

TEST_CASE("disk light: limits and stiff cases") {
  const SpecularOptions none = spec_options(SpecularMethod::kNone);
  SUBCASE("far disk = point light of intensity pi R^2 cos(theta_l)") {
    const DiskLight<double> d{{0, 0, 1000}, {0, 0.2, -1}, 1};
    const ShadingPoint<double> sp{{0, 0, 0}, {0, 0, 1}, {0, 0, 1}, 1};
    const double cos_l = dot(normalize(d.normal), Vec3d{0, 0, -1});
    CHECK(shade_disk(d, sp, none).diffuse == doctest::Approx(M_PI * cos_l / 1e6).epsilon(1e-6));
  }
  SUBCASE("behind, horizon crossing, float") {
    const DiskLight<double> d{{0, 0, 1}, {0, 0, -1}, 1};
    CHECK(shade_disk(d, {{0, 0, 2}, {0, 0, -1}, {0, 0, -1}, 1}, none).diffuse == 0);
    const Response<double> r = shade_disk(d, {{0.3, 0, 0.5}, {1, 0, 0}, {1, 0, 0}, 10}, spec_options(SpecularMethod::kExact));
    CHECK(all_finite(r));
    CHECK(r.diffuse > 0);
    const DiskLight<float> df{{0, 0, 1}, {0, 0, -1}, 1};
    const Response<float> rf = shade_disk(df, ShadingPoint<float>{{0.3f, 0, 0.5f}, {1, 0, 0}, {1, 0, 0}, 10}, spec_options(SpecularMethod::kExact));
    CHECK(rf.diffuse == doctest::Approx(r.diffuse).epsilon(1e-6));
  }
  SUBCASE("invalid disks are rejected") {
    CHECK_THROWS_AS(shade_disk(DiskLight<double>{{0, 0, 1}, {0, 0, 0}, 1}, {{0, 0, 0}, {0, 0, 1}, {0, 0, 1}, 1}, none), std::invalid_argument);
    CHECK_THROWS_AS(shade_disk(DiskLight<double>{{0, 0, 1}, {0, 0, -1}, 0}, {{0, 0, 0}, {0, 0, 1}, {0, 0, 1}, 1}, none), std::invalid_argument);
  }
}
