#include "scene/material.h"

#include <algorithm>
#include <cmath>

namespace vlit {

PhongMaterial phong_from_metallic_roughness(const Material& m) {
  const double metallic = std::clamp(m.metallic, 0.0, 1.0);
  const double roughness = std::clamp(m.roughness, 0.0, 1.0);
  PhongMaterial p;
  p.kd = m.base_color;
  p.ks = Vec3d{0.04, 0.04, 0.04} * (1 - metallic) + m.base_color * metallic;
  const double alpha = roughness * roughness;
  const double exponent = alpha > 0 ? 2 / (alpha * alpha) - 2 : 1e4;
  p.shininess = std::clamp(exponent, 1.0, 1e4);
  return p;
}

double roughness_for_shininess(double shininess) {
  const double m = std::clamp(shininess, 1.0, 1e4);
  return std::pow(2 / (m + 2), 0.25);  // alpha^2 = roughness^4 = 2 / (m + 2)
}

}  // namespace vlit
