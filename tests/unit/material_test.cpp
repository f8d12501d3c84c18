#include <doctest/doctest.h>

#include <cmath>

#include "scene/material.h"

using namespace vlit;

TEST_CASE("metallic-roughness to Phong mapping (docs/conventions.md)") {
  Material m;
  m.base_color = {0.5, 0.25, 1};
  m.metallic = 0;
  m.roughness = 0.5;
  PhongMaterial p = phong_from_metallic_roughness(m);
  CHECK(p.kd == Vec3d{0.5, 0.25, 1});
  CHECK(p.ks.x == doctest::Approx(0.04));
  // alpha = 0.25: m = 2 / 0.0625 - 2 = 30.
  CHECK(p.shininess == doctest::Approx(30));

  m.metallic = 1;
  m.roughness = 1;  // alpha = 1: 2 - 2 = 0, clamped to 1
  p = phong_from_metallic_roughness(m);
  CHECK(p.ks == m.base_color);
  CHECK(p.kd == m.base_color);
  CHECK(p.shininess == 1);

  m.roughness = 0;  // mirror: the largest exponent
  CHECK(phong_from_metallic_roughness(m).shininess == 1e4);
}
