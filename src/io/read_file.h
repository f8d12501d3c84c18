// Reading whole files with errors that name the file. Inputs are only ever opened for reading.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace vlit {

// Throws InputError(path, ...) if the file cannot be opened or read, or is larger than max_bytes.
std::string read_text_file(const std::string& path, std::uint64_t max_bytes = std::uint64_t(1) << 30);

}  // namespace vlit
