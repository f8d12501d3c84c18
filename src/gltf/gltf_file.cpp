#include "gltf/gltf_file.h"

#include <algorithm>
#include <fstream>

#include "core/input_error.h"
#include "io/read_file.h"

namespace vlit {
namespace {

// Images are kept as they are in the file (uri or bufferView); their pixels are never decoded.
bool keep_image_undecoded(tinygltf::Image*, const int, std::string*, std::string*, int, int,
                          const unsigned char*, int, void*) {
  return true;
}

// Extensions that change where or how vertex data is stored. An asset that requires one of
// them cannot be lit correctly without decoding it, so it is refused.
const char* const kUndecodableExtensions[] = {
    "KHR_draco_mesh_compression", "EXT_meshopt_compression", "KHR_meshopt_compression",
};

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return s;
}

}  // namespace

bool is_gltf_path(const std::string& path) {
  const std::string p = lower(path);
  auto ends_with = [&](const std::string& suffix) {
    return p.size() >= suffix.size() && p.compare(p.size() - suffix.size(), suffix.size(), suffix) == 0;
  };
  return ends_with(".gltf") || ends_with(".glb");
}

GltfFile load_gltf_file(const std::string& path) {
  GltfFile file;
  file.path = path;
  const std::string bytes = read_text_file(path);
  const bool binary = bytes.size() >= 4 && bytes.compare(0, 4, "glTF") == 0;

  tinygltf::TinyGLTF loader;
  loader.SetImageLoader(&keep_image_undecoded, nullptr);
  loader.SetStoreOriginalJSONForExtrasAndExtensions(false);
  std::string err, warn;
  const std::string base_dir = [&] {
    const auto slash = path.find_last_of('/');
    return slash == std::string::npos ? std::string(".") : path.substr(0, slash);
  }();
  bool ok = false;
  if (binary) {
    ok = loader.LoadBinaryFromMemory(&file.model, &err, &warn, reinterpret_cast<const unsigned char*>(bytes.data()),
                                     static_cast<unsigned int>(bytes.size()), base_dir);
  } else {
    ok = loader.LoadASCIIFromString(&file.model, &err, &warn, bytes.data(), static_cast<unsigned int>(bytes.size()),
                                    base_dir);
  }
  if (!ok) {
    std::string message = err.empty() ? std::string("cannot parse glTF") : err;
    // tinygltf's messages may span lines; keep the first so the error stays one line.
    message = message.substr(0, message.find('\n'));
    while (!message.empty() && (message.back() == '\r' || message.back() == ' ')) message.pop_back();
    throw InputError(path, "not a valid glTF 2.0 file: " + message);
  }
  if (!warn.empty()) file.warnings.push_back(warn.substr(0, warn.find('\n')));

  for (const std::string& ext : file.model.extensionsRequired)
    for (const char* undecodable : kUndecodableExtensions)
      if (ext == undecodable) throw InputError(path, "requires " + ext + ", which vlit does not decode");
  return file;
}

}  // namespace vlit
