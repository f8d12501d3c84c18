#include "batch/recursive_glob.h"

#include <filesystem>

#include <fnmatch.h>

namespace vlit {
namespace {

namespace fs = std::filesystem;

std::vector<std::string> components(const fs::path& path) {
  std::vector<std::string> out;
  for (const fs::path& part : path)
    if (!part.empty() && part != ".") out.push_back(part.string());
  return out;
}

// Does `name[n..]` match `pattern[p..]`? `**` takes zero or more components (a leading dot only
// explicitly, like `*`).
bool match(const std::vector<std::string>& pattern, std::size_t p, const std::vector<std::string>& name, std::size_t n) {
  if (p == pattern.size()) return n == name.size();
  if (pattern[p] == "**") {
    for (std::size_t k = n; k <= name.size(); ++k) {
      if (match(pattern, p + 1, name, k)) return true;
      if (k < name.size() && name[k].starts_with(".")) return false;  // ** does not enter hidden folders
    }
    return false;
  }
  return n < name.size() && ::fnmatch(pattern[p].c_str(), name[n].c_str(), FNM_PERIOD) == 0 &&
         match(pattern, p + 1, name, n + 1);
}

}  // namespace

bool has_recursive_wildcard(const std::string& pattern) {
  for (const std::string& part : components(pattern))
    if (part == "**") return true;
  return false;
}

std::vector<std::string> recursive_glob(const std::string& pattern, const std::string& root) {
  std::vector<std::string> found;
  const fs::path root_path = root.empty() ? fs::path(".") : fs::path(root);
  // The pattern below its root: the components after those of the root.
  const std::vector<std::string> all = components(pattern), root_parts = components(root_path);
  std::size_t skip = 0;
  while (skip < root_parts.size() && skip < all.size() && all[skip] == root_parts[skip]) ++skip;
  const std::vector<std::string> below(all.begin() + static_cast<long>(skip), all.end());
  std::error_code ec;
  for (auto it = fs::recursive_directory_iterator(root_path, fs::directory_options::skip_permission_denied, ec);
       !ec && it != fs::recursive_directory_iterator(); it.increment(ec)) {
    if (!it->is_regular_file(ec)) continue;
    const fs::path relative = it->path().lexically_relative(root_path);
    if (match(below, 0, components(relative), 0)) found.push_back((root_path / relative).string());
  }
  return found;
}

}  // namespace vlit
