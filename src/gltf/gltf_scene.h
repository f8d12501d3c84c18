// From a loaded glTF to the world-space Scene the lighting works on: walks the node hierarchy of
// the default scene, applies transforms, reads every triangle primitive, computes missing normals
// and maps materials and cameras.
#pragma once

#include <string>
#include <vector>

#include "gltf/gltf_file.h"
#include "scene/scene.h"

namespace vlit {

// Throws InputError for a malformed asset (bad accessors, indices out of range, node cycles).
// Primitives that cannot be lit (points, lines, missing POSITION) are skipped with a warning
// appended to `warnings`.
Scene build_scene(const GltfFile& file, std::vector<std::string>& warnings);

// glTF primitive modes TRIANGLES, TRIANGLE_STRIP, TRIANGLE_FAN as a triangle list (3 indices per
// triangle, consistent winding); `indices` are the primitive's vertex indices in draw order.
std::vector<std::uint32_t> triangle_list(int mode, const std::vector<std::uint32_t>& indices);

}  // namespace vlit
