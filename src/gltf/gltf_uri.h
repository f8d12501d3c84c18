// URIs inside a glTF file (buffers, images) as file names.
#pragma once

#include <string>

namespace vlit {

// "%20" -> " ": a relative URI's path as a file name (glTF URIs are percent-encoded, RFC 3986).
// A '%' not followed by two hex digits is kept as it is.
std::string percent_decode(const std::string& uri);

}  // namespace vlit
