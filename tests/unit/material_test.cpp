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

TEST_CASE("roughness_for_shininess inverts the shininess mapping (an OBJ's Ns)") {
  for (const double ns : {1.0, 2.5, 10.0, 30.0, 250.0, 1000.0, 1e4}) {
    Material m;
    m.roughness = roughness_for_shininess(ns);
    CHECK(m.roughness >= 0);
    CHECK(m.roughness <= 1);
    CHECK(phong_from_metallic_roughness(m).shininess == doctest::Approx(ns).epsilon(1e-12));
  }
  // Roughness 0.5 is m = 30 (above); the inverse gives it back.
  CHECK(roughness_for_shininess(30) == doctest::Approx(0.5).epsilon(1e-15));
  // Outside [1, 1e4] the exponent is clamped first, as the forward mapping clamps.
  CHECK(roughness_for_shininess(0) == roughness_for_shininess(1));
  CHECK(roughness_for_shininess(1e9) == roughness_for_shininess(1e4));
}
