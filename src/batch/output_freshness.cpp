#include "batch/output_freshness.h"

#include <filesystem>

namespace vlit {

bool output_is_current(const std::string& output, const std::string& input, const std::string& lights) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const auto written = fs::last_write_time(output, ec);
  if (ec || !fs::is_regular_file(output, ec)) return false;
  for (const std::string& source : {input, lights}) {
    if (source.empty()) continue;
    const auto changed = fs::last_write_time(source, ec);
    if (ec || !(written > changed)) return false;
  }
  return true;
}

}  // namespace vlit
