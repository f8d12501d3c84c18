#include "gltf/gltf_file.h"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <optional>

#include "core/input_error.h"
#include "gltf/decompress_geometry.h"
#include "gltf/gltf_uri.h"
#include "gltf/required_extensions.h"
#include "io/read_file.h"

namespace vlit {
namespace {

// Images are kept as they are in the file (uri or bufferView); their pixels are never decoded.
bool keep_image_undecoded(tinygltf::Image*, const int, std::string*, std::string*, int, int,
                          const unsigned char*, int, void*) {
  return true;
}

// File access for external buffers and images. tinygltf's reader trusts tellg(), so a path that
// is not a regular file (e.g. a directory) turns into an allocation of 2^63 bytes (found under
// AddressSanitizer with the malformed corpus: tinygltf/tests/issue-416.gltf). Ours: only regular files are read, sizes are bounded, nothing
// is ever written, and paths are used literally (tinygltf 2.7 no longer runs wordexp(3) on URIs,
// as older releases did; we do not rely on the library version for that).
constexpr std::uint64_t kMaxExternalFileBytes = std::uint64_t(1) << 31;

bool regular_file_exists(const std::string& path, void*) {
  std::error_code ec;
  return std::filesystem::is_regular_file(path, ec);
}

std::string literal_path(const std::string& path, void*) { return path; }

// The sum over all external files of one asset: many buffers (or images) may name the same big
// file, and each is read again.
constexpr std::uint64_t kMaxExternalBytesTotal = std::uint64_t(1) << 32;
struct ExternalReadBudget {
  std::uint64_t remaining = kMaxExternalBytesTotal;
};

bool read_regular_file(std::vector<unsigned char>* out, std::string* err, const std::string& path, void* user_data) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) {
    if (err) *err += "not a regular file: " + path + "\n";
    return false;
  }
  const auto size = std::filesystem::file_size(path, ec);
  if (ec || size > kMaxExternalFileBytes) {
    if (err) *err += "file too large or unreadable: " + path + "\n";
    return false;
  }
  auto* budget = static_cast<ExternalReadBudget*>(user_data);
  if (budget) {
    if (size > budget->remaining) {
      if (err) *err += "external files of this asset exceed " + std::to_string(kMaxExternalBytesTotal) + " bytes in total: " + path + "\n";
      return false;
    }
    budget->remaining -= size;
  }
  std::ifstream in(path, std::ios::binary);
  out->resize(static_cast<std::size_t>(size));
  if (size > 0 && !in.read(reinterpret_cast<char*>(out->data()), static_cast<std::streamsize>(size))) {
    if (err) *err += "read error: " + path + "\n";
    return false;
  }
  return true;
}

bool refuse_write(std::string* err, const std::string& path, const std::vector<unsigned char>&, void*) {
  if (err) *err += "vlit does not write through the glTF loader: " + path + "\n";
  return false;
}

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
  const std::string base_dir = [&] {
    const auto slash = path.find_last_of('/');
    return slash == std::string::npos ? std::string(".") : path.substr(0, slash);
  }();
  ExternalReadBudget budget;
  // Required extensions are checked and compressed geometry decoded before tinygltf parses.
  std::string bytes = read_text_file(path);
  std::optional<std::string> decoded = decompress_geometry(bytes, path, [&](const std::string& uri) {
    if (uri.find("://") != std::string::npos) throw InputError(path, "vlit reads no URLs: " + uri);
    std::vector<unsigned char> data;
    std::string err;
    if (!read_regular_file(&data, &err, base_dir + "/" + percent_decode(uri), &budget))
      throw InputError(path, err.substr(0, err.find('\n')));
    return std::string(data.begin(), data.end());
  });
  if (decoded) bytes = std::move(*decoded);
  const bool binary = bytes.size() >= 4 && bytes.compare(0, 4, "glTF") == 0;

  tinygltf::TinyGLTF loader;
  loader.SetImageLoader(&keep_image_undecoded, nullptr);
  loader.SetFsCallbacks(tinygltf::FsCallbacks{&regular_file_exists, &literal_path, &read_regular_file, &refuse_write, &budget});
  loader.SetStoreOriginalJSONForExtrasAndExtensions(false);
  std::string err, warn;
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
  if (!warn.empty()) {
    std::string first = warn.substr(0, warn.find('\n'));
    while (!first.empty() && (first.back() == '\r' || first.back() == ' ')) first.pop_back();
    file.warnings.push_back(path + ": " + first);
  }

  check_decodable(file.model, path);
  return file;
}

void check_decodable(const tinygltf::Model& model, const std::string& name) {
  for (const std::string& ext : model.extensionsRequired)
    if (is_compression_extension(ext))
      throw InputError(name, "requires " + ext + ", which vlit decodes only while it reads a file (vlit::load_model)");
}

}  // namespace vlit
