// The render's "specular dominates" criterion (bake/specular_dominance.h): counts against vertex
// lights set by hand, the threshold on both sides, and the line it prints naming the method.
#include <doctest/doctest.h>

#include <string>

#include "bake/specular_dominance.h"

using namespace vlit;

namespace {

// Above the vertices (all at the origin, normal +z): every vertex faces it. Exposure 1e-3 keeps
// every vertex far from saturating, so the ratio alone decides unless a test says otherwise.
const Vec3d kEye{0, 0, 5};

// One primitive of `n` vertices with a material of kd = base colour, ks from metallic.
Scene scene_of(std::size_t n, double base, double metallic) {
  Scene scene;
  Material material;
  material.base_color = {base, base, base};
  material.metallic = metallic;
  material.roughness = 0.5;
  scene.materials.push_back(material);
  ScenePrimitive prim;
  prim.material = 0;
  prim.positions.assign(n, Vec3d{});
  prim.normals.assign(n, Vec3d{0, 0, 1});
  scene.primitives.push_back(prim);
  return scene;
}

}  // namespace

TEST_CASE("specular dominance: more than half the lit vertices with ks x specular > 10 x kd x diffuse") {
  // Metal of base colour 0.5: kd = 0.5, ks = 0.5. Vertex terms: diffuse 0.5 d, specular 0.5 s.
  const Scene scene = scene_of(10, 0.5, 1.0);
  VertexLight light;
  light.diffuse.assign(10, Vec3f{1, 1, 1});
  light.specular.assign(10, Vec3f{0, 0, 0});
  light.diffuse[9] = Vec3f{};  // one unlit vertex: not counted
  SUBCASE("5 of 9 lit vertices above 10x: dominates") {
    for (int v = 0; v < 5; ++v) light.specular[v] = Vec3f{10.5f, 0, 0};  // brightest channel counts
    const SpecularDominance d = measure_specular_dominance(scene, {light}, kEye, 1e-3);
    CHECK(d.lit == 9);
    CHECK(d.dominated == 5);
    CHECK(d.dominates());
    SpecularOptions peak{SpecularMethod::kPeak};
    const std::string line = specular_dominance_warning(d, peak);
    CHECK(line.find("5 of 9 lit vertices") != std::string::npos);
    CHECK(line.find("saturates") != std::string::npos);
    CHECK(line.find("--specular peak") != std::string::npos);
    CHECK(line.find("--specular exact") != std::string::npos);  // how to change it
    CHECK(line.find('\n') == std::string::npos);               // one line
  }
  SUBCASE("exactly 10x is not above: 4 of 9 and the ratio at the threshold do not dominate") {
    for (int v = 0; v < 4; ++v) light.specular[v] = Vec3f{10.5f, 10.5f, 10.5f};
    light.specular[4] = Vec3f{10, 10, 10};  // 0.5 x 10 = 10 x (0.5 x 1): not above
    const SpecularDominance d = measure_specular_dominance(scene, {light}, kEye, 1e-3);
    CHECK(d.dominated == 4);
    CHECK_FALSE(d.dominates());
    CHECK(specular_dominance_warning(d, SpecularOptions{}).empty());
  }
  SUBCASE("a specular-only vertex (diffuse 0) counts as lit and dominated") {
    light.diffuse[9] = Vec3f{};
    light.specular[9] = Vec3f{1e-6f, 0, 0};
    const SpecularDominance d = measure_specular_dominance(scene, {light}, kEye, 1e-3);
    CHECK(d.lit == 10);
    CHECK(d.dominated == 1);
  }
}

TEST_CASE("specular dominance: the material's kd and ks weigh the terms") {
  // A dielectric of base 0.8: kd = 0.8, ks = 0.04. Specular 100 x diffuse in light is only 5x in
  // the drawn colour: no dominance.
  const Scene scene = scene_of(4, 0.8, 0.0);
  VertexLight light;
  light.diffuse.assign(4, Vec3f{1, 1, 1});
  light.specular.assign(4, Vec3f{100, 100, 100});
  CHECK_FALSE(measure_specular_dominance(scene, {light}, kEye, 1e-3).dominates());
  light.specular.assign(4, Vec3f{250, 250, 250});  // 0.04 x 250 = 10 = 12.5 x 0.8
  CHECK(measure_specular_dominance(scene, {light}, kEye, 1e-3).dominates());
}

TEST_CASE("specular dominance: the line names the method and the way out") {
  SpecularDominance d;
  d.lit = 4;
  d.dominated = 3;
  SpecularOptions exact;  // the default
  CHECK(specular_dominance_warning(d, exact).find("--specular exact: the lobe integrated") != std::string::npos);
  CHECK(specular_dominance_warning(d, exact).find("--specular none") != std::string::npos);
  SpecularOptions paper;
  paper.falloff = SpecularFalloff::kNone;
  CHECK(specular_dominance_warning(d, paper).find("--specular exact-no-falloff") != std::string::npos);
  CHECK(specular_dominance_warning(d, paper).find("--specular exact integrates") != std::string::npos);
}

TEST_CASE("specular dominance: a specular that saturates a vertex dominates it, vertices facing away do not count") {
  const Scene scene = scene_of(4, 0.5, 1.0);  // kd = ks = 0.5
  VertexLight light;
  light.diffuse.assign(4, Vec3f{1, 1, 1});     // diffuse term 0.5
  light.specular.assign(4, Vec3f{1.2f, 0, 0}); // specular term 0.6: 1.2x, not 10x
  CHECK_FALSE(measure_specular_dominance(scene, {light}, kEye, 1e-3).dominates());
  // At exposure 1 the red channel reaches 1.1 while the diffuse alone is 0.5: saturated.
  const SpecularDominance d = measure_specular_dominance(scene, {light}, kEye, 1.0);
  CHECK(d.lit == 4);
  CHECK(d.dominated == 4);
  // A diffuse that saturates alone (exposure 4: 2.0) is not the specular's doing.
  CHECK(measure_specular_dominance(scene, {light}, kEye, 4.0).dominated == 0);
  // Seen from below (the eye behind every vertex): nothing counted.
  const SpecularDominance below = measure_specular_dominance(scene, {light}, Vec3d{0, 0, -5}, 1.0);
  CHECK(below.lit == 0);
  CHECK_FALSE(below.dominates());
}
