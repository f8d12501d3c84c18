// The shading dispatch: each light model reached through prepare_light/shade gives the value
// derived by hand for a simple configuration, times its intensity handling.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>

#include "shading/prepared_light.h"

using namespace vlit;

TEST_CASE("linear light over the point, parallel to the surface: Id = 1/sqrt 2 per unit intensity") {
  // P at the origin, N = +Y, segment from (-1, 1, 0) to (1, 1, 0), falloff 2. With x = 2t - 1,
  // Id = ∫ 1 / (1 + x^2)^(3/2) dx / 2 over [-1, 1] = [x / sqrt(1 + x^2)] / 2 = 1 / sqrt 2.
  LightSource l;
  l.type = LightType::kLinear;
  l.from = {-1, 1, 0};
  l.to = {1, 1, 0};
  l.falloff = 2;
  const auto sp = make_shading_point<double>({0, 0, 0}, {0, 1, 0}, {0, 5, 0}, 1.0);
  ShadeOptions options;
  CHECK(shade(prepare_light<double>(l), sp, options).diffuse == doctest::Approx(1 / std::sqrt(2.0)).epsilon(1e-12));
  CHECK(shade(prepare_light<float>(l), make_shading_point<float>({0, 0, 0}, {0, 1, 0}, {0, 5, 0}, 1.0f), options).diffuse ==
        doctest::Approx(1 / std::sqrt(2.0)).epsilon(1e-6));
  // Falloff 0: Id = ∫ 1 / (1 + x^2)^(1/2) dx / 2 = asinh(1).
  l.falloff = 0;
  CHECK(shade(prepare_light<double>(l), sp, options).diffuse == doctest::Approx(std::asinh(1.0)).epsilon(1e-12));
  // Specular off in the options gives no specular even with a shiny point looking at the light.
  options.with_specular = false;
  CHECK(shade(prepare_light<double>(l), sp, options).specular == 0.0);
}

TEST_CASE("square panel centred above the point: the closed form of a parallel rectangle") {
  // Id = ∫∫ h^2 / (x^2 + y^2 + h^2)^2 dx dy. For the quarter [0, a] x [0, b] with X = a/h, Y = b/h
  // (the classic point-to-parallel-rectangle form factor times pi):
  //   (1/2) [X / sqrt(1+X^2) atan(Y / sqrt(1+X^2)) + Y / sqrt(1+Y^2) atan(X / sqrt(1+Y^2))].
  // A centred square of half-side a is four quarters with X = Y.
  auto expected = [](double a, double h) {
    const double x = a / h, s = std::sqrt(1 + x * x);
    return 4 * x / s * std::atan(x / s);
  };
  const auto sp = make_shading_point<double>({0, 0, 0}, {0, 0, 1}, {0, 0, 5}, 10.0);
  for (const double h : {0.5, 1.0, 3.0}) {
    LightSource l;
    l.type = LightType::kArea;
    l.polygon = {{-1, -1, h}, {-1, 1, h}, {1, 1, h}, {1, -1, h}};  // counter-clockwise seen from below
    CHECK(shade(prepare_light<double>(l), sp, ShadeOptions{}).diffuse == doctest::Approx(expected(1, h)).epsilon(1e-12));
    // The same square wound the other way emits upwards, away from the point: nothing.
    std::reverse(l.polygon.begin(), l.polygon.end());
    CHECK(shade(prepare_light<double>(l), sp, ShadeOptions{}).diffuse == 0.0);
    l.two_sided = true;
    CHECK(shade(prepare_light<double>(l), sp, ShadeOptions{}).diffuse == doctest::Approx(expected(1, h)).epsilon(1e-12));
  }
}

TEST_CASE("with_diffuse = false: a tube's, a panel's and a disk's specular unchanged, their diffuse skipped (0)") {
  // The bake's scalar specular path asks for the specular only where the batch kernel has the diffuse.
  const auto sp = make_shading_point<double>({0.2, 0.1, 0}, {0, 0, 1}, {0.5, 0, 5}, 40.0);
  LightSource tube, panel, disk;
  tube.type = LightType::kLinear;
  tube.from = {-1, 0.2, 1};
  tube.to = {1, 0.3, 1};
  tube.falloff = 1.5;  // the diffuse by quadrature
  panel.type = LightType::kArea;
  panel.polygon = {{-1, -1, 1}, {-1, 1, 1}, {1, 1, 1}, {1, -1, 1}};
  disk.type = LightType::kDisk;
  disk.center = {0.3, 0, 1};
  disk.normal = {0, 0, -1};
  disk.radius = 0.5;
  for (const LightSource& l : {tube, panel, disk}) {
    const PreparedLight<double> light = prepare_light<double>(l);
    ShadeOptions both, specular_only;
    specular_only.with_diffuse = false;
    const Response<double> full = shade(light, sp, both), spec = shade(light, sp, specular_only);
    INFO("light type ", int(l.type));
    CHECK(full.diffuse > 0);
    CHECK(full.specular > 0);
    CHECK(spec.specular == full.specular);
    CHECK(spec.diffuse == 0.0);
  }
}

TEST_CASE("disk facing the point on its axis: Id = pi R^2 / (R^2 + h^2)") {
  // The projected solid angle of a cap of half-angle alpha is pi sin^2 alpha.
  const auto sp = make_shading_point<double>({0, 0, 0}, {0, 0, 1}, {0, 0, 5}, 10.0);
  LightSource l;
  l.type = LightType::kDisk;
  l.center = {0, 0, 2};
  l.normal = {0, 0, -1};
  l.radius = 0.5;
  const double expected = M_PI * 0.25 / (0.25 + 4);
  CHECK(shade(prepare_light<double>(l), sp, ShadeOptions{}).diffuse == doctest::Approx(expected).epsilon(1e-6));
}
