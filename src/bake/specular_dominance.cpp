#include "bake/specular_dominance.h"

#include <algorithm>
#include <cstdio>

#include "scene/material.h"

namespace vlit {
namespace {

double brightest(const Vec3d& c) { return std::max({c.x, c.y, c.z}); }

// What the method computed, in the words of docs/conventions.md.
const char* method_words(const SpecularOptions& s) {
  switch (s.method) {
    case SpecularMethod::kPeak: return "--specular peak: the lobe's maximum over each light, without distance falloff";
    case SpecularMethod::kNeighborhood:
      return "--specular neighborhood: the lobe's maximum over each light, without distance falloff";
    case SpecularMethod::kExact:
      return s.falloff == SpecularFalloff::kAsDiffuse
                 ? "--specular exact: the lobe integrated over each light with its distance falloff"
                 : "--specular exact-no-falloff: the lobe integrated over each light without distance falloff";
    case SpecularMethod::kNone: return "--specular none";
  }
  return "?";
}

// How to change it: the definition when a paper form was used, else leaving the specular out.
const char* remedy_words(const SpecularOptions& s) {
  if (s.method == SpecularMethod::kExact && s.falloff == SpecularFalloff::kAsDiffuse)
    return "--specular none draws the diffuse only; rougher or non-metallic materials have smaller highlights";
  return "--specular exact integrates the lobe with the light's falloff (the definition), --specular none draws the "
         "diffuse only";
}

}  // namespace

SpecularDominance measure_specular_dominance(const Scene& scene, const std::vector<VertexLight>& light,
                                             const Vec3d& eye, double exposure) {
  SpecularDominance d;
  for (std::size_t i = 0; i < scene.primitives.size() && i < light.size(); ++i) {
    const ScenePrimitive& prim = scene.primitives[i];
    const PhongMaterial phong = phong_from_metallic_roughness(scene.material_of(prim));
    const VertexLight& l = light[i];
    for (std::size_t v = 0; v < l.diffuse.size() && v < prim.positions.size(); ++v) {
      if (v < prim.normals.size() && !(dot(prim.normals[v], eye - prim.positions[v]) > 0)) continue;
      const Vec3d diffuse_term = hadamard(phong.kd, static_cast<Vec3d>(l.diffuse[v]));
      const Vec3d specular_term =
          v < l.specular.size() ? hadamard(phong.ks, static_cast<Vec3d>(l.specular[v])) : Vec3d{};
      const double diffuse = brightest(diffuse_term), specular = brightest(specular_term);
      if (!(diffuse > 0) && !(specular > 0)) continue;
      ++d.lit;
      const bool saturates = exposure * diffuse < 1 && exposure * brightest(diffuse_term + specular_term) >= 1;
      if (specular > kSpecularDominanceRatio * diffuse || saturates) ++d.dominated;
    }
  }
  return d;
}

std::string specular_dominance_warning(const SpecularDominance& d, const SpecularOptions& specular) {
  if (!d.dominates()) return {};
  char head[160];
  std::snprintf(head, sizeof head,
                "the specular is over %gx the diffuse or saturates at %zu of %zu lit vertices facing the eye (%.1f %%) ",
                kSpecularDominanceRatio, d.dominated, d.lit, 100.0 * double(d.dominated) / double(d.lit));
  return std::string(head) + "(" + method_words(specular) + "); " + remedy_words(specular);
}

}  // namespace vlit
