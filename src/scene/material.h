// Surface material: what the glTF says (metallic-roughness) and the Phong terms the kernels use.
#pragma once

#include <string>

#include "core/vec3.h"

namespace vlit {

struct Material {
  std::string name;           // the file's name for it (glTF name, OBJ usemtl), for messages and output
  Vec3d base_color{1, 1, 1};  // linear RGB (glTF baseColorFactor, alpha ignored)
  bool base_color_texture = false;  // the glTF has a baseColorTexture (vlit does not sample textures)
  double metallic = 1;        // glTF defaults
  double roughness = 1;
  bool double_sided = false;
  // Emission (glTF emissiveFactor x KHR_materials_emissive_strength): luminance in nits, linear
  // RGB. A material with an emissive texture is not used as a light (textures are not sampled).
  Vec3d emissive_factor{0, 0, 0};
  double emissive_strength = 1;
  bool emissive_texture = false;

  Vec3d emission() const { return emissive_factor * emissive_strength; }
};

// The Phong material of paper eq. 1 and 6 derived from a metallic-roughness material
// (docs/conventions.md "Material mapping"):
//   kd = base_color   (metallic does not darken the diffuse: with no environment light a metal
//                      would bake black, glTF's default material is fully metallic, and COLOR_0
//                      must be a plain multiplier of baseColor; see docs/conventions.md)
//   ks = mix(0.04, base_color, metallic)            (F0 of a dielectric is 4%)
//   m  = clamp(2 / alpha^2 - 2, 1, 1e4) with alpha = roughness^2
//        (the Blinn-Phong exponent with the same lobe width as a GGX of that roughness).
struct PhongMaterial {
  Vec3d kd{1, 1, 1};
  Vec3d ks{0, 0, 0};
  double shininess = 1;
};

PhongMaterial phong_from_metallic_roughness(const Material& material);

// The inverse of the shininess mapping above: the roughness whose Phong exponent is `shininess`
// (clamped to [1, 1e4] first), roughness = (2 / (m + 2))^(1/4). For materials that come with an
// exponent (an OBJ's .mtl Ns), so phong_from_metallic_roughness gives that exponent back.
double roughness_for_shininess(double shininess);

}  // namespace vlit
