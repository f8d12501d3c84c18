// The shading dispatch: each light model reached through prepare_light/shade gives the value
// derived by hand for a simple configuration, times its intensity handling.
#include <doctest/doctest.h>

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
