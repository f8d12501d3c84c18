// The scene as the lighting and the rasterizer see it: world-space triangle meshes (one per glTF
// primitive instance), their materials, the lights and the cameras. Built by the loaders
// in src/gltf/ and src/io/, read by src/bake/ and src/raster/.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "core/vec3.h"
#include "scene/light_source.h"
#include "scene/material.h"

namespace vlit {

// One drawn instance of a glTF mesh primitive, in world space. Vertices are the glTF's own
// (never welded or reordered), so a colour per vertex maps back onto the primitive's accessors.
struct ScenePrimitive {
  int node = -1;                      // glTF node that instances it (-1 for non-glTF meshes)
  int mesh = -1;                      // glTF mesh index
  int primitive = -1;                 // index within the mesh
  std::vector<Vec3d> positions;       // world space
  std::vector<Vec3d> normals;         // world space, unit length
  std::vector<std::uint32_t> triangles;  // 3 indices per triangle, counter-clockwise front faces
  int material = -1;                  // index into Scene::materials, -1 = default material
  // glTF COLOR_0 as linear RGB (alpha dropped), one per vertex; read only when asked for
  // (SceneOptions::vertex_colors), else empty, as for a primitive without COLOR_0.
  std::vector<Vec3f> colors;
};

// A camera mirroring glTF 2.0's: looks down its local -Z with +Y up.
struct SceneCamera {
  int index = -1;    // glTF cameras[index]
  std::string name;  // the camera's name, else its node's name, else empty
  Vec3d position;
  Vec3d right{1, 0, 0}, up{0, 1, 0}, back{0, 0, 1};  // world-space camera axes (unit, orthogonal)
  bool orthographic = false;
  double yfov = 0.8;
  std::optional<double> aspect;  // the file's aspectRatio (the image's aspect wins when rendering)
  double xmag = 1, ymag = 1;
  double znear = 0.01;
  std::optional<double> zfar;
};

struct Scene {
  std::vector<ScenePrimitive> primitives;
  std::vector<Material> materials;
  std::vector<LightSource> lights;
  // The first node instance of each usable camera, in the order the default scene's nodes are
  // visited (depth first, file order): cameras.front() is "the file's first camera".
  std::vector<SceneCamera> cameras;

  const Material& material_of(const ScenePrimitive& p) const {
    static const Material kDefault{};
    return p.material >= 0 && static_cast<std::size_t>(p.material) < materials.size() ? materials[p.material] : kDefault;
  }
  std::size_t vertex_count() const {
    std::size_t n = 0;
    for (const auto& p : primitives) n += p.positions.size();
    return n;
  }
};

}  // namespace vlit
