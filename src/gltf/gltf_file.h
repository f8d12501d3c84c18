// Opening a glTF 2.0 file (.gltf with external or embedded buffers, or .glb) with tinygltf,
// without decoding images (vlit never needs their pixels; they pass through to the output) and
// without ever touching the network. Extensions that change how geometry is stored and that vlit
// cannot decode are refused up front.
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

// Throws InputError(path, ...) if the file cannot be parsed or needs an unsupported extension.
GltfFile load_gltf_file(const std::string& path);

// Throws InputError(name, ...) if the model requires an extension that stores geometry in a way
// vlit cannot decode (Draco, meshopt); load_gltf_file applies it to every file.
void check_decodable(const tinygltf::Model& model, const std::string& name);

// True if the path names a glTF asset (by extension .gltf / .glb, case-insensitive).
bool is_gltf_path(const std::string& path);

}  // namespace vlit
