// Glob patterns with `**`, as in bash's globstar and gitignore: a path component that is exactly
// `**` matches zero or more folders, every other component is matched by fnmatch(3) (`*`, `?`,
// `[...]`; a leading dot is matched only explicitly). POSIX glob(3) has no `**`: there it is `*`.
#pragma once

#include <string>
#include <vector>

namespace vlit {

// True when some path component of `pattern` is exactly "**".
bool has_recursive_wildcard(const std::string& pattern);

// The regular files under `root` (a folder, the pattern's part before its first wildcard) whose
// path matches `pattern`, each as the pattern spells its root joined with the found path, in no
// particular order. Unreadable folders are skipped; a symbolic link to a folder is not followed
// (no cycles).
std::vector<std::string> recursive_glob(const std::string& pattern, const std::string& root);

}  // namespace vlit
