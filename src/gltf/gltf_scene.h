// From a loaded glTF to the world-space Scene the lighting works on: walks the node hierarchy of
// the default scene, applies transforms, reads every triangle primitive, computes missing normals
// and maps materials and cameras.
#pragma once

#include <string>
#include <vector>

#include "gltf/gltf_file.h"
#include "scene/scene.h"

namespace vlit {

// Limits that protect the machine from an asset that would need more memory than any real one:
// checked against accessor counts before anything is allocated. Every node instance of a mesh
// counts (the bake lights each instance separately).
struct SceneLimits {
  std::size_t max_vertices = 50'000'000;  // all primitives of all node instances
  // Lights made from emissive geometry (one per merged polygon, triangle or line segment): beyond
  // this, the brightest are kept with a warning, so an asset with thousands of emissive
  // triangles does not make a bake thousands of times slower.
  std::size_t max_emissive_lights = 64;
  // Triangle corners (3 per triangle) may be at most kCornersPerVertex x max_vertices.
  static constexpr std::size_t kCornersPerVertex = 6;
};

// SceneLimits{}: the defaults of --max-vertices and --max-emissive-lights. Nothing changes them:
// a caller with other limits passes them (SceneOptions, load_mesh_file).
SceneLimits default_scene_limits();

// How build_scene (and load_scene, load/load_scene.h) reads an asset.
struct SceneOptions {
  SceneLimits limits;
  // false ignores every light of the file (KHR_lights_punctual, EXT_lights_area,
  // VLIT_lights_linear, emissive geometry) without reading it; emissive lines are then skipped.
  bool file_lights = true;
  // true reads each primitive's COLOR_0 into ScenePrimitive::colors (render's preview of a baked
  // asset); the bake does not need it.
  bool vertex_colors = false;
};

// Throws InputError for a malformed asset (bad accessors, indices out of range, node cycles,
// malformed light extensions) or one beyond `limits`. Primitives that cannot be lit (points,
// non-emissive lines, missing POSITION) are skipped with a warning appended to `warnings`.
// Lights of the file: KHR_lights_punctual, EXT_lights_area (gltf_area_lights.h),
// VLIT_lights_linear (gltf_linear_lights.h) and emissive geometry (scene/emissive_lights.h), unless
// options.file_lights is false.
Scene build_scene(const GltfFile& file, std::vector<std::string>& warnings, const SceneOptions& options = {});

// glTF primitive modes TRIANGLES, TRIANGLE_STRIP, TRIANGLE_FAN as a triangle list (3 indices per
// triangle, consistent winding); `indices` are the primitive's vertex indices in draw order.
std::vector<std::uint32_t> triangle_list(int mode, const std::vector<std::uint32_t>& indices);

// glTF line modes LINES, LINE_STRIP, LINE_LOOP as a list of segments (2 indices each): LINES
// pairs, LINE_STRIP consecutive indices, LINE_LOOP consecutive plus the closing segment.
std::vector<std::uint32_t> line_segments(int mode, const std::vector<std::uint32_t>& indices);

}  // namespace vlit
