// Emissive geometry as lights (docs/gltf-lights.md "Emissive geometry"), for every loader whose
// scene can hold emissive materials (glTF: gltf/gltf_scene.cpp; OBJ with .mtl: load/load_scene.cpp):
// - each segment of a LINES / LINE_STRIP / LINE_LOOP primitive with an emissive material is a
//   linear light of Ip = emission x world length (emission read as candela per metre, as
//   VLIT_lights_linear's intensity);
// - the emissive triangles of a primitive are area lights of Ip = emission (luminance in nits, as
//   EXT_lights_area), coplanar edge-adjacent triangles merged into one polygon
//   (mesh/planar_polygons.h); one-sided along the front face unless the material is double-sided.
// Emission = emissiveFactor x emissiveStrength; a material with an emissiveTexture is not a light
// (vlit does not sample textures). The lights of a primitive do not light that primitive itself.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "mesh/planar_polygons.h"
#include "scene/light_source.h"
#include "scene/material.h"
#include "scene/scene.h"

namespace vlit {

bool emits_light(const Material& material);

// One linear light per segment of non-zero length (world-space positions).
std::vector<LightSource> emissive_line_lights(const std::vector<Vec3d>& positions, const std::vector<std::uint32_t>& segments,
                                              const Material& material, const std::string& name);

// Area lights for the triangles of `primitive` (world space), which is Scene::primitives[index].
std::vector<LightSource> emissive_triangle_lights(const ScenePrimitive& primitive, std::size_t index, const Material& material,
                                                  const std::string& name, PlanarMergeStats* stats = nullptr);

// Luminous flux of a light, for ranking emissive lights when there are too many: pi L A for a
// one-sided area light (twice for two-sided), 4 pi Ip for a linear light (isotropic elements).
double luminous_flux(const LightSource& light);

// The lights of a file's emissive geometry, the brightest `limit` at any time, so an asset with a
// million emissive triangles never holds a million lights: a heap whose front is the weakest kept
// light (by luminous flux; on equal flux the later one in the file is weaker). Used by every
// loader whose scene can hold emissive materials (glTF, OBJ with .mtl).
class EmissiveLightSet {
 public:
  explicit EmissiveLightSet(std::size_t limit) : limit_(limit) {}

  void add(LightSource light);
  // emissive_triangle_lights of one primitive (Scene::primitives[index]), merge statistics summed.
  void add_triangles(const ScenePrimitive& primitive, std::size_t index, const Material& material, const std::string& name);
  std::size_t seen() const { return seen_; }
  // Appends the kept lights to `lights` (file order when nothing was dropped, brightest first
  // otherwise), with a warning naming `file` when lights were dropped or regions not merged.
  void finish(const std::string& file, std::vector<LightSource>& lights, std::vector<std::string>& warnings);

 private:
  struct Ranked {
    double flux;
    std::size_t order;
    LightSource light;
  };
  static bool stronger(const Ranked& a, const Ranked& b) {
    return a.flux > b.flux || (a.flux == b.flux && a.order < b.order);
  }
  std::size_t limit_, seen_ = 0;
  std::vector<Ranked> kept_;
  PlanarMergeStats merge_;  // summed over primitives, for the message about merging
};

// The emissive triangles of every primitive of `scene` (a mesh file's, already in world space)
// as area lights, ranked and limited by EmissiveLightSet, appended to scene.lights.
void add_emissive_triangle_lights(Scene& scene, const std::string& file, std::size_t limit,
                                  std::vector<std::string>& warnings);

}  // namespace vlit
