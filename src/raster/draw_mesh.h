// What the rasterizer draws: a world-space triangle list with one linear RGB colour per vertex.
// Lighting happened before; the rasterizer only interpolates these colours.
#pragma once

#include <cstdint>
#include <vector>

#include "core/vec3.h"

namespace vlit::raster {

struct DrawMesh {
  std::vector<Vec3f> positions;   // world space
  std::vector<Vec3f> colors;      // linear RGB per vertex; missing entries (shorter list) draw white
  std::vector<uint32_t> indices;  // triangle list; triangles with an index out of range are skipped
  // Counter-clockwise (as seen by the camera, glTF) is the front face. The glTF loader flips the
  // winding of nodes whose world transform has a negative determinant before handing meshes over.
  bool double_sided = true;       // a double-sided mesh is never culled
  // Back faces culled whatever RenderOptions::cull_back_faces says (the back of a one-sided
  // emitter, drawn separately in its own colour).
  bool always_cull_back_faces = false;
};

}  // namespace vlit::raster
