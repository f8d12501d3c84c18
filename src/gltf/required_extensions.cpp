#include "gltf/required_extensions.h"

#include <string_view>

#include "core/input_error.h"

namespace vlit {
namespace {

// Decoded into plain buffers before parsing (gltf/decompress_geometry.cpp).
constexpr std::string_view kDecoded[] = {
    "KHR_draco_mesh_compression", "EXT_meshopt_compression", "KHR_meshopt_compression",
};

// Read by vlit (docs/gltf-lights.md; KHR_mesh_quantization by gltf/accessor_reader.cpp), or kept
// as they are because vlit's lighting does not depend on them: image formats and texture
// transforms (vlit never samples a texture), and material extensions whose base colour is the
// core baseColorFactor vlit reads (KHR_materials_pbrSpecularGlossiness is not: its colour lives
// in the extension, so an asset requiring it is refused rather than lit with the wrong albedo).
constexpr std::string_view kHonoured[] = {
    "KHR_lights_punctual", "EXT_lights_area", "VLIT_lights_linear", "KHR_mesh_quantization",
    "KHR_materials_emissive_strength", "KHR_materials_unlit", "KHR_materials_clearcoat",
    "KHR_materials_sheen", "KHR_materials_specular", "KHR_materials_ior", "KHR_materials_transmission",
    "KHR_materials_volume", "KHR_materials_iridescence", "KHR_materials_anisotropy",
    "KHR_materials_dispersion", "KHR_materials_variants", "KHR_texture_transform", "KHR_texture_basisu",
    "EXT_texture_webp", "EXT_texture_avif", "KHR_xmp_json_ld",
};

}  // namespace

bool is_compression_extension(const std::string& extension) {
  for (std::string_view e : kDecoded)
    if (extension == e) return true;
  return false;
}

void check_required_extensions(const nlohmann::json& root, const std::string& name) {
  if (!root.is_object()) return;
  const auto required = root.find("extensionsRequired");
  if (required == root.end() || !required->is_array()) return;
  for (const auto& entry : *required) {
    if (!entry.is_string()) continue;
    const std::string extension = entry.get<std::string>();
    bool known = is_compression_extension(extension);
    for (std::string_view e : kHonoured) known = known || extension == e;
    if (!known) throw InputError(name, "requires extension " + extension + ", which vlit does not support");
  }
}

}  // namespace vlit
