// The material library (.mtl) of an OBJ file, as far as the scene's material model can use it
// (docs/mesh-files.md "OBJ materials"): `newmtl` starts a material; `Kd` (diffuse colour),
// `Ks` (specular colour, validated but not used: a metallic-roughness dielectric has ks = 0.04),
// `Ns` (Phong exponent) and `Ke` (emission, luminance in nits) are read; every other statement
// (Ka, d, Tr, illum, Ni, map_*, ...) is ignored. Colours are `r [g b]` (one number is grey);
// the `spectral` and `xyz` forms are ignored with a warning.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "core/vec3.h"
#include "scene/material.h"

namespace vlit {

struct MtlMaterial {
  std::string name;
  std::optional<Vec3d> kd, ks, ke;
  std::optional<double> ns;
};

// Materials in file order. Throws InputError(path, problem, "line N") for a malformed statement
// (a number that does not parse or is negative or not finite, a colour of 2 or more than 3
// numbers, a statement before the first `newmtl`, `newmtl` without a name); a Kd above 1 is
// clamped to 1 with a warning (glTF's baseColorFactor is at most 1).
std::vector<MtlMaterial> read_mtl_file(const std::string& path, std::vector<std::string>& warnings);

// The scene material of an .mtl material: base_color = Kd (0.8 grey without Kd), metallic 0,
// roughness = roughness_for_shininess(Ns) (0.5 without Ns), emission = Ke (strength 1),
// one-sided like any OBJ face.
Material material_from_mtl(const MtlMaterial& mtl);

}  // namespace vlit
