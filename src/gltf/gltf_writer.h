// Writing a (modified) tinygltf model as .glb or .gltf, atomically (io/atomic_write.h).
// - .glb: all buffers are merged into the one binary chunk.
// - .gltf: buffers are embedded as base64 data URIs, so no side file next to the output can
//   collide with (or overwrite) the input's own .bin files.
// Images are never decoded or re-encoded: bufferView images stay in their buffer. A .glb embeds
// the files of relative URI images in its binary chunk (a bufferView with the mimeType found from
// the file's signature: PNG, JPEG, WebP, KTX2), as gltfpack and gltf-transform do, so that the
// output can be moved on its own; with embed_images false, or for a .gltf, URI images keep their
// URI, rewritten to stay valid relative to the output's directory. Data and absolute URIs, files
// of an unknown type and files that cannot be read (the loader tolerates a missing image) keep
// their URI.
#pragma once

#include <string>

#include <tiny_gltf.h>

namespace vlit {

struct GltfWriteOptions {
  bool embed_images = true;  // .glb only: relative URI images become bufferViews (--keep-image-links: false)
  bool meshopt = false;      // vertex and index data encoded with EXT_meshopt_compression (meshopt_view_encoder.h)
};

// `input_path` is the file the model was read from (for relative image URIs).
// Throws InputError(output_path, ...) on failure, leaving no output file.
void write_gltf(tinygltf::Model model, const std::string& input_path, const std::string& output_path,
                const GltfWriteOptions& options = {});

}  // namespace vlit
