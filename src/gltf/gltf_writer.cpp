#include "gltf/gltf_writer.h"

#include <filesystem>
#include <cstring>
#include <map>
#include <sstream>

#include <nlohmann/json.hpp>

#include "core/input_error.h"
#include "gltf/gltf_file.h"
#include "gltf/gltf_uri.h"
#include "gltf/meshopt_view_encoder.h"
#include "io/atomic_write.h"
#include "io/read_file.h"

namespace vlit {
namespace {

namespace fs = std::filesystem;

// Passes an image through: a bufferView image keeps its bufferView (empty URI); a URI image
// keeps the URI given in user_data's map (already made relative to the output).
bool pass_image_through(const std::string*, const std::string*, const tinygltf::Image* image, bool,
                        std::string* out_uri, void*) {
  *out_uri = image->bufferView >= 0 ? std::string() : image->uri;
  return true;
}

std::string percent_encode_path(const std::string& s) {
  std::string out;
  for (unsigned char c : s) {
    if (std::isalnum(c) || c == '/' || c == '.' || c == '-' || c == '_' || c == '~') out += static_cast<char>(c);
    else {
      char buf[4];
      std::snprintf(buf, sizeof buf, "%%%02X", c);
      out += buf;
    }
  }
  return out;
}

bool is_relative_uri(const std::string& uri) {
  return !uri.empty() && uri.rfind("data:", 0) != 0 && uri.find("://") == std::string::npos && uri[0] != '/';
}

// The image's media type from its first bytes; empty when unknown.
std::string image_mime_type(const std::string& bytes) {
  auto starts = [&](std::string_view signature, std::size_t at = 0) {
    return bytes.size() >= at + signature.size() && bytes.compare(at, signature.size(), signature) == 0;
  };
  if (starts("\x89PNG\r\n\x1a\n")) return "image/png";
  if (starts("\xff\xd8\xff")) return "image/jpeg";
  if (starts("RIFF") && starts("WEBP", 8)) return "image/webp";
  if (starts("\xabKTX 20\xbb\r\n\x1a\n")) return "image/ktx2";
  return {};
}

// Copies the files of relative URI images into buffer 0 (the .glb's binary chunk) as new
// bufferViews; an image file named twice is stored once. Call after merge_buffers.
void embed_images(tinygltf::Model& model, const fs::path& in_dir) {
  std::map<std::string, std::pair<int, std::string>> view_of_file;  // file -> bufferView, mimeType
  for (std::size_t i = 0; i < model.images.size(); ++i) {
    tinygltf::Image& image = model.images[i];
    if (image.bufferView >= 0 || !is_relative_uri(image.uri)) continue;
    const std::string file = (in_dir / percent_decode(image.uri)).lexically_normal().string();
    auto it = view_of_file.find(file);
    if (it == view_of_file.end()) {
      std::string bytes;
      try {
        bytes = read_text_file(file);
      } catch (const InputError&) {
        continue;  // missing or unreadable in the input too (the loader tolerates it): left as a link
      }
      const std::string mime = image_mime_type(bytes);
      if (mime.empty()) continue;  // not a glTF image type: left as a link
      if (model.buffers.empty()) model.buffers.emplace_back();
      auto& data = model.buffers[0].data;
      while (data.size() % 4 != 0) data.push_back(0);
      tinygltf::BufferView view;
      view.buffer = 0;
      view.byteOffset = data.size();
      view.byteLength = bytes.size();
      data.insert(data.end(), bytes.begin(), bytes.end());
      model.bufferViews.push_back(view);
      it = view_of_file.emplace(file, std::make_pair(static_cast<int>(model.bufferViews.size()) - 1, mime)).first;
    }
    image.bufferView = it->second.first;
    image.mimeType = it->second.second;
    image.uri.clear();
  }
}

void merge_buffers(tinygltf::Model& model) {
  if (model.buffers.size() <= 1) {
    for (auto& b : model.buffers) b.uri.clear();
    return;
  }
  tinygltf::Buffer merged;
  merged.name = model.buffers[0].name;
  std::vector<std::size_t> base(model.buffers.size());
  for (std::size_t i = 0; i < model.buffers.size(); ++i) {
    while (merged.data.size() % 16 != 0) merged.data.push_back(0);  // keeps every view's alignment
    base[i] = merged.data.size();
    merged.data.insert(merged.data.end(), model.buffers[i].data.begin(), model.buffers[i].data.end());
  }
  for (auto& view : model.bufferViews) {
    if (view.buffer >= 0 && static_cast<std::size_t>(view.buffer) < base.size()) {
      view.byteOffset += base[view.buffer];
      view.buffer = 0;
    }
  }
  model.buffers.assign(1, std::move(merged));
}

// Repairs what tinygltf 2.7 serializes wrongly:
// - an object with no properties (a node, scene, texture, ... that is just {}) comes out as null,
//   which no loader accepts (tinygltf itself: "`nodes' does not contain an JSON object"; found by
//   the malformed corpus, tests/robustness/corpus_test.cpp): top-level arrays get {} back;
// - an empty array is dropped, so a skin read with "joints": [] is written without its required
//   "joints" and cannot be read again (same corpus, skin/empty_joints_array.gltf);
// - it leaves out a perspective camera's "yfov" when it is <= 0, but its reader requires it, so
//   the output could not be read again (found by fuzz/fuzz_gltf.cpp): the model's value is put back;
// - it always writes a perspective camera's "zfar", even 0 for an infinite projection, which the
//   glTF spec forbids (zfar must be > 0 when present).
void repair_serialized_json(nlohmann::json& root, const tinygltf::Model& model) {
  for (auto& [key, value] : root.items())
    if (value.is_array())
      for (auto& element : value)
        if (element.is_null()) element = nlohmann::json::object();
  if (root.contains("skins") && root["skins"].is_array())
    for (auto& skin : root["skins"])
      if (skin.is_object() && !skin.contains("joints")) skin["joints"] = nlohmann::json::array();
  if (!root.contains("cameras") || !root["cameras"].is_array()) return;
  for (std::size_t i = 0; i < root["cameras"].size(); ++i) {
    auto& camera = root["cameras"][i];
    if (!camera.is_object() || !camera.contains("perspective") || !camera["perspective"].is_object()) continue;
    auto& p = camera["perspective"];
    if (!p.contains("yfov") && i < model.cameras.size()) p["yfov"] = model.cameras[i].perspective.yfov;
    if (p.contains("zfar") && p["zfar"].is_number() && !(p["zfar"].get<double>() > 0)) p.erase("zfar");
  }
}

std::uint32_t read_u32(const std::string& s, std::size_t at) {
  std::uint32_t v = 0;
  std::memcpy(&v, s.data() + at, 4);
  return v;
}
void append_u32(std::string& s, std::uint32_t v) { s.append(reinterpret_cast<const char*>(&v), 4); }

// Applies repair_serialized_json to a .gltf text or to the JSON chunk of a .glb, keeping the
// binary chunk as it is.
// Also adds what the meshopt encoding needs in the JSON.
std::string repaired(const std::string& bytes, bool binary, const tinygltf::Model& model,
                     const MeshoptEncoding& meshopt) {
  if (!binary) {
    nlohmann::json root = nlohmann::json::parse(bytes);
    repair_serialized_json(root, model);
    add_meshopt_json(root, meshopt);
    return root.dump(2);
  }
  // GLB: 12-byte header, then chunks of (length, type, data) with 4-byte aligned lengths.
  const std::uint32_t json_length = read_u32(bytes, 12);
  nlohmann::json root = nlohmann::json::parse(bytes.substr(20, json_length));
  repair_serialized_json(root, model);
  add_meshopt_json(root, meshopt);
  std::string json = root.dump();
  while (json.size() % 4 != 0) json.push_back(' ');
  const std::string rest = bytes.substr(20 + json_length);
  std::string out = bytes.substr(0, 12);
  append_u32(out, static_cast<std::uint32_t>(json.size()));
  append_u32(out, 0x4E4F534Au);  // "JSON"
  out += json;
  out += rest;
  const std::uint32_t total = static_cast<std::uint32_t>(out.size());
  std::memcpy(out.data() + 8, &total, 4);
  return out;
}

}  // namespace

void write_gltf(tinygltf::Model model, const std::string& input_path, const std::string& output_path,
                const GltfWriteOptions& options) {
  const bool binary = [&] {
    std::string ext = fs::path(output_path).extension().string();
    for (auto& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    if (ext == ".glb") return true;
    if (ext == ".gltf") return false;
    throw InputError(output_path, "output must end in .glb or .gltf");
  }();

  if (binary || options.meshopt) merge_buffers(model);  // the encoder reads buffer 0
  else
    for (auto& b : model.buffers) b.uri.clear();

  std::error_code ec;
  const fs::path in_dir = fs::absolute(fs::path(input_path)).parent_path();
  if (binary && options.embed_images) embed_images(model, in_dir);
  // Keep the other relative image URIs pointing at the same files from the output's directory.
  const fs::path out_dir = fs::absolute(fs::path(output_path)).parent_path();
  if (fs::weakly_canonical(in_dir, ec) != fs::weakly_canonical(out_dir, ec)) {
    const fs::path prefix = fs::relative(in_dir, out_dir, ec);
    for (auto& image : model.images)
      if (image.bufferView < 0 && is_relative_uri(image.uri) && !ec)
        image.uri = percent_encode_path(prefix.generic_string()) + "/" + image.uri;
  }

  const MeshoptEncoding meshopt = options.meshopt ? encode_views_with_meshopt(model) : MeshoptEncoding{};

  tinygltf::TinyGLTF writer;
  writer.SetImageWriter(&pass_image_through, nullptr);
  std::ostringstream stream;
  if (!writer.WriteGltfSceneToStream(&model, stream, /*prettyPrint=*/!binary, binary))
    throw InputError(output_path, "tinygltf could not serialize the model");
  write_file_atomically(output_path, repaired(stream.str(), binary, model, meshopt));
}

}  // namespace vlit
