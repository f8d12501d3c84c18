// The step between the bytes of a glTF asset and tinygltf's parser: the required extensions are
// checked (gltf/required_extensions.h) and geometry stored with KHR_draco_mesh_compression,
// EXT_meshopt_compression or KHR_meshopt_compression is decoded into plain buffers, so that the
// parser, the scene and the writer only ever see uncompressed glTF. The result is a valid glTF
// without those extensions (they leave extensionsUsed and extensionsRequired): a bake of a
// compressed asset is written uncompressed.
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <string_view>

namespace vlit {

// Reads the bytes of an external buffer given its URI as written in the asset; throws
// InputError when it cannot.
using ReadBufferUri = std::function<std::string(const std::string& uri)>;

// Throws InputError(name, ...) if the asset requires an extension vlit does not support, or if
// its compressed geometry does not decode. Returns a self-contained GLB (the asset's JSON with
// every bufferView moved into one binary chunk, compressed views decoded, Draco primitives turned
// into plain accessors) when the asset names a compression extension, and nothing otherwise (the
// asset is then parsed exactly as it is). Bytes that are not well-formed JSON or GLB are left to
// the parser and its messages.
std::optional<std::string> decompress_geometry(std::string_view bytes, const std::string& name, const ReadBufferUri& read);

}  // namespace vlit
