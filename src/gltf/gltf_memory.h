// Opening a glTF 2.0 asset (.gltf JSON or .glb) that is already in memory, with the same rules as
// load_gltf_file (gltf/gltf_file.h): images are never decoded, the network is never touched, the
// required extensions are checked and compressed geometry is decoded before parsing. A memory asset has no directory, so
// external files are never opened: only the GLB binary chunk and data: URIs are read; an external
// buffer URI is a load error. Used by the fuzz targets (fuzz/) and by tests.
#pragma once

#include <string>
#include <string_view>

#include "gltf/gltf_file.h"

namespace vlit {

// `name` stands for the path in messages and in GltfFile::path.
// Throws InputError(name, ...) exactly where load_gltf_file would.
GltfFile load_gltf_from_memory(std::string_view bytes, const std::string& name);

}  // namespace vlit
