// Appending data to a tinygltf model being built: buffer views in buffer 0 (4-byte aligned, so any
// component type may start there) and float VEC3 accessors. Used by the mesh-file bake
// (mesh_to_gltf) and the scene generators in assets/.
#pragma once

#include <cstddef>
#include <vector>

#include <tiny_gltf.h>

#include "core/vec3.h"

namespace vlit {

// Copies `bytes` bytes to the end of buffer 0 (created if missing, padded to a multiple of 4
// first) and returns the index of a new bufferView over them with the given target.
int append_buffer_view(tinygltf::Model& model, const void* data, std::size_t bytes, int target);

// A float VEC3 accessor over `values` (rounded to float) in a new buffer view; with_bounds adds
// min/max of the stored floats (glTF requires them on POSITION). Returns the accessor's index.
int append_vec3_accessor(tinygltf::Model& model, const std::vector<Vec3d>& values, bool with_bounds);

}  // namespace vlit
