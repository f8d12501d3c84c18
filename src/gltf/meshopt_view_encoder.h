// Encoding a model's vertex and index data with EXT_meshopt_compression, the inverse of
// meshopt_view_decoder.h: libmeshoptimizer's lossless vertex codec (mode "ATTRIBUTES") and index
// codecs ("TRIANGLES" for a triangle list read by one accessor, "INDICES" otherwise), no filter.
// Source: the extension's specification (KHR glTF repository,
// extensions/2.0/Vendor/EXT_meshopt_compression) and meshoptimizer.h.
//
// A bufferView is encoded when every accessor that reads it is a mesh attribute (or a morph
// target's) and its elements have one stride, a multiple of 4 up to 256, that divides its length;
// or when every accessor that reads it is a primitive's 16- or 32-bit indices. Other views (images,
// animation data, sparse accessors, 8-bit indices, 6-byte elements, ...) keep their bytes. The
// encoded data goes to buffer 0; each encoded view keeps its place (offset, length) in a
// fallback buffer that holds no bytes: a loader without the extension could not read the file, so
// the extension is also required.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>
#include <tiny_gltf.h>

namespace vlit {

struct MeshoptEncoding {
  struct View {
    int view;
    std::size_t byte_offset, byte_length;  // of the encoded data in buffer 0
    std::size_t byte_stride, count;
    std::string mode;  // "ATTRIBUTES", "TRIANGLES" or "INDICES"
  };
  std::vector<View> views;     // empty: nothing was encoded (the model is unchanged)
  int fallback_buffer = -1;
  std::size_t fallback_bytes = 0;
};

// Encodes the eligible views of a model whose data is all in buffer 0 (the writer merges the
// buffers first). Adds the fallback buffer and names the extension as used and required.
MeshoptEncoding encode_views_with_meshopt(tinygltf::Model& model);

// Puts what tinygltf 2.7 does not serialize (bufferView and buffer extensions) into the written
// JSON: each encoded view's extension object, and the fallback buffer without data.
void add_meshopt_json(nlohmann::json& root, const MeshoptEncoding& encoding);

}  // namespace vlit
