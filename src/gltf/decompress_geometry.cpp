#include "gltf/decompress_geometry.h"

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <map>
#include <vector>

#include <nlohmann/json.hpp>
#include <tiny_gltf.h>

#include "core/input_error.h"
#include "gltf/draco_primitive_decoder.h"
#include "gltf/meshopt_view_decoder.h"
#include "gltf/required_extensions.h"

namespace vlit {
namespace {

using json = nlohmann::json;

constexpr std::uint32_t kGlbMagic = 0x46546C67u;  // "glTF"
constexpr std::uint32_t kChunkJson = 0x4E4F534Au;
constexpr std::uint32_t kChunkBin = 0x004E4942u;

std::uint32_t read_u32(std::string_view s, std::size_t at) {
  std::uint32_t v = 0;
  std::memcpy(&v, s.data() + at, 4);
  return v;
}
void append_u32(std::string& s, std::uint32_t v) { s.append(reinterpret_cast<const char*>(&v), 4); }

// A GLB's JSON chunk and optional binary chunk (glTF 2.0, "Binary glTF Layout"); nothing when the
// container is malformed (the parser then says how).
struct GlbParts {
  std::string_view json, bin;
  bool has_bin = false;
};
std::optional<GlbParts> split_glb(std::string_view bytes) {
  if (bytes.size() < 20 || read_u32(bytes, 0) != kGlbMagic) return std::nullopt;
  const std::uint64_t json_length = read_u32(bytes, 12);
  if (read_u32(bytes, 16) != kChunkJson || 20 + json_length > bytes.size()) return std::nullopt;
  GlbParts parts;
  parts.json = bytes.substr(20, json_length);
  const std::uint64_t bin_at = 20 + ((json_length + 3) & ~std::uint64_t(3));
  if (bin_at + 8 <= bytes.size() && read_u32(bytes, bin_at + 4) == kChunkBin) {
    const std::uint64_t bin_length = read_u32(bytes, bin_at);
    if (bin_at + 8 + bin_length > bytes.size()) return std::nullopt;
    parts.bin = bytes.substr(bin_at + 8, bin_length);
    parts.has_bin = true;
  }
  return parts;
}

std::string make_glb(const std::string& json_text, const std::string& bin) {
  std::string json_chunk = json_text;
  while (json_chunk.size() % 4 != 0) json_chunk.push_back(' ');
  std::string bin_chunk = bin;
  while (bin_chunk.size() % 4 != 0) bin_chunk.push_back('\0');
  std::string out;
  append_u32(out, kGlbMagic);
  append_u32(out, 2);
  append_u32(out, static_cast<std::uint32_t>(12 + 8 + json_chunk.size() + 8 + bin_chunk.size()));
  append_u32(out, static_cast<std::uint32_t>(json_chunk.size()));
  append_u32(out, kChunkJson);
  out += json_chunk;
  append_u32(out, static_cast<std::uint32_t>(bin_chunk.size()));
  append_u32(out, kChunkBin);
  out += bin_chunk;
  return out;
}

// RFC 4648 base64 as used by data: URIs; throws on a character outside the alphabet.
std::string base64_decode(std::string_view text, const std::string& name, const std::string& where) {
  auto value = [&](char c) -> int {
    if (c >= 'A' && c <= 'Z') return c - 'A';
    if (c >= 'a' && c <= 'z') return c - 'a' + 26;
    if (c >= '0' && c <= '9') return c - '0' + 52;
    if (c == '+' || c == '-') return 62;
    if (c == '/' || c == '_') return 63;
    throw InputError(name, "invalid base64 in data URI", where);
  };
  std::string out;
  out.reserve(text.size() / 4 * 3);
  std::uint32_t acc = 0;
  int bits = 0;
  for (char c : text) {
    if (c == '=') break;
    acc = (acc << 6) | static_cast<std::uint32_t>(value(c));
    bits += 6;
    if (bits >= 8) {
      bits -= 8;
      out.push_back(static_cast<char>((acc >> bits) & 0xFF));
    }
  }
  return out;
}

const json* extension_of(const json& object, const char* extension) {
  if (!object.is_object()) return nullptr;
  const auto extensions = object.find("extensions");
  if (extensions == object.end() || !extensions->is_object()) return nullptr;
  const auto it = extensions->find(extension);
  return it != extensions->end() && it->is_object() ? &*it : nullptr;
}
void erase_extension(json& object, const char* extension) {
  json& extensions = object["extensions"];
  extensions.erase(extension);
  if (extensions.empty()) object.erase("extensions");
}

std::uint64_t uint_field(const json& object, const char* key, std::uint64_t fallback, const std::string& name,
                         const std::string& where) {
  const auto it = object.find(key);
  if (it == object.end()) return fallback;
  if (!it->is_number_unsigned() && !(it->is_number_integer() && it->get<std::int64_t>() >= 0))
    throw InputError(name, std::string("\"") + key + "\" must be a non-negative integer", where);
  return it->get<std::uint64_t>();
}
std::string string_field(const json& object, const char* key, const std::string& fallback) {
  const auto it = object.find(key);
  return it != object.end() && it->is_string() ? it->get<std::string>() : fallback;
}
json& array_field(json& root, const char* key) {
  if (!root.contains(key) || !root[key].is_array()) root[key] = json::array();
  return root[key];
}

// Replaces the accessor's min and max by those of its decoded values (glTF requires them to be
// exact; Draco's quantization moves the extremes slightly, so the encoder's bounds no longer
// hold). Sets them when `required` (POSITION) even if the file had none.
void refresh_bounds(json& acc, const std::string& bytes, int component_type, int components, std::size_t stride,
                    std::size_t count, bool required) {
  if (!required && !acc.contains("min") && !acc.contains("max")) return;
  if (count == 0) {
    acc.erase("min");
    acc.erase("max");
    return;
  }
  std::vector<double> lo(static_cast<std::size_t>(components), 0), hi(static_cast<std::size_t>(components), 0);
  for (std::size_t i = 0; i < count; ++i)
    for (int c = 0; c < components; ++c) {
      const char* p = bytes.data() + i * stride;
      double v = 0;
      switch (component_type) {
        case TINYGLTF_COMPONENT_TYPE_FLOAT: { float f; std::memcpy(&f, p + 4 * c, 4); v = f; break; }
        case TINYGLTF_COMPONENT_TYPE_BYTE: v = static_cast<std::int8_t>(p[c]); break;
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: v = static_cast<std::uint8_t>(p[c]); break;
        case TINYGLTF_COMPONENT_TYPE_SHORT: { std::int16_t x; std::memcpy(&x, p + 2 * c, 2); v = x; break; }
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: { std::uint16_t x; std::memcpy(&x, p + 2 * c, 2); v = x; break; }
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: { std::uint32_t x; std::memcpy(&x, p + 4 * c, 4); v = x; break; }
        default: return;
      }
      const std::size_t k = static_cast<std::size_t>(c);
      if (i == 0 || v < lo[k]) lo[k] = v;
      if (i == 0 || v > hi[k]) hi[k] = v;
    }
  acc["min"] = lo;
  acc["max"] = hi;
}

const char* const kMeshoptExtensions[] = {"EXT_meshopt_compression", "KHR_meshopt_compression"};
const char* const kDraco = "KHR_draco_mesh_compression";

bool names_compression(const json& root) {
  for (const char* list : {"extensionsUsed", "extensionsRequired"})
    if (root.contains(list) && root[list].is_array())
      for (const auto& e : root[list])
        if (e.is_string() && is_compression_extension(e.get<std::string>())) return true;
  return false;
}

bool is_meshopt_fallback(const json& buffer) {
  for (const char* ext : kMeshoptExtensions)
    if (const json* e = extension_of(buffer, ext); e && e->value("fallback", false)) return true;
  return false;
}

class Decompressor {
 public:
  Decompressor(json& root, const GlbParts* glb, const std::string& name, const ReadBufferUri& read)
      : root_(root), glb_(glb), name_(name), read_(read) {}

  std::string run() {
    load_buffers();
    json& views = array_field(root_, "bufferViews");
    for (std::size_t i = 0; i < views.size(); ++i) view_bytes_.push_back(view_data(views[i], i));
    decode_draco_primitives();
    return merge_views();
  }

 private:
  std::string where_view(std::size_t i) const { return "bufferViews[" + std::to_string(i) + "]"; }

  // Every buffer's bytes; a meshopt fallback buffer has none (it only reserves the size of the
  // decoded data for loaders that do not decode).
  void load_buffers() {
    json& buffers = array_field(root_, "buffers");
    for (std::size_t i = 0; i < buffers.size(); ++i) {
      const std::string where = "buffers[" + std::to_string(i) + "]";
      const json& buffer = buffers[i];
      fallback_.push_back(is_meshopt_fallback(buffer));
      std::string uri = buffer.is_object() ? string_field(buffer, "uri", "") : "";
      if (!uri.empty()) {
        if (uri.rfind("data:", 0) == 0) {
          const auto comma = uri.find(',');
          if (comma == std::string::npos || uri.rfind(";base64", comma) == std::string::npos)
            throw InputError(name_, "a data URI buffer must be base64", where);
          buffers_.push_back(base64_decode(std::string_view(uri).substr(comma + 1), name_, where));
        } else {
          buffers_.push_back(read_(uri));
        }
      } else if (i == 0 && glb_ && glb_->has_bin) {
        buffers_.emplace_back(glb_->bin);
      } else if (fallback_.back()) {
        buffers_.emplace_back();
      } else {
        throw InputError(name_, "buffer has no uri and is not the GLB binary chunk", where);
      }
      const std::uint64_t length = buffer.is_object() ? uint_field(buffer, "byteLength", 0, name_, where) : 0;
      if (!fallback_.back() && buffers_.back().size() < length)
        throw InputError(name_, "holds " + std::to_string(buffers_.back().size()) + " bytes, byteLength says " + std::to_string(length), where);
    }
  }

  std::string_view slice(std::uint64_t buffer, std::uint64_t offset, std::uint64_t length, const std::string& where) const {
    if (buffer >= buffers_.size()) throw InputError(name_, "buffer " + std::to_string(buffer) + " does not exist", where);
    if (fallback_[buffer])
      throw InputError(name_, "reads the meshopt fallback buffer " + std::to_string(buffer) + ", which holds no data", where);
    const std::string& b = buffers_[buffer];
    if (offset > b.size() || length > b.size() - offset)
      throw InputError(name_, "bytes " + std::to_string(offset) + ".." + std::to_string(offset + length) +
                                  " are outside buffer " + std::to_string(buffer) + " (" + std::to_string(b.size()) + " bytes)", where);
    return std::string_view(b).substr(offset, length);
  }

  // The bytes a view stands for: decoded when it is meshopt-compressed, its slice otherwise.
  std::string view_data(json& view, std::size_t i) {
    const std::string where = where_view(i);
    if (!view.is_object()) throw InputError(name_, "must be an object", where);
    const std::uint64_t length = uint_field(view, "byteLength", 0, name_, where);
    for (const char* ext : kMeshoptExtensions) {
      const json* e = extension_of(view, ext);
      if (!e) continue;
      const std::string ext_where = where + ".extensions." + ext;
      MeshoptStream stream;
      stream.count = uint_field(*e, "count", 0, name_, ext_where);
      stream.byte_stride = uint_field(*e, "byteStride", 0, name_, ext_where);
      stream.mode = string_field(*e, "mode", "");
      stream.filter = string_field(*e, "filter", "NONE");
      const std::string_view compressed = slice(uint_field(*e, "buffer", ~std::uint64_t(0), name_, ext_where),
                                                uint_field(*e, "byteOffset", 0, name_, ext_where),
                                                uint_field(*e, "byteLength", 0, name_, ext_where), ext_where);
      std::string decoded = decode_meshopt_stream(compressed, stream, name_, ext_where);
      if (decoded.size() > length)
        throw InputError(name_, "decodes to " + std::to_string(decoded.size()) + " bytes, more than its byteLength " + std::to_string(length), ext_where);
      decoded.resize(length, '\0');
      erase_extension(view, ext);
      return decoded;
    }
    return std::string(slice(uint_field(view, "buffer", ~std::uint64_t(0), name_, where),
                             uint_field(view, "byteOffset", 0, name_, where), length, where));
  }

  // Adds a view holding `bytes` and returns its index.
  std::size_t add_view(std::string bytes, int target, std::size_t byte_stride) {
    json view = json::object();
    view["buffer"] = 0;
    view["byteLength"] = bytes.size();
    view["target"] = target;
    if (byte_stride) view["byteStride"] = byte_stride;
    root_["bufferViews"].push_back(view);
    view_bytes_.push_back(std::move(bytes));
    return view_bytes_.size() - 1;
  }

  json& accessor(std::uint64_t index, const std::string& where) {
    json& accessors = array_field(root_, "accessors");
    if (index >= accessors.size() || !accessors[index].is_object())
      throw InputError(name_, "accessor " + std::to_string(index) + " does not exist", where);
    return accessors[index];
  }

  void decode_draco_primitives() {
    if (!root_.contains("meshes") || !root_["meshes"].is_array()) return;
    std::map<std::uint64_t, DracoPrimitive> decoded_views;  // a Draco bufferView shared by primitives is decoded once
    std::vector<bool> filled(array_field(root_, "accessors").size(), false);
    json& meshes = root_["meshes"];
    for (std::size_t m = 0; m < meshes.size(); ++m) {
      if (!meshes[m].is_object() || !meshes[m].contains("primitives") || !meshes[m]["primitives"].is_array()) continue;
      json& primitives = meshes[m]["primitives"];
      for (std::size_t p = 0; p < primitives.size(); ++p) {
        json& prim = primitives[p];
        const json* e = extension_of(prim, kDraco);
        if (!e) continue;
        const std::string where = "meshes[" + std::to_string(m) + "].primitives[" + std::to_string(p) + "]";
        const std::string ext_where = where + ".extensions." + kDraco;
        if (prim.value("mode", 4) != 4) throw InputError(name_, "Draco compresses triangles only (mode 4)", where);
        const std::uint64_t view = uint_field(*e, "bufferView", ~std::uint64_t(0), name_, ext_where);
        if (view >= view_bytes_.size()) throw InputError(name_, "bufferView " + std::to_string(view) + " does not exist", ext_where);
        auto it = decoded_views.find(view);
        if (it == decoded_views.end()) it = decoded_views.emplace(view, DracoPrimitive(view_bytes_[view], name_, ext_where)).first;
        const DracoPrimitive& draco = it->second;

        // Indices: the primitive's accessor, or a new one when it has none.
        if (!prim.contains("indices")) {
          json index_accessor = {{"componentType", TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT}, {"count", draco.index_count()}, {"type", "SCALAR"}};
          root_["accessors"].push_back(index_accessor);
          filled.push_back(false);
          prim["indices"] = root_["accessors"].size() - 1;
        }
        const std::uint64_t index_accessor = uint_field(prim, "indices", 0, name_, where);
        json& indices = accessor(index_accessor, where + ".indices");
        if (!filled[index_accessor]) {
          if (uint_field(indices, "count", 0, name_, where + ".indices") != draco.index_count())
            throw InputError(name_, "index accessor count " + std::to_string(indices.value("count", 0)) + " differs from the " +
                                        std::to_string(draco.index_count()) + " indices Draco decoded", where);
          const int type = indices.value("componentType", 0);
          std::string values = draco.indices(type);
          const std::size_t size = static_cast<std::size_t>(std::max(0, tinygltf::GetComponentSizeInBytes(static_cast<std::uint32_t>(type))));
          refresh_bounds(indices, values, type, 1, size, draco.index_count(), false);
          indices["bufferView"] = add_view(std::move(values), TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER, 0);
          indices.erase("byteOffset");
          filled[index_accessor] = true;
        }

        if (!e->contains("attributes") || !(*e)["attributes"].is_object())
          throw InputError(name_, "has no \"attributes\" object", ext_where);
        if (!prim.contains("attributes") || !prim["attributes"].is_object()) throw InputError(name_, "has no attributes", where);
        for (const auto& [semantic, id] : (*e)["attributes"].items()) {
          if (!prim["attributes"].contains(semantic))
            throw InputError(name_, "names " + semantic + ", which the primitive's attributes do not", ext_where);
          const std::string attr_where = where + ".attributes." + semantic;
          const std::uint64_t a = uint_field(prim["attributes"], semantic.c_str(), 0, name_, where + ".attributes");
          json& acc = accessor(a, attr_where);
          if (filled[a]) continue;
          if (uint_field(acc, "count", 0, name_, attr_where) != draco.point_count())
            throw InputError(name_, "accessor count " + std::to_string(acc.value("count", 0)) + " differs from the " +
                                        std::to_string(draco.point_count()) + " points Draco decoded", attr_where);
          const int components = tinygltf::GetNumComponentsInType(static_cast<std::uint32_t>(
              [&] {
                const std::string t = string_field(acc, "type", "");
                if (t == "SCALAR") return TINYGLTF_TYPE_SCALAR;
                if (t == "VEC2") return TINYGLTF_TYPE_VEC2;
                if (t == "VEC3") return TINYGLTF_TYPE_VEC3;
                if (t == "VEC4") return TINYGLTF_TYPE_VEC4;
                throw InputError(name_, "Draco attributes must be SCALAR or VECn, not \"" + t + "\"", attr_where);
              }()));
          const int component_type = acc.value("componentType", 0);
          const std::size_t size = static_cast<std::size_t>(std::max(0, tinygltf::GetComponentSizeInBytes(static_cast<std::uint32_t>(component_type))));
          if (!id.is_number_integer()) throw InputError(name_, "the id of " + semantic + " must be an integer", ext_where);
          // glTF aligns every vertex attribute element to 4 bytes; a padded stride is written out.
          const std::size_t element = size * static_cast<std::size_t>(components);
          const std::size_t stride = (element + 3) / 4 * 4;
          std::string values = draco.attribute(id.get<int>(), component_type, components, stride);
          refresh_bounds(acc, values, component_type, components, stride, draco.point_count(), semantic == "POSITION");
          acc["bufferView"] = add_view(std::move(values), TINYGLTF_TARGET_ARRAY_BUFFER, stride != element ? stride : 0);
          acc.erase("byteOffset");
          filled[a] = true;
        }
        erase_extension(prim, kDraco);
      }
    }
  }

  // One buffer holding every view, each 16-byte aligned (so every accessor keeps its alignment);
  // views are renumbered nowhere, only their buffer and offsets change.
  std::string merge_views() {
    std::string bin;
    json& views = root_["bufferViews"];
    for (std::size_t i = 0; i < views.size(); ++i) {
      while (bin.size() % 16 != 0) bin.push_back('\0');
      views[i]["buffer"] = 0;
      views[i]["byteOffset"] = bin.size();
      views[i]["byteLength"] = view_bytes_[i].size();
      bin += view_bytes_[i];
    }
    if (bin.size() > 0xFFFFFFF0u) throw InputError(name_, "decoded geometry exceeds the 4 GiB of a GLB");
    json buffer = json::object();
    buffer["byteLength"] = std::max<std::size_t>(bin.size(), 1);
    if (bin.empty()) bin.push_back('\0');
    root_["buffers"] = json::array({buffer});
    return bin;
  }

  json& root_;
  const GlbParts* glb_;
  const std::string& name_;
  const ReadBufferUri& read_;
  std::vector<std::string> buffers_;
  std::vector<bool> fallback_;
  std::vector<std::string> view_bytes_;
};

void drop_compression_extensions(json& root) {
  for (const char* list : {"extensionsUsed", "extensionsRequired"}) {
    if (!root.contains(list) || !root[list].is_array()) continue;
    json kept = json::array();
    for (const auto& e : root[list])
      if (!e.is_string() || !is_compression_extension(e.get<std::string>())) kept.push_back(e);
    if (kept.empty()) root.erase(list);
    else root[list] = kept;
  }
}

}  // namespace

std::optional<std::string> decompress_geometry(std::string_view bytes, const std::string& name, const ReadBufferUri& read) {
  const std::optional<GlbParts> glb = split_glb(bytes);
  const bool binary = bytes.size() >= 4 && bytes.substr(0, 4) == "glTF";
  if (binary && !glb) return std::nullopt;
  const std::string_view text = binary ? glb->json : bytes;
  // Most assets neither require an extension nor compress: a search for the two keys spares them
  // a second JSON parse (their bytes go to the parser untouched).
  if (text.find("extensionsRequired") == std::string_view::npos && text.find("_compression") == std::string_view::npos)
    return std::nullopt;
  json root = json::parse(text.begin(), text.end(), nullptr, /*allow_exceptions=*/false);
  if (root.is_discarded() || !root.is_object()) return std::nullopt;
  check_required_extensions(root, name);
  if (!names_compression(root)) return std::nullopt;
  const std::string bin = Decompressor(root, glb ? &*glb : nullptr, name, read).run();
  drop_compression_extensions(root);
  return make_glb(root.dump(), bin);
}

}  // namespace vlit
