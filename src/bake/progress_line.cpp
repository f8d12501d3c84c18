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

std::string fit_width(const std::string& line, const std::string& name, std::size_t width) {
  if (width == 0 || line.size() <= width) return line;
  std::string fitted = line;
  const std::size_t at = name.empty() ? std::string::npos : line.find(name);
  const std::size_t excess = line.size() - width;
  static const std::string kEllipsis = "...";
  if (at != std::string::npos && name.size() > excess + kEllipsis.size() + 4)
    return fitted.replace(at, name.size(), kEllipsis + name.substr(excess + kEllipsis.size()));
  return fitted.substr(0, width);
}

std::string long_bake_warning(const std::string& name, double done, double total, double seconds) {
  if (seconds < kLongBakeMinSeconds || done <= 0 || total <= done) return {};
  const double left = (total - done) * seconds / done;
  if (left <= kLongBakeSeconds) return {};
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.0f%% done after ", 100.0 * done / total);
  return name + ": this bake will take about " + format_duration(left) + " more (" + buf + format_duration(seconds) +
         "); Ctrl-C stops it without writing an output";
}

}  // namespace vlit
