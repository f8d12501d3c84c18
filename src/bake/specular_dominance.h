// Whether a render's specular dominates its diffuse, and the one line render prints when it does.
//
// Criterion (docs/conventions.md "What a render draws"): over the vertices that receive light and
// face the eye (N.(E - P) > 0: the others cannot be seen), the specular term dominates at a vertex
// when the brightest channel of ks x specular exceeds kSpecularDominanceRatio (10) times the
// brightest channel of kd x diffuse, or when it saturates the vertex (some channel of
// exposure x (kd x diffuse + ks x specular) is >= 1 while exposure x kd x diffuse is < 1); the
// render dominates when more than half of those vertices do. Such an image is a highlight map, often washed out
// to white: a light bright enough for the diffuse gives a far brighter specular (the lobe's
// maximum of a linear or area light has no distance falloff, docs/accuracy.md), so render says
// what it computed and how to change it. Tested in tests/unit/specular_dominance_test.cpp.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "bake/light_vertices.h"
#include "conventions.h"
#include "scene/scene.h"

namespace vlit {

inline constexpr double kSpecularDominanceRatio = 10;

struct SpecularDominance {
  std::size_t lit = 0;        // vertices facing the eye with some light (diffuse or specular term > 0)
  std::size_t dominated = 0;  // of those, vertices whose specular term > 10 x the diffuse term or saturates
  bool dominates() const { return dominated * 2 > lit; }
};

// Counts over every primitive of `scene`; `light[i]` belongs to scene.primitives[i]. A primitive
// without specular light counts its lit vertices only. `exposure`: render's --exposure.
SpecularDominance measure_specular_dominance(const Scene& scene, const std::vector<VertexLight>& light,
                                             const Vec3d& eye, double exposure);

// The line render prints (without a trailing newline) when `d.dominates()`, naming the specular
// method used (`specular`) and the options that change it; empty otherwise.
std::string specular_dominance_warning(const SpecularDominance& d, const SpecularOptions& specular);

}  // namespace vlit
