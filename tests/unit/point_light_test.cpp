// Point, directional and spot kernels against values derived by hand in each test.
#include <doctest/doctest.h>

#include <cmath>

#include "directional_light.h"
#include "shading/prepared_light.h"
#include "point_light.h"
#include "spot_light.h"

using namespace vlit;

namespace {
ShadingPoint<double> up_point_seen_from_above() {
  // P at the origin, N = +Z, eye straight above: V = Rv = +Z.
  return make_shading_point<double>({0, 0, 0}, {0, 0, 1}, {0, 0, 10}, 8.0);
}
}  // namespace

TEST_CASE("point light straight above: diffuse = 1/d^n, specular = 1/d^n (eq. 6 without falloff: 1)") {
  const auto sp = up_point_seen_from_above();
  for (double n : {0.0, 1.0, 2.0, 3.0, 1.5}) {
    const Response<double> r = shade_point(PointLight<double>{{0, 0, 2}, n}, sp, true);
    CHECK(r.diffuse == doctest::Approx(1.0 / std::pow(2.0, n)).epsilon(1e-15));
    CHECK(r.specular == doctest::Approx(1.0 / std::pow(2.0, n)).epsilon(1e-15));
    const Response<double> paper = shade_point(PointLight<double>{{0, 0, 2}, n}, sp, true, SpecularFalloff::kNone);
    CHECK(paper.diffuse == r.diffuse);
    CHECK(paper.specular == doctest::Approx(1.0).epsilon(1e-15));
  }
}

TEST_CASE("point light at a 3-4-5 triangle: cos = 4/5, |L| = 5") {
  const auto sp = up_point_seen_from_above();
  const PointLight<double> light{{3, 0, 4}, 2};
  const Response<double> r = shade_point(light, sp, true);
  CHECK(r.diffuse == doctest::Approx(0.8 / 25).epsilon(1e-15));
  // Rv = +Z, L̂ = (0.6, 0, 0.8): specular = 0.8^8 / 5^2 (the diffuse's falloff), 0.8^8 without it.
  CHECK(r.specular == doctest::Approx(std::pow(0.8, 8) / 25).epsilon(1e-14));
  CHECK(shade_point(light, sp, true, SpecularFalloff::kNone).specular == doctest::Approx(std::pow(0.8, 8)).epsilon(1e-14));
  // Linear falloff n = 1: cos / |L|.
  CHECK(shade_point(PointLight<double>{{3, 0, 4}, 1}, sp, false).diffuse == doctest::Approx(0.8 / 5).epsilon(1e-15));
}

TEST_CASE("point light below the horizon gives nothing, also no specular") {
  // Eye below too, so Rv points at the light: only horizon clipping can zero the specular.
  const auto sp = make_shading_point<double>({0, 0, 0}, {0, 0, 1}, {0, 0, -1}, 1.0);
  const Response<double> r = shade_point(PointLight<double>{{0, 0, -2}, 2}, sp, true);
  CHECK(r.diffuse == 0.0);
  CHECK(r.specular == 0.0);
}

TEST_CASE("point light at the surface point gives zero, not Inf") {
  const auto sp = up_point_seen_from_above();
  const Response<double> r = shade_point(PointLight<double>{{0, 0, 0}, 2}, sp, true);
  CHECK(r.diffuse == 0.0);
  CHECK(r.specular == 0.0);
}

TEST_CASE("directional light: diffuse = cos, no falloff") {
  const auto sp = up_point_seen_from_above();
  const Vec3d dir = normalize(Vec3d{-3, 0, -4});  // travels down and to -x: comes from (3, 0, 4)
  const Response<double> r = shade_directional(DirectionalLight<double>{dir}, sp, true);
  CHECK(r.diffuse == doctest::Approx(0.8).epsilon(1e-15));
  CHECK(r.specular == doctest::Approx(std::pow(0.8, 8)).epsilon(1e-14));
  CHECK(shade_directional(DirectionalLight<double>{{0, 0, 1}}, sp, true).diffuse == 0.0);
}

TEST_CASE("spot light: point light inside the inner cone, dark outside the outer, s^2 between") {
  const auto sp = up_point_seen_from_above();
  SpotLight<double> spot;
  spot.position = {0, 0, 2};
  spot.falloff = 2;
  spot.cos_inner = std::cos(0.2);
  spot.cos_outer = std::cos(0.4);
  // Axis straight at P: full point light.
  spot.direction = {0, 0, -1};
  CHECK(shade_spot(spot, sp, false).diffuse == doctest::Approx(0.25).epsilon(1e-15));
  // Specular (Rv at the light, lobe 1): the point light's falloff 1/2^2, or none (eq. 6).
  CHECK(shade_spot(spot, sp, true).specular == doctest::Approx(0.25).epsilon(1e-15));
  CHECK(shade_spot(spot, sp, true, SpecularFalloff::kNone).specular == doctest::Approx(1.0).epsilon(1e-15));
  // Axis tilted by 0.3 rad: P is at angle 0.3, between the cones.
  spot.direction = {std::sin(0.3), 0, -std::cos(0.3)};
  const double s = (std::cos(0.3) - std::cos(0.4)) / (std::cos(0.2) - std::cos(0.4));
  CHECK(shade_spot(spot, sp, false).diffuse == doctest::Approx(0.25 * s * s).epsilon(1e-12));
  // Tilted by 0.5 rad: outside the outer cone.
  spot.direction = {std::sin(0.5), 0, -std::cos(0.5)};
  CHECK(shade_spot(spot, sp, true).diffuse == 0.0);
}

TEST_CASE("glTF range: the KHR_lights_punctual window 1 - (d/r)^4, zero beyond") {
  const auto sp = up_point_seen_from_above();
  LightSource l;
  l.type = LightType::kPoint;
  l.position = {0, 0, 2};
  l.range = 4.0;
  ShadeOptions options;
  const PreparedLight<double> light = prepare_light<double>(l);
  // d = 2, r = 4: window = 1 - (1/2)^4 = 15/16, on top of 1/d^2 = 1/4.
  CHECK(shade(light, sp, options).diffuse == doctest::Approx(0.25 * 15.0 / 16.0).epsilon(1e-15));
  l.range = 1.5;  // beyond range
  CHECK(shade(prepare_light<double>(l), sp, options).diffuse == 0.0);
}

TEST_CASE("the specular falloff option reaches point and spot lights through shade()") {
  const auto sp = up_point_seen_from_above();  // Rv = +Z, lobe 1 at a light straight above
  for (LightType type : {LightType::kPoint, LightType::kSpot}) {
    LightSource l;
    l.type = type;
    l.position = {0, 0, 4};
    l.direction = {0, 0, -1};
    l.falloff = 2;
    ShadeOptions options;  // default: exact, with the diffuse's falloff
    const PreparedLight<double> light = prepare_light<double>(l);
    CHECK(shade(light, sp, options).specular == doctest::Approx(1.0 / 16).epsilon(1e-15));
    options.specular.falloff = SpecularFalloff::kNone;  // --specular exact-no-falloff
    CHECK(shade(light, sp, options).specular == doctest::Approx(1.0).epsilon(1e-15));
  }
}
