#include "batch/batch_inputs.h"

#include <algorithm>
#include <map>
#include <glob.h>

#include "batch/recursive_glob.h"
#include "core/input_error.h"
#include "gltf/gltf_file.h"
#include "mesh/mesh_file.h"

namespace vlit {
namespace {

namespace fs = std::filesystem;

bool has_wildcard(const std::string& s) { return s.find_first_of("*?[") != std::string::npos; }

// The same file, however it was named.
std::string identity(const std::string& path) {
  std::error_code ec;
  const fs::path canonical = fs::weakly_canonical(path, ec);
  return ec ? fs::absolute(path).lexically_normal().string() : canonical.string();
}

}  // namespace

bool is_batch_argument(const std::string& arg) {
  std::error_code ec;
  return fs::is_directory(arg, ec) || (!fs::exists(arg, ec) && has_wildcard(arg));
}

fs::path glob_root(const std::string& pattern) {
  fs::path root;
  for (const fs::path& part : fs::path(pattern)) {
    if (has_wildcard(part.string())) break;
    root /= part;
  }
  // A pattern's last component is the wildcard part or a file name; the root is a folder.
  if (root == fs::path(pattern)) root = root.parent_path();
  return root.empty() ? fs::path(".") : root;
}

std::vector<BatchInput> expand_batch_argument(const std::string& arg) {
  std::vector<BatchInput> files;
  std::error_code ec;
  if (fs::is_directory(arg, ec)) {
    for (auto it = fs::recursive_directory_iterator(arg, ec); !ec && it != fs::recursive_directory_iterator(); it.increment(ec))
      if (it->is_regular_file(ec) && (is_gltf_path(it->path().string()) || is_mesh_path(it->path().string())))
        files.push_back({it->path().string(), fs::relative(it->path(), arg, ec).generic_string()});
    if (files.empty()) throw InputError(arg, "directory holds no .gltf, .glb, .obj, .ply, .off or .stl file");
  } else if (!fs::exists(arg, ec) && has_wildcard(arg)) {
    const fs::path root = glob_root(arg);
    std::vector<std::string> matches;
    if (has_recursive_wildcard(arg)) {
      matches = recursive_glob(arg, root.string());
    } else {
      glob_t g{};
      if (::glob(arg.c_str(), 0, nullptr, &g) == 0) matches.assign(g.gl_pathv, g.gl_pathv + g.gl_pathc);
      ::globfree(&g);
    }
    for (const std::string& match : matches) {
      const fs::path found(match);
      if (fs::is_regular_file(found, ec)) files.push_back({found.string(), found.lexically_relative(root).generic_string()});
    }
    if (files.empty()) throw InputError(arg, "pattern matches no file");
  } else {
    if (!fs::is_regular_file(arg, ec)) throw InputError(arg, "no such file");
    files.push_back({arg, fs::path(arg).filename().generic_string()});
  }
  std::sort(files.begin(), files.end(), [](const BatchInput& a, const BatchInput& b) { return a.key < b.key; });
  return files;
}

std::vector<BatchItem> lay_out_batch(const std::vector<BatchInput>& inputs, const fs::path& out_dir) {
  std::vector<BatchItem> items;
  // output -> the distinct inputs (by identity) that map to it, in order of appearance
  std::map<std::string, std::vector<std::pair<std::string, std::string>>> by_output;
  std::vector<std::string> collisions;  // outputs in order of first collision
  for (const BatchInput& in : inputs) {
    fs::path relative(in.key);
    if (!is_gltf_path(in.path)) relative.replace_extension(".glb");  // a mesh file's bake is a new glTF
    const fs::path output = (out_dir / relative).lexically_normal();
    auto& claimants = by_output[output.string()];
    const std::string id = identity(in.path);
    const bool same_file = std::any_of(claimants.begin(), claimants.end(), [&](const auto& c) { return c.first == id; });
    if (same_file) continue;  // named twice: baked once
    claimants.emplace_back(id, in.path);
    if (claimants.size() == 2) collisions.push_back(output.string());
    items.push_back({in.path, in.key, output});
  }
  if (!collisions.empty()) {
    std::string problem = std::to_string(collisions.size()) + " output(s) would be written by more than one input:";
    const std::size_t shown = std::min<std::size_t>(collisions.size(), 5);
    for (std::size_t i = 0; i < shown; ++i) {
      problem += " " + collisions[i] + " <-";
      const auto& claimants = by_output[collisions[i]];
      for (std::size_t k = 0; k < claimants.size(); ++k) problem += (k ? ", " : " ") + claimants[k].second;
      problem += ";";
    }
    if (collisions.size() > shown) problem += " ...;";
    problem += " nothing was written. Pass the folder that holds them (or a quoted glob) so that outputs keep "
               "their folders, or bake them in separate runs";
    throw InputError(out_dir.string(), problem);
  }
  return items;
}

}  // namespace vlit
