#include "bake/progress_line.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace vlit {

std::string format_duration(double seconds) {
  const long s = std::lround(std::max(0.0, std::min(seconds, 1e9)));
  char buf[64];
  if (s < 60) std::snprintf(buf, sizeof buf, "%ld s", s);
  else if (s < 3600) std::snprintf(buf, sizeof buf, "%ld min %ld s", s / 60, s % 60);
  else std::snprintf(buf, sizeof buf, "%ld h %ld min", s / 3600, (s % 3600) / 60);
  return buf;
}

std::string progress_line(const std::string& label, double done, double total, double seconds) {
  char buf[128];
  std::string line = label;
  std::snprintf(buf, sizeof buf, "  %3.0f%%", total > 0 ? 100.0 * std::min(done, total) / total : 0.0);
  line += buf;
  if (seconds > 0 && done > 0) {
    const double rate = done / seconds;
    std::snprintf(buf, sizeof buf, "  %.2f M vertices/s", rate / 1e6);
    line += buf;
    line += "  ETA " + format_duration((total - done) / rate);
  }
  return line;
}

std::string batch_progress_line(std::size_t files_done, std::size_t files_total, const std::string& current,
                                double fraction, double seconds) {
  char buf[128];
  std::snprintf(buf, sizeof buf, "baking %zu/%zu files", files_done, files_total);
  std::string line = buf;
  if (!current.empty()) {
    std::snprintf(buf, sizeof buf, " %.0f%%", 100.0 * std::clamp(fraction, 0.0, 1.0));
    line += "  " + current + buf;
  }
  const double done = static_cast<double>(files_done) + (current.empty() ? 0.0 : std::clamp(fraction, 0.0, 1.0));
  if (seconds > 0 && done > 0) {
    const double rate = done / seconds;
    std::snprintf(buf, sizeof buf, "  %.2f files/s", rate);
    line += buf;
    line += "  ETA " + format_duration((static_cast<double>(files_total) - done) / rate);
  }
  return line;
}

}  // namespace vlit
