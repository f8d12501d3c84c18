#include "batch/abandoned_temporaries.h"

#include "io/atomic_write.h"

namespace vlit {

std::size_t remove_abandoned_temporaries(const std::filesystem::path& out_dir, const std::set<std::string>& outputs) {
  namespace fs = std::filesystem;
  std::size_t removed = 0;
  std::error_code ec;
  for (auto it = fs::recursive_directory_iterator(out_dir, ec); !ec && it != fs::recursive_directory_iterator();
       it.increment(ec)) {
    if (!it->is_regular_file(ec)) continue;
    const std::string output = output_of_temporary(it->path().string());
    if (output.empty() || !outputs.count(fs::path(output).lexically_normal().string())) continue;
    if (fs::remove(it->path(), ec)) ++removed;
  }
  return removed;
}

}  // namespace vlit
