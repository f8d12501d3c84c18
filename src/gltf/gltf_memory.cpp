#include "gltf/gltf_memory.h"

#include <limits>
#include <optional>

#include "core/input_error.h"
#include "gltf/decompress_geometry.h"

namespace vlit {
namespace {

bool keep_image_undecoded(tinygltf::Image*, const int, std::string*, std::string*, int, int,
                          const unsigned char*, int, void*) {
  return true;
}

// No file system at all: every external URI is "missing".
bool no_file_exists(const std::string&, void*) { return false; }
std::string literal_path(const std::string& path, void*) { return path; }
bool refuse_read(std::vector<unsigned char>*, std::string* err, const std::string& path, void*) {
  if (err) *err += "an asset in memory cannot read external files: " + path + "\n";
  return false;
}
bool refuse_write(std::string* err, const std::string& path, const std::vector<unsigned char>&, void*) {
  if (err) *err += "vlit does not write through the glTF loader: " + path + "\n";
  return false;
}

std::string first_line(const std::string& s) {
  std::string line = s.substr(0, s.find('\n'));
  while (!line.empty() && (line.back() == '\r' || line.back() == ' ')) line.pop_back();
  return line;
}

}  // namespace

GltfFile load_gltf_from_memory(std::string_view bytes, const std::string& name) {
  GltfFile file;
  file.path = name;
  if (bytes.size() > std::numeric_limits<unsigned int>::max())
    throw InputError(name, "asset is larger than 4 GiB");
  // Required extensions are checked and compressed geometry decoded before tinygltf parses.
  const std::optional<std::string> decoded = decompress_geometry(bytes, name, [&](const std::string& uri) -> std::string {
    throw InputError(name, "an asset in memory cannot read external files: " + uri);
  });
  if (decoded) bytes = *decoded;
  const bool binary = bytes.size() >= 4 && bytes.substr(0, 4) == "glTF";

  tinygltf::TinyGLTF loader;
  loader.SetImageLoader(&keep_image_undecoded, nullptr);
  loader.SetFsCallbacks(tinygltf::FsCallbacks{&no_file_exists, &literal_path, &refuse_read, &refuse_write, nullptr});
  loader.SetStoreOriginalJSONForExtrasAndExtensions(false);
  std::string err, warn;
  bool ok = false;
  if (binary) {
    ok = loader.LoadBinaryFromMemory(&file.model, &err, &warn, reinterpret_cast<const unsigned char*>(bytes.data()),
                                     static_cast<unsigned int>(bytes.size()), "");
  } else {
    ok = loader.LoadASCIIFromString(&file.model, &err, &warn, bytes.data(), static_cast<unsigned int>(bytes.size()), "");
  }
  if (!ok) {
    const std::string message = first_line(err);
    throw InputError(name, "not a valid glTF 2.0 file: " + (message.empty() ? std::string("cannot parse glTF") : message));
  }
  if (!warn.empty()) file.warnings.push_back(name + ": " + first_line(warn));
  check_decodable(file.model, name);
  return file;
}

}  // namespace vlit
