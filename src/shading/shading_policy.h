// The shading policy of bake and render, in one place. A lit vertex looks like
//   kd x diffuse + ks x specular        (per channel; docs/conventions.md)
// with kd and ks from the glTF material (phong_from_metallic_roughness, scene/material.h) and the
// light's diffuse and specular from the kernels (bake/light_vertices.h). render draws that colour;
// a bake stores the multiplier of the base colour (kd) that a viewer turns into it.
#pragma once

#include <array>

#include "scene/material.h"

namespace vlit {

// The colour render draws (bake/lit_draw_mesh.cpp). `specular` may be null (no specular light).
inline Vec3d shaded_color(const PhongMaterial& phong, const Vec3d& diffuse, const Vec3d* specular) {
  Vec3d color = hadamard(phong.kd, diffuse);
  if (specular) color += hadamard(phong.ks, *specular);
  return color;
}

// The specular part of a bake's base-colour multiplier (bake/vertex_color_bake.cpp): adds
// ks x specular x exposure / kd to each channel of `multiplier` (its diffuse part, diffuse x
// exposure, is there already), so that viewer = kd x multiplier = kd x diffuse + ks x specular.
// Returns false when a channel with specular light has kd = 0: no multiplier of a black base
// colour can show it (that channel's specular is left out).
inline bool add_specular_to_multiplier(const PhongMaterial& phong, const Vec3d& specular, double exposure,
                                       std::array<double, 4>& multiplier) {
  const double ks[3] = {phong.ks.x, phong.ks.y, phong.ks.z}, albedo[3] = {phong.kd.x, phong.kd.y, phong.kd.z};
  const double spec[3] = {specular.x, specular.y, specular.z};
  bool represented = true;
  for (int ch = 0; ch < 3; ++ch) {
    const double term = ks[ch] * spec[ch] * exposure;
    if (!(term > 0)) continue;
    if (albedo[ch] > 0) multiplier[ch] += term / albedo[ch];
    else represented = false;
  }
  return represented;
}

}  // namespace vlit
