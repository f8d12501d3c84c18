// Writing a (modified) tinygltf model as .glb or .gltf, atomically (io/atomic_write.h).
// - .glb: all buffers are merged into the one binary chunk.
// - .gltf: buffers are embedded as base64 data URIs, so no side file next to the output can
//   collide with (or overwrite) the input's own .bin files.
// Images are never decoded or re-encoded: bufferView images stay in their buffer, URI images
// keep their URI, rewritten to stay valid relative to the output's directory.
#pragma once

#include <string>

#include <tiny_gltf.h>

namespace vlit {

// `input_path` is the file the model was read from (for relative image URIs).
// Throws InputError(output_path, ...) on failure, leaving no output file.
void write_gltf(tinygltf::Model model, const std::string& input_path, const std::string& output_path);

}  // namespace vlit
