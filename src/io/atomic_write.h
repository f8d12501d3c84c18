// Writing an output file so that it is either complete or absent: the bytes go to a temporary
// file in the same directory, which is flushed and then renamed over the destination. An
// existing file is replaced only by a complete one; on any failure the temporary is removed.
#pragma once

#include <string>
#include <string_view>

namespace vlit {

// Throws InputError(path, ...) if the file cannot be written.
void write_file_atomically(const std::string& path, std::string_view bytes);

// The file a temporary of write_file_atomically is for: "DIR/.NAME.vlit-tmp-XXXXXX" -> "DIR/NAME";
// empty when `path` is not named like such a temporary. A process killed while writing (SIGKILL,
// power loss) leaves one behind; batch/abandoned_temporaries.h removes them on resume.
std::string output_of_temporary(const std::string& path);

// Removes the temporary file of a write in progress, if there is one. Async-signal-safe: for a
// signal handler that ends the process at once (a second Ctrl-C), so that not even a temporary
// is left. (One write at a time is tracked; the others still clean up when they fail.)
void remove_temporary_in_progress() noexcept;

}  // namespace vlit
