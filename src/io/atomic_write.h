// Writing an output file so that it is either complete or absent: the bytes go to a temporary
// file in the same directory, which is flushed and then renamed over the destination. An
// existing file is replaced only by a complete one; on any failure the temporary is removed.
#pragma once

#include <string>
#include <string_view>

namespace vlit {

// Throws InputError(path, ...) if the file cannot be written.
void write_file_atomically(const std::string& path, std::string_view bytes);

}  // namespace vlit
