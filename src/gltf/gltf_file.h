// Opening a glTF 2.0 file (.gltf with external or embedded buffers, or .glb) with tinygltf,
// without decoding images (vlit never needs their pixels; they pass through to the output) and
// without ever touching the network. Before tinygltf parses, the required extensions are checked
// and Draco or meshopt compressed geometry is decoded (gltf/decompress_geometry.h).
#pragma once

#include <string>
#include <vector>

#include <tiny_gltf.h>

namespace vlit {

struct GltfFile {
  std::string path;
  tinygltf::Model model;
  std::vector<std::string> warnings;
};

// Throws InputError(path, ...) if the file cannot be parsed, requires an unsupported extension or
// holds compressed geometry that does not decode.
GltfFile load_gltf_file(const std::string& path);

// Throws InputError(name, ...) if a model parsed elsewhere (a library caller's tinygltf) still
// requires a compression extension: vlit decodes those only while reading a file.
void check_decodable(const tinygltf::Model& model, const std::string& name);

// True if the path names a glTF asset (by extension .gltf / .glb, case-insensitive).
bool is_gltf_path(const std::string& path);

}  // namespace vlit
