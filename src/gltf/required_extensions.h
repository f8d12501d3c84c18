// Which glTF extensions an asset may require of vlit. A loader must refuse an asset whose
// `extensionsRequired` names an extension it does not implement (glTF 2.0, section 3.12), and it
// must do so before it trusts the rest of the file: a Draco asset's accessors have no bufferView,
// so a parser that does not know the extension fails on them with a misleading message. The
// check therefore runs on the raw JSON, before tinygltf sees the file.
#pragma once

#include <string>

#include <nlohmann/json.hpp>

namespace vlit {

// Throws InputError(name, "requires extension X, which vlit does not support") for the first
// entry of root["extensionsRequired"] that vlit neither decodes (gltf/decompress_geometry.h),
// reads (lights, KHR_mesh_quantization, ...) nor can pass through unchanged because it does not
// affect what vlit reads (texture formats and transforms, material extensions other than the
// specular-glossiness workflow). A malformed extensionsRequired is left to the parser.
void check_required_extensions(const nlohmann::json& root, const std::string& name);

// True for the geometry compression extensions that vlit decodes before parsing.
bool is_compression_extension(const std::string& extension);

}  // namespace vlit
