#include "gltf/gltf_writer.h"

#include <filesystem>
#include <sstream>

#include "core/input_error.h"
#include "gltf/gltf_file.h"
#include "io/atomic_write.h"

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

}  // namespace

void write_gltf(tinygltf::Model model, const std::string& input_path, const std::string& output_path) {
  const bool binary = [&] {
    std::string ext = fs::path(output_path).extension().string();
    for (auto& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    if (ext == ".glb") return true;
    if (ext == ".gltf") return false;
    throw InputError(output_path, "output must end in .glb or .gltf");
  }();

  if (binary) merge_buffers(model);
  else
    for (auto& b : model.buffers) b.uri.clear();

  // Keep relative image URIs pointing at the same files from the output's directory.
  std::error_code ec;
  const fs::path in_dir = fs::absolute(fs::path(input_path)).parent_path();
  const fs::path out_dir = fs::absolute(fs::path(output_path)).parent_path();
  if (fs::weakly_canonical(in_dir, ec) != fs::weakly_canonical(out_dir, ec)) {
    const fs::path prefix = fs::relative(in_dir, out_dir, ec);
    for (auto& image : model.images)
      if (image.bufferView < 0 && is_relative_uri(image.uri) && !ec)
        image.uri = percent_encode_path(prefix.generic_string()) + "/" + image.uri;
  }

  tinygltf::TinyGLTF writer;
  writer.SetImageWriter(&pass_image_through, nullptr);
  std::ostringstream stream;
  if (!writer.WriteGltfSceneToStream(&model, stream, /*prettyPrint=*/!binary, binary))
    throw InputError(output_path, "tinygltf could not serialize the model");
  write_file_atomically(output_path, stream.str());
}

}  // namespace vlit
